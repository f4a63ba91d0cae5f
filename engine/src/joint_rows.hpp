// The rows of each joint type: preparation at the start of a step, the warm
// start, and the sweep of one solver pass. Each type's functions are in its
// own file; joint_solver.cpp calls them for every joint row.
//
// Conventions: a row's bodies are A and B with states sA, sB (a static or
// sleeping body gets a zero state that is thrown away); rA, rB are the anchors
// relative to the centres of mass at the step's start, turned by each body's
// rotation since (BodyState::dq); positional errors come from the motion since
// the step began (BodyState::dp, dq), as for contacts. A rigid row's velocity
// target is −bias with, per pass (JointContext):
//   soft_bias   bias = biasRate·C with the joint softness (WorldSettings::jointHertz)
//   baumgarte   bias = β·C/h (Tamis and Maggiore (2015), Constraint based physics solver, eq. 5.2.3)
//   otherwise   bias = 0 (relax passes; split mode's velocity pass)
// and a one-sided row (a limit) that is not violated (C > 0) allows the
// approach that closes it within the (sub)step: bias = C/h, speculatively.
#pragma once

#include <cmath>

#include "joint.hpp"

namespace i2d::detail {

struct WorldState;

/// The velocity target terms of a rigid row in `ctx`'s pass (see above).
struct RowBias {
    float bias = 0.0f, massScale = 1.0f, impulseScale = 0.0f;
};
inline RowBias rigidBias(const JointContext& ctx, float C) {
    if (ctx.pass == SolvePass::soft_bias)
        return {ctx.jointSoft.biasRate * C, ctx.jointSoft.massScale, ctx.jointSoft.impulseScale};
    if (ctx.pass == SolvePass::baumgarte) return {ctx.pushFactor * ctx.invH * C, 1.0f, 0.0f};
    return {};
}
/// A one-sided row (C ≥ 0 allowed): speculative while C > 0, rigid otherwise.
inline RowBias limitBias(const JointContext& ctx, float C) {
    if (C > 0.0f) return {C * ctx.invH, 1.0f, 0.0f};
    return rigidBias(ctx, C);
}
/// A soft row with its own spring (springs, soft welds, the mouse joint):
/// the same softness in every pass, since it is physical, not a correction.
inline RowBias springBias(const Softness& s, float C) { return {s.biasRate * C, s.massScale, s.impulseScale}; }

/// m/m_eff for makeSpring: the bodies' reduced mass over the row's effective
/// mass `effectiveMass` (1 when neither body translates or the row is empty).
inline float springMassRatio(const JointConstraint& jc, float effectiveMass) {
    const float sum = jc.invMassA + jc.invMassB;
    if (!(sum > 0.0f) || !(effectiveMass > 0.0f)) return 1.0f;
    const float ratio = (1.0f / sum) / effectiveMass;
    return ratio > 1.0f && ratio < INFINITY ? ratio : 1.0f;
}

/// Adds `impulse` to `accumulated` within [lo, hi]; returns the part applied.
inline float boundedIncrement(float& accumulated, float impulse, float lo, float hi) {
    const float total = clamp(accumulated + impulse, lo, hi);
    impulse = total - accumulated;
    accumulated = total;
    return impulse;
}

/// The symmetric 2×2 effective-mass matrix of a joint's rows, in double
/// precision: a body of tiny mass (1e-37 kg is accepted) has inverse masses
/// near 1e37 whose products overflow single precision and turned joint
/// solutions into NaN (found by fuzz_world).
struct Sym22 {
    double k11, k12, k22;
};

/// K of a point constraint between anchors rA, rB:
/// [ m_A⁻¹ + m_B⁻¹ + I_A⁻¹ r_Ay² + I_B⁻¹ r_By²    −I_A⁻¹ r_Ax r_Ay − I_B⁻¹ r_Bx r_By ]
/// [ −I_A⁻¹ r_Ax r_Ay − I_B⁻¹ r_Bx r_By          m_A⁻¹ + m_B⁻¹ + I_A⁻¹ r_Ax² + I_B⁻¹ r_Bx² ]
inline Sym22 pointMatrix(double mA, double iA, double mB, double iB, Vec2 rA, Vec2 rB) {
    const double ax = rA.x, ay = rA.y, bx = rB.x, by = rB.y;
    return {mA + mB + ay * ay * iA + by * by * iB, -ay * ax * iA - by * bx * iB, mA + mB + ax * ax * iA + bx * bx * iB};
}

/// Solves K·x = b (x = 0 when K is singular); in single precision when the
/// products of K's entries fit in it (every practical mass ratio), in double
/// otherwise.
inline Vec2 solveSymmetric22(const Sym22& k, Vec2 b) {
    constexpr double kSingleSafe = 1.0e18;  // a product of two entries stays below 3.4e38
    if (std::abs(k.k11) < kSingleSafe && std::abs(k.k12) < kSingleSafe && std::abs(k.k22) < kSingleSafe) {
        const float a11 = static_cast<float>(k.k11), a12 = static_cast<float>(k.k12), a22 = static_cast<float>(k.k22);
        float inv = a11 * a22 - a12 * a12;
        if (inv != 0.0f) inv = 1.0f / inv;
        return {inv * (a22 * b.x - a12 * b.y), inv * (a11 * b.y - a12 * b.x)};
    }
    double det = k.k11 * k.k22 - k.k12 * k.k12;
    if (det != 0.0) det = 1.0 / det;
    return {static_cast<float>(det * (k.k22 * b.x - k.k12 * b.y)),
            static_cast<float>(det * (k.k11 * b.y - k.k12 * b.x))};
}

/// K⁻¹ b for the point rows of anchors rA, rB (pointMatrix): in single
/// precision when prepareJoints found every entry of K small enough for it
/// (JointConstraint::singlePrecision: every practical mass ratio), which
/// costs a third less in the sweep; in double precision otherwise.
/// Below this bound on every entry of a point matrix, products of two
/// entries stay within single precision (3.4e38) with room.
constexpr double kSinglePrecisionBound = 1.0e18;

inline Vec2 solvePointRows(const JointConstraint& jc, Vec2 rA, Vec2 rB, Vec2 b) {
    const float mA = jc.invMassA, iA = jc.invIA, mB = jc.invMassB, iB = jc.invIB;
    if (!jc.singlePrecision) return solveSymmetric22(pointMatrix(mA, iA, mB, iB, rA, rB), b);
    const float k11 = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    const float k12 = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    const float k22 = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    float inv = k11 * k22 - k12 * k12;
    if (inv != 0.0f) inv = 1.0f / inv;
    return {inv * (k22 * b.x - k12 * b.y), inv * (k11 * b.y - k12 * b.x)};
}

/// Relative angle of B to A now: angle(qB·qA⁻¹) with the rotations since the step began.
inline float relativeAngle(const JointConstraint& jc, const BodyState& sA, const BodyState& sB) {
    const Rot qA = mulRot(sA.dq, jc.qA), qB = mulRot(sB.dq, jc.qB);
    return angleOf(invMulRot(qA, qB));
}

/// Applies a linear impulse P at the anchors (and an extra angular impulse L) to A (−) and B (+).
inline void applyImpulse(const JointConstraint& jc, Vec2 rA, Vec2 rB, Vec2 P, float L, BodyState& sA, BodyState& sB) {
    sA.v = mulSub(sA.v, jc.invMassA, P);
    sA.w -= jc.invIA * (cross(rA, P) + L);
    sB.v = mulAdd(sB.v, jc.invMassB, P);
    sB.w += jc.invIB * (cross(rB, P) + L);
}

/// A joint's equality rows for the exact solve of joint trees
/// (joint_tree.cpp): row k's rate is J v = jA[k]·(v_A, ω_A) + jB[k]·(v_B, ω_B),
/// its position error error[k]; the accumulated impulses are read and written
/// through the type's own fields (readImpulse, addImpulse in joint_tree.cpp).
struct EqualityRows {
    int count = 0;
    float jA[3][3]{}, jB[3][3]{};
    float error[3]{};
};
/// Geometry of a joint along an axis fixed in body A (prismatic, wheel), now:
/// d = p_B − p_A, the axis u turned with A and its perpendicular n, and the
/// angular Jacobian terms of rows along them: a translation row along u has
/// J v = u·(v_B − v_A) + aB ω_B − aA ω_A with aA = (d + r_A) × u, aB = r_B × u
/// (likewise sA, sB along n).
struct SliderFrame {
    Vec2 rA, rB, d, axis, perp;
    float aA, aB, sA, sB;
    float translation;  ///< u·d
};
inline SliderFrame sliderFrame(const JointConstraint& jc, Vec2 axisA, const BodyState& stA, const BodyState& stB) {
    SliderFrame f;
    f.rA = rotate(stA.dq, jc.rA);
    f.rB = rotate(stB.dq, jc.rB);
    f.d = (stB.dp - stA.dp) + jc.deltaCenter + f.rB - f.rA;
    f.axis = rotate(stA.dq, axisA);
    f.perp = leftPerp(f.axis);
    f.aA = cross(f.d + f.rA, f.axis);
    f.aB = cross(f.rB, f.axis);
    f.sA = cross(f.d + f.rA, f.perp);
    f.sB = cross(f.rB, f.perp);
    f.translation = dot(f.axis, f.d);
    return f;
}
/// Applies impulses along the axis (λu), the perpendicular (λn) and about the
/// joint (L) to A (−) and B (+).
inline void applySliderImpulse(const JointConstraint& jc, const SliderFrame& f, float axial, float perpendicular,
                               float angular, BodyState& stA, BodyState& stB) {
    const Vec2 P = axial * f.axis + perpendicular * f.perp;
    const float LA = axial * f.aA + perpendicular * f.sA + angular;
    const float LB = axial * f.aB + perpendicular * f.sB + angular;
    stA.v = mulSub(stA.v, jc.invMassA, P);
    stA.w -= jc.invIA * LA;
    stB.v = mulAdd(stB.v, jc.invMassB, P);
    stB.w += jc.invIB * LB;
}
/// The rate of the translation: J v of a row along the axis.
inline float axialSpeed(const SliderFrame& f, const BodyState& stA, const BodyState& stB) {
    return dot(f.axis, stB.v - stA.v) + f.aB * stB.w - f.aA * stA.w;
}
/// Row r of a slider's equality rows: B's motion along `dir` (the
/// perpendicular or the axis) with its arms, J v = dir·(v_B − v_A) + arm_B ω_B
/// − arm_A ω_A, and its error (joint_tree.cpp).
inline void sliderRow(Vec2 dir, float armA, float armB, float error, int r, EqualityRows& rows) {
    rows.jA[r][0] = -dir.x, rows.jA[r][1] = -dir.y, rows.jA[r][2] = -armA;
    rows.jB[r][0] = dir.x, rows.jB[r][1] = dir.y, rows.jB[r][2] = armB;
    rows.error[r] = error;
}
/// Row r as the relative angle's: J v = ω_B − ω_A, its error `error`.
inline void angleRow(float error, int r, EqualityRows& rows) {
    rows.jA[r][0] = rows.jA[r][1] = rows.jB[r][0] = rows.jB[r][1] = 0.0f;
    rows.jA[r][2] = -1.0f;
    rows.jB[r][2] = 1.0f;
    rows.error[r] = error;
}
/// A joint's limited coordinate now (a revolute joint's angle, a slider's
/// translation, a distance joint's length) and its bounds.
struct LimitCoordinate {
    float value = 0.0f, lower = 0.0f, upper = 0.0f;
};
/// −1 when `value` is at or below `lower`, +1 at or above `upper`, else 0.
inline int limitSide(float value, float lower, float upper) {
    if (value <= lower) return -1;
    if (value >= upper) return 1;
    return 0;
}
/// The translation limits of a slider (prismatic, wheel): one-sided rows on
/// u·d − lower ≥ 0 and upper − u·d ≥ 0 with effective mass `mass`.
inline void solveSliderLimits(JointConstraint& jc, const JointContext& ctx, const SliderFrame& f, float mass,
                              float lower, float upper, BodyState& sA, BodyState& sB) {
    JointImpulses& acc = jc.impulses;
    {
        const RowBias rb = limitBias(ctx, f.translation - lower);
        float impulse = -rb.massScale * mass * (axialSpeed(f, sA, sB) + rb.bias) - rb.impulseScale * acc.lower;
        impulse = boundedIncrement(acc.lower, impulse, 0.0f, INFINITY);
        applySliderImpulse(jc, f, impulse, 0.0f, 0.0f, sA, sB);
    }
    {
        const RowBias rb = limitBias(ctx, upper - f.translation);
        float impulse = -rb.massScale * mass * (-axialSpeed(f, sA, sB) + rb.bias) - rb.impulseScale * acc.upper;
        impulse = boundedIncrement(acc.upper, impulse, 0.0f, INFINITY);
        applySliderImpulse(jc, f, -impulse, 0.0f, 0.0f, sA, sB);
    }
}

/// Adds `impulse` to the accumulated linear impulse within a disc of radius
/// maxImpulse (a force cap); returns the part applied.
inline Vec2 discBoundedIncrement(Vec2& accumulated, Vec2 impulse, float maxImpulse) {
    const Vec2 old = accumulated;
    accumulated += impulse;
    const float len2 = lengthSquared(accumulated);
    if (len2 > maxImpulse * maxImpulse) accumulated *= maxImpulse / std::sqrt(len2);
    return accumulated - old;
}

/// A joint's anchors relative to the bodies' centres of mass at the step's
/// start, in world axes (from anchors given relative to the bodies' origins).
inline void setAnchors(const Body& bA, const Body& bB, Vec2 localAnchorA, Vec2 localAnchorB, JointConstraint& jc) {
    jc.rA = rotate(bA.xf.q, localAnchorA - bA.localCenter);
    jc.rB = rotate(bB.xf.q, localAnchorB - bB.localCenter);
}

inline float axialMass(const JointConstraint& jc, const SliderFrame& f) {
    const float k = jc.invMassA + jc.invMassB + jc.invIA * f.aA * f.aA + jc.invIB * f.aB * f.aB;
    return k > 0.0f ? 1.0f / k : 0.0f;
}

/// A slider's spring along its axis (`mass` its row's, axialMass): stiffness
/// m·ω² and damping 2·m·ζ·ω with m the bodies' reduced mass (makeSpring,
/// springMassRatio).
inline Softness sliderSpring(const JointConstraint& jc, float mass, float hertz, float dampingRatio, float h) {
    return makeSpring(hertz, dampingRatio, h, springMassRatio(jc, mass));
}

/// The equality rows a joint hands to the tree solve: the revolute joint's
/// point, the rigid weld's point and angle, the rigid distance joint's length,
/// the prismatic joint's perpendicular and angle, the wheel joint's
/// perpendicular, the limited distance joint's limit while held (its rows
/// count 1, handed over only then); 0 rows for every other joint (its rows
/// stay in the Gauss-Seidel sweep).
/// Each type's part is in its own file; the dispatch is in joint_tree.cpp.
int equalityRowCount(const Joint& joint);
/// Whether those rows are a limit's, handed over only while it holds (a rope,
/// a spring with limits): the tree takes such joints after the others.
bool rowsOnlyAtLimit(const Joint& joint);
/// Fills the rows at the states' current motion (count = equalityRowCount).
void equalityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows);
/// The point rows of anchors rA, rB turned to now: C = p_B − p_A.
inline void pointRows(Vec2 rA, Vec2 rB, Vec2 separation, EqualityRows& rows) {
    // ∂(v + ω × r)/∂(v, ω) = [1 0 −r_y; 0 1 r_x].
    rows.jA[0][0] = -1.0f, rows.jA[0][1] = 0.0f, rows.jA[0][2] = rA.y;
    rows.jA[1][0] = 0.0f, rows.jA[1][1] = -1.0f, rows.jA[1][2] = -rA.x;
    rows.jB[0][0] = 1.0f, rows.jB[0][1] = 0.0f, rows.jB[0][2] = -rB.y;
    rows.jB[1][0] = 0.0f, rows.jB[1][1] = 1.0f, rows.jB[1][2] = rB.x;
    rows.error[0] = separation.x;
    rows.error[1] = separation.y;
}
void revoluteEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows);
/// The limited angle of a revolute joint with a limit and a side that turns (false otherwise).
bool revoluteLimitCoordinate(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, LimitCoordinate& out);
void weldEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows);
/// The prismatic joint's perpendicular and angle, and its limit while the tree holds it.
void prismaticEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows);
/// The wheel joint's perpendicular, and its limit while the tree holds it.
void wheelEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows);
/// The limited length of a distance joint with limits (not a rigid one; false otherwise).
bool distanceLimitCoordinate(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, LimitCoordinate& out);
/// The limited coordinate of a joint whose limit its tree may hold (false:
/// no limit, or a joint type whose limits stay in the sweep).
bool limitCoordinate(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, LimitCoordinate& out);
void distanceEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows);
/// Whether a joint has a spring the tree solve can take as an auxiliary row
/// (JointConstraint::treeSpring): a revolute, prismatic, wheel or distance
/// joint's enabled spring, or a weld's angular spring. The dispatch of the
/// rows below is in joint_tree.cpp.
bool hasSpringRow(const Joint& joint);
/// A joint's spring as one row (rows.count = 1, C in rows.error[0]) and the
/// softness its sweep gives it at substep h, so that the same implicit spring
/// is solved with the tree as beside it.
void springRow(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, float h, EqualityRows& rows,
               Softness& soft);
/// A distance joint's spring along its axis: C the length less its rest length.
void distanceSpringRow(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, float h, EqualityRows& rows,
                       Softness& soft);
/// An angular spring (a revolute joint's, a weld's): ω_B − ω_A, C the angle
/// from `referenceAngle`, the softness of a spring relative to the row's own
/// mass (makeSoft), as the joints' sweeps give it.
inline void angularSpringRow(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, float referenceAngle,
                             float hertz, float dampingRatio, float h, EqualityRows& rows, Softness& soft) {
    rows.count = 1;
    angleRow(unwindAngle(relativeAngle(jc, sA, sB) - referenceAngle), 0, rows);
    soft = makeSoft(hertz, dampingRatio, h);
}
/// A slider's spring along its axis (prismatic, wheel): C the translation.
inline void sliderSpringRow(const JointConstraint& jc, const SliderFrame& f, float hertz, float dampingRatio, float h,
                            EqualityRows& rows, Softness& soft) {
    rows.count = 1;
    sliderRow(f.axis, f.aA, f.aB, f.translation, 0, rows);
    soft = sliderSpring(jc, axialMass(jc, f), hertz, dampingRatio, h);
}

void prepareDistanceJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartDistanceJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
void solveDistanceJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);
/// Split mode: the distance joint's position error on the pseudo-velocities pA, pB.
void pushDistanceJoint(const JointConstraint& jc, const JointContext& ctx, const BodyState& sA, const BodyState& sB,
                       BodyState& pA, BodyState& pB);

void prepareRevoluteJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartRevoluteJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
/// The point impulse a revolute joint's limits apply with their angular one
/// (revolute_joint.cpp): part of the force the anchor carries.
Vec2 revoluteLimitPointImpulse(const JointConstraint& jc, const BodyState& sA, const BodyState& sB);
void solveRevoluteJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);

void preparePrismaticJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartPrismaticJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
void solvePrismaticJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);

void prepareWeldJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartWeldJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
void solveWeldJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);

void prepareWheelJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartWheelJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
void solveWheelJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);

void prepareMotorJoint(const WorldState& w, const Joint& joint, JointConstraint& jc, float dt);
void warmStartMotorJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
void solveMotorJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);

void prepareMouseJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartMouseJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
void solveMouseJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);

void preparePulleyJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartPulleyJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB);
void solvePulleyJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB);

/// The gear's four bodies: A, B (its own) and C, D (the frames of its joints).
struct GearStates {
    BodyState& a;
    BodyState& b;
    BodyState& c;
    BodyState& d;
};
void prepareGearJoint(const WorldState& w, const Joint& joint, JointConstraint& jc);
void warmStartGearJoint(const JointConstraint& jc, GearStates s);
void solveGearJoint(JointConstraint& jc, const JointContext& ctx, GearStates s);
/// The gear's error C with the states' motion since the step began (kept in
/// Joint::constant at the end of each step).
float gearCoordinateError(const JointConstraint& jc, GearStates s);
/// coordinate1 + ratio·coordinate2 at the world's current poses (angles
/// wrapped to (−π, π]), for inspection.
float gearCoordinate(const WorldState& w, const Joint& gear);

}  // namespace i2d::detail
