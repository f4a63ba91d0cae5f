// The joint rows of a step (joint_solver.cpp): prepare, warm start, one
// sweep per pass, split mode's push, store.
#pragma once

#include "joint.hpp"

namespace i2d::detail {

struct WorldState;

/// Rows of every joint with an awake body, coloured; dt is the whole step, h
/// a substep (the exact trees' geometric stiffness, buildJointTrees).
void prepareJoints(WorldState& w, float dt, float h);
void warmStartJoints(WorldState& w);
/// One Gauss-Seidel sweep over the joint rows in ctx's pass.
void solveJoints(WorldState& w, const JointContext& ctx);
/// Split mode (Tamis and Maggiore (2015) §8.1): the joints' position error on
/// the pseudo-velocities (SolverArrays::biasV, biasW); with `deepOnly`, the
/// soft step's deep joints' alone (isDeepJoint, world_state.hpp).
void pushJoints(WorldState& w, const JointContext& ctx, bool deepOnly = false);
/// Impulses back into the joints for the next warm start; reaction force,
/// torque and motor effort. `h` is the interval the accumulated impulses act
/// over: the substep in soft_step (each substep re-solves from the warm
/// start, so the accumulated impulse is one substep's), the step otherwise.
void storeJoints(WorldState& w, float h);

}  // namespace i2d::detail
