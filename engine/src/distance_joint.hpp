// The distance joint: what the world keeps of it, and its constraint rows.
//
// Constraint (Tamis and Maggiore (2015), Constraint based physics solver,
// §5.2): C = |p_B − p_A| − L, with p_A, p_B the anchors in world space. Its
// Jacobian is the unit axis u = (p_B − p_A)/|p_B − p_A| applied at the
// anchors: J v = u·(v_B + ω_B × r_B − v_A − ω_A × r_A). The paper's
// ½(|p_AB|² − L²) has the same Jacobian direction scaled by |p_AB|, so the
// effective mass is taken along the unit axis:
//   m_eff = 1 / (m_A⁻¹ + m_B⁻¹ + I_A⁻¹ (r_A × u)² + I_B⁻¹ (r_B × u)²).
// Rigid: one bilateral row, softened in soft_step by the joint hertz and
// damping ratio of the world (soft_constraint.hpp), pushed by the push factor
// in baumgarte and split. Spring: the row softened by the joint's own hertz
// and damping ratio in every pass. Limits: two one-sided rows, length ≥ min
// (pushes apart) and length ≤ max (a rope, pulls together), speculative
// while inside the range.
#pragma once

#include <cstdint>
#include <vector>

#include "body.hpp"
#include "impulse2d/types.hpp"
#include "slot_array.hpp"
#include "soft_constraint.hpp"

namespace i2d::detail {

struct WorldState;

struct DistanceJoint {
    DistanceJointDef def{};
    int bodyA = kNullIndex, bodyB = kNullIndex;
    float impulse = 0.0f;       ///< rigid/spring axial impulse (N·s), kept for the warm start
    float lowerImpulse = 0.0f;  ///< min-length limit
    float upperImpulse = 0.0f;  ///< max-length limit
    float lastForce = 0.0f;     ///< N, over the last step
    std::uint32_t generation = 1;
    bool alive = false;
};

/// One distance joint's rows during a step, in the contiguous array the
/// passes stream through.
struct DistanceJointConstraint {
    int joint = kNullIndex;
    int a = kNullIndex, b = kNullIndex;  ///< solver body indices; kNullIndex for a body that does not move this step
    Vec2 rA{}, rB{};                     ///< anchors relative to the centres of mass at step start (world)
    Vec2 deltaCenter{};                  ///< centre B − centre A at step start
    float axialMass = 0.0f;
    float invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
    float length = 0, minLength = 0, maxLength = 0;
    float hertz = 0, dampingRatio = 0;
    float impulse = 0, lowerImpulse = 0, upperImpulse = 0;
    bool rigid = true;  ///< not a spring (or a spring pinned by equal limits)
    bool enableLimit = false;
};

/// Builds this step's rows of every joint with an awake body.
void prepareDistanceJoints(WorldState& w);
void warmStartDistanceJoints(WorldState& w);
void solveDistanceJoints(WorldState& w, float h, SolvePass pass);
/// Split mode: the joints' position error solved on the pseudo-velocities.
void solveDistanceJointPush(WorldState& w, float h);
/// Impulses back into the joints for the next warm start; the force of the step.
void storeDistanceJointImpulses(WorldState& w, float dt);

}  // namespace i2d::detail
