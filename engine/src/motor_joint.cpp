// The motor joint: drives body B towards a position and angle relative to
// body A with limited force and torque.
//
// Linear: the point of A at linearOffset (A's frame) and B's origin should
// coincide: C = p_B − p_A, J v as the revolute joint's point rows (2×2 block).
// Angular: C = θ_B − θ_A − θ_offset, J v = ω_B − ω_A. Each is driven by the
// velocity target −(correctionFactor/Δt)·C (Δt the whole step, so the rate of
// correction does not depend on the substeps) in every pass, and its
// accumulated impulse is clamped to h·maxForce (a disc) and ±h·maxTorque: with
// correctionFactor 0 the joint only resists relative motion up to those
// limits, which is friction for a top-down game.
// Impulses: linear, angular.
#include <cmath>

#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void prepareMotorJoint(const WorldState& w, const Joint& joint, JointConstraint& jc, float dt) {
    const MotorJointDef& def = std::get<MotorJointDef>(joint.def);
    const Body& bA = w.bodies[joint.bodyA];
    const Body& bB = w.bodies[joint.bodyB];
    jc.rA = rotate(bA.xf.q, def.linearOffset - bA.localCenter);
    jc.rB = rotate(bB.xf.q, Vec2{} - bB.localCenter);
    MotorRow& row = jc.row.motor;
    const float k = jc.invIA + jc.invIB;
    row.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
    row.angularOffset = def.angularOffset;
    row.maxForce = def.maxForce;
    row.maxTorque = def.maxTorque;
    row.correctionRate = def.correctionFactor / dt;
}

void warmStartMotorJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    applyImpulse(jc, rA, rB, jc.impulses.linear, jc.impulses.angular, sA, sB);
}

void solveMotorJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const MotorRow& row = jc.row.motor;
    JointImpulses& acc = jc.impulses;
    const float iA = jc.invIA, iB = jc.invIB;
    if (iA + iB > 0.0f) {
        const float C = unwindAngle(relativeAngle(jc, sA, sB) - row.angularOffset);
        const float maxImpulse = ctx.h * row.maxTorque;
        float impulse = -row.axialMass * (sB.w - sA.w + row.correctionRate * C);
        impulse = boundedIncrement(acc.angular, impulse, -maxImpulse, maxImpulse);
        sA.w -= iA * impulse;
        sB.w += iB * impulse;
    }
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    const Vec2 separation = (sB.dp - sA.dp) + (rB - rA) + jc.deltaCenter;
    const Vec2 cdot = (sB.v + cross(sB.w, rB)) - (sA.v + cross(sA.w, rA)) + row.correctionRate * separation;
    const float mA = jc.invMassA, mB = jc.invMassB;
    const Sym22 K = pointMatrix(mA, iA, mB, iB, rA, rB);
    Vec2 impulse = -1.0f * solveSymmetric22(K, cdot);
    impulse = discBoundedIncrement(acc.linear, impulse, ctx.h * row.maxForce);
    applyImpulse(jc, rA, rB, impulse, 0.0f, sA, sB);
}

}  // namespace i2d::detail
