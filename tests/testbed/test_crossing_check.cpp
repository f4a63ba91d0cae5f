// Tunnelling and snag counts of `testbed run`, on scripted trajectories whose
// answer is known by construction, and on the shipped collision scenes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "crossing_check.hpp"
#include "run_command.hpp"
#include "run_report.hpp"
#include "scene_loader.hpp"
#include "scripted_simulation.hpp"
#include "simulation.hpp"

namespace {

const std::string kAssets = TB_TEST_ASSETS_DIR;

using tb::test::ScriptedSimulation;

// A static wall 0.1 m thick (x from 0 to 0.1, y from −5 to 5), a static
// segment on x = 5 and a dynamic ball.
tb::SceneDesc wallScene() {
    tb::SceneDesc d;
    tb::BodyDesc wall;
    wall.def.type = i2d::BodyType::static_body;
    tb::ShapeDesc box;
    box.type = i2d::ShapeType::polygon;
    box.polygon = i2d::makeOffsetBox(0.05f, 5.0f, {0.05f, 0.0f}, 0.0f);
    wall.shapes.push_back(box);
    tb::ShapeDesc seg;
    seg.type = i2d::ShapeType::segment;
    seg.segment = {{5.0f, -5.0f}, {5.0f, 5.0f}};
    wall.shapes.push_back(seg);
    d.bodies.push_back(wall);
    tb::BodyDesc ball;
    ball.def.type = i2d::BodyType::dynamic_body;
    tb::ShapeDesc circle;
    circle.type = i2d::ShapeType::circle;
    circle.circle.radius = 0.05f;
    ball.shapes.push_back(circle);
    d.bodies.push_back(ball);
    return d;
}

ScriptedSimulation simulationOf(const tb::SceneDesc& d) {
    ScriptedSimulation sim;
    sim.bodies.resize(d.bodies.size());
    sim.bodies[1].dynamic = true;
    return sim;
}

int tunnelledAlong(const std::vector<float>& xs) {
    const tb::SceneDesc d = wallScene();
    ScriptedSimulation sim = simulationOf(d);
    tb::CrossingCheck check(d);
    sim.place(1, xs.front(), 0.0f);
    check.start(sim);
    for (std::size_t i = 1; i < xs.size(); ++i) {
        sim.place(1, xs[i], 0.0f);
        check.observe(sim);
    }
    return check.tunnelled();
}

TEST(CrossingCheck, CountsPassagesNotPenetration) {
    EXPECT_EQ(tunnelledAlong({-1.0f, 1.0f}), 1);              // through the wall in one step
    EXPECT_EQ(tunnelledAlong({-1.0f, 0.05f, 0.5f}), 1);       // into it, then out of the far face
    EXPECT_EQ(tunnelledAlong({-1.0f, 0.004f, -0.2f}), 0);     // sunk 4 mm, back out the near face
    EXPECT_EQ(tunnelledAlong({-1.0f, -0.5f, -0.1f}), 0);      // never reached it
    EXPECT_EQ(tunnelledAlong({4.0f, 5.5f}), 1);               // across the segment, 0.5 m past it
    EXPECT_EQ(tunnelledAlong({4.0f, 5.01f, 4.9f}), 0);        // 0.01 m past, then back: penetration
    EXPECT_EQ(tunnelledAlong({4.0f, 5.01f, 5.03f}), 1);       // then 0.03 m past: more than kBeyond
    EXPECT_EQ(tunnelledAlong({-1.0f, 1.0f, 3.0f, 6.0f}), 1);  // counted once per body
}

TEST(CrossingCheck, ChainsCountOnlyFromTheirCollidingSide) {
    tb::SceneDesc d = wallScene();
    tb::ShapeDesc chain;
    chain.type = i2d::ShapeType::segment;
    chain.chain = true;
    // Drawn downwards along x = 10: its right side faces −x.
    chain.chainPoints = {{10.0f, 5.0f}, {10.0f, 0.0f}, {10.0f, -5.0f}};
    d.bodies[0].shapes = {chain};
    for (const auto& [from, to, expected] :
         std::vector<std::tuple<float, float, int>>{{9.0f, 11.0f, 1}, {11.0f, 9.0f, 0}}) {
        ScriptedSimulation sim = simulationOf(d);
        tb::CrossingCheck check(d);
        sim.place(1, from, 1.0f);
        check.start(sim);
        sim.place(1, to, 1.0f);
        check.observe(sim);
        EXPECT_EQ(check.tunnelled(), expected) << from << " -> " << to;
    }
}

TEST(CrossingCheck, CountsDrivenBodiesThatSnag) {
    tb::SceneDesc d = wallScene();
    d.bodies[1].driveSpeed = 6.0f;
    ScriptedSimulation sim = simulationOf(d);
    tb::CrossingCheck check(d);
    sim.place(1, -20.0f, 0.0f, 6.0f);
    check.start(sim);
    // Five settling steps are not judged, even at rest and jumping.
    for (int i = 0; i < 5; ++i) {
        sim.place(1, -20.0f, 0.0f, 0.0f, 3.0f);
        check.observe(sim);
    }
    EXPECT_EQ(check.snagged(), 0);
    EXPECT_FLOAT_EQ(check.drivenMaxVerticalSpeed(), 0.0f);
    sim.place(1, -19.9f, 0.0f, 5.9f, 0.05f);
    check.observe(sim);
    EXPECT_EQ(check.snagged(), 0);
    EXPECT_FLOAT_EQ(check.drivenMaxVerticalSpeed(), 0.05f);
    sim.place(1, -19.85f, 0.0f, 2.9f, 0.0f);  // below half of 6 m/s: caught
    check.observe(sim);
    EXPECT_EQ(check.snagged(), 1);
    EXPECT_EQ(check.driven(), 1);
}

// The collision scenes, each over its full default run of 600 steps
// (tiles: every player crosses 60-200 m of tiles; bullets: every shot has
// reached its target within the first 10 steps): in Impulse2D nothing
// tunnels, nothing snags and no driven body is kicked up by a seam (the
// issue's 0.1 m/s). Box2D 2.4.1 must run them too; its figures are reported
// in docs/performance.md, not asserted here.
TEST(CrossingCheck, ShippedCollisionScenesHoldInImpulse2D) {
    for (const char* name : {"tiles", "chain_terrain", "bullets"}) {
        const tb::SceneDesc desc = tb::loadSceneDesc(name, kAssets);
        const tb::RunReport r = tb::runScene(desc, 600);
        EXPECT_EQ(r.tunnelled, 0) << name;
        EXPECT_EQ(r.snagged, 0) << name;
        EXPECT_EQ(r.stepsCompleted, 600) << name;
        if (std::string(name) == "tiles") {
            EXPECT_EQ(r.driven, 4);
            EXPECT_LT(r.drivenMaxVerticalSpeed, 0.1f);
        }
        if (tb::box2dAvailable()) {
            const tb::RunReport b = tb::runScene(desc, 600, tb::EngineKind::box2d);
            EXPECT_EQ(b.stepsCompleted, 600) << name;
        }
    }
}

}  // namespace
