// Testbed — a scene's joints as Box2D 2.4.1 joints (see box2d_joints.hpp).
#include "box2d_joints.hpp"

#include <type_traits>
#include <variant>

namespace tb {

namespace {

b2Vec2 toB2(i2d::Vec2 v) { return {v.x, v.y}; }

using Note = std::function<void(const std::string&)>;

b2Joint* distance(b2World& world, b2DistanceJointDef& jd, const i2d::DistanceJointDef& d) {
    jd.localAnchorA = toB2(d.localAnchorA);
    jd.localAnchorB = toB2(d.localAnchorB);
    jd.length = d.length;
    // Box2D 2.4.1's distance joint is rigid when minLength == maxLength,
    // otherwise a spring (stiffness > 0) and/or a length range.
    if (!d.enableSpring) {
        jd.minLength = jd.maxLength = d.length;
    } else {
        b2LinearStiffness(jd.stiffness, jd.damping, d.hertz, d.dampingRatio, jd.bodyA, jd.bodyB);
        jd.minLength = d.enableLimit ? d.minLength : 0.0f;
        jd.maxLength = d.enableLimit ? d.maxLength : b2_maxFloat;
    }
    return world.CreateJoint(&jd);
}

b2Joint* revolute(b2World& world, b2RevoluteJointDef& jd, const i2d::RevoluteJointDef& d, const Note& note) {
    jd.localAnchorA = toB2(d.localAnchorA);
    jd.localAnchorB = toB2(d.localAnchorB);
    jd.referenceAngle = d.referenceAngle;
    jd.enableLimit = d.enableLimit;
    jd.lowerAngle = d.lowerAngle;
    jd.upperAngle = d.upperAngle;
    jd.enableMotor = d.enableMotor;
    jd.motorSpeed = d.motorSpeed;
    jd.maxMotorTorque = d.maxMotorTorque;
    if (d.enableSpring)
        note("revolute springs: Box2D 2.4.1's revolute joint has no spring; those joints turn freely there");
    return world.CreateJoint(&jd);
}

b2Joint* prismatic(b2World& world, b2PrismaticJointDef& jd, const i2d::PrismaticJointDef& d, const Note& note) {
    jd.localAnchorA = toB2(d.localAnchorA);
    jd.localAnchorB = toB2(d.localAnchorB);
    jd.localAxisA = toB2(i2d::normalize(d.localAxisA));
    jd.referenceAngle = d.referenceAngle;
    jd.enableLimit = d.enableLimit;
    jd.lowerTranslation = d.lowerTranslation;
    jd.upperTranslation = d.upperTranslation;
    jd.enableMotor = d.enableMotor;
    jd.motorSpeed = d.motorSpeed;
    jd.maxMotorForce = d.maxMotorForce;
    if (d.enableSpring)
        note("prismatic springs: Box2D 2.4.1's prismatic joint has no spring; those joints slide freely there");
    return world.CreateJoint(&jd);
}

b2Joint* weld(b2World& world, b2WeldJointDef& jd, const i2d::WeldJointDef& d, const Note& note) {
    jd.localAnchorA = toB2(d.localAnchorA);
    jd.localAnchorB = toB2(d.localAnchorB);
    jd.referenceAngle = d.referenceAngle;
    // Box2D 2.4.1's weld is soft in rotation only (stiffness in N·m/rad).
    if (d.angularHertz > 0.0f)
        b2AngularStiffness(jd.stiffness, jd.damping, d.angularHertz, d.angularDampingRatio, jd.bodyA, jd.bodyB);
    if (d.linearHertz > 0.0f)
        note("weld joints: Box2D 2.4.1's weld is soft in rotation only; the linear spring (linear_hertz) is rigid "
             "there");
    if (d.angularHertz > 0.0f)
        note("weld joints: Box2D 2.4.1 softens the angle with a stiffness and damping folded into its velocity "
             "rows (b2AngularStiffness over both bodies' inertia), not with Impulse2D's soft-constraint "
             "coefficients per substep");
    return world.CreateJoint(&jd);
}

b2Joint* wheel(b2World& world, b2WheelJointDef& jd, const i2d::WheelJointDef& d, const Note& note) {
    jd.localAnchorA = toB2(d.localAnchorA);
    jd.localAnchorB = toB2(d.localAnchorB);
    jd.localAxisA = toB2(i2d::normalize(d.localAxisA));
    jd.enableLimit = d.enableLimit;
    jd.lowerTranslation = d.lowerTranslation;
    jd.upperTranslation = d.upperTranslation;
    jd.enableMotor = d.enableMotor;
    jd.motorSpeed = d.motorSpeed;
    jd.maxMotorTorque = d.maxMotorTorque;
    jd.stiffness = jd.damping = 0.0f;
    if (d.enableSpring && d.hertz > 0.0f) {
        b2LinearStiffness(jd.stiffness, jd.damping, d.hertz, d.dampingRatio, jd.bodyA, jd.bodyB);
        note("wheel joints: Box2D 2.4.1's suspension is a spring of stiffness and damping in N/m from "
             "b2LinearStiffness over both bodies' masses (the body's mass, not the wheel's effective mass along "
             "the axis) solved in its velocity rows");
    }
    return world.CreateJoint(&jd);
}

b2Joint* motor(b2World& world, b2MotorJointDef& jd, const i2d::MotorJointDef& d, const Note& note) {
    // Both engines hold body B's origin at linearOffset from body A's origin, in A's frame.
    jd.linearOffset = toB2(d.linearOffset);
    jd.angularOffset = d.angularOffset;
    jd.maxForce = d.maxForce;
    jd.maxTorque = d.maxTorque;
    jd.correctionFactor = d.correctionFactor;
    note("motor joints: Box2D 2.4.1 corrects the offset by a velocity bias of correction_factor / dt times the "
         "error in its velocity iterations once per step, its force and torque caps applying to the whole step; "
         "Impulse2D applies the same bias in every substep");
    return world.CreateJoint(&jd);
}

b2Joint* mouse(b2World& world, b2MouseJointDef& jd, const i2d::MouseJointDef& d, const Note& note) {
    jd.target = toB2(d.target);
    jd.maxForce = d.maxForce;
    b2LinearStiffness(jd.stiffness, jd.damping, d.hertz, d.dampingRatio, jd.bodyA, jd.bodyB);
    note("mouse joints: Box2D 2.4.1 ignores body_a (only body_b is pulled, by a spring of b2LinearStiffness "
         "over both bodies' masses) and damps body_b's rotation by 2% every step");
    return world.CreateJoint(&jd);
}

b2Joint* pulley(b2World& world, b2PulleyJointDef& jd, const i2d::PulleyJointDef& d) {
    jd.groundAnchorA = toB2(d.groundAnchorA);
    jd.groundAnchorB = toB2(d.groundAnchorB);
    jd.localAnchorA = toB2(d.localAnchorA);
    jd.localAnchorB = toB2(d.localAnchorB);
    jd.lengthA = d.lengthA;
    jd.lengthB = d.lengthB;
    jd.ratio = d.ratio;
    return world.CreateJoint(&jd);
}

}  // namespace

b2Joint* createBox2DJoint(b2World& world, const std::vector<b2Body*>& bodies, const std::vector<b2Joint*>& joints,
                          const JointDesc& j, const Note& note) {
    b2Body* a = bodies[static_cast<std::size_t>(j.bodyA)];
    b2Body* b = bodies[static_cast<std::size_t>(j.bodyB)];
    auto common = [&](b2JointDef& jd, bool collide) {
        jd.bodyA = a;
        jd.bodyB = b;
        jd.collideConnected = collide;
    };
    return std::visit(
        [&](const auto& d) -> b2Joint* {
            using D = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<D, i2d::DistanceJointDef>) {
                b2DistanceJointDef jd;
                common(jd, d.collideConnected);
                return distance(world, jd, d);
            } else if constexpr (std::is_same_v<D, i2d::RevoluteJointDef>) {
                b2RevoluteJointDef jd;
                common(jd, d.collideConnected);
                return revolute(world, jd, d, note);
            } else if constexpr (std::is_same_v<D, i2d::PrismaticJointDef>) {
                b2PrismaticJointDef jd;
                common(jd, d.collideConnected);
                return prismatic(world, jd, d, note);
            } else if constexpr (std::is_same_v<D, i2d::WeldJointDef>) {
                b2WeldJointDef jd;
                common(jd, d.collideConnected);
                return weld(world, jd, d, note);
            } else if constexpr (std::is_same_v<D, i2d::WheelJointDef>) {
                b2WheelJointDef jd;
                common(jd, d.collideConnected);
                return wheel(world, jd, d, note);
            } else if constexpr (std::is_same_v<D, i2d::MotorJointDef>) {
                b2MotorJointDef jd;
                common(jd, d.collideConnected);
                return motor(world, jd, d, note);
            } else if constexpr (std::is_same_v<D, i2d::MouseJointDef>) {
                b2MouseJointDef jd;
                common(jd, d.collideConnected);
                return mouse(world, jd, d, note);
            } else if constexpr (std::is_same_v<D, i2d::PulleyJointDef>) {
                b2PulleyJointDef jd;
                common(jd, d.collideConnected);
                return pulley(world, jd, d);
            } else {
                // The gear's bodies are the second bodies of its joints, as in Impulse2D.
                b2GearJointDef jd;
                common(jd, d.collideConnected);
                jd.joint1 = joints[static_cast<std::size_t>(j.joint1)];
                jd.joint2 = joints[static_cast<std::size_t>(j.joint2)];
                jd.bodyA = jd.joint1->GetBodyB();
                jd.bodyB = jd.joint2->GetBodyB();
                jd.ratio = d.ratio;
                return world.CreateJoint(&jd);
            }
        },
        j.def);
}

}  // namespace tb
