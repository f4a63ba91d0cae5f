// Impulse2D — handles to bodies, shapes and joints.
//
// A handle is a small value: a slot index, that slot's generation and the id
// of the world that made it. The world bumps the generation when it frees a
// slot, so a handle kept after its object was destroyed no longer matches
// and is reported as stale instead of silently naming whatever reuses the
// slot; a handle passed to another world is refused too. The all-zero handle
// is null.
#pragma once

#include <cstdint>

namespace i2d {

template <class Tag>
struct Handle {
    std::uint32_t index1 = 0;      ///< slot index + 1; 0 means null
    std::uint32_t generation = 0;  ///< slot generation when the handle was made
    std::uint32_t world = 0;       ///< id of the world that made it (never 0 for a live world)

    constexpr bool isNull() const { return index1 == 0; }
    friend constexpr bool operator==(Handle a, Handle b) = default;
};

struct BodyTag {};
struct ShapeTag {};
struct JointTag {};

/// A rigid body in a World.
using BodyId = Handle<BodyTag>;
/// A shape attached to a body.
using ShapeId = Handle<ShapeTag>;
/// A joint (constraint) between two bodies.
using JointId = Handle<JointTag>;

}  // namespace i2d
