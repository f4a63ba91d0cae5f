// The distance joint's rows (the constraint and its effective mass are in
// distance_joint.hpp).
#include <algorithm>
#include <cmath>

#include "distance_joint.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// The anchors and the axis at the current point of the step.
struct JointFrame {
    Vec2 rA, rB, axis;
    float length;
};

JointFrame currentFrame(const JointConstraint& jc, const BodyState& sA, const BodyState& sB) {
    JointFrame f;
    f.rA = rotate(sA.dq, jc.rA);
    f.rB = rotate(sB.dq, jc.rB);
    Vec2 d = (sB.dp - sA.dp) + jc.deltaCenter + f.rB - f.rA;
    f.axis = normalize(d, f.length);
    return f;
}

/// The effective mass along the axis at the frame's point of the step,
/// 1/(m_A⁻¹ + m_B⁻¹ + I_A⁻¹(r_A × n)² + I_B⁻¹(r_B × n)²). It is the frame's,
/// not the step start's: the lever arms r × n of a body that turns within
/// the step change with it, and for a small body hung by a point far from
/// its centre they are most of the sum (a 0.12 m disc hung 0.87 m off its
/// centre: I⁻¹(r × n)² is 110 times m⁻¹ across the arm and 0 along it). With
/// the mass of the step's start, a row prepared with the arm along the axis
/// took the body's whole mass where, a substep later, a hundredth of it
/// moved the anchor: each pass overshot a hundredfold and the disc spun up to
/// the rotation limit, 2,700 times its energy.
float axialMassOf(const JointConstraint& jc, const JointFrame& f) {
    const float crA = cross(f.rA, f.axis), crB = cross(f.rB, f.axis);
    const float k = jc.invMassA + jc.invMassB + jc.invIA * crA * crA + jc.invIB * crB * crB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

void applyAxial(const JointConstraint& jc, const JointFrame& f, float impulse, BodyState& sA, BodyState& sB) {
    Vec2 P = impulse * f.axis;
    sA.v = mulSub(sA.v, jc.invMassA, P);
    sA.w -= jc.invIA * cross(f.rA, P);
    sB.v = mulAdd(sB.v, jc.invMassB, P);
    sB.w += jc.invIB * cross(f.rB, P);
}

}  // namespace

void prepareDistanceJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const DistanceJointDef& def = std::get<DistanceJointDef>(joint.def);
    const Body& bA = w.bodies[joint.bodyA];
    const Body& bB = w.bodies[joint.bodyB];
    DistanceRow& row = jc.row.distance;
    setAnchors(bA, bB, def.localAnchorA, def.localAnchorB, jc);
    row.length = def.length;
    row.minLength = def.minLength;
    row.maxLength = def.maxLength;
    row.hertz = def.hertz;
    row.dampingRatio = def.dampingRatio;
    row.enableLimit = def.enableLimit;
    row.rigid = isRigidDistance(def);
}

void warmStartDistanceJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    JointFrame f = currentFrame(jc, sA, sB);
    applyAxial(jc, f, jc.impulses.axial + jc.impulses.lower - jc.impulses.upper, sA, sB);
}

void solveDistanceJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const DistanceRow& row = jc.row.distance;
    JointFrame f = currentFrame(jc, sA, sB);
    const float mass = axialMassOf(jc, f);
    // A joint's impulse per (sub)step never needs to exceed what changes
    // the relative speed along it by twice the speed limit; bounding it
    // keeps a diverging row (a fuzzed, stretched 600:1 joint reached
    // 1e36 N·s, then NaN) finite.
    const float maxImpulse = 2.0f * ctx.maxLinearSpeed * mass;
    auto cdot = [&]() {
        Vec2 dv = (sB.v + cross(sB.w, f.rB)) - (sA.v + cross(sA.w, f.rA));
        return dot(dv, f.axis);
    };
    if (row.rigid && jc.inTree) {
        // the length is solved with its tree (joint_tree.cpp)
    } else if (row.rigid) {
        const RowBias rb = rigidBias(ctx, f.length - row.length);
        float impulse = -rb.massScale * mass * (cdot() + rb.bias) - rb.impulseScale * jc.impulses.axial;
        impulse = boundedIncrement(jc.impulses.axial, impulse, -maxImpulse, maxImpulse);
        applyAxial(jc, f, impulse, sA, sB);
    } else if (row.hertz > 0.0f && !jc.treeSpring) {  // (else it is solved with the trees, joint_tree.cpp)
        // A spring: its softness is physical, so it applies in every pass.
        const RowBias rb = springBias(makeSpring(row.hertz, row.dampingRatio, ctx.h, springMassRatio(jc, mass)),
                                      f.length - row.length);
        float impulse = -rb.massScale * mass * (cdot() + rb.bias) - rb.impulseScale * jc.impulses.axial;
        impulse = boundedIncrement(jc.impulses.axial, impulse, -maxImpulse, maxImpulse);
        applyAxial(jc, f, impulse, sA, sB);
    }
    if (row.enableLimit && row.minLength < row.maxLength && jc.treeLimit == 0) {  // (else the tree holds it)
        // One-sided limit row along `sign`·axis: C ≥ 0 is allowed (speculative
        // when positive), the accumulated impulse stays ≥ 0.
        auto limitRow = [&](float C, float sign, float& accumulated) {
            const RowBias rb = limitBias(ctx, C);
            float impulse = -rb.massScale * mass * (sign * cdot() + rb.bias) - rb.impulseScale * accumulated;
            impulse = boundedIncrement(accumulated, impulse, 0.0f, maxImpulse);
            applyAxial(jc, f, sign * impulse, sA, sB);
        };
        // Lower limit: length ≥ minLength (pushes apart).
        limitRow(f.length - row.minLength, 1.0f, jc.impulses.lower);
        // Upper limit: length ≤ maxLength, a rope (pulls together).
        limitRow(row.maxLength - f.length, -1.0f, jc.impulses.upper);
    }
}

bool distanceLimitCoordinate(const JointConstraint& jc, const BodyState& sA, const BodyState& sB,
                             LimitCoordinate& out) {
    const DistanceRow& row = jc.row.distance;
    if (row.rigid || !row.enableLimit || !(row.minLength < row.maxLength)) return false;
    out = {currentFrame(jc, sA, sB).length, row.minLength, row.maxLength};
    return true;
}

void distanceEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows) {
    const DistanceRow& row = jc.row.distance;
    // A rigid joint's length; a rope's or a limited spring's limit only while
    // the tree holds it, as an equality row along the axis whose error is the
    // length beyond it (let go when it would pull, joint_tree.cpp).
    rows.count = row.rigid || jc.treeLimit != 0 ? 1 : 0;
    if (rows.count == 0) return;
    const JointFrame f = currentFrame(jc, sA, sB);
    const float crA = cross(f.rA, f.axis), crB = cross(f.rB, f.axis);
    rows.jA[0][0] = -f.axis.x, rows.jA[0][1] = -f.axis.y, rows.jA[0][2] = -crA;
    rows.jB[0][0] = f.axis.x, rows.jB[0][1] = f.axis.y, rows.jB[0][2] = crB;
    rows.error[0] = f.length - (row.rigid ? row.length : jc.treeLimit < 0 ? row.minLength : row.maxLength);
}

void distanceSpringRow(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, float h, EqualityRows& rows,
                       Softness& soft) {
    const DistanceRow& row = jc.row.distance;
    const JointFrame f = currentFrame(jc, sA, sB);
    const float crA = cross(f.rA, f.axis), crB = cross(f.rB, f.axis);
    rows.count = 1;
    rows.jA[0][0] = -f.axis.x, rows.jA[0][1] = -f.axis.y, rows.jA[0][2] = -crA;
    rows.jB[0][0] = f.axis.x, rows.jB[0][1] = f.axis.y, rows.jB[0][2] = crB;
    rows.error[0] = f.length - row.length;
    soft = makeSpring(row.hertz, row.dampingRatio, h, springMassRatio(jc, axialMassOf(jc, f)));
}

void pushDistanceJoint(const JointConstraint& jc, const JointContext& ctx, const BodyState& sA, const BodyState& sB,
                       BodyState& pA, BodyState& pB) {
    const DistanceRow& row = jc.row.distance;
    JointFrame f = currentFrame(jc, sA, sB);
    float C;
    if (row.rigid) {
        C = f.length - row.length;
    } else if (row.enableLimit && f.length < row.minLength) {
        C = f.length - row.minLength;
    } else if (row.enableLimit && f.length > row.maxLength) {
        C = f.length - row.maxLength;
    } else {
        return;
    }
    Vec2 dv = (pB.v + cross(pB.w, f.rB)) - (pA.v + cross(pA.w, f.rA));
    float target = -ctx.pushFactor * ctx.invH * C;
    float impulse = -axialMassOf(jc, f) * (dot(dv, f.axis) - target);
    applyAxial(jc, f, impulse, pA, pB);
}

}  // namespace i2d::detail
