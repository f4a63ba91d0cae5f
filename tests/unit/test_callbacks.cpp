// The custom filter and pre-solve callbacks, hit events, rolling resistance
// and tangent speed.
#include <gtest/gtest.h>

#include <cmath>

#include "world_fixtures.hpp"

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;

TEST(CustomFilter, RefusedPairsMakeNoContact) {
    World w;
    BodyId ground = test::makeGround(w);
    BodyId ghost = test::makeBox(w, {0.0f, 2.0f});
    BodyId solid = test::makeBox(w, {3.0f, 2.0f});
    const ShapeId ghostShape = w.bodyShapes(ghost).front();
    int calls = 0;
    w.setCustomFilter([&](ShapeId a, ShapeId b) {
        ++calls;
        return a != ghostShape && b != ghostShape;
    });
    for (int i = 0; i < 120; ++i) w.step(kDt);
    EXPECT_GT(calls, 0);
    EXPECT_LT(w.position(ghost).y, -5.0f);  // fell through the ground
    EXPECT_NEAR(w.position(solid).y, 0.5f, kLinearSlop);
    (void)ground;
    // An empty function removes the filter.
    w.setCustomFilter({});
    w.setTransform(ghost, {0.0f, 2.0f}, 0.0f);
    w.setLinearVelocity(ghost, {0, 0});
    for (int i = 0; i < 120; ++i) w.step(kDt);
    EXPECT_NEAR(w.position(ghost).y, 0.5f, kLinearSlop);
}

// The documented one-way platform: contacts whose normal would not push the
// player up are switched off. A ball thrown up from below passes through
// the platform and lands on it.
TEST(PreSolve, OneWayPlatformLetsABodyThroughFromBelowAndHoldsItFromAbove) {
    World w;
    BodyId platformBody = w.createBody({.position = {0.0f, 3.0f}});
    const ShapeId platform = w.createPolygonShape(platformBody, {}, i2d::makeBox(2.0f, 0.1f));
    BodyId ball = w.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 1.0f}, .linearVelocity = {0, 10}});
    w.createCircleShape(ball, {}, {{0, 0}, 0.25f});
    w.setPreSolve([&](ShapeId a, ShapeId b, const Manifold& m) {
        // The normal points from A to B; make it point from the platform to the other shape.
        Vec2 up = a == platform ? m.normal : -m.normal;
        if (a != platform && b != platform) return true;
        return up.y > 0.7f && w.linearVelocity(ball).y <= 0.5f;
    });
    float highest = 0.0f;
    for (int i = 0; i < 180; ++i) {
        w.step(kDt);
        highest = std::max(highest, w.position(ball).y);
    }
    EXPECT_GT(highest, 3.5f);  // went through the platform on the way up
    // Rests on its top face (3.1 m) at its radius, within the slop.
    EXPECT_NEAR(w.position(ball).y, 3.1f + 0.25f, kLinearSlop);
}

TEST(PreSolve, CallbackCannotChangeTheWorld) {
    World w;
    test::makeGround(w);
    BodyId box = test::makeBox(w, {0.0f, 0.5f});
    bool refused = false;
    w.setPreSolve([&](ShapeId, ShapeId, const Manifold&) {
        try {
            w.destroyBody(box);
        } catch (const Error&) {
            refused = true;
        }
        return true;
    });
    w.step(kDt);
    EXPECT_TRUE(refused);
    EXPECT_TRUE(w.isValid(box));
}

// A ball dropped 5 m: one hit event, at about √(2·g·4.5) (its bottom falls
// 4.5 m before the speculative contact forms, 2 cm above the ground).
TEST(HitEvents, ADroppedBallReportsOneHitAtItsImpactSpeed) {
    World w;
    test::makeGround(w);
    BodyId ball = w.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 5.0f}});
    const ShapeId s = w.createCircleShape(ball, {.enableHitEvents = true}, {{0, 0}, 0.5f});
    BodyId quiet = w.createBody({.type = BodyType::dynamic_body, .position = {3.0f, 5.0f}});
    w.createCircleShape(quiet, {}, {{0, 0}, 0.5f});
    int hits = 0;
    float speed = 0.0f;
    for (int i = 0; i < 180; ++i) {
        w.step(kDt);
        for (const ContactHitEvent& e : w.contactHitEvents()) {
            EXPECT_TRUE(e.shapeA == s || e.shapeB == s);  // the quiet ball reports none
            ++hits;
            speed = e.approachSpeed;
        }
    }
    EXPECT_EQ(hits, 1);
    // Within one step's gain of speed (g·Δt = 0.17 m/s) of the free-fall value.
    EXPECT_NEAR(speed, std::sqrt(2.0f * 10.0f * 4.5f), 10.0f * kDt);
}

TEST(HitEvents, BelowTheThresholdNothingIsReported) {
    World w({.hitEventThreshold = 20.0f});
    test::makeGround(w);
    BodyId ball = w.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 5.0f}});
    w.createCircleShape(ball, {.enableHitEvents = true}, {{0, 0}, 0.5f});
    for (int i = 0; i < 180; ++i) {
        w.step(kDt);
        EXPECT_TRUE(w.contactHitEvents().empty());
    }
    EXPECT_THROW(w.setSettings({.hitEventThreshold = -1.0f}), Error);
}

// A disc rolling on flat ground with rolling resistance c loses c·m·g·v of
// power: (3/4)m v² falls at that rate, so a = −(2/3)·c·g and it stops after
// v₀²/(2|a|) = 6 m from 2 m/s with c = 0.05. Without it, it keeps rolling.
TEST(RollingResistance, ARollingDiscStopsWhereTheEnergyBalanceSays) {
    auto run = [](float resistance) {
        World w;
        test::makeGround(w, 100.0f);
        BodyId disc = w.createBody({.type = BodyType::dynamic_body,
                                    .position = {0.0f, 0.5f},
                                    .linearVelocity = {2, 0},
                                    .angularVelocity = -4});
        w.createCircleShape(disc, {.rollingResistance = resistance}, {{0, 0}, 0.5f});
        for (int i = 0; i < 600; ++i) w.step(kDt);
        return std::make_pair(w.position(disc).x, w.linearVelocity(disc).x);
    };
    auto [x, v] = run(0.05f);
    EXPECT_NEAR(v, 0.0f, 0.01f);
    // Within 10 %: the resisting torque acts through the soft contact's
    // normal impulse, which carries the weight only on average.
    EXPECT_NEAR(x, 6.0f, 0.6f);
    auto [xFree, vFree] = run(0.0f);
    EXPECT_NEAR(vFree, 2.0f, 0.02f);
    EXPECT_GT(xFree, 19.0f);
}

// A conveyor: ground with a tangent speed carries a box along at that speed.
TEST(TangentSpeed, AConveyorCarriesABoxAtItsSpeed) {
    World w;
    BodyId ground = w.createBody({});
    const ShapeId belt = w.createPolygonShape(ground, {.friction = 0.8f, .tangentSpeed = 2.0f},
                                              makeOffsetBox(50.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
    BodyId box = test::makeBox(w, {0.0f, 0.5f});
    for (int i = 0; i < 120; ++i) w.step(kDt);
    // Friction reaches the belt's speed within a fraction of a second (μg =
    // 8 m/s²); after 2 s the box moves with it, within 1 %.
    EXPECT_NEAR(w.linearVelocity(box).x, 2.0f, 0.02f);
    EXPECT_NEAR(w.linearVelocity(box).y, 0.0f, 0.01f);
    w.setTangentSpeed(belt, -1.0f);
    for (int i = 0; i < 120; ++i) w.step(kDt);
    EXPECT_NEAR(w.linearVelocity(box).x, -1.0f, 0.01f);
    EXPECT_EQ(w.tangentSpeed(belt), -1.0f);
    EXPECT_THROW(w.setTangentSpeed(belt, std::nanf("")), Error);
    EXPECT_THROW(w.setRollingResistance(belt, -1.0f), Error);
}

}  // namespace
}  // namespace i2d
