// Impulse2D — the error policy.
//
// Every public entry point checks its arguments before touching the world.
// A call that cannot be honoured (non-finite or out-of-range value, stale or
// null handle, another world's handle, degenerate geometry, a change while
// the world is stepping, a call on a moved-from World)
// throws i2d::Error and leaves the world exactly as it was. Exceptions were
// chosen over return codes because a refused call must not be ignored by
// accident, and over assertions because bad input comes from players and
// level files at run time, in release builds too.
#pragma once

#include <stdexcept>
#include <string>

namespace i2d {

class Error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

}  // namespace i2d
