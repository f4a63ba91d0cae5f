// The shipped `platformer` scene: its script plays the level through (the
// one-way ledge passed from below and stood on, the lift ridden, both coins
// collected), and a player driven by input, as the viewer's keys drive it.
#include <gtest/gtest.h>

#include <algorithm>

#include "game/platformer.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace {

tb::Scene loadPlatformer() { return tb::buildScene(tb::loadSceneDesc("platformer", TB_TEST_ASSETS_DIR)); }

// The player's capsule stands 0.3 m (its radius) above what it stands on;
// 1 cm covers the contact's slop and the soft contact's sag.
constexpr float kStandTolerance = 0.01f;

TEST(Platformer, TheScriptPlaysTheLevelThrough) {
    tb::Scene s = loadPlatformer();
    ASSERT_TRUE(s.game);
    const i2d::BodyId player = s.named.at("player");
    const i2d::BodyId lift = s.named.at("lift");
    i2d::World& w = *s.world;
    float highestUnderLedge = 0.0f;
    bool stoodOnLedge = false, rodeLift = false;
    for (int i = 0; i < 15 * 60; ++i) {
        tb::stepScene(s, s.desc.dt);
        const i2d::Vec2 p = w.position(player);
        if (p.x > 1.5f && p.x < 4.5f) highestUnderLedge = std::max(highestUnderLedge, p.y);
        // On the ledge: its top is 2.3 m.
        if (p.x > 1.5f && p.x < 4.5f && std::abs(p.y - 2.6f) < kStandTolerance && s.game->playerGrounded())
            stoodOnLedge = true;
        // On the lift, moving with it between the plateau and the far platform.
        const i2d::Vec2 l = w.position(lift);
        if (p.x > 19.5f && p.x < 23.5f && std::abs(p.x - l.x) < 1.0f && std::abs(p.y - 2.3f) < kStandTolerance &&
            w.linearVelocity(lift).x > 0.5f)
            rodeLift = true;
    }
    EXPECT_GT(highestUnderLedge, 2.6f);  // came up through the ledge from below
    EXPECT_TRUE(stoodOnLedge);           // and was held by it from above
    EXPECT_TRUE(rodeLift);
    EXPECT_EQ(s.game->coinsCollected(), 2);
    EXPECT_FALSE(w.isEnabled(s.named.at("coin1")));
    EXPECT_FALSE(w.isEnabled(s.named.at("coin2")));
    // Ends on the far platform (2 m high, from x = 26 to 31).
    const i2d::Vec2 end = w.position(player);
    EXPECT_GT(end.x, 26.5f);
    EXPECT_LT(end.x, 31.0f);
    EXPECT_NEAR(end.y, 2.3f, kStandTolerance);
}

// Input instead of the script (the viewer's arrow keys): run right for 1 s
// from the start, then jump.
TEST(Platformer, InputDrivesThePlayer) {
    tb::Scene s = loadPlatformer();
    const i2d::BodyId player = s.named.at("player");
    i2d::World& w = *s.world;
    const float x0 = w.position(player).x;
    tb::PlayerInput right{1.0f, false};
    for (int i = 0; i < 60; ++i) tb::stepScene(s, s.desc.dt, &right);
    // 5 m/s for 1 s, less the first step's start (the velocity is set before each step).
    EXPECT_NEAR(w.position(player).x, x0 + 5.0f, 0.1f);
    tb::PlayerInput jump{0.0f, true};
    float top = 0.0f;
    for (int i = 0; i < 90; ++i) {
        tb::stepScene(s, s.desc.dt, &jump);
        top = std::max(top, w.position(player).y);
    }
    // v²/(2g) = 7²/20 = 2.45 m above the standing height, within 5 cm (the
    // discrete integration and the take-off from the soft contact).
    EXPECT_NEAR(top, 0.3f + 2.45f, 0.05f);
    // Held jump key: one jump per press, it is back on the ground.
    EXPECT_NEAR(w.position(player).y, 0.3f, kStandTolerance);
}

TEST(Platformer, BadSectionsAreRefused) {
    const std::string base = R"({"bodies": [{"name": "p", "shapes": [{"type": "circle", "radius": 0.3}]},
                                             {"name": "s", "type": "static"}], "platformer": )";
    EXPECT_THROW(tb::parseSceneDesc(base + R"({"player": "s"}})", "f", "f"), std::exception);  // not dynamic
    EXPECT_THROW(tb::parseSceneDesc(base + R"({"player": "p", "coins": ["s"]}})", "f", "f"),
                 std::exception);  // no sensor
    EXPECT_THROW(tb::parseSceneDesc(
                     base + R"({"player": "p", "moving": [{"body": "s", "from": [0, 0], "to": [1, 0]}]}})", "f", "f"),
                 std::exception);  // not kinematic
    EXPECT_THROW(tb::parseSceneDesc(base + R"({"player": "p", "script": [{"until": 2}, {"until": 1}]}})", "f", "f"),
                 std::exception);
    EXPECT_NO_THROW(tb::parseSceneDesc(base + R"({"player": "p"}})", "f", "f"));
}

}  // namespace
