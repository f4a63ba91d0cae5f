// Joints: what every joint type shares (the two bodies, collideConnected) and
// the bookkeeping that links joints to bodies. The rows of each type are in
// their own file (distance_joint.*).
#pragma once

#include "distance_joint.hpp"

namespace i2d::detail {

struct WorldState;

/// Links a new joint to its bodies, drops the contacts between them when
/// they may not collide, and wakes both.
void linkJoint(WorldState& w, int joint);

/// Unlinks and frees a joint; wakes both bodies and lets the broadphase
/// look at their shapes again (they may collide now).
void destroyJoint(WorldState& w, int joint);

}  // namespace i2d::detail
