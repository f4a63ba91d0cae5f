// The joint scenes in both engines: each builds with every joint in Impulse2D
// and in the Box2D 2.4.1 backend and runs a second with finite state; every
// joint type maps to Box2D's own joint, and what Box2D does differently is
// listed in its notes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "metrics.hpp"
#include "run_report.hpp"
#include "scene_loader.hpp"
#include "simulation.hpp"

namespace {

const std::string kAssets = TB_TEST_ASSETS_DIR;

const std::vector<std::string> kJointScenes = {"ragdoll", "car",        "chain_swing", "slider_crank", "gears",
                                               "pulley",  "joint_grid", "heavy_chain", "bridge",       "crane"};

bool hasNote(const tb::Simulation& sim, const std::string& part) {
    return std::any_of(sim.notes().begin(), sim.notes().end(),
                       [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

class JointScene : public ::testing::TestWithParam<std::string> {};

TEST_P(JointScene, BuildsInBothEnginesAndRunsFinite) {
    const tb::SceneDesc desc = tb::loadSceneDesc(GetParam(), kAssets);
    ASSERT_FALSE(desc.joints.empty());
    std::vector<tb::EngineKind> engines = {tb::EngineKind::impulse2d};
    if (tb::box2dAvailable()) engines.push_back(tb::EngineKind::box2d);
    for (tb::EngineKind kind : engines) {
        SCOPED_TRACE(tb::engineName(kind));
        auto sim = tb::makeSimulation(desc, kind);
        EXPECT_EQ(sim->jointCount(), static_cast<int>(desc.joints.size()));
        for (int i = 0; i < 60; ++i) sim->step(desc.dt);
        EXPECT_TRUE(tb::allFinite(*sim));
    }
}

INSTANTIATE_TEST_SUITE_P(Shipped, JointScene, ::testing::ValuesIn(kJointScenes),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(JointScenes, UseTheJointTypesTheirNamesPromise) {
    auto count = [](const tb::SceneDesc& d, i2d::JointType t) {
        return std::count_if(d.joints.begin(), d.joints.end(), [&](const tb::JointDesc& j) { return j.type() == t; });
    };
    using JT = i2d::JointType;
    EXPECT_EQ(count(tb::loadSceneDesc("chain_swing", kAssets), JT::revolute), 21);
    EXPECT_EQ(count(tb::loadSceneDesc("car", kAssets), JT::wheel), 2);
    const tb::SceneDesc crank = tb::loadSceneDesc("slider_crank", kAssets);
    EXPECT_GE(count(crank, JT::revolute), 2);
    EXPECT_EQ(count(crank, JT::prismatic), 1);
    EXPECT_GE(count(tb::loadSceneDesc("gears", kAssets), JT::gear), 2);
    EXPECT_EQ(count(tb::loadSceneDesc("pulley", kAssets), JT::pulley), 1);
    const tb::SceneDesc crane = tb::loadSceneDesc("crane", kAssets);
    EXPECT_EQ(count(crane, JT::prismatic), 1);
    EXPECT_EQ(count(crane, JT::distance), 1);
    EXPECT_EQ(count(crane, JT::revolute), 1);
    for (const char* name : {"joint_grid", "heavy_chain", "bridge"}) {
        const tb::SceneDesc d = tb::loadSceneDesc(name, kAssets);
        EXPECT_EQ(count(d, JT::revolute), static_cast<long>(d.joints.size())) << name;
    }
    // chain_swing: the ball weighs 100 links.
    const tb::SceneDesc chain = tb::loadSceneDesc("chain_swing", kAssets);
    auto sim = tb::makeSimulation(chain, tb::EngineKind::impulse2d);
    int ball = -1, link = -1;
    for (std::size_t i = 0; i < chain.bodies.size(); ++i) {
        if (chain.bodies[i].name == "ball") ball = static_cast<int>(i);
        if (chain.bodies[i].name == "link_first") link = static_cast<int>(i);
    }
    ASSERT_GE(ball, 0);
    ASSERT_GE(link, 0);
    EXPECT_NEAR(sim->sample(ball).mass / sim->sample(link).mass, 100.0f, 0.01f);
}

// The shipped heavy chains at the defaults, sleeping off, 10 s (the joints
// issue's bar): every joint within 5 cm and the energy never above its start
// (1 % allows the float sum of 22 bodies' energies with room; a gain from
// the solver grows without bound). Both are trees of a 100:1 mass ratio,
// solved exactly (joint_tree.cpp): measured 1.9 cm (chain_swing) and 1.7 cm
// (heavy_chain); swept, 7.2 and 6.0 cm.
TEST(JointScenes, HeavyChainsHoldTheirJointsWithin5cm) {
    for (const char* name : {"chain_swing", "heavy_chain"}) {
        tb::SceneDesc desc = tb::loadSceneDesc(name, kAssets);
        desc.settings.enableSleep = false;
        const tb::RunReport r = tb::runScene(desc, 600);
        EXPECT_FALSE(r.nan) << name;
        EXPECT_LE(r.jointErrorMax, 0.05) << name;
        EXPECT_LE(r.energyMax, r.energyInitial + 0.01 * std::abs(r.energyInitial)) << name;
    }
}

// One joint of every type in a scene made in code.
tb::SceneDesc everyJointType() {
    tb::SceneDesc d;
    d.name = "every_joint";
    auto body = [&](i2d::BodyType type, i2d::Vec2 p) {
        tb::BodyDesc b;
        b.def.type = type;
        b.def.position = p;
        if (type == i2d::BodyType::dynamic_body) {
            tb::ShapeDesc s;
            s.type = i2d::ShapeType::circle;
            s.circle.radius = 0.25f;
            s.def.filter.groupIndex = -1;
            b.shapes.push_back(s);
        }
        d.bodies.push_back(b);
        return static_cast<int>(d.bodies.size()) - 1;
    };
    const int ground = body(i2d::BodyType::static_body, {0, 0});
    auto add = [&](int a, int b, tb::JointDefs def) {
        tb::JointDesc j;
        j.bodyA = a;
        j.bodyB = b;
        j.def = def;
        d.joints.push_back(j);
        return static_cast<int>(d.joints.size()) - 1;
    };
    int b1 = body(i2d::BodyType::dynamic_body, {0, 5});
    add(ground, b1, i2d::DistanceJointDef{.localAnchorA = {0, 6}, .length = 1.0f});
    int b2 = body(i2d::BodyType::dynamic_body, {2, 5});
    const int rev = add(ground, b2,
                        i2d::RevoluteJointDef{.localAnchorA = {2, 5},
                                              .enableLimit = true,
                                              .lowerAngle = -1,
                                              .upperAngle = 1,
                                              .enableMotor = true,
                                              .motorSpeed = 1,
                                              .maxMotorTorque = 10,
                                              .enableSpring = true,
                                              .hertz = 2,
                                              .dampingRatio = 0.5f});
    int b3 = body(i2d::BodyType::dynamic_body, {4, 5});
    const int pri = add(ground, b3,
                        i2d::PrismaticJointDef{.localAnchorA = {4, 5},
                                               .localAxisA = {0, 1},
                                               .enableLimit = true,
                                               .lowerTranslation = -1,
                                               .upperTranslation = 1,
                                               .enableSpring = true,
                                               .hertz = 1});
    int b4 = body(i2d::BodyType::dynamic_body, {6, 5});
    add(b4, body(i2d::BodyType::dynamic_body, {6.5f, 5}),
        i2d::WeldJointDef{
            .localAnchorA = {0.25f, 0}, .localAnchorB = {-0.25f, 0}, .linearHertz = 5, .angularHertz = 5});
    int b5 = body(i2d::BodyType::dynamic_body, {8, 5});
    add(b5, body(i2d::BodyType::dynamic_body, {8, 4}),
        i2d::WheelJointDef{.localAnchorA = {0, -1}, .enableMotor = true, .motorSpeed = 3, .maxMotorTorque = 5});
    add(ground, body(i2d::BodyType::dynamic_body, {10, 5}),
        i2d::MotorJointDef{.linearOffset = {10, 6}, .maxForce = 100, .maxTorque = 10});
    add(ground, body(i2d::BodyType::dynamic_body, {12, 5}), i2d::MouseJointDef{.target = {12, 6}, .maxForce = 100});
    add(body(i2d::BodyType::dynamic_body, {14, 5}), body(i2d::BodyType::dynamic_body, {16, 5}),
        i2d::PulleyJointDef{
            .groundAnchorA = {14, 8}, .groundAnchorB = {16, 8}, .lengthA = 3, .lengthB = 3, .ratio = 1});
    tb::JointDesc gear;
    gear.joint1 = rev;
    gear.joint2 = pri;
    gear.bodyA = b2;
    gear.bodyB = b3;
    gear.def = i2d::GearJointDef{.ratio = 2};
    d.joints.push_back(gear);
    return d;
}

TEST(Box2DJoints, EveryTypeMapsToBox2DsOwnJointWithNotes) {
    if (!tb::box2dAvailable()) GTEST_SKIP() << "built without the Box2D 2.4.1 backend";
    const tb::SceneDesc d = everyJointType();
    auto sim = tb::makeSimulation(d, tb::EngineKind::box2d);
    EXPECT_EQ(sim->jointCount(), 9);
    for (int i = 0; i < 60; ++i) sim->step(d.dt);
    EXPECT_TRUE(tb::allFinite(*sim));
    // The rigid ones hold: the distance joint keeps its length, the pulley its rope.
    EXPECT_LT(tb::jointError(d.joints[0], sim->sample(0), sim->sample(1)), 0.01f);
    for (const char* part :
         {"revolute springs", "prismatic springs", "weld joints", "wheel joints", "motor joints", "mouse joints"})
        EXPECT_TRUE(hasNote(*sim, part)) << part;
}

TEST(Box2DJoints, EveryTypeBuildsInImpulse2D) {
    const tb::SceneDesc d = everyJointType();
    auto sim = tb::makeSimulation(d, tb::EngineKind::impulse2d);
    EXPECT_EQ(sim->jointCount(), 9);
    for (int i = 0; i < 60; ++i) sim->step(d.dt);
    EXPECT_TRUE(tb::allFinite(*sim));
    EXPECT_TRUE(sim->notes().empty());
}

TEST(Box2DJoints, AGearOverAnotherJointTypeIsRefused) {
    tb::SceneDesc d = everyJointType();
    d.joints.back().joint2 = 0;  // the distance joint
    if (tb::box2dAvailable()) {
        EXPECT_THROW(tb::makeSimulation(d, tb::EngineKind::box2d), tb::SceneError);
    }
    EXPECT_THROW(tb::makeSimulation(d, tb::EngineKind::impulse2d), tb::SceneError);
}

}  // namespace
