// The per-scene error figure: which scene gets which metric, the `error`
// object of `testbed run --json`, and each metric computed on trajectories
// whose answer can be worked out by hand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "error_metric.hpp"
#include "run_command.hpp"
#include "scene_loader.hpp"
#include "scripted_simulation.hpp"

namespace {

const std::string kAssets = TB_TEST_ASSETS_DIR;

using tb::test::ScriptedSimulation;

tb::BodySample dynamicAt(float x, float y, float mass = 1.0f) {
    tb::BodySample s;
    s.x = s.cx = x;
    s.y = s.cy = y;
    s.mass = mass;
    s.dynamic = true;
    return s;
}

tb::BodyDesc bodyDesc(const std::string& name, i2d::BodyType type, float restitution) {
    tb::BodyDesc b;
    b.name = name;
    b.def.type = type;
    tb::ShapeDesc s;
    s.type = i2d::ShapeType::circle;
    s.circle.radius = 0.5f;
    s.def.restitution = restitution;
    b.shapes.push_back(s);
    return b;
}

TEST(ErrorMetric, EveryBenchmarkSceneReportsItsMetricInTheJson) {
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"pyramid100", "max_excursion"}, {"many_pyramids", "max_excursion"}, {"many_pyramids_small", "max_excursion"},
        {"tall_stack20", "max_sway"},    {"tall_stack50", "max_sway"},       {"card_house", "max_excursion"},
        {"rain1000", "max_penetration"}, {"joint_grid", "joint_stretch"},    {"heavy_chain", "joint_stretch"},
        {"bounce", "rebound_error"},     {"pendulum_wave", "energy_drift"},  {"circle_pile1000", "max_penetration"},
    };
    for (const auto& [scene, metric] : expected) {
        std::ostringstream out, err;
        ASSERT_EQ(tb::runRunCommand({scene, "--steps", "2", "--json", "--assets", kAssets}, out, err), 0) << err.str();
        nlohmann::json j = nlohmann::json::parse(out.str());
        ASSERT_TRUE(j.contains("error") && j["error"].is_object()) << scene;
        EXPECT_EQ(j["error"]["metric"], metric) << scene;
        ASSERT_TRUE(j["error"]["value"].is_number()) << scene;
        EXPECT_GE(j["error"]["value"].get<double>(), 0.0) << scene;
        EXPECT_EQ(j["error"]["unit"], metric == "energy_drift" ? "1" : "m") << scene;
        EXPECT_EQ(j["error"].contains("collapsed"), metric == "max_excursion" || metric == "max_sway") << scene;
    }
    // A scene outside the benchmark set has no figure.
    std::ostringstream out, err;
    ASSERT_EQ(tb::runRunCommand({"stack5", "--steps", "2", "--json", "--assets", kAssets}, out, err), 0);
    EXPECT_TRUE(nlohmann::json::parse(out.str()).at("error").is_null());
}

// One body launched at (3, 4) m/s without gravity: after 1 s it is 5 m from
// its start, 3 m of it sideways, and has moved far enough to count as a collapse.
TEST(ErrorMetric, ExcursionAndSwayOfABodyInUniformMotion) {
    tb::SceneDesc desc;
    desc.settings.gravity = {0.0f, 0.0f};
    desc.settings.enableSleep = false;
    tb::BodyDesc b = bodyDesc("ball", i2d::BodyType::dynamic_body, 0.0f);
    b.def.linearVelocity = {3.0f, 4.0f};
    desc.bodies.push_back(b);
    desc.name = "pyramid100";  // the metric is chosen by scene name
    tb::RunReport excursion = tb::runScene(desc, 60);
    EXPECT_EQ(excursion.error.metric, tb::ErrorMetric::max_excursion);
    EXPECT_NEAR(excursion.error.value, 5.0, 1e-3);
    EXPECT_TRUE(excursion.error.collapsed);
    desc.name = "tall_stack20";
    tb::RunReport sway = tb::runScene(desc, 60);
    EXPECT_EQ(sway.error.metric, tb::ErrorMetric::max_sway);
    EXPECT_NEAR(sway.error.value, 3.0, 1e-3);
    // Straight up instead: no sway at all, no collapse, though it moved 5 m.
    desc.bodies[0].def.linearVelocity = {0.0f, 5.0f};
    tb::RunReport up = tb::runScene(desc, 60);
    EXPECT_NEAR(up.error.value, 0.0, 1e-6);
    EXPECT_FALSE(up.error.collapsed);
}

// Dropped from y = 5 to a lowest point y = 1 (d = 4 m) with e = max(0.5, 0)
// = 0.5: the rebound should reach e² d = 1 m above the lowest point, y = 2.
// It reaches y = 2.5, an error of 0.5 m.
TEST(ErrorMetric, ReboundErrorFromTheApexOfTheFirstRebound) {
    tb::SceneDesc desc;
    desc.bodies.push_back(bodyDesc("ground", i2d::BodyType::static_body, 0.0f));
    desc.bodies.push_back(bodyDesc("ball", i2d::BodyType::dynamic_body, 0.5f));
    ScriptedSimulation sim;
    sim.bodies = {tb::BodySample{}, dynamicAt(0, 5)};
    tb::ErrorTracker t(desc, tb::ErrorMetric::rebound_error);
    t.start(sim);
    // (y, vy) after each step: fall, touch, rise to 2.5, fall again lower than the start of the rise.
    const float path[][2] = {{4, -4},      {2, -8},    {1, -2},    {1.2f, 3}, {2.0f, 2},
                             {2.5f, 0.5f}, {2.4f, -1}, {0.5f, -6}, {3.0f, 6}};
    for (const auto& p : path) {
        sim.bodies[1].y = p[0];
        sim.bodies[1].vy = p[1];
        t.observe(sim, 0.0f, 0.0f);
    }
    tb::ErrorValue r = t.result(sim);
    EXPECT_EQ(r.metric, tb::ErrorMetric::rebound_error);
    EXPECT_NEAR(r.value, 0.5, 1e-6);
}

// The ground's restitution takes part: with e_ground = 1 the pair's
// restitution is max(0.5, 1) = 1 and the expected rebound is the whole drop.
TEST(ErrorMetric, ReboundUsesThePairsRestitutionByMaxMixing) {
    tb::SceneDesc desc;
    desc.bodies.push_back(bodyDesc("ground", i2d::BodyType::static_body, 1.0f));
    desc.bodies.push_back(bodyDesc("ball", i2d::BodyType::dynamic_body, 0.5f));
    ScriptedSimulation sim;
    sim.bodies = {tb::BodySample{}, dynamicAt(0, 5)};
    tb::ErrorTracker t(desc, tb::ErrorMetric::rebound_error);
    t.start(sim);
    const float path[][2] = {{1, -8}, {3, 4}, {4.9f, 0.1f}, {4.8f, -0.5f}};
    for (const auto& p : path) {
        sim.bodies[1].y = p[0];
        sim.bodies[1].vy = p[1];
        t.observe(sim, 0.0f, 0.0f);
    }
    EXPECT_NEAR(t.result(sim).value, 0.1, 1e-5);  // reached 3.9 m of the 4 m drop
}

// A 2 kg bob at y = 2 on a 2 m joint from a static pivot at y = 3: it can
// swing down to y = 1, so its swing energy is m g · 1 m = 20 J. Gaining 1 J of
// kinetic energy (v = 1 m/s) at the same height is a drift of 1/20.
TEST(ErrorMetric, EnergyDriftIsRelativeToTheSwingEnergy) {
    tb::SceneDesc desc;
    desc.bodies.push_back(bodyDesc("pivot", i2d::BodyType::static_body, 0.0f));
    desc.bodies.push_back(bodyDesc("bob", i2d::BodyType::dynamic_body, 0.0f));
    tb::JointDesc j;
    j.bodyA = 0;
    j.bodyB = 1;
    j.as<i2d::DistanceJointDef>().length = 2.0f;
    desc.joints.push_back(j);
    ScriptedSimulation sim;
    tb::BodySample pivot;
    pivot.y = 3.0f;
    sim.bodies = {pivot, dynamicAt(0, 2, 2.0f)};
    tb::ErrorTracker t(desc, tb::ErrorMetric::energy_drift);
    t.start(sim);
    t.observe(sim, 0.0f, 0.0f);
    EXPECT_NEAR(t.result(sim).value, 0.0, 1e-9);
    sim.bodies[1].vx = 1.0f;
    t.observe(sim, 0.0f, 0.0f);
    sim.bodies[1].vx = 0.5f;  // the largest drift counts, not the last
    t.observe(sim, 0.0f, 0.0f);
    EXPECT_NEAR(t.result(sim).value, 0.05, 1e-6);
}

TEST(ErrorMetric, PenetrationAndStretchAreTheLargestSeen) {
    tb::SceneDesc desc;
    ScriptedSimulation sim;
    tb::ErrorTracker pen(desc, tb::ErrorMetric::max_penetration), stretch(desc, tb::ErrorMetric::joint_stretch);
    pen.start(sim);
    stretch.start(sim);
    for (float v : {0.01f, 0.03f, 0.02f}) {
        pen.observe(sim, v, 2 * v);
        stretch.observe(sim, v, 2 * v);
    }
    EXPECT_NEAR(pen.result(sim).value, 0.03, 1e-7);
    EXPECT_NEAR(stretch.result(sim).value, 0.06, 1e-7);
}

}  // namespace
