// Testbed — `testbed view`: open a window and run scenes interactively (the
// viewer itself is render/viewer.hpp, which lists its keys).
//
//   testbed view [SCENE] [--assets DIR] [--size WxH] [--paused]
//                [--screenshot FILE --frames N]
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace tb {

/// `testbed view ...`; args are the words after "view". Returns the exit
/// code: 2 for bad arguments, 1 when no scene or window can be had.
int runViewCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace tb
