// The joint plan (slots, exact trees, colouring, wide lanes) is kept from step
// to step while nothing it was made from changes (joint_solver.cpp). Every
// change the API allows to a joint, its bodies' masses, types or enabled
// flags, or the settings must make a new plan: a world that keeps its plan
// must step bit for bit as worlds that plan every step. Those are made to
// plan by a change that changes nothing, through two paths (so that each
// path's own mark is tested by the other world): setting their unchanged
// settings again, or switching off a motor that is already off.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <vector>

#include <impulse2d/impulse2d.hpp>

namespace {

using namespace i2d;

struct Rig {
    World world{WorldSettings{}};
    BodyId ceiling{};
    std::vector<BodyId> links;
    std::vector<JointId> hinges;
    JointId slider{}, spring{}, mouse{};
};

/// A hanging chain of 16 alike hinged boxes (wide rows), a slider and a
/// distance spring on it (scalar rows), and a free chain of four with a
/// heavy end (solved exactly as a tree; not hung from the ceiling, which
/// would join it to the first chain's tree through the immovable bodies).
void build(Rig& r) {
    WorldSettings set;
    set.enableSleep = false;
    r.world.setSettings(set);
    r.ceiling = r.world.createBody({});
    BodyId previous = r.ceiling;
    for (int i = 0; i < 16; ++i) {
        const BodyId link = r.world.createBody(
            {.type = BodyType::dynamic_body, .position = {0.6f * static_cast<float>(i) + 0.3f, 10.0f}});
        r.world.createPolygonShape(link, {.density = 1.0f}, makeBox(0.3f, 0.1f));
        RevoluteJointDef hinge;
        hinge.bodyA = previous;
        hinge.bodyB = link;
        hinge.localAnchorA = i == 0 ? Vec2{0.0f, 10.0f} : Vec2{0.3f, 0.0f};
        hinge.localAnchorB = {-0.3f, 0.0f};
        r.hinges.push_back(r.world.createRevoluteJoint(hinge));
        r.links.push_back(link);
        previous = link;
    }
    previous = BodyId{};
    for (int i = 0; i < 4; ++i) {
        const BodyId link = r.world.createBody(
            {.type = BodyType::dynamic_body, .position = {-0.6f * static_cast<float>(i) - 0.3f, 10.0f}});
        r.world.createPolygonShape(link, {.density = i == 3 ? 200.0f : 1.0f}, makeBox(0.3f, 0.1f));
        if (i > 0) {
            RevoluteJointDef hinge;
            hinge.bodyA = previous;
            hinge.bodyB = link;
            hinge.localAnchorA = {-0.3f, 0.0f};
            hinge.localAnchorB = {0.3f, 0.0f};
            r.world.createRevoluteJoint(hinge);
        }
        previous = link;
    }
    const BodyId slide = r.world.createBody({.type = BodyType::dynamic_body, .position = {2.0f, 8.0f}});
    r.world.createCircleShape(slide, {.density = 1.0f}, Circle{{}, 0.2f});
    PrismaticJointDef prismatic;
    prismatic.bodyA = r.links[3];
    prismatic.bodyB = slide;
    prismatic.localAnchorA = {0.0f, -2.0f};
    prismatic.localAxisA = {0.0f, 1.0f};
    r.slider = r.world.createPrismaticJoint(prismatic);
    DistanceJointDef distance;
    distance.bodyA = r.ceiling;
    distance.bodyB = r.links[8];
    distance.localAnchorA = {5.0f, 12.0f};
    distance.length = 3.0f;
    distance.enableSpring = true;
    distance.hertz = 2.0f;
    distance.dampingRatio = 0.3f;
    r.spring = r.world.createDistanceJoint(distance);
}

/// Every body's pose and velocity, as bytes.
std::vector<unsigned char> snapshot(const World& world) {
    std::vector<unsigned char> bytes;
    for (BodyId b : world.bodies()) {
        const Transform xf = world.transform(b);
        const Vec2 v = world.linearVelocity(b);
        const float w = world.angularVelocity(b);
        const float values[7] = {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, w};
        const auto* p = reinterpret_cast<const unsigned char*>(values);
        bytes.insert(bytes.end(), p, p + sizeof(values));
    }
    return bytes;
}

TEST(JointPlan, AKeptPlanStepsAsOneMadeEveryStep) {
    Rig kept, fresh, freshToo;
    build(kept);
    build(fresh);
    build(freshToo);
    // Each change at its step, applied to both worlds alike.
    const std::vector<std::pair<int, std::function<void(Rig&)>>> changes = {
        // A mass like the other links' (0.12 kg): ten times theirs would make
        // the chain a tree solved exactly, off the wide path this test is about.
        {10,
         [](Rig& r) {
             r.world.setMassData(r.links[3], {0.15f, {0.05f, 0.0f}, 0.002f});
         }},
        {20, [](Rig& r) { r.world.setFixedRotation(r.links[5], true); }},
        {30,
         [](Rig& r) {
             RevoluteJointDef def = r.world.revoluteJointDef(r.hinges[4]);
             def.lowerAngle = 0.0f;  // the hinge held at its reference angle: the limit acts at once
             def.upperAngle = 0.0f;
             r.world.setRevoluteJointDef(r.hinges[4], def);
             r.world.enableJointLimit(r.hinges[4], true);
         }},
        {40, [](Rig& r) { r.world.enableJointLimit(r.hinges[4], false); }},
        {45,
         [](Rig& r) {
             RevoluteJointDef def = r.world.revoluteJointDef(r.hinges[6]);
             def.motorSpeed = 2.0f;
             def.maxMotorTorque = 50.0f;
             r.world.setRevoluteJointDef(r.hinges[6], def);
             r.world.enableJointMotor(r.hinges[6], true);
         }},
        // A motor's speed and a mouse joint's target, which games set every
        // frame, keep the plan (the rows read them every step).
        {46, [](Rig& r) { r.world.setJointMotorSpeed(r.hinges[6], -3.0f); }},
        {47, [](Rig& r) { r.world.setJointMotorSpeed(r.hinges[6], 5.0f); }},
        {48,
         [](Rig& r) {
             MouseJointDef def;
             def.bodyA = r.ceiling;
             def.bodyB = r.links[14];
             def.target = r.world.worldCenterOfMass(r.links[14]);
             def.maxForce = 20.0f;
             r.mouse = r.world.createMouseJoint(def);
         }},
        {49,
         [](Rig& r) {
             r.world.setMouseJointTarget(r.mouse, {9.0f, 12.0f});
         }},
        {50, [](Rig& r) { r.world.setBodyType(r.links[7], BodyType::kinematic_body); }},
        {55,
         [](Rig& r) {
             r.world.setMouseJointTarget(r.mouse, {7.0f, 8.0f});
         }},
        {60, [](Rig& r) { r.world.setBodyType(r.links[7], BodyType::dynamic_body); }},
        {70, [](Rig& r) { r.world.disableBody(r.links[9]); }},
        {75, [](Rig& r) { r.world.disableBody(r.ceiling); }},  // static: the awake bodies stay the same
        {80, [](Rig& r) { r.world.enableBody(r.links[9]); }},
        {85, [](Rig& r) { r.world.enableBody(r.ceiling); }},
        {90, [](Rig& r) { r.world.destroyJoint(r.hinges[2]); }},
        {100,
         [](Rig& r) {
             RevoluteJointDef def;
             def.bodyA = r.links[1];
             def.bodyB = r.links[2];
             def.localAnchorA = {0.3f, 0.0f};
             def.localAnchorB = {-0.3f, 0.0f};
             r.hinges[2] = r.world.createRevoluteJoint(def);
         }},
        {110,
         [](Rig& r) {
             RevoluteJointDef def = r.world.revoluteJointDef(r.hinges[10]);
             def.localAnchorB = {-0.25f, 0.02f};
             r.world.setRevoluteJointDef(r.hinges[10], def);
         }},
        {120, [](Rig& r) { r.world.setDensity(r.world.bodyShapes(r.links[11])[0], 4.0f); }},
        {130,
         [](Rig& r) {
             r.world.createCircleShape(r.links[12], {.density = 2.0f}, Circle{{0.2f, 0.0f}, 0.1f});
         }},
        {140,
         [](Rig& r) {
             WorldSettings set = r.world.settings();
             set.enableWarmStarting = false;
             r.world.setSettings(set);
         }},
        {150,
         [](Rig& r) {
             WorldSettings set = r.world.settings();
             set.enableWarmStarting = true;
             set.exactJointMassRatio = 1e30f;  // no exact trees
             r.world.setSettings(set);
         }},
        {160, [](Rig& r) { r.world.destroyShape(r.world.bodyShapes(r.links[12])[1]); }},
        {170, [](Rig& r) { r.world.resetMassData(r.links[3]); }},
        {180, [](Rig& r) { r.world.destroyBody(r.links[13]); }},
        {190, [](Rig& r) { r.world.setDistanceJointLength(r.spring, 2.5f); }},
        {200,
         [](Rig& r) {
             WorldSettings set = r.world.settings();
             set.positionCorrection = PositionCorrection::split;  // no wide rows
             r.world.setSettings(set);
         }},
        {210,
         [](Rig& r) {
             WorldSettings set = r.world.settings();
             set.positionCorrection = PositionCorrection::soft_step;
             set.exactJointMassRatio = 10.0f;
             r.world.setSettings(set);
         }},
    };
    std::size_t next = 0;
    for (int step = 0; step < 240; ++step) {
        for (; next < changes.size() && changes[next].first == step; ++next) {
            for (Rig* r : {&kept, &fresh, &freshToo}) changes[next].second(*r);
        }
        fresh.world.setSettings(fresh.world.settings());
        freshToo.world.enableJointMotor(freshToo.hinges[0], false);
        for (Rig* r : {&kept, &fresh, &freshToo}) r->world.step(1.0f / 60.0f);
        const std::vector<unsigned char> now = snapshot(kept.world);
        ASSERT_EQ(now, snapshot(fresh.world)) << "after step " << step;
        ASSERT_EQ(now, snapshot(freshToo.world)) << "after step " << step;
    }
    // The rig moved (a test of a world at rest would prove nothing).
    EXPECT_GT(std::abs(kept.world.linearVelocity(kept.links[15]).x) +
                  std::abs(kept.world.linearVelocity(kept.links[15]).y),
              0.1f);
}

}  // namespace
