// The game-kit shape fields in scene files (tangent_speed, rolling_resistance,
// enable_hit_events) and the world's hit_event_threshold: read by the
// loader, refused out of range, and carried to both engines (tangent speed
// through Box2D 2.4.1's pre-solve listener; rolling resistance noted as
// missing there).
#include <gtest/gtest.h>

#include <string>

#include "scene_build.hpp"
#include "scene_loader.hpp"
#include "simulation.hpp"

namespace {

const char* const kConveyor = R"({
  "world": {"hit_event_threshold": 2.5},
  "bodies": [
    {"type": "static", "shapes": [{"type": "box", "hx": 20, "hy": 0.5, "center": [0, -0.5],
                                   "friction": 0.8, "tangent_speed": 2.0}]},
    {"name": "crate", "position": [0, 0.5], "shapes": [{"type": "box", "hx": 0.5, "hy": 0.5,
                                                         "enable_hit_events": true}]},
    {"name": "ball", "position": [5, 0.5],
     "shapes": [{"type": "circle", "radius": 0.5, "rolling_resistance": 0.05}]}
  ]
})";

TEST(GameFields, LoadedIntoTheShapeDefinitions) {
    tb::SceneDesc d = tb::parseSceneDesc(kConveyor, "conveyor.json", "conveyor");
    EXPECT_EQ(d.settings.hitEventThreshold, 2.5f);
    EXPECT_EQ(d.bodies[0].shapes[0].def.tangentSpeed, 2.0f);
    EXPECT_TRUE(d.bodies[1].shapes[0].def.enableHitEvents);
    EXPECT_EQ(d.bodies[2].shapes[0].def.rollingResistance, 0.05f);
}

TEST(GameFields, OutOfRangeIsRefused) {
    std::string bad = kConveyor;
    bad.replace(bad.find("0.05"), 4, "-0.5");
    EXPECT_THROW(tb::parseSceneDesc(bad, "bad.json", "bad"), std::exception);
}

// The crate rides the belt at 2 m/s in both engines after 2 s (friction
// reaches the belt's speed in a quarter of a second at μg = 8 m/s²; 1 %
// covers either solver's residual slip).
TEST(GameFields, TangentSpeedCarriesTheCrateInBothEngines) {
    const tb::SceneDesc d = tb::parseSceneDesc(kConveyor, "conveyor.json", "conveyor");
    for (tb::EngineKind kind : {tb::EngineKind::impulse2d, tb::EngineKind::box2d}) {
        if (kind == tb::EngineKind::box2d && !tb::box2dAvailable()) continue;
        auto sim = tb::makeSimulation(d, kind);
        for (int i = 0; i < 120; ++i) sim->step(d.dt);
        EXPECT_NEAR(sim->sample(1).vx, 2.0f, 0.02f) << tb::engineName(kind);
        if (kind == tb::EngineKind::box2d) {
            bool noted = false;
            for (const std::string& n : sim->notes())
                noted = noted || n.find("rolling resistance") != std::string::npos;
            EXPECT_TRUE(noted);
        }
    }
}

// The shipped `conveyor` scene: the ball with rolling resistance 0.05 (r =
// 0.5 m, from 3 m/s) stops after v²/(2·(2/3)·c·g) = 13.5 m in Impulse2D
// (10 %: the resisting torque follows the soft contact's normal impulse);
// Box2D 2.4.1 has no rolling resistance and lets it roll on at 3 m/s.
TEST(GameFields, ConveyorSceneRollingResistanceInBothEngines) {
    const tb::SceneDesc d = tb::loadSceneDesc("conveyor", TB_TEST_ASSETS_DIR);
    int ball = -1;
    for (std::size_t i = 0; i < d.bodies.size(); ++i)
        if (d.bodies[i].name == "ball_resisting") ball = static_cast<int>(i);
    ASSERT_GE(ball, 0);
    auto impulse = tb::makeSimulation(d, tb::EngineKind::impulse2d);
    for (int i = 0; i < 600; ++i) impulse->step(d.dt);
    EXPECT_NEAR(impulse->sample(ball).x - d.bodies[static_cast<std::size_t>(ball)].def.position.x, 13.5f, 1.35f);
    EXPECT_NEAR(impulse->sample(ball).vx, 0.0f, 0.01f);
    if (!tb::box2dAvailable()) return;
    auto box2d = tb::makeSimulation(d, tb::EngineKind::box2d);
    for (int i = 0; i < 600; ++i) box2d->step(d.dt);
    EXPECT_NEAR(box2d->sample(ball).vx, 3.0f, 0.05f);
}

}  // namespace
