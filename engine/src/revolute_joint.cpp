// The revolute joint (a hinge): anchors A and B coincide, the bodies turn
// freely about them, with an optional angle limit, motor and rotational spring.
//
// Point constraint: C = p_B − p_A (2 rows), J v = v_B + ω_B × r_B − v_A − ω_A × r_A,
// effective mass K = (m_A⁻¹ + m_B⁻¹) I + I_A⁻¹ [r_A]ᵀ[r_A] + I_B⁻¹ [r_B]ᵀ[r_B] with
// [r] = (−r_y, r_x), i.e.
//   K = [ m_A⁻¹ + m_B⁻¹ + I_A⁻¹ r_Ay² + I_B⁻¹ r_By²      −I_A⁻¹ r_Ax r_Ay − I_B⁻¹ r_Bx r_By ]
//       [ −I_A⁻¹ r_Ax r_Ay − I_B⁻¹ r_Bx r_By      m_A⁻¹ + m_B⁻¹ + I_A⁻¹ r_Ax² + I_B⁻¹ r_Bx² ],
// solved as one 2×2 block and softened like every rigid row (joint_rows.hpp).
// Angular rows (spring, motor, limits): C = θ_B − θ_A − θ_ref, J v = ω_B − ω_A,
// m_eff = 1/(I_A⁻¹ + I_B⁻¹). The spring is soft by its own hertz in every
// pass; the motor drives ω_B − ω_A to the motor speed within ±h·maxTorque per
// (sub)step; the limits are one-sided rows on θ − lower ≥ 0 and upper − θ ≥ 0.
// Impulses: linear (point), spring, motor, lower, upper.
#include <cmath>

#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void prepareRevoluteJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const RevoluteJointDef& def = std::get<RevoluteJointDef>(joint.def);
    const Body& bA = w.bodies[joint.bodyA];
    const Body& bB = w.bodies[joint.bodyB];
    setAnchors(bA, bB, def.localAnchorA, def.localAnchorB, jc);
    RevoluteRow& row = jc.row.revolute;
    const float k = jc.invIA + jc.invIB;
    row.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
    row.referenceAngle = def.referenceAngle;
    row.lowerAngle = def.lowerAngle;
    row.upperAngle = def.upperAngle;
    row.motorSpeed = def.motorSpeed;
    row.maxMotorTorque = def.maxMotorTorque;
    row.hertz = def.hertz;
    row.dampingRatio = def.dampingRatio;
    row.enableLimit = def.enableLimit;
    row.enableMotor = def.enableMotor;
    row.enableSpring = def.enableSpring;
}

namespace {

/// A limit acts through the point constraint: its angular impulse L comes
/// with the point impulse P = −L·K⁻¹k that leaves the anchors' relative
/// velocity as it is (K the point rows' matrix, k = I_A⁻¹·perp(r_A) +
/// I_B⁻¹·perp(r_B) what an angular impulse does to that velocity), so the
/// point row solved next does not undo it. The limit row's mass is then
/// 1/(I_A⁻¹ + I_B⁻¹ − kᵀK⁻¹k): for a body on a fixed pivot, its inertia about
/// the pivot, I + m·r². With the bodies' own inertias alone, 1/(I_A⁻¹ + I_B⁻¹),
/// the point row gave back all but I/(I + m·r²) of each stop: a small bob on
/// a 1.94 m arm swung into its limit at 8 m/s passed it by 0.2 rad, and at
/// 50 m/s went past π, where the wrapped angle put it beyond the other limit,
/// which threw it on (its energy ×14). The pair (L, P) is applied together
/// whenever L is, warm start included; P is not part of the point row's own
/// accumulated impulse (its softness would take a share of it back and leave
/// the rest of L unpaired).
struct LimitThroughPoint {
    float mass;   ///< the limit row's effective mass
    Vec2 follow;  ///< P per unit of L
};

LimitThroughPoint limitThroughPoint(const JointConstraint& jc, Vec2 rA, Vec2 rB) {
    // A joint of an exact tree has its point solved with the tree, and its
    // limit too while it holds (joint_tree.cpp): a point impulse from this
    // joint's own K alone would not pair with the tree's.
    if (jc.inTree) return {jc.row.revolute.axialMass, {}};
    const float iA = jc.invIA, iB = jc.invIB;
    const Vec2 k = iA * leftPerp(rA) + iB * leftPerp(rB);
    const Vec2 kInvK = solvePointRows(jc, rA, rB, k);
    const float schur = iA + iB - dot(k, kInvK);
    if (!(schur > 0.0f) || !std::isfinite(schur)) return {jc.row.revolute.axialMass, {}};
    return {1.0f / schur, -kInvK};
}

/// The point impulse that goes with the limits' accumulated impulse.
Vec2 limitPointImpulse(const JointConstraint& jc, Vec2 rA, Vec2 rB) {
    const float limit = jc.impulses.lower - jc.impulses.upper;
    if (limit == 0.0f || !(jc.invIA + jc.invIB > 0.0f)) return {};
    return limit * limitThroughPoint(jc, rA, rB).follow;
}

}  // namespace

Vec2 revoluteLimitPointImpulse(const JointConstraint& jc, const BodyState& sA, const BodyState& sB) {
    return limitPointImpulse(jc, rotate(sA.dq, jc.rA), rotate(sB.dq, jc.rB));
}

void warmStartRevoluteJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    const JointImpulses& acc = jc.impulses;
    const float axial = acc.spring + acc.motor + acc.lower - acc.upper;
    applyImpulse(jc, rA, rB, acc.linear + limitPointImpulse(jc, rA, rB), axial, sA, sB);
}

void solveRevoluteJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const RevoluteRow& row = jc.row.revolute;
    JointImpulses& acc = jc.impulses;
    const float iA = jc.invIA, iB = jc.invIB;
    const bool turns = iA + iB > 0.0f;
    auto applyAngular = [&](float impulse) {
        sA.w -= iA * impulse;
        sB.w += iB * impulse;
    };
    float angle = 0.0f;
    if (turns && (row.enableSpring || row.enableLimit))
        angle = unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle);

    // (A spring the tree solve takes is solved there, joint_tree.cpp.)
    if (row.enableSpring && turns && row.hertz > 0.0f && !jc.treeSpring) {
        const RowBias rb = springBias(makeSoft(row.hertz, row.dampingRatio, ctx.h), angle);
        const float impulse = -rb.massScale * row.axialMass * (sB.w - sA.w + rb.bias) - rb.impulseScale * acc.spring;
        acc.spring += impulse;
        applyAngular(impulse);
    }
    if (row.enableMotor && turns) {
        const float maxImpulse = ctx.h * row.maxMotorTorque;
        float impulse = -row.axialMass * (sB.w - sA.w - row.motorSpeed);
        impulse = boundedIncrement(acc.motor, impulse, -maxImpulse, maxImpulse);
        applyAngular(impulse);
    }
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    // The point constraint, solved as one 2×2 block (or with its tree,
    // joint_tree.cpp). Before the limits: a warm start or an angular row
    // leaves a small body on a long arm spinning at a speed its anchor does
    // not have until the point row has acted, and a limit judged on that
    // spin let go of a bob held against it.
    if (!jc.inTree) {
        const Vec2 cdot = (sB.v + cross(sB.w, rB)) - (sA.v + cross(sA.w, rA));
        const Vec2 separation = (sB.dp - sA.dp) + (rB - rA) + jc.deltaCenter;
        const RowBias rb = rigidBias(ctx, 1.0f);  // the rates, applied to each component of the separation
        const Vec2 x = solvePointRows(jc, rA, rB, cdot + rb.bias * separation);
        const Vec2 impulse = -rb.massScale * x - rb.impulseScale * acc.linear;
        acc.linear += impulse;
        applyImpulse(jc, rA, rB, impulse, 0.0f, sA, sB);
    }
    if (row.enableLimit && turns && jc.treeLimit == 0) {  // (else the tree holds it)
        const LimitThroughPoint through = limitThroughPoint(jc, rA, rB);
        auto applyLimit = [&](float impulse) { applyImpulse(jc, rA, rB, impulse * through.follow, impulse, sA, sB); };
        // Lower: θ − lower ≥ 0, along +(ω_B − ω_A).
        {
            const RowBias rb = limitBias(ctx, angle - row.lowerAngle);
            float impulse = -rb.massScale * through.mass * (sB.w - sA.w + rb.bias) - rb.impulseScale * acc.lower;
            impulse = boundedIncrement(acc.lower, impulse, 0.0f, INFINITY);
            applyLimit(impulse);
        }
        // Upper: upper − θ ≥ 0, along −(ω_B − ω_A).
        {
            const RowBias rb = limitBias(ctx, row.upperAngle - angle);
            float impulse = -rb.massScale * through.mass * (sA.w - sB.w + rb.bias) - rb.impulseScale * acc.upper;
            impulse = boundedIncrement(acc.upper, impulse, 0.0f, INFINITY);
            applyLimit(-impulse);
        }
    }
}

bool revoluteLimitCoordinate(const JointConstraint& jc, const BodyState& sA, const BodyState& sB,
                             LimitCoordinate& out) {
    const RevoluteRow& row = jc.row.revolute;
    if (!row.enableLimit || !(jc.invIA + jc.invIB > 0.0f)) return false;
    out = {unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle), row.lowerAngle, row.upperAngle};
    return true;
}

void revoluteEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows) {
    const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
    rows.count = 2;
    pointRows(rA, rB, (sB.dp - sA.dp) + (rB - rA) + jc.deltaCenter, rows);
    if (jc.treeLimit == 0) return;
    // The limit the tree holds, as an equality row on ω_B − ω_A whose error is
    // the angle beyond it (the sign check in joint_tree.cpp lets it go when it
    // would pull).
    const RevoluteRow& row = jc.row.revolute;
    const float angle = unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle);
    rows.count = 3;
    angleRow(angle - (jc.treeLimit < 0 ? row.lowerAngle : row.upperAngle), 2, rows);
}

}  // namespace i2d::detail
