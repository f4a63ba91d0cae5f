// The prismatic joint (a slider): body B moves along an axis fixed in body A
// and keeps its angle relative to A; optional translation limit, motor and
// spring along the axis.
//
// With d = p_B − p_A, the axis u (turning with A) and its perpendicular n
// (joint_rows.hpp, SliderFrame):
//   perpendicular and angle, one 2×2 block: C = (n·d, θ_B − θ_A − θ_ref),
//     J v = (n·(v_B − v_A) + s_B ω_B − s_A ω_A, ω_B − ω_A),
//     K = [ m_A⁻¹ + m_B⁻¹ + I_A⁻¹ s_A² + I_B⁻¹ s_B²    I_A⁻¹ s_A + I_B⁻¹ s_B ]
//         [ I_A⁻¹ s_A + I_B⁻¹ s_B                     I_A⁻¹ + I_B⁻¹         ];
//   along the axis (spring, motor, limits): C = u·d − target, J v = u·(v_B − v_A)
//     + a_B ω_B − a_A ω_A, m_eff = 1/(m_A⁻¹ + m_B⁻¹ + I_A⁻¹ a_A² + I_B⁻¹ a_B²).
// Impulses: axial (perpendicular), angular, spring, motor, lower, upper.
#include <cmath>

#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void preparePrismaticJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const PrismaticJointDef& def = std::get<PrismaticJointDef>(joint.def);
    const Body& bA = w.bodies[joint.bodyA];
    const Body& bB = w.bodies[joint.bodyB];
    setAnchors(bA, bB, def.localAnchorA, def.localAnchorB, jc);
    PrismaticRow& row = jc.row.prismatic;
    row.axisA = rotate(bA.xf.q, normalize(def.localAxisA));
    row.referenceAngle = def.referenceAngle;
    row.lower = def.lowerTranslation;
    row.upper = def.upperTranslation;
    row.motorSpeed = def.motorSpeed;
    row.maxMotorForce = def.maxMotorForce;
    row.hertz = def.hertz;
    row.dampingRatio = def.dampingRatio;
    row.enableLimit = def.enableLimit;
    row.enableMotor = def.enableMotor;
    row.enableSpring = def.enableSpring;
}

void warmStartPrismaticJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    const SliderFrame f = sliderFrame(jc, jc.row.prismatic.axisA, sA, sB);
    const JointImpulses& acc = jc.impulses;
    applySliderImpulse(jc, f, acc.spring + acc.motor + acc.lower - acc.upper, acc.axial, acc.angular, sA, sB);
}

void solvePrismaticJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const PrismaticRow& row = jc.row.prismatic;
    JointImpulses& acc = jc.impulses;
    const SliderFrame f = sliderFrame(jc, row.axisA, sA, sB);
    const float mass = axialMass(jc, f);

    // (A spring the tree solve takes is solved there, joint_tree.cpp.)
    if (row.enableSpring && row.hertz > 0.0f && !jc.treeSpring) {
        const RowBias rb = springBias(sliderSpring(jc, mass, row.hertz, row.dampingRatio, ctx.h), f.translation);
        const float impulse = -rb.massScale * mass * (axialSpeed(f, sA, sB) + rb.bias) - rb.impulseScale * acc.spring;
        acc.spring += impulse;
        applySliderImpulse(jc, f, impulse, 0.0f, 0.0f, sA, sB);
    }
    if (row.enableMotor) {
        const float maxImpulse = ctx.h * row.maxMotorForce;
        float impulse = -mass * (axialSpeed(f, sA, sB) - row.motorSpeed);
        impulse = boundedIncrement(acc.motor, impulse, -maxImpulse, maxImpulse);
        applySliderImpulse(jc, f, impulse, 0.0f, 0.0f, sA, sB);
    }
    // A limit the tree holds and the perpendicular and angle of a joint in an
    // exact tree are solved with the tree (joint_tree.cpp).
    if (row.enableLimit && jc.treeLimit == 0) solveSliderLimits(jc, ctx, f, mass, row.lower, row.upper, sA, sB);
    if (jc.inTree) return;

    // Perpendicular and angle as one 2×2 block.
    const float iA = jc.invIA, iB = jc.invIB;
    const double dA = iA, dB = iB, sa = f.sA, sb = f.sB;
    Sym22 K{double(jc.invMassA) + jc.invMassB + dA * sa * sa + dB * sb * sb, dA * sa + dB * sb, dA + dB};
    if (K.k22 == 0.0) K.k22 = 1.0;  // neither body turns: the angle row is moot
    const Vec2 cdot{dot(f.perp, sB.v - sA.v) + f.sB * sB.w - f.sA * sA.w, sB.w - sA.w};
    const Vec2 C{dot(f.perp, f.d), unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle)};
    const RowBias rb = rigidBias(ctx, 1.0f);
    const Vec2 x = solveSymmetric22(K, cdot + rb.bias * C);
    const Vec2 impulse = -rb.massScale * x - rb.impulseScale * Vec2{acc.axial, acc.angular};
    acc.axial += impulse.x;
    acc.angular += impulse.y;
    applySliderImpulse(jc, f, 0.0f, impulse.x, impulse.y, sA, sB);
}

void prismaticEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows) {
    const PrismaticRow& row = jc.row.prismatic;
    const SliderFrame f = sliderFrame(jc, row.axisA, sA, sB);
    rows.count = 2;
    sliderRow(f.perp, f.sA, f.sB, dot(f.perp, f.d), 0, rows);
    angleRow(unwindAngle(relativeAngle(jc, sA, sB) - row.referenceAngle), 1, rows);
    if (jc.treeLimit == 0) return;
    // The limit the tree holds: an equality row along the axis whose error is
    // the translation beyond it (let go when it would pull, joint_tree.cpp).
    rows.count = 3;
    sliderRow(f.axis, f.aA, f.aB, f.translation - (jc.treeLimit < 0 ? row.lower : row.upper), 2, rows);
}

}  // namespace i2d::detail
