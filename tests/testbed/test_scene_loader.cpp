// Scene files: every kind of bad input is refused with a message naming the
// file, the field path and the problem; every shipped scene parses.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "scene_loader.hpp"

namespace {

const std::string kAssets = TB_TEST_ASSETS_DIR;

// A valid minimal scene to which each test adds one mistake.
std::string scene(const std::string& bodies, const std::string& extra = "") {
    return R"({"description": "t", )" + extra + R"("bodies": [)" + bodies + "]}";
}
const std::string kBall = R"({"name": "ball", "position": [0, 1], "shapes": [{"type": "circle", "radius": 0.5}]})";

// Parses `text` expecting a SceneError whose message contains every part.
void expectError(const std::string& text, const std::vector<std::string>& parts) {
    try {
        tb::parseSceneDesc(text, "bad.json", "bad");
        ADD_FAILURE() << "no error for: " << text;
    } catch (const tb::SceneError& e) {
        std::string msg = e.what();
        EXPECT_EQ(msg.rfind("bad.json: ", 0), 0u) << msg;  // the file comes first
        for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
    }
}

TEST(SceneLoader, MinimalSceneParses) {
    tb::SceneDesc d = tb::parseSceneDesc(scene(kBall), "ok.json", "ok");
    ASSERT_EQ(d.bodies.size(), 1u);
    EXPECT_EQ(d.name, "ok");
    EXPECT_EQ(d.bodies[0].name, "ball");
    EXPECT_EQ(d.bodies[0].def.type, i2d::BodyType::dynamic_body);
    EXPECT_EQ(d.bodies[0].def.position.y, 1.0f);
    ASSERT_EQ(d.bodies[0].shapes.size(), 1u);
    EXPECT_EQ(d.bodies[0].shapes[0].circle.radius, 0.5f);
}

TEST(SceneLoader, MalformedJson) {
    expectError(R"({"description": "t", "bodies": [ )", {"malformed JSON"});
    expectError(R"({"bodies": [], })", {"malformed JSON", "line 1"});
}

TEST(SceneLoader, UnknownField) {
    expectError(scene(R"({"shapes": [{"type": "circle", "radius": 0.5, "radius2": 1}]})"),
                {"bodies[0].shapes[0].radius2", "unknown field"});
    expectError(scene(kBall, R"("wrld": {}, )"), {"wrld: unknown field"});
    expectError(scene(kBall, R"("world": {"substep": 4}, )"), {"world.substep: unknown field"});
}

TEST(SceneLoader, DuplicateField) {
    expectError(scene(R"({"position": [0, 1], "position": [0, 2]})"), {"bodies[0]", "duplicate field 'position'"});
}

TEST(SceneLoader, WrongType) {
    expectError(scene(R"({"shapes": [{"type": "circle", "radius": "big"}]})"),
                {"bodies[0].shapes[0].radius", "expected a number, got a string"});
    expectError(scene(R"({"position": [0, 1, 2]})"), {"bodies[0].position", "array of 2 numbers"});
    expectError(scene(kBall, R"("world": {"velocity_iterations": 2.5}, )"),
                {"world.velocity_iterations", "expected an integer"});
    expectError(scene(kBall, R"("world": {"enable_sleep": 1}, )"), {"world.enable_sleep", "expected a boolean"});
    expectError(R"({"bodies": {}})", {"bodies: expected an array"});
    expectError(scene(kBall, R"("world": {"position_correction": "magic"}, )"),
                {"world.position_correction", "unknown value \"magic\"", "soft_step"});
}

TEST(SceneLoader, OutOfRange) {
    expectError(scene(R"({"shapes": [{"type": "circle", "radius": -1}]})"),
                {"bodies[0].shapes[0].radius", "out of range"});
    expectError(scene(R"({"shapes": [{"type": "circle", "radius": 0.5, "restitution": 1.5}]})"),
                {"bodies[0].shapes[0].restitution", "out of range", "[0, 1]"});
    expectError(scene(kBall, R"("dt": 0, )"), {"dt", "out of range"});
    // Below the engine's smallest step: named here, not by the engine at the first step.
    expectError(scene(kBall, R"("dt": 1e-7, )"), {"dt", "out of range"});
    expectError(scene(kBall, R"("world": {"substeps": 0}, )"), {"world.substeps", "out of range"});
    // Counts are capped so that a typo cannot exhaust memory.
    expectError(scene(R"({"generator": "row", "count": 100000000, "step": [1, 0], "body": {}})"),
                {"bodies[0].count", "out of range"});
    expectError(scene(R"({"generator": "grid", "columns": 1000, "rows": 1000, "spacing": [1, 1], "body": {}})"),
                {"bodies[0]", "too many bodies"});
}

TEST(SceneLoader, NonFiniteAndHugeNumbers) {
    // nlohmann-json refuses 1e999 while parsing (out_of_range 406, "number
    // overflow"); the loader still names the field it was reading.
    expectError(scene(R"({"position": [0, 1e999]})"), {"bodies[0].position[1]", "not a finite number"});
    expectError(scene(R"({"shapes": [{"type": "circle", "radius": -1e999}]})"),
                {"bodies[0].shapes[0].radius", "not a finite number"});
    // Finite as a double but not as a float.
    expectError(scene(R"({"position": [1e39, 0]})"), {"bodies[0].position[0]", "too large for a 32-bit float"});
    // Finite as a float but beyond the documented coordinate limit (1e7 m).
    expectError(scene(R"({"position": [1e30, 0]})"), {"bodies[0].position[0]", "out of range"});
    expectError(scene(R"({"linear_velocity": [0, -1e20]})"), {"bodies[0].linear_velocity[1]", "out of range"});
    // Integers beyond 64 bits are read as floating point by nlohmann-json.
    expectError(scene(kBall, R"("world": {"velocity_iterations": 18446744073709551616}, )"),
                {"world.velocity_iterations", "expected an integer"});
    expectError(scene(kBall, R"("world": {"velocity_iterations": 18446744073709551615}, )"),
                {"world.velocity_iterations", "out of range"});
    // JSON has no NaN literal: it is a syntax error.
    expectError(scene(R"({"angle": NaN})"), {"malformed JSON"});
}

TEST(SceneLoader, MissingRequiredField) {
    expectError(R"({"description": "no bodies"})", {"missing required field 'bodies'"});
    expectError(scene(R"({"shapes": [{"type": "circle"}]})"),
                {"bodies[0].shapes[0]", "missing required field 'radius'"});
    expectError(scene(R"({"shapes": [{"radius": 1}]})"), {"bodies[0].shapes[0]", "missing required field 'type'"});
    expectError(scene(kBall, R"("joints": [{"body_a": "ball"}], )"), {"joints[0]", "missing required field 'body_b'"});
}

TEST(SceneLoader, UnknownBodyInJoint) {
    const std::string two = kBall + R"(, {"name": "anchor", "type": "static", "position": [0, 3]})";
    expectError(scene(two, R"("joints": [{"body_a": "anchor", "body_b": "bal"}], )"),
                {"joints[0].body_b", "unknown body name 'bal'"});
    expectError(scene(two, R"("joints": [{"body_a": 0, "body_b": 7}], )"), {"joints[0].body_b", "out of range"});
    expectError(scene(two, R"("joints": [{"body_a": "ball", "body_b": "ball"}], )"),
                {"joints[0]", "two different bodies"});
    expectError(scene(two, R"("joints": [{"body_a": "anchor", "body_b": "ball", "anchor_b": [0, 2]}], )"),
                {"joints[0]", "anchors are 0 m apart"});
    // Chain attachments are resolved the same way.
    expectError(
        scene(R"({"generator": "chain", "count": 2, "step": [1, 0], "body": {}, "attach_start": {"body": "nail"}})"),
        {"bodies[0].attach_start.body", "unknown body name 'nail'"});
}

TEST(SceneLoader, DegenerateGeometry) {
    expectError(scene(R"({"shapes": [{"type": "polygon", "points": [[0, 0], [1, 1], [2, 2]]}]})"),
                {"bodies[0].shapes[0].points", "degenerate polygon"});
    expectError(scene(R"({"shapes": [{"type": "polygon", "points": [[0, 0], [0.001, 0], [0, 0.001]]}]})"),
                {"bodies[0].shapes[0].points", "degenerate polygon"});
    expectError(scene(R"({"shapes": [{"type": "polygon", "points": [[0, 0], [1, 0]]}]})"),
                {"bodies[0].shapes[0].points", "3 to 8 points"});
    expectError(scene(R"({"shapes": [{"type": "segment", "point1": [0, 0], "point2": [0, 0]}]})"),
                {"bodies[0].shapes[0].point2", "closer than 0.005 m"});
    expectError(scene(R"({"shapes": [{"type": "box", "hx": 0, "hy": 1}]})"),
                {"bodies[0].shapes[0].hx", "out of range"});
}

TEST(SceneLoader, DuplicateBodyNameAndTemplateName) {
    expectError(scene(kBall + "," + kBall), {"bodies[1]", "duplicate body name 'ball'"});
    expectError(scene(R"({"generator": "row", "count": 2, "step": [1, 0], "body": {"name": "x"}})"),
                {"bodies[0].body.name", "set by the generator"});
}

TEST(SceneLoader, GeneratorsExpand) {
    std::string text = scene(R"(
        {"name": "ground", "type": "static"},
        {"generator": "pyramid", "base": 3, "origin": [0, 0.5], "spacing": [1, 1], "name_last": "top",
         "body": {"shapes": [{"type": "box", "hx": 0.5, "hy": 0.5}]}},
        {"generator": "grid", "columns": 2, "rows": 3, "origin": [10, 0], "spacing": [2, 1], "name_at": {"5": "g5"},
         "link": {}, "body": {}},
        {"generator": "chain", "count": 3, "origin": [0, 10], "step": [1, 0], "anchor_prev": [-0.4, 0],
         "anchor_next": [0.4, 0], "attach_start": {"body": "ground", "anchor": [-0.6, 10]}, "name_prefix": "link",
         "body": {}},
        {"generator": "row", "count": 2, "origin": [0, 20], "step": [0, 1], "copies": [3, 2], "copy_step": [5, 10],
         "name_first": "r_first", "body": {"type": "kinematic"}})");
    tb::SceneDesc d = tb::parseSceneDesc(text, "gen.json", "gen");
    ASSERT_EQ(d.bodies.size(), 1u + 6u + 6u + 3u + 12u);
    // Pyramid: rows of 3, 2, 1 centred on x = 0; the apex is last.
    EXPECT_FLOAT_EQ(d.bodies[1].def.position.x, -1.0f);
    EXPECT_FLOAT_EQ(d.bodies[4].def.position.x, -0.5f);
    EXPECT_FLOAT_EQ(d.bodies[4].def.position.y, 1.5f);
    EXPECT_EQ(d.bodies[6].name, "top");
    EXPECT_FLOAT_EQ(d.bodies[6].def.position.y, 2.5f);
    // Grid: row-major from the bottom row; index 5 is column 1 of row 2.
    EXPECT_EQ(d.bodies[7 + 5].name, "g5");
    EXPECT_FLOAT_EQ(d.bodies[7 + 5].def.position.x, 12.0f);
    EXPECT_FLOAT_EQ(d.bodies[7 + 5].def.position.y, 2.0f);
    // Chain links named by prefix.
    EXPECT_EQ(d.bodies[13].name, "link0");
    EXPECT_EQ(d.bodies[15].name, "link2");
    // Copies: 3 columns x 2 rows of a 2-body row.
    EXPECT_EQ(d.bodies[16].name, "r_first");
    EXPECT_EQ(d.bodies[16].def.type, i2d::BodyType::kinematic_body);
    EXPECT_FLOAT_EQ(d.bodies[27].def.position.x, 10.0f);
    EXPECT_FLOAT_EQ(d.bodies[27].def.position.y, 31.0f);
    // Joints: grid 2x3 has 3 horizontal + 4 vertical links; chain has 1 attachment + 2 links.
    ASSERT_EQ(d.joints.size(), 7u + 3u);
    EXPECT_FLOAT_EQ(d.joints[0].as<i2d::DistanceJointDef>().length, 2.0f);  // grid link, centre to centre along x
    const tb::JointDesc& attach = d.joints[7];
    EXPECT_EQ(attach.bodyA, 0);
    EXPECT_EQ(attach.bodyB, 13);
    EXPECT_NEAR(attach.as<i2d::DistanceJointDef>().length, 0.2f, 1e-5f);       // (−0.6, 10) to link0's (−0.4, 10)
    EXPECT_NEAR(d.joints[8].as<i2d::DistanceJointDef>().length, 0.2f, 1e-5f);  // 0.4 → 0.6 between link0 and link1
}

TEST(SceneLoader, WorldSettingsAndJointOptions) {
    std::string text = scene(kBall + R"(, {"name": "anchor", "type": "static", "position": [0, 3]})",
                             R"("dt": 0.01, "world": {"gravity": [0, -9.81], "position_correction": "split",
                                "impact_model": "velocity_bias", "substeps": 8, "enable_sleep": false,
                                "exact_column_tilt": false},
                                "camera": {"center": [1, 2], "height": 5},
                                "joints": [{"body_a": "anchor", "body_b": "ball", "spring": {"hertz": 2, "damping_ratio": 0.1},
                                            "limit": {"min": 1, "max": 3}}], )");
    tb::SceneDesc d = tb::parseSceneDesc(text, "s.json", "s");
    EXPECT_FLOAT_EQ(d.dt, 0.01f);
    EXPECT_FLOAT_EQ(d.settings.gravity.y, -9.81f);
    EXPECT_EQ(d.settings.positionCorrection, i2d::PositionCorrection::split);
    EXPECT_EQ(d.settings.impactModel, i2d::ImpactModel::velocity_bias);
    EXPECT_EQ(d.settings.substeps, 8);
    EXPECT_FALSE(d.settings.enableSleep);
    EXPECT_FALSE(d.settings.exactColumnTilt);
    EXPECT_TRUE(tb::parseSceneDesc(scene(kBall), "ok.json", "ok").settings.exactColumnTilt);  // the default
    ASSERT_TRUE(d.camera);
    EXPECT_FLOAT_EQ(d.camera->height, 5.0f);
    ASSERT_EQ(d.joints.size(), 1u);
    EXPECT_EQ(d.joints[0].bodyA, 1);
    const auto& dj = d.joints[0].as<i2d::DistanceJointDef>();
    EXPECT_FLOAT_EQ(dj.length, 2.0f);  // anchors (0, 3) and (0, 1), measured from the layout
    EXPECT_TRUE(dj.enableSpring);
    EXPECT_TRUE(dj.enableLimit);
    EXPECT_FLOAT_EQ(dj.maxLength, 3.0f);
}

TEST(SceneLoader, MissingFileAndUnknownScene) {
    EXPECT_THROW(tb::loadSceneDesc("no/such/file.json", kAssets), tb::SceneError);
    try {
        tb::loadSceneDesc("no_such_scene", kAssets);
        ADD_FAILURE();
    } catch (const tb::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("no such scene"), std::string::npos) << e.what();
    }
}

TEST(ShippedScenes, ListedWithDescriptions) {
    auto scenes = tb::listScenes(kAssets);
    std::vector<std::string> expected = {"stack5",
                                         "stack5_overlap",
                                         "funnel",
                                         "pendulum_wave",
                                         "pendulum_grid",
                                         "pyramid20",
                                         "pyramid100",
                                         "tall_stack20",
                                         "tall_stack50",
                                         "card_house",
                                         "dominoes",
                                         "newtons_cradle",
                                         "bridge",
                                         "heavy_chain",
                                         "rain1000",
                                         "circle_pile1000",
                                         "many_pyramids",
                                         "many_pyramids_small",
                                         "joint_grid",
                                         "bullets",
                                         "spinning_rod",
                                         "incline",
                                         "bounce",
                                         "ragdoll",
                                         "car",
                                         "chain_swing",
                                         "slider_crank",
                                         "gears",
                                         "pulley",
                                         "crane",
                                         "high_mass_ratio"};
    for (const auto& name : expected) {
        auto it = std::find_if(scenes.begin(), scenes.end(), [&](const auto& s) { return s.first == name; });
        ASSERT_NE(it, scenes.end()) << name;
        EXPECT_FALSE(it->second.empty()) << name << " has no description";
    }
    for (const auto& s : scenes) EXPECT_NE(s.first, "scene.schema") << "the schema is not a scene";
}

TEST(ShippedScenes, EveryOneParses) {
    auto scenes = tb::listScenes(kAssets);
    ASSERT_GE(scenes.size(), 28u);
    for (const auto& [name, description] : scenes) {
        SCOPED_TRACE(name);
        tb::SceneDesc d;
        ASSERT_NO_THROW(d = tb::loadSceneDesc(name, kAssets));
        EXPECT_EQ(d.name, name);
        EXPECT_FALSE(d.bodies.empty());
    }
}

TEST(ShippedScenes, CountsMatchTheirDescriptions) {
    auto count = [](const tb::SceneDesc& d) {
        return std::count_if(d.bodies.begin(), d.bodies.end(),
                             [](const tb::BodyDesc& b) { return b.def.type == i2d::BodyType::dynamic_body; });
    };
    EXPECT_EQ(count(tb::loadSceneDesc("pyramid100", kAssets)), 5050);
    EXPECT_EQ(count(tb::loadSceneDesc("pyramid20", kAssets)), 210);
    EXPECT_EQ(count(tb::loadSceneDesc("many_pyramids", kAssets)), 22000);
    EXPECT_EQ(count(tb::loadSceneDesc("many_pyramids_small", kAssets)), 1100);
    EXPECT_EQ(count(tb::loadSceneDesc("rain1000", kAssets)), 1000);
    EXPECT_EQ(count(tb::loadSceneDesc("circle_pile1000", kAssets)), 1000);
    EXPECT_EQ(count(tb::loadSceneDesc("card_house", kAssets)), 40);
    EXPECT_EQ(count(tb::loadSceneDesc("pendulum_wave", kAssets)), 50);
    tb::SceneDesc stack = tb::loadSceneDesc("stack5", kAssets);
    ASSERT_EQ(count(stack), 5);
    // 1.2 kg boxes of side 2.4 m: density 1.2 / 2.4² (the file rounds to 6 decimals).
    EXPECT_NEAR(stack.bodies[1].shapes[0].def.density * 2.4f * 2.4f, 1.2f, 1e-5f);
    EXPECT_EQ(stack.bodies.back().name, "top");
    EXPECT_FLOAT_EQ(stack.bodies.back().def.position.y, 14.0f);
}

}  // namespace

namespace {

// Chains, bullets and driven bodies in the scene format.
TEST(SceneLoader, ChainsBulletsAndDrivenBodies) {
    const tb::SceneDesc d = tb::parseSceneDesc(
        scene(
            R"({"type": "static", "shapes": [{"type": "chain", "points": [[3, 0], [0, 0], [-3, 0]], "friction": 0.2}]},
                 {"type": "static", "shapes": [{"type": "chain", "points": [[0, 0], [1, 0], [1, 1]], "loop": true}]},
                 {"position": [0, 1], "bullet": true, "drive_speed": 5, "shapes": [{"type": "circle", "radius": 0.5}]})"),
        "ok.json", "ok");
    ASSERT_EQ(d.bodies.size(), 3u);
    const tb::ShapeDesc& open = d.bodies[0].shapes[0];
    EXPECT_TRUE(open.chain);
    EXPECT_FALSE(open.chainLoop);
    EXPECT_EQ(open.chainPoints.size(), 3u);
    EXPECT_FLOAT_EQ(open.def.friction, 0.2f);
    EXPECT_TRUE(d.bodies[1].shapes[0].chainLoop);
    EXPECT_TRUE(d.bodies[2].def.isBullet);
    ASSERT_TRUE(d.bodies[2].driveSpeed.has_value());
    EXPECT_FLOAT_EQ(*d.bodies[2].driveSpeed, 5.0f);

    expectError(scene(R"({"type": "static", "shapes": [{"type": "chain", "points": [[0, 0]]}]})"),
                {"bad.json", "bodies[0].shapes[0].points", "at least 2 points"});
    expectError(scene(R"({"type": "static", "shapes": [{"type": "chain", "points": [[0, 0], [0, 0]]}]})"),
                {"bodies[0].shapes[0].points", "apart"});
    expectError(
        scene(
            R"({"type": "static", "shapes": [{"type": "chain", "points": [[0, 0], [2, 0], [0, 2], [2, 2]], "loop": true}]})"),
        {"bodies[0].shapes[0].points", "crosses or touches itself"});
    expectError(
        scene(R"({"type": "static", "shapes": [{"type": "chain", "points": [[0, 0], [1, 0]], "sensor": true}]})"),
        {"bodies[0].shapes[0].sensor", "cannot be a sensor"});
    expectError(scene(R"({"type": "static", "drive_speed": 3, "shapes": []})"),
                {"bodies[0].drive_speed", "only a dynamic body"});
}

}  // namespace
