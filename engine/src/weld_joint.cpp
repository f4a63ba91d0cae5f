// The weld joint: the anchors coincide and the relative angle is held.
// Point rows as the revolute joint's 2×2 block (revolute_joint.cpp); the
// angle row C = θ_B − θ_A − θ_ref, J v = ω_B − ω_A, m_eff = 1/(I_A⁻¹ + I_B⁻¹).
// Each part is rigid (softened like every rigid row) when its hertz is 0, or a
// spring of its own hertz and damping ratio in every pass.
// Impulses: linear, angular.
#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void prepareWeldJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const WeldJointDef& def = std::get<WeldJointDef>(joint.def);
    const Body& bA = w.bodies[joint.bodyA];
    const Body& bB = w.bodies[joint.bodyB];
    jc.rA = rotate(bA.xf.q, def.localAnchorA - bA.localCenter);
    jc.rB = rotate(bB.xf.q, def.localAnchorB - bB.localCenter);
    WeldRow& row = jc.row.weld;
    const float k = jc.invIA + jc.invIB;
    row.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
    row.referenceAngle = def.referenceAngle;
    row.linearHertz = def.linearHertz;
    row.linearDampingRatio = def.linearDampingRatio;
    row.angularHertz = def.angularHertz;
    row.angularDampingRatio = def.angularDampingRatio;
}

void warmStartWeldJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    applyImpulse(jc, rA, rB, jc.impulses.linear, jc.impulses.angular, sA, sB);
}

void solveWeldJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const WeldRow& row = jc.row.weld;
    JointImpulses& acc = jc.impulses;
    const float iA = jc.invIA, iB = jc.invIB;
    if (iA + iB > 0.0f) {
        const float C = unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle);
        const RowBias rb = row.angularHertz > 0.0f
                               ? springBias(makeSoft(row.angularHertz, row.angularDampingRatio, ctx.h), C)
                               : rigidBias(ctx, C);
        const float impulse = -rb.massScale * row.axialMass * (sB.w - sA.w + rb.bias) - rb.impulseScale * acc.angular;
        acc.angular += impulse;
        sA.w -= iA * impulse;
        sB.w += iB * impulse;
    }
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    const Vec2 cdot = (sB.v + cross(sB.w, rB)) - (sA.v + cross(sA.w, rA));
    const Vec2 separation = (sB.dp - sA.dp) + (rB - rA) + jc.deltaCenter;
    const RowBias rb = row.linearHertz > 0.0f
                           ? springBias(makeSoft(row.linearHertz, row.linearDampingRatio, ctx.h), 1.0f)
                           : rigidBias(ctx, 1.0f);
    const float mA = jc.invMassA, mB = jc.invMassB;
    const float k11 = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    const float k12 = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    const float k22 = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    const Vec2 x = solveSymmetric22(k11, k12, k22, cdot + rb.bias * separation);
    const Vec2 impulse = -rb.massScale * x - rb.impulseScale * acc.linear;
    acc.linear += impulse;
    applyImpulse(jc, rA, rB, impulse, 0.0f, sA, sB);
}

}  // namespace i2d::detail
