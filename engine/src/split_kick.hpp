// Forces split around the drift: the velocity Verlet (kick-drift-kick)
// integration of bodies that touch nothing, in soft_step.
//
// The soft step's substep is semi-implicit Euler: v += h·a, solve, x += h·v,
// relax. Its stored velocity lags the body's true velocity by half a
// substep of acceleration (v_true = v + a·h/2, impact_stage.cpp), and the
// energy it shows swings by about ω·h/2 of the motion's energy (ω the
// motion's angular frequency): a 1 m pendulum at one substep rose 1.1 to
// 1.4 % above its release, pendulums of 5 to 20 cm at four substeps 1.1 to
// 1.4 % (docs/validation.md, energy audit). Split, the substep is
//   v += (h/2)·a, solve (biased), x += h·v, v += (h/2)·a, relax,
// which is RATTLE, the velocity Verlet method for constrained motion
// (Andersen (1983), Rattle: a "velocity" version of the Shake algorithm for
// molecular dynamics calculations; Hairer, Lubich and Wanner (2006),
// Geometric Numerical Integration, §VII.1): the biased pass holds the
// constraints at the new positions, the relax pass projects the velocity
// onto them there, and the method is of second order and symmetric. The
// stored velocity is the true one: a body in flight follows its parabola
// exactly, and a pendulum's energy never rises above its release (measured:
// not at all at 1, 2 and 4 substeps, Joints.APendulumNeverRaisesItsEnergy).
//
// Only where the relax pass can carry the second half kick. A body resting
// on others needs its share of the weight from the relax pass's one
// Gauss-Seidel sweep, which does not reach up a stack (split everywhere, the
// top of a column of 20 ended every step falling at h·g/2 = 0.021 m/s), so
// a body with a contact row keeps the whole kick before the solve, as does
// every body joined to it through joints, and every body joined to a
// spring, a motor or a drive (a soft spring solved in the biased pass took
// the load of the first half only: a slider on a 3.6 Hz spring gained 6.5 %
// of the energy it exchanges at one substep). The choice is made each
// step; a body whose choice changes has its velocity moved by ±g·h/2 (half
// a substep of its gravity) from one meaning to the other, which keeps a
// free body's flight exact (recordChoice, split_kick.cpp, says why gravity
// alone, and why a jointed body's is moved too).
#pragma once

#include "body.hpp"

namespace i2d::detail {

struct WorldState;
struct SolverArrays;
struct Joint;

/// Body b's velocity made the lagging one in place (as laggingVelocity, the
/// spin by its torque's angular acceleration the same way, within the speed
/// limits maxSpeed and maxSpin) before the impact stage strikes it: a struck
/// body has a contact and takes the whole kick this step.
void makeVelocityLag(Body& b, Vec2 gravity, float halfSubstep, float maxSpeed, float maxSpin);

/// Whether a joint only holds (a rigid row, a limit): no spring, motor or
/// drive, whose load the relax pass could not carry.
bool jointOnlyHolds(const Joint& j);

/// In the solve stage, after the colouring (which marks the bodies with
/// contact rows): which awake bodies without joints have their forces split
/// this step (soft_step, no contact row), each one's velocity moved to that
/// meaning when its choice changed, and their substep accelerations and
/// damping halved (the kick is given twice); marked in
/// BodyIntegration::split, SolverArrays::splitKickCount of them. In the
/// other modes no body is split. h is the substep.
void splitFreeBodies(WorldState& w, float h, bool soft);

/// The same for the bodies with joints, once the joint plan is made: a body
/// is split when no body joined to it through the plan's joints has a contact
/// row or a joint that does more than hold.
void splitJointedBodies(WorldState& w, float h, bool soft);

/// The groups of moving states the joint plan's joints join (a union-find,
/// each member naming its root in SolverArrays::splitKickGroup) and whether
/// each group has a joint that does more than hold (splitKickDrives, by
/// root): made with the plan (joint_solver.cpp), which is kept while the
/// awake bodies and the joints are, so a step only marks the groups with a
/// contact row. Found afresh every step (with the second half kick given
/// body by body), joint_grid's step was 30 % slower; now 7 %.
void groupJointedStates(SolverArrays& s);

/// The second half kick of the split bodies, after a substep's drift and
/// before its relax pass, within the speed limit.
void kickAfterDrift(SolverArrays& s, float h, float maxSpeed);

}  // namespace i2d::detail
