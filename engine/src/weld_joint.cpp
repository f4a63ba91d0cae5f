// The weld joint: the anchors coincide and the relative angle is held.
// Point rows as the revolute joint's 2×2 block (revolute_joint.cpp); the
// angle row C = θ_B − θ_A − θ_ref, J v = ω_B − ω_A, m_eff = 1/(I_A⁻¹ + I_B⁻¹).
// Each part is rigid (softened like every rigid row) when its hertz is 0, or a
// spring of its own hertz and damping ratio in every pass. A fully rigid weld
// solves the point and the angle as one 3×3 block.
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
    const float iA = jc.invIA, iB = jc.invIB, mA = jc.invMassA, mB = jc.invMassB;
    const bool rigid = row.linearHertz == 0.0f && row.angularHertz == 0.0f;
    if (!rigid && iA + iB > 0.0f) {
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
    const float k11 = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    const float k12 = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    const float k22 = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    if (rigid) {
        // Point and angle as one 3×3 block: with a long lever arm the rows are
        // strongly coupled (the angle row moves the anchors), and solving
        // them one after the other converges too slowly to hold the weld.
        //   K = [ k11 k12 k13 ; k12 k22 k23 ; k13 k23 k33 ] with
        //   k13 = −r_Ay I_A⁻¹ − r_By I_B⁻¹, k23 = r_Ax I_A⁻¹ + r_Bx I_B⁻¹, k33 = I_A⁻¹ + I_B⁻¹.
        const float k13 = -rA.y * iA - rB.y * iB, k23 = rA.x * iA + rB.x * iB;
        float k33 = iA + iB;
        if (k33 == 0.0f) k33 = 1.0f;  // neither body turns: the angle row is moot
        const float angleError = unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle);
        const RowBias rb = rigidBias(ctx, 1.0f);
        const float b1 = cdot.x + rb.bias * separation.x, b2 = cdot.y + rb.bias * separation.y;
        const float b3 = sB.w - sA.w + rb.bias * angleError;
        // Cramer's rule on the symmetric 3×3 system.
        const float c11 = k22 * k33 - k23 * k23, c12 = k13 * k23 - k12 * k33, c13 = k12 * k23 - k13 * k22;
        float det = k11 * c11 + k12 * c12 + k13 * c13;
        if (det != 0.0f) det = 1.0f / det;
        const float c22 = k11 * k33 - k13 * k13, c23 = k13 * k12 - k11 * k23, c33 = k11 * k22 - k12 * k12;
        const float x = det * (c11 * b1 + c12 * b2 + c13 * b3);
        const float y = det * (c12 * b1 + c22 * b2 + c23 * b3);
        const float z = det * (c13 * b1 + c23 * b2 + c33 * b3);
        const Vec2 impulse = -rb.massScale * Vec2{x, y} - rb.impulseScale * acc.linear;
        const float angular = -rb.massScale * z - rb.impulseScale * acc.angular;
        acc.linear += impulse;
        acc.angular += angular;
        applyImpulse(jc, rA, rB, impulse, angular, sA, sB);
        return;
    }
    const RowBias rb = row.linearHertz > 0.0f
                           ? springBias(makeSoft(row.linearHertz, row.linearDampingRatio, ctx.h), 1.0f)
                           : rigidBias(ctx, 1.0f);
    const Vec2 x = solveSymmetric22(k11, k12, k22, cdot + rb.bias * separation);
    const Vec2 impulse = -rb.massScale * x - rb.impulseScale * acc.linear;
    acc.linear += impulse;
    applyImpulse(jc, rA, rB, impulse, 0.0f, sA, sB);
}

}  // namespace i2d::detail
