// The warm starts a step begins with: the impulses each contact and joint
// kept from the last step, made to fit this one.
//
// A warm start is an impulse per substep, a force times the substep length
// h, re-applied at the start of every substep. Two things make the last
// step's impulse wrong for this one. The substep may be of another length
// (the game steps with its frame time, or changes the substep count): the
// loads are the same forces over a different h, so each impulse is scaled by
// h/h_last, as Box2D 2.4.1 scales its warm starts by the ratio of the steps
// (b2TimeStep::dtRatio). Unscaled, a column of 20 unit boxes stepped with
// lengths drawn from [1/75, 1/50] s moved at 0.19 m/s, a pyramid of 20 rows
// at 0.32 m/s (scaled: 0.004 and 0.0004). Lengths that swing far apart every
// step (1/30 and 1/120 s in turn) still shake some columns, more than
// unscaled (docs/validation.md, "Steps of changing length"). And the game may
// have stopped applying a force, or changed the gravity, the contacts and
// joints carried (releaseRemovedForces, lost_load.hpp).
#pragma once

namespace i2d::detail {

struct WorldState;

/// At the start of a step of length dt, before the contacts carry their
/// impulses to this step's manifolds: every contact's and joint's impulses
/// scaled to this step's substep when its length changed since the last
/// step, then the forces and weights the game took away released.
void carryWarmStarts(WorldState& w, float dt);

}  // namespace i2d::detail
