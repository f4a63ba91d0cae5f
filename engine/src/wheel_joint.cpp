// The wheel joint: anchor B stays on the line through anchor A along an axis
// fixed in A (the perpendicular row), a spring along the axis is the
// suspension, with an optional translation limit, and B turns freely or by a
// motor. Rows along the axis and the perpendicular as for the prismatic joint
// (joint_rows.hpp, SliderFrame); the motor drives ω_B − ω_A to its speed within
// ±h·maxTorque, m_eff = 1/(I_A⁻¹ + I_B⁻¹).
// Impulses: axial (perpendicular), spring, lower, upper (along the axis), motor.
#include <cmath>

#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void prepareWheelJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const WheelJointDef& def = std::get<WheelJointDef>(joint.def);
    const Body& bA = w.bodies[joint.bodyA];
    const Body& bB = w.bodies[joint.bodyB];
    setAnchors(bA, bB, def.localAnchorA, def.localAnchorB, jc);
    WheelRow& row = jc.row.wheel;
    row.axisA = rotate(bA.xf.q, normalize(def.localAxisA));
    const float k = jc.invIA + jc.invIB;
    row.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
    row.lower = def.lowerTranslation;
    row.upper = def.upperTranslation;
    row.motorSpeed = def.motorSpeed;
    row.maxMotorTorque = def.maxMotorTorque;
    row.hertz = def.hertz;
    row.dampingRatio = def.dampingRatio;
    row.enableLimit = def.enableLimit;
    row.enableMotor = def.enableMotor;
    row.enableSpring = def.enableSpring;
}

void warmStartWheelJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    const SliderFrame f = sliderFrame(jc, jc.row.wheel.axisA, sA, sB);
    const JointImpulses& acc = jc.impulses;
    applySliderImpulse(jc, f, acc.spring + acc.lower - acc.upper, acc.axial, acc.motor, sA, sB);
}

void solveWheelJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const WheelRow& row = jc.row.wheel;
    JointImpulses& acc = jc.impulses;
    const SliderFrame f = sliderFrame(jc, row.axisA, sA, sB);
    const float mass = axialMass(jc, f);

    if (row.enableMotor && jc.invIA + jc.invIB > 0.0f) {
        const float maxImpulse = ctx.h * row.maxMotorTorque;
        float impulse = -row.axialMass * (sB.w - sA.w - row.motorSpeed);
        impulse = boundedIncrement(acc.motor, impulse, -maxImpulse, maxImpulse);
        sA.w -= jc.invIA * impulse;
        sB.w += jc.invIB * impulse;
    }
    // (A spring the tree solve takes is solved there, joint_tree.cpp.)
    if (row.enableSpring && row.hertz > 0.0f && !jc.treeSpring) {
        const RowBias rb = springBias(sliderSpring(jc, mass, row.hertz, row.dampingRatio, ctx.h), f.translation);
        const float impulse = -rb.massScale * mass * (axialSpeed(f, sA, sB) + rb.bias) - rb.impulseScale * acc.spring;
        acc.spring += impulse;
        applySliderImpulse(jc, f, impulse, 0.0f, 0.0f, sA, sB);
    }
    // A limit the tree holds and the perpendicular of a joint in an exact
    // tree are solved with the tree (joint_tree.cpp).
    if (row.enableLimit && jc.treeLimit == 0) solveSliderLimits(jc, ctx, f, mass, row.lower, row.upper, sA, sB);
    // The point stays on the axis line.
    if (!jc.inTree) {
        const float k = jc.invMassA + jc.invMassB + jc.invIA * f.sA * f.sA + jc.invIB * f.sB * f.sB;
        const float perpMass = k > 0.0f ? 1.0f / k : 0.0f;
        const RowBias rb = rigidBias(ctx, dot(f.perp, f.d));
        const float cdot = dot(f.perp, sB.v - sA.v) + f.sB * sB.w - f.sA * sA.w;
        const float impulse = -rb.massScale * perpMass * (cdot + rb.bias) - rb.impulseScale * acc.axial;
        acc.axial += impulse;
        applySliderImpulse(jc, f, 0.0f, impulse, 0.0f, sA, sB);
    }
}

void wheelEqualityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows) {
    const WheelRow& row = jc.row.wheel;
    const SliderFrame f = sliderFrame(jc, row.axisA, sA, sB);
    rows.count = 1;
    sliderRow(f.perp, f.sA, f.sB, dot(f.perp, f.d), 0, rows);
    if (jc.treeLimit == 0) return;
    rows.count = 2;  // the limit the tree holds, along the axis (as the prismatic joint's)
    sliderRow(f.axis, f.aA, f.aB, f.translation - (jc.treeLimit < 0 ? row.lower : row.upper), 1, rows);
}

}  // namespace i2d::detail
