// The mouse joint: pulls a point of body B towards a target in the world
// with a spring of the joint's hertz and damping ratio and at most maxForce
// (dragging a body with the mouse). Body A is only a reference and is never
// moved. C = p_B − target (2 rows), J v = v_B + ω_B × r_B,
// K = m_B⁻¹ I + I_B⁻¹ [r_B]ᵀ[r_B]; soft in every pass (soft_constraint.hpp),
// accumulated impulse clamped to a disc of h·maxForce.
// Impulses: linear.
#include <cmath>

#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void prepareMouseJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const MouseJointDef& def = std::get<MouseJointDef>(joint.def);
    const Body& bB = w.bodies[joint.bodyB];
    // Body A is a reference only: the row never moves it.
    jc.invMassA = jc.invIA = 0.0f;
    jc.rA = {};
    jc.rB = rotate(bB.xf.q, joint.localAnchorB - bB.localCenter);
    MouseRow& row = jc.row.mouse;
    row.targetFromCenterB = def.target - bB.center;
    row.hertz = def.hertz;
    row.dampingRatio = def.dampingRatio;
    row.maxForce = def.maxForce;
}

void warmStartMouseJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    const Vec2 rB = rotate(sB.dq, jc.rB);
    applyImpulse(jc, Vec2{}, rB, jc.impulses.linear, 0.0f, sA, sB);
}

void solveMouseJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const MouseRow& row = jc.row.mouse;
    JointImpulses& acc = jc.impulses;
    const Vec2 rB = rotate(sB.dq, jc.rB);
    const Vec2 C = sB.dp + rB - row.targetFromCenterB;
    const RowBias rb = springBias(makeSoft(row.hertz, row.dampingRatio, ctx.h), 1.0f);
    const Vec2 cdot = sB.v + cross(sB.w, rB);
    const float mB = jc.invMassB, iB = jc.invIB;
    const Sym22 K = pointMatrix(0.0, 0.0, mB, iB, Vec2{}, rB);
    const Vec2 x = solveSymmetric22(K, cdot + rb.bias * C);
    Vec2 impulse = -rb.massScale * x - rb.impulseScale * acc.linear;
    impulse = discBoundedIncrement(acc.linear, impulse, ctx.h * row.maxForce);
    applyImpulse(jc, Vec2{}, rB, impulse, 0.0f, sA, sB);
}

}  // namespace i2d::detail
