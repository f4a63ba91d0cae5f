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
    setAnchors(bA, bB, def.localAnchorA, def.localAnchorB, jc);
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
    // A weld of an exact tree has its rigid parts solved with the tree
    // (joint_tree.cpp): the point and the angle, the point alone beside an
    // angular spring, or the angle alone beside a linear spring.
    // (An angular spring the trees solve is solved there too.)
    if (!rigid && iA + iB > 0.0f && !(jc.inTree && row.angularHertz == 0.0f) && !jc.treeSpring) {
        const float C = unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle);
        const RowBias rb = row.angularHertz > 0.0f
                               ? springBias(makeSoft(row.angularHertz, row.angularDampingRatio, ctx.h), C)
                               : rigidBias(ctx, C);
        const float impulse = -rb.massScale * row.axialMass * (sB.w - sA.w + rb.bias) - rb.impulseScale * acc.angular;
        acc.angular += impulse;
        sA.w -= iA * impulse;
        sB.w += iB * impulse;
    }
    if (jc.inTree && row.linearHertz == 0.0f) return;  // the point (and a rigid weld's angle) is the tree's
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    const Vec2 cdot = (sB.v + cross(sB.w, rB)) - (sA.v + cross(sA.w, rA));
    const Vec2 separation = (sB.dp - sA.dp) + (rB - rA) + jc.deltaCenter;
    const Sym22 K = pointMatrix(mA, iA, mB, iB, rA, rB);
    if (rigid) {
        // Point and angle as one 3×3 block: with a long lever arm the rows are
        // strongly coupled (the angle row moves the anchors), and solving
        // them one after the other converges too slowly to hold the weld.
        //   K = [ k11 k12 k13 ; k12 k22 k23 ; k13 k23 k33 ] with
        //   k13 = −r_Ay I_A⁻¹ − r_By I_B⁻¹, k23 = r_Ax I_A⁻¹ + r_Bx I_B⁻¹, k33 = I_A⁻¹ + I_B⁻¹.
        const double K13 = -double(rA.y) * iA - double(rB.y) * iB, K23 = double(rA.x) * iA + double(rB.x) * iB;
        double K33 = double(iA) + iB;
        if (K33 == 0.0) K33 = 1.0;  // neither body turns: the angle row is moot
        const float angleError = unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle);
        const RowBias rb = rigidBias(ctx, 1.0f);
        const float b1 = cdot.x + rb.bias * separation.x, b2 = cdot.y + rb.bias * separation.y;
        const float b3 = sB.w - sA.w + rb.bias * angleError;
        // Cramer's rule on the symmetric 3×3 system, in double precision (see
        // Sym22: the entries of a tiny body overflow single precision).
        const double K11 = K.k11, K12 = K.k12, K22 = K.k22;
        const double c11 = K22 * K33 - K23 * K23, c12 = K13 * K23 - K12 * K33, c13 = K12 * K23 - K13 * K22;
        double det = K11 * c11 + K12 * c12 + K13 * c13;
        if (det != 0.0) det = 1.0 / det;
        const double c22 = K11 * K33 - K13 * K13, c23 = K13 * K12 - K11 * K23, c33 = K11 * K22 - K12 * K12;
        const float x = static_cast<float>(det * (c11 * b1 + c12 * b2 + c13 * b3));
        const float y = static_cast<float>(det * (c12 * b1 + c22 * b2 + c23 * b3));
        const float z = static_cast<float>(det * (c13 * b1 + c23 * b2 + c33 * b3));
        const Vec2 impulse = -rb.massScale * Vec2{x, y} - rb.impulseScale * acc.linear;
        const float angular = -rb.massScale * z - rb.impulseScale * acc.angular;
        acc.linear += impulse;
        acc.angular += angular;
        applyImpulse(jc, rA, rB, impulse, angular, sA, sB);
        return;
    }
    PointSpring spring;
    if (row.linearHertz > 0.0f &&
        makePointSpring(row.linearHertz, row.linearDampingRatio, ctx.h, mA + mB, K.k11 + K.k22, spring)) {
        // A spring of fixed stiffness on the anchors (soft_constraint.hpp).
        const double g = spring.gamma;
        const Vec2 x = solveSymmetric22({K.k11 + g, K.k12, K.k22 + g},
                                        cdot + spring.biasRate * separation + spring.gamma * acc.linear);
        acc.linear -= x;
        applyImpulse(jc, rA, rB, -x, 0.0f, sA, sB);
        return;
    }
    const RowBias rb = row.linearHertz > 0.0f
                           ? springBias(makeSoft(row.linearHertz, row.linearDampingRatio, ctx.h), 1.0f)
                           : rigidBias(ctx, 1.0f);
    const Vec2 x = solveSymmetric22(K, cdot + rb.bias * separation);
    const Vec2 impulse = -rb.massScale * x - rb.impulseScale * acc.linear;
    acc.linear += impulse;
    applyImpulse(jc, rA, rB, impulse, 0.0f, sA, sB);
}

void weldEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows) {
    // Its rigid parts (equalityRowCount): the point (rows 0, 1) unless it is
    // a spring, then the angle unless it is one.
    const WeldRow& row = jc.row.weld;
    int angle = 0;
    if (row.linearHertz == 0.0f) {
        const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
        pointRows(rA, rB, (sB.dp - sA.dp) + (rB - rA) + jc.deltaCenter, rows);
        angle = 2;
    }
    rows.count = angle;
    if (row.angularHertz != 0.0f) return;
    rows.count = angle + 1;
    angleRow(unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle), angle, rows);
}

}  // namespace i2d::detail
