// Scene files: every joint type's fields are read into its definition, values
// left to the layout are measured there, and each bad value is refused with a
// message naming the joint and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene_loader.hpp"

namespace {

// A static ground, a dynamic circle "a" at (0, 1) and a dynamic box "b" at
// (2, 1) turned by 0.5 rad, then the given joints.
std::string withJoints(const std::string& joints) {
    return R"({"bodies": [
        {"name": "ground", "type": "static"},
        {"name": "a", "position": [0, 1], "shapes": [{"type": "circle", "radius": 0.5}]},
        {"name": "b", "position": [2, 1], "angle": 0.5, "shapes": [{"type": "box", "hx": 0.5, "hy": 0.5}]}],
        "joints": [)" +
           joints + "]}";
}

tb::SceneDesc parse(const std::string& joints) { return tb::parseSceneDesc(withJoints(joints), "j.json", "j"); }

void expectError(const std::string& joints, const std::vector<std::string>& parts) {
    try {
        tb::parseSceneDesc(withJoints(joints), "bad.json", "bad");
        ADD_FAILURE() << "no error for: " << joints;
    } catch (const tb::SceneError& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("bad.json: ", 0), 0u) << msg;
        for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
    }
}

TEST(JointLoader, TypeDefaultsToDistanceAndUnknownTypesAreRefused) {
    tb::SceneDesc d = parse(R"({"body_a": "a", "body_b": "b"})");
    ASSERT_EQ(d.joints.size(), 1u);
    EXPECT_EQ(d.joints[0].type(), i2d::JointType::distance);
    EXPECT_FLOAT_EQ(d.joints[0].as<i2d::DistanceJointDef>().length, 2.0f);
    expectError(R"({"type": "hinge", "body_a": "a", "body_b": "b"})",
                {"joints[0].type", "unknown value \"hinge\"", "\"revolute\""});
    // A field of another type is unknown here.
    expectError(R"({"type": "weld", "body_a": "a", "body_b": "b", "limit": {}})", {"joints[0].limit: unknown field"});
    expectError(R"({"type": "revolute", "body_a": "a", "body_b": "b", "length": 1})",
                {"joints[0].length: unknown field"});
}

TEST(JointLoader, Revolute) {
    tb::SceneDesc d = parse(R"({"type": "revolute", "name": "hinge", "body_a": "a", "body_b": "b", "anchor_a": [1, 0],
        "anchor_b": [-1, 0], "limit": {"lower_angle": -0.5, "upper_angle": 1.5}, "collide_connected": true,
        "motor": {"motor_speed": 2, "max_motor_torque": 30}, "spring": {"hertz": 3, "damping_ratio": 0.4}})");
    ASSERT_EQ(d.joints.size(), 1u);
    const tb::JointDesc& j = d.joints[0];
    EXPECT_EQ(j.name, "hinge");
    EXPECT_EQ(j.bodyA, 1);
    EXPECT_EQ(j.bodyB, 2);
    const auto& r = j.as<i2d::RevoluteJointDef>();
    EXPECT_FLOAT_EQ(r.localAnchorA.x, 1.0f);
    EXPECT_FLOAT_EQ(r.localAnchorB.x, -1.0f);
    EXPECT_NEAR(r.referenceAngle, 0.5f, 1e-6f);  // from the layout: angle(b) − angle(a)
    EXPECT_TRUE(r.enableLimit);
    EXPECT_FLOAT_EQ(r.lowerAngle, -0.5f);
    EXPECT_FLOAT_EQ(r.upperAngle, 1.5f);
    EXPECT_TRUE(r.enableMotor);
    EXPECT_FLOAT_EQ(r.motorSpeed, 2.0f);
    EXPECT_FLOAT_EQ(r.maxMotorTorque, 30.0f);
    EXPECT_TRUE(r.enableSpring);
    EXPECT_FLOAT_EQ(r.hertz, 3.0f);
    EXPECT_FLOAT_EQ(r.dampingRatio, 0.4f);
    EXPECT_TRUE(r.collideConnected);

    const auto plain = parse(R"({"type": "revolute", "body_a": "a", "body_b": "b", "reference_angle": 0.25})")
                           .joints[0]
                           .as<i2d::RevoluteJointDef>();
    EXPECT_FLOAT_EQ(plain.referenceAngle, 0.25f);
    EXPECT_FALSE(plain.enableLimit || plain.enableMotor || plain.enableSpring);

    const std::string rev = R"({"type": "revolute", "body_a": "a", "body_b": "b", )";
    expectError(rev + R"("limit": {"lower_angle": 1, "upper_angle": -1}})",
                {"joints[0].limit.lower_angle", "above upper_angle"});
    expectError(rev + R"("limit": {"lower_angle": -4, "upper_angle": 1}})",
                {"joints[0].limit.lower_angle", "out of range"});
    expectError(rev + R"("limit": {"lower_angle": -1}})", {"joints[0].limit", "missing required field 'upper_angle'"});
    expectError(rev + R"("limit": {"lower_angle": -1, "upper_angle": 1e999}})",
                {"joints[0].limit.upper_angle", "not a finite number"});
    expectError(rev + R"("motor": {"motor_speed": 1, "max_motor_torque": -1}})",
                {"joints[0].motor.max_motor_torque", "out of range"});
    expectError(rev + R"("motor": {"motor_speed": 1}})",
                {"joints[0].motor", "missing required field 'max_motor_torque'"});
    expectError(rev + R"("spring": {"hertz": -2}})", {"joints[0].spring.hertz", "out of range"});
    expectError(rev + R"("reference_angle": 4})", {"joints[0].reference_angle", "out of range"});
    expectError(rev + R"("anchor_a": [0, 1e999]})", {"joints[0].anchor_a[1]", "not a finite number"});
    expectError(rev + R"("name": ""})", {"joints[0].name", "must not be empty"});
}

TEST(JointLoader, Prismatic) {
    const auto p = parse(R"({"type": "prismatic", "body_a": "ground", "body_b": "a", "anchor_a": [0, 1],
        "axis_a": [0, 2], "reference_angle": 0.1, "limit": {"lower_translation": -1, "upper_translation": 2},
        "motor": {"motor_speed": -1, "max_motor_force": 500}, "spring": {"hertz": 1, "damping_ratio": 0.5}})")
                       .joints[0]
                       .as<i2d::PrismaticJointDef>();
    EXPECT_FLOAT_EQ(p.localAxisA.y, 2.0f);  // the engine normalises it
    EXPECT_FLOAT_EQ(p.referenceAngle, 0.1f);
    EXPECT_TRUE(p.enableLimit);
    EXPECT_FLOAT_EQ(p.lowerTranslation, -1.0f);
    EXPECT_FLOAT_EQ(p.upperTranslation, 2.0f);
    EXPECT_TRUE(p.enableMotor);
    EXPECT_FLOAT_EQ(p.motorSpeed, -1.0f);
    EXPECT_FLOAT_EQ(p.maxMotorForce, 500.0f);
    EXPECT_TRUE(p.enableSpring);
    EXPECT_FLOAT_EQ(p.hertz, 1.0f);

    const std::string pri = R"({"type": "prismatic", "body_a": "ground", "body_b": "a", )";
    expectError(pri + R"("axis_a": [0, 0]})", {"joints[0].axis_a", "must not be zero"});
    expectError(pri + R"("limit": {"lower_translation": 3, "upper_translation": 2}})",
                {"joints[0].limit.lower_translation", "above upper_translation"});
    expectError(pri + R"("motor": {"max_motor_force": -5}})", {"joints[0].motor.max_motor_force", "out of range"});
    expectError(pri + R"("motor": {"max_motor_force": 5, "max_motor_torque": 5}})",
                {"joints[0].motor.max_motor_torque: unknown field"});
}

TEST(JointLoader, Weld) {
    const auto w = parse(R"({"type": "weld", "body_a": "a", "body_b": "b", "anchor_a": [1, 0], "anchor_b": [-1, 0],
        "linear_hertz": 5, "linear_damping_ratio": 0.5, "angular_hertz": 6, "angular_damping_ratio": 0.7})")
                       .joints[0]
                       .as<i2d::WeldJointDef>();
    EXPECT_NEAR(w.referenceAngle, 0.5f, 1e-6f);
    EXPECT_FLOAT_EQ(w.linearHertz, 5.0f);
    EXPECT_FLOAT_EQ(w.linearDampingRatio, 0.5f);
    EXPECT_FLOAT_EQ(w.angularHertz, 6.0f);
    EXPECT_FLOAT_EQ(w.angularDampingRatio, 0.7f);
    const std::string weld = R"({"type": "weld", "body_a": "a", "body_b": "b", )";
    expectError(weld + R"("angular_hertz": -1})", {"joints[0].angular_hertz", "out of range"});
    expectError(weld + R"("linear_damping_ratio": 1e999})", {"joints[0].linear_damping_ratio", "not a finite number"});
}

TEST(JointLoader, Wheel) {
    const auto def = parse(R"({"type": "wheel", "body_a": "b", "body_b": "a"})").joints[0].as<i2d::WheelJointDef>();
    EXPECT_TRUE(def.enableSpring);  // the definition's default suspension: on, 1 Hz, 0.7
    EXPECT_FLOAT_EQ(def.hertz, 1.0f);
    EXPECT_FLOAT_EQ(def.dampingRatio, 0.7f);
    EXPECT_FLOAT_EQ(def.localAxisA.y, 1.0f);
    const auto w = parse(R"({"type": "wheel", "body_a": "b", "body_b": "a", "anchor_a": [-2, -0.5], "axis_a": [0.5, 1],
        "spring": {"hertz": 4, "damping_ratio": 0.9}, "limit": {"lower_translation": -0.2, "upper_translation": 0.3},
        "motor": {"motor_speed": -20, "max_motor_torque": 15}})")
                       .joints[0]
                       .as<i2d::WheelJointDef>();
    EXPECT_FLOAT_EQ(w.localAxisA.x, 0.5f);
    EXPECT_FLOAT_EQ(w.hertz, 4.0f);
    EXPECT_FLOAT_EQ(w.dampingRatio, 0.9f);
    EXPECT_TRUE(w.enableLimit);
    EXPECT_FLOAT_EQ(w.upperTranslation, 0.3f);
    EXPECT_TRUE(w.enableMotor);
    EXPECT_FLOAT_EQ(w.maxMotorTorque, 15.0f);
    EXPECT_FALSE(parse(R"({"type": "wheel", "body_a": "b", "body_b": "a", "spring": false})")
                     .joints[0]
                     .as<i2d::WheelJointDef>()
                     .enableSpring);
    const std::string wheel = R"({"type": "wheel", "body_a": "b", "body_b": "a", )";
    expectError(wheel + R"("spring": true})", {"joints[0].spring", "or false"});
    expectError(wheel + R"("axis_a": [0, 0]})", {"joints[0].axis_a", "must not be zero"});
    expectError(wheel + R"("limit": {"lower_translation": 1, "upper_translation": 0}})",
                {"joints[0].limit.lower_translation", "above upper_translation"});
    expectError(wheel + R"("motor": {"max_motor_torque": -1}})", {"joints[0].motor.max_motor_torque", "out of range"});
}

TEST(JointLoader, Motor) {
    const auto m = parse(R"({"type": "motor", "body_a": "ground", "body_b": "a", "linear_offset": [0, 1],
        "angular_offset": 0.3, "max_force": 50, "max_torque": 20, "correction_factor": 0.5})")
                       .joints[0]
                       .as<i2d::MotorJointDef>();
    EXPECT_FLOAT_EQ(m.linearOffset.y, 1.0f);
    EXPECT_FLOAT_EQ(m.angularOffset, 0.3f);
    EXPECT_FLOAT_EQ(m.maxForce, 50.0f);
    EXPECT_FLOAT_EQ(m.maxTorque, 20.0f);
    EXPECT_FLOAT_EQ(m.correctionFactor, 0.5f);
    const std::string motor = R"({"type": "motor", "body_a": "ground", "body_b": "a", )";
    expectError(motor + R"("correction_factor": 1.5})", {"joints[0].correction_factor", "out of range"});
    expectError(motor + R"("max_force": -1})", {"joints[0].max_force", "out of range"});
    expectError(motor + R"("max_torque": 1e999})", {"joints[0].max_torque", "not a finite number"});
}

TEST(JointLoader, Mouse) {
    const auto m = parse(R"({"type": "mouse", "body_a": "ground", "body_b": "a", "target": [0.2, 1.5], "hertz": 4,
        "damping_ratio": 0.5, "max_force": 300})")
                       .joints[0]
                       .as<i2d::MouseJointDef>();
    EXPECT_FLOAT_EQ(m.target.x, 0.2f);
    EXPECT_FLOAT_EQ(m.hertz, 4.0f);
    EXPECT_FLOAT_EQ(m.dampingRatio, 0.5f);
    EXPECT_FLOAT_EQ(m.maxForce, 300.0f);
    const std::string mouse = R"({"type": "mouse", "body_a": "ground", "body_b": "a", )";
    expectError(mouse + R"("hertz": 5})", {"joints[0]", "missing required field 'target'"});
    expectError(mouse + R"("target": [0, 1], "hertz": 0})", {"joints[0].hertz", "out of range"});
    expectError(mouse + R"("target": [0, 1], "max_force": -3})", {"joints[0].max_force", "out of range"});
}

TEST(JointLoader, Pulley) {
    const auto p = parse(R"({"type": "pulley", "body_a": "a", "body_b": "b", "ground_anchor_a": [0, 4],
        "ground_anchor_b": [2, 5], "ratio": 1.5})")
                       .joints[0]
                       .as<i2d::PulleyJointDef>();
    EXPECT_FLOAT_EQ(p.groundAnchorB.y, 5.0f);
    EXPECT_FLOAT_EQ(p.lengthA, 3.0f);  // measured from the layout: (0, 4) to a's origin (0, 1)
    EXPECT_FLOAT_EQ(p.lengthB, 4.0f);
    EXPECT_FLOAT_EQ(p.ratio, 1.5f);
    const auto given = parse(R"({"type": "pulley", "body_a": "a", "body_b": "b", "ground_anchor_a": [0, 4],
        "ground_anchor_b": [2, 5], "length_a": 2, "length_b": 6})")
                           .joints[0]
                           .as<i2d::PulleyJointDef>();
    EXPECT_FLOAT_EQ(given.lengthA, 2.0f);
    EXPECT_FLOAT_EQ(given.lengthB, 6.0f);
    const std::string pulley = R"({"type": "pulley", "body_a": "a", "body_b": "b", "ground_anchor_a": [0, 4], )";
    expectError(pulley + R"("ratio": 1})", {"joints[0]", "missing required field 'ground_anchor_b'"});
    expectError(pulley + R"("ground_anchor_b": [2, 5], "ratio": 0})", {"joints[0].ratio", "out of range"});
    expectError(pulley + R"("ground_anchor_b": [2, 5], "length_a": -1})", {"joints[0].length_a", "out of range"});
    expectError(pulley + R"("ground_anchor_b": [2, 1]})", {"joints[0]", "ground anchor B and anchor B", "0 m apart"});
}

TEST(JointLoader, GearByNameAndByIndex) {
    const std::string joints = R"(
        {"type": "revolute", "name": "axle", "body_a": "ground", "body_b": "a", "anchor_a": [0, 1]},
        {"type": "prismatic", "body_a": "ground", "body_b": "b", "anchor_a": [2, 1]},
        {"type": "gear", "joint1": "axle", "joint2": 1, "ratio": -2, "collide_connected": true})";
    tb::SceneDesc d = parse(joints);
    ASSERT_EQ(d.joints.size(), 3u);
    const tb::JointDesc& g = d.joints[2];
    EXPECT_EQ(g.type(), i2d::JointType::gear);
    EXPECT_EQ(g.joint1, 0);
    EXPECT_EQ(g.joint2, 1);
    EXPECT_EQ(g.bodyA, 1);  // the joints' second bodies
    EXPECT_EQ(g.bodyB, 2);
    EXPECT_FLOAT_EQ(g.as<i2d::GearJointDef>().ratio, -2.0f);
    EXPECT_TRUE(g.as<i2d::GearJointDef>().collideConnected);

    const std::string two = R"({"type": "revolute", "name": "axle", "body_a": "ground", "body_b": "a"},
        {"type": "weld", "name": "glue", "body_a": "ground", "body_b": "b"}, )";
    expectError(two + R"({"type": "gear", "joint1": "axle", "joint2": "glue"})",
                {"joints[2].joint2", "joints[1], a weld joint", "revolute or prismatic"});
    expectError(two + R"({"type": "gear", "joint1": "axle", "joint2": "nope"})",
                {"joints[2].joint2", "unknown joint name 'nope'"});
    expectError(two + R"({"type": "gear", "joint1": 0, "joint2": 0})", {"joints[2].joint2", "two different joints"});
    expectError(two + R"({"type": "gear", "joint1": 0, "joint2": 7})", {"joints[2].joint2", "out of range"});
    expectError(two + R"({"type": "gear", "joint1": 0, "joint2": 1.5})", {"joints[2].joint2", "expected a joint name"});
    expectError(two +
                    R"({"type": "gear", "joint1": 0, "joint2": 3}, {"type": "revolute", "body_a": "a", "body_b": "b"})",
                {"joints[2].joint2", "does not come before this gear"});
    expectError(two + R"({"type": "gear", "joint1": "axle", "joint2": "glue", "ratio": 0})",
                {"joints[2].ratio", "must not be zero"});
    expectError(two + R"({"type": "gear", "joint1": "axle", "joint2": "glue", "body_a": "a"})",
                {"joints[2].body_a: unknown field"});
    expectError(two + R"({"type": "gear", "joint1": "axle"})", {"joints[2]", "missing required field 'joint2'"});
    expectError(R"({"type": "revolute", "name": "x", "body_a": "ground", "body_b": "a"},
                   {"type": "revolute", "name": "x", "body_a": "ground", "body_b": "b"})",
                {"joints[1].name", "duplicate joint name 'x'"});
}

TEST(JointLoader, GeneratorsMakeRevoluteJoints) {
    const std::string text = R"({"bodies": [
        {"name": "ground", "type": "static"},
        {"generator": "chain", "count": 3, "origin": [0.5, 5], "step": [1, 0], "joint_type": "revolute",
         "anchor_prev": [-0.5, 0], "anchor_next": [0.5, 0], "limit": {"lower_angle": -1, "upper_angle": 1},
         "attach_start": {"body": "ground", "anchor": [0, 5]}, "body": {}},
        {"generator": "grid", "columns": 2, "rows": 2, "origin": [10, 0], "spacing": [2, 1],
         "link": {"type": "revolute"}, "body": {}}]})";
    tb::SceneDesc d = tb::parseSceneDesc(text, "g.json", "g");
    ASSERT_EQ(d.joints.size(), 3u + 4u);
    for (const tb::JointDesc& j : d.joints) EXPECT_EQ(j.type(), i2d::JointType::revolute);
    // The chain's joints come first (attachment, then links), then the grid's.
    const auto& attach = d.joints[0].as<i2d::RevoluteJointDef>();
    EXPECT_EQ(d.joints[0].bodyA, 0);
    EXPECT_FLOAT_EQ(attach.localAnchorA.y, 5.0f);
    EXPECT_FLOAT_EQ(attach.localAnchorB.x, -0.5f);
    EXPECT_TRUE(attach.enableLimit);
    EXPECT_FLOAT_EQ(attach.upperAngle, 1.0f);
    const auto& right = d.joints[3].as<i2d::RevoluteJointDef>();  // grid: body 0 → its right neighbour
    EXPECT_FLOAT_EQ(right.localAnchorA.x, 1.0f);                  // hinged at the midpoint between them
    EXPECT_FLOAT_EQ(right.localAnchorB.x, -1.0f);
    const auto& up = d.joints[4].as<i2d::RevoluteJointDef>();
    EXPECT_FLOAT_EQ(up.localAnchorA.y, 0.5f);
    EXPECT_FLOAT_EQ(up.localAnchorB.y, -0.5f);

    try {
        tb::parseSceneDesc(R"({"bodies": [{"generator": "chain", "count": 2, "step": [1, 0], "joint_type": "weld",
            "body": {}}]})",
                           "g.json", "g");
        ADD_FAILURE() << "a weld chain was taken";
    } catch (const tb::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("bodies[0].joint_type"), std::string::npos) << e.what();
    }
}

}  // namespace
