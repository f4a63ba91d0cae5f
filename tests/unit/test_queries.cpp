// Shape casts, shape overlap, ray casts with a filter callback, a body's
// contacts, enable/disable, shape user data and the explosion helper.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "world_fixtures.hpp"

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;
// castShape stops once the gap is within 0.1·kLinearSlop (0.5 mm) of touching
// and never past it (world.hpp): a cast along L metres ends at a fraction in
// [exact − 0.0005/L, exact].
constexpr float kCastBand = 0.1f * kLinearSlop;

TEST(ShapeCast, CircleDroppedOnTheGroundStopsAtItsSurface) {
    World w;
    test::makeGround(w);
    const ShapeProxy ball = makeProxy(Circle{{0, 0}, 0.5f}, Transform{{0.0f, 5.0f}, {}});
    auto hit = w.castShape(ball, {0.0f, -10.0f});
    ASSERT_TRUE(hit.has_value());
    // The ball's bottom (4.5 m up) reaches y = 0 after 4.5 of 10 m.
    EXPECT_LE(hit->fraction, 0.45f + 1e-6f);
    EXPECT_GE(hit->fraction, 0.45f - kCastBand / 10.0f - 1e-6f);
    EXPECT_NEAR(hit->normal.x, 0.0f, 1e-4f);
    EXPECT_NEAR(hit->normal.y, 1.0f, 1e-4f);
    EXPECT_NEAR(hit->point.x, 0.0f, 1e-3f);
    EXPECT_NEAR(hit->point.y, 0.0f, 1e-4f);
}

// A box cast sideways at a rotated box (a diamond): its right face meets the
// diamond's left corner. The corner is at x = 5 − √2·0.5; the box's face
// starts at x = 0.5, so the gap is 4.5 − 0.7071 = 3.7929 m of 10 m.
TEST(ShapeCast, BoxCastAtARotatedBoxMeetsItsCorner) {
    World w({.gravity = {0, 0}});
    BodyId diamond = w.createBody({.position = {5.0f, 0.0f}, .angle = 0.7853982f});
    ShapeId target = w.createPolygonShape(diamond, {}, i2d::makeBox(0.5f, 0.5f));
    const ShapeProxy box = makeProxy(i2d::makeBox(0.5f, 0.5f), Transform{});
    auto hit = w.castShape(box, {10.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, target);
    const float exact = (4.5f - std::sqrt(2.0f) * 0.5f) / 10.0f;
    EXPECT_LE(hit->fraction, exact + 1e-5f);
    EXPECT_GE(hit->fraction, exact - kCastBand / 10.0f - 1e-5f);
    // The point hit is the diamond's corner.
    EXPECT_NEAR(hit->point.x, 5.0f - std::sqrt(2.0f) * 0.5f, 1e-3f);
    EXPECT_NEAR(hit->point.y, 0.0f, 1e-3f);
}

// A capsule cast diagonally onto a segment: only the motion across the
// segment closes the gap (convex gap, no stalling on the sliding part).
TEST(ShapeCast, CapsuleCastDiagonallyOntoASegment) {
    World w({.gravity = {0, 0}});
    BodyId ground = w.createBody({});
    w.createSegmentShape(ground, {}, {{-20.0f, 0.0f}, {20.0f, 0.0f}});
    const ShapeProxy capsule = makeProxy(Capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.25f}, Transform{{0.0f, 2.25f}, {}});
    auto hit = w.castShape(capsule, {6.0f, -4.0f});
    ASSERT_TRUE(hit.has_value());
    // The bottom (2 m up) reaches y = 0 at half of the 4 m descent.
    EXPECT_LE(hit->fraction, 0.5f + 1e-6f);
    EXPECT_GE(hit->fraction, 0.5f - kCastBand / 4.0f - 1e-6f);
    EXPECT_NEAR(hit->normal.y, 1.0f, 1e-4f);
}

TEST(ShapeCast, SkipsSensorsHonoursFiltersAndTheAcceptCallback) {
    World w({.gravity = {0, 0}});
    BodyId b = w.createBody({});
    w.createPolygonShape(b, {.isSensor = true}, makeOffsetBox(0.5f, 3.0f, {2.0f, 0.0f}, 0.0f));
    ShapeId near = w.createPolygonShape(b, {.filter = {.categoryBits = 2}}, makeOffsetBox(0.5f, 3.0f, {4.0f, 0.0f}, 0));
    ShapeId far = w.createPolygonShape(b, {}, makeOffsetBox(0.5f, 3.0f, {6.0f, 0.0f}, 0.0f));
    const ShapeProxy ball = makeProxy(Circle{{0, 0}, 0.5f}, Transform{});
    auto hit = w.castShape(ball, {10.0f, 0.0f});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, near);  // the sensor in front of it is passed through
    hit = w.castShape(ball, {10.0f, 0.0f}, {.maskBits = 1});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, far);
    hit = w.castShape(ball, {10.0f, 0.0f}, {.accept = [&](ShapeId s) { return s != near && s != far; }});
    EXPECT_FALSE(hit.has_value());
}

TEST(ShapeCast, TouchingAtTheStartHitsAtZeroOnlyWhenMovingIn) {
    World w;
    test::makeGround(w);
    // Resting 0.2 mm above the ground: within the cast's band.
    const ShapeProxy ball = makeProxy(Circle{{0, 0}, 0.5f}, Transform{{0.0f, 0.5002f}, {}});
    auto down = w.castShape(ball, {0.0f, -1.0f});
    ASSERT_TRUE(down.has_value());
    EXPECT_EQ(down->fraction, 0.0f);
    EXPECT_NEAR(down->normal.y, 1.0f, 1e-3f);
    EXPECT_FALSE(w.castShape(ball, {0.0f, 1.0f}).has_value());  // leaving
    EXPECT_FALSE(w.castShape(ball, {1.0f, 0.0f}).has_value());  // sliding along
}

TEST(ShapeCast, BadInputIsRefused) {
    World w;
    test::makeGround(w);
    const ShapeProxy ball = makeProxy(Circle{{0, 0}, 0.5f}, Transform{{0.0f, 2.0f}, {}});
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW((void)w.castShape(ball, {nan, -1.0f}), Error);
    EXPECT_THROW((void)w.castShape(ball, {0.0f, 1.0e9f}), Error);
    ShapeProxy empty;
    EXPECT_THROW((void)w.castShape(empty, {0.0f, -1.0f}), Error);
    ShapeProxy negative = ball;
    negative.radius = -1.0f;
    EXPECT_THROW((void)w.overlapShape(negative), Error);
    ShapeProxy nanPoint = ball;
    nanPoint.points[0].x = nan;
    EXPECT_THROW((void)w.overlapShape(nanPoint), Error);
}

// Exact overlap: a circle beside a box's corner overlaps its bounding box
// but not the box.
TEST(ShapeOverlap, IsExactNotByBoundingBox) {
    World w({.gravity = {0, 0}});
    BodyId b = w.createBody({});
    ShapeId box = w.createPolygonShape(b, {}, i2d::makeBox(1.0f, 1.0f));
    ShapeId disc = w.createCircleShape(b, {}, {{5.0f, 0.0f}, 1.0f});
    // Centre 0.6 m beyond the corner (1, 1) along the diagonal, radius 0.5.
    const Vec2 c = Vec2{1.0f, 1.0f} + (0.6f / std::sqrt(2.0f)) * Vec2{1.0f, 1.0f};
    const ShapeProxy nearCorner = makeProxy(Circle{{0, 0}, 0.5f}, Transform{c, {}});
    EXPECT_EQ(w.overlapAABB({c - Vec2{0.5f, 0.5f}, c + Vec2{0.5f, 0.5f}}).size(), 1u);  // the boxes overlap
    EXPECT_TRUE(w.overlapShape(nearCorner).empty());
    const ShapeProxy across = makeProxy(Capsule{{0.5f, 0.0f}, {4.5f, 0.0f}, 0.1f}, Transform{});
    auto both = w.overlapShape(across);
    ASSERT_EQ(both.size(), 2u);
    EXPECT_EQ(both[0], box);
    EXPECT_EQ(both[1], disc);
}

TEST(RayCast, AnyClosestAndAllWithAnAcceptCallback) {
    World w({.gravity = {0, 0}});
    BodyId b = w.createBody({});
    ShapeId first = w.createPolygonShape(b, {}, makeOffsetBox(0.5f, 1.0f, {3.0f, 0.0f}, 0.0f));
    ShapeId second = w.createPolygonShape(b, {}, makeOffsetBox(0.5f, 1.0f, {6.0f, 0.0f}, 0.0f));
    auto any = w.rayCastAny({0, 0}, {10, 0});
    ASSERT_TRUE(any.has_value());
    EXPECT_TRUE(any->shape == first || any->shape == second);
    EXPECT_FALSE(w.rayCastAny({0, 5}, {10, 0}).has_value());
    auto skipFirst = QueryFilter{.accept = [&](ShapeId s) { return s != first; }};
    auto closest = w.rayCastClosest({0, 0}, {10, 0}, skipFirst);
    ASSERT_TRUE(closest.has_value());
    EXPECT_EQ(closest->shape, second);
    EXPECT_NEAR(closest->point.x, 5.5f, 1e-4f);
    auto all = w.rayCastAll({0, 0}, {10, 0}, skipFirst);
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0].shape, second);
    auto any2 = w.rayCastAny({0, 0}, {10, 0}, skipFirst);
    ASSERT_TRUE(any2.has_value());
    EXPECT_EQ(any2->shape, second);
}

// The world is locked while a query calls the game's accept function.
TEST(RayCast, AcceptCallbackCannotChangeTheWorld) {
    World w({.gravity = {0, 0}});
    BodyId b = w.createBody({.type = BodyType::dynamic_body});
    w.createCircleShape(b, {}, {{3.0f, 0.0f}, 0.5f});
    bool refused = false;
    auto hit = w.rayCastClosest({0, 0}, {10, 0}, {.accept = [&](ShapeId) {
                                    try {
                                        w.destroyBody(b);
                                    } catch (const Error&) {
                                        refused = true;
                                    }
                                    return true;
                                }});
    EXPECT_TRUE(refused);
    EXPECT_TRUE(hit.has_value());
    EXPECT_TRUE(w.isValid(b));
    w.destroyBody(b);  // unlocked again afterwards
    EXPECT_EQ(w.bodyCount(), 0);
}

TEST(BodyContacts, ABoxOnTheGroundHasOneContactCarryingItsWeight) {
    World w;
    BodyId ground = test::makeGround(w);
    BodyId box = test::makeBox(w, {0.0f, 0.5f});
    BodyId other = test::makeBox(w, {5.0f, 0.5f});
    for (int i = 0; i < 60; ++i) w.step(kDt);
    auto contacts = w.bodyContacts(box);
    ASSERT_EQ(contacts.size(), 1u);
    const ShapeId boxShape = w.bodyShapes(box).front();
    EXPECT_TRUE(contacts[0].shapeA == boxShape || contacts[0].shapeB == boxShape);
    EXPECT_EQ(contacts[0].manifold.pointCount, 2);
    // At rest the normal impulses over the last substep carry m·g·h (soft
    // step, 4 substeps): 1 kg·10 m/s²·(1/240 s) within 2 % (the soft
    // contact's residual correction).
    const float total = contacts[0].normalImpulse[0] + contacts[0].normalImpulse[1];
    EXPECT_NEAR(total, 10.0f / 240.0f, 0.02f * 10.0f / 240.0f);
    EXPECT_EQ(w.bodyContacts(ground).size(), 2u);
    EXPECT_EQ(w.bodyContacts(other).size(), 1u);
}

TEST(EnableBody, ADisabledBodyLeavesSimulationAndQueriesAndComesBack) {
    World w;
    test::makeGround(w);
    BodyId box = test::makeBox(w, {0.0f, 3.0f});
    const Vec2 start = w.position(box);
    w.disableBody(box);
    EXPECT_FALSE(w.isEnabled(box));
    for (int i = 0; i < 60; ++i) w.step(kDt);
    EXPECT_EQ(w.position(box).x, start.x);  // not moved at all
    EXPECT_EQ(w.position(box).y, start.y);
    EXPECT_TRUE(w.queryPoint({0.0f, 3.0f}).empty());
    EXPECT_FALSE(w.rayCastClosest({-5.0f, 3.0f}, {10.0f, 0.0f}).has_value());
    EXPECT_EQ(w.bodyCount(), 2);  // kept in memory
    w.enableBody(box);
    EXPECT_TRUE(w.isEnabled(box));
    EXPECT_EQ(w.queryPoint({0.0f, 3.0f}).size(), 1u);
    for (int i = 0; i < 120; ++i) w.step(kDt);
    // It fell and rests on the ground again (0.5 m half height, within the 5 mm slop).
    EXPECT_NEAR(w.position(box).y, 0.5f, kLinearSlop);
}

// A pendulum whose pivot body is disabled: the joint acts on nothing, the bob falls freely.
TEST(EnableBody, JointsOfADisabledBodyActOnNothing) {
    World w;
    BodyId pivot = w.createBody({.type = BodyType::kinematic_body, .position = {0.0f, 10.0f}});
    BodyId bob = w.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 8.0f}});
    w.createCircleShape(bob, {}, {{0, 0}, 0.25f});
    w.createDistanceJoint(
        {.bodyA = pivot, .bodyB = bob, .localAnchorA = {0, 0}, .localAnchorB = {0, 0}, .length = 2.0f});
    for (int i = 0; i < 30; ++i) w.step(kDt);
    EXPECT_NEAR(w.position(bob).y, 8.0f, 0.01f);  // held by the rope
    w.disableBody(pivot);
    for (int i = 0; i < 60; ++i) w.step(kDt);
    // Free fall for 1 s from rest: g·t²/2 = 5 m, exactly, for a body that
    // touches nothing takes its gravity in two halves around each substep's
    // drift (split_kick.hpp); 1 cm allows for the rope's last velocity before
    // it let go.
    EXPECT_NEAR(w.position(bob).y, 8.0f - 5.0f, 0.01f);
}

TEST(ShapeUserData, SetAndGet) {
    World w;
    BodyId b = w.createBody({});
    ShapeId s = w.createCircleShape(b, {.userData = 7}, {});
    EXPECT_EQ(w.userData(s), 7u);
    w.setUserData(s, 42);
    EXPECT_EQ(w.userData(s), 42u);
    w.destroyShape(s);
    EXPECT_THROW(w.setUserData(s, 1), Error);
}

TEST(Explosion, PushesBodiesAwayWithFalloff) {
    World w({.gravity = {0, 0}});
    auto ball = [&](Vec2 p) {
        BodyId b = w.createBody({.type = BodyType::dynamic_body, .position = p});
        w.createCircleShape(b, {.density = 1.0f / 3.14159265f}, {{0, 0}, 1.0f});  // 1 kg
        return b;
    };
    BodyId inside = ball({3.0f, 0.0f});    // surface 2 m from the centre: within the radius
    BodyId halfway = ball({0.0f, -5.0f});  // surface 4 m away: halfway through the falloff
    BodyId beyond = ball({-8.0f, 0.0f});   // surface 7 m away: beyond radius + falloff
    BodyId wall = w.createBody({.position = {0.0f, 3.0f}});
    w.createCircleShape(wall, {}, {{0, 0}, 1.0f});
    w.explode({.center = {0, 0}, .radius = 3.0f, .falloff = 2.0f, .impulse = 4.0f});
    // Impulse 4 N·s on 1 kg, through the centre of mass: 4 m/s, no spin.
    EXPECT_NEAR(w.linearVelocity(inside).x, 4.0f, 1e-4f);
    EXPECT_NEAR(w.linearVelocity(inside).y, 0.0f, 1e-4f);
    EXPECT_NEAR(w.angularVelocity(inside), 0.0f, 1e-4f);
    EXPECT_NEAR(w.linearVelocity(halfway).y, -2.0f, 1e-4f);
    EXPECT_EQ(w.linearVelocity(beyond).x, 0.0f);
    EXPECT_EQ(w.linearVelocity(wall).y, 0.0f);
}

TEST(Explosion, BadInputIsRefusedAndChangesNothing) {
    World w({.gravity = {0, 0}});
    BodyId b = w.createBody({.type = BodyType::dynamic_body, .position = {1.0f, 0.0f}});
    w.createCircleShape(b, {}, {{0, 0}, 0.5f});
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(w.explode({.center = {0, 0}, .radius = nan}), Error);
    EXPECT_THROW(w.explode({.center = {nan, 0}}), Error);
    EXPECT_THROW(w.explode({.center = {0, 0}, .radius = 1.0f, .falloff = -1.0f}), Error);
    EXPECT_THROW(w.explode({.center = {0, 0}, .radius = 1.0f, .impulse = 1.0e30f}), Error);
    EXPECT_EQ(w.linearVelocity(b).x, 0.0f);
    // An impulse too large for a tiny body: refused before any change.
    BodyId dust = w.createBody({.type = BodyType::dynamic_body, .position = {-1.0f, 0.0f}});
    w.createCircleShape(dust, {.density = 1.0e-30f}, {{0, 0}, 0.5f});
    EXPECT_THROW(w.explode({.center = {0, 0}, .radius = 2.0f, .impulse = 1.0e6f}), Error);
    EXPECT_EQ(w.linearVelocity(b).x, 0.0f);
    EXPECT_EQ(w.linearVelocity(dust).x, 0.0f);
}

}  // namespace
}  // namespace i2d

namespace i2d {
namespace {

// The game-kit calls refuse stale handles and calls made from inside a
// callback (the world is locked there), and leave the world as it was.
TEST(GameKitValidation, StaleHandlesAndLockedCallsAreRefused) {
    World w;
    test::makeGround(w);
    BodyId box = test::makeBox(w, {0.0f, 0.5f});
    BodyId gone = test::makeBox(w, {3.0f, 0.5f});
    const ShapeId goneShape = w.bodyShapes(gone).front();
    w.destroyBody(gone);
    EXPECT_THROW(w.disableBody(gone), Error);
    EXPECT_THROW(w.enableBody(gone), Error);
    EXPECT_THROW((void)w.isEnabled(gone), Error);
    EXPECT_THROW((void)w.bodyContacts(gone), Error);
    EXPECT_THROW(w.setTangentSpeed(goneShape, 1.0f), Error);
    EXPECT_THROW((void)w.rollingResistance(goneShape), Error);
    int refused = 0;
    w.setPreSolve([&](ShapeId, ShapeId, const Manifold&) {
        for (auto call :
             {std::function<void()>([&] { w.disableBody(box); }), std::function<void()>([&] { w.setCustomFilter({}); }),
              std::function<void()>([&] { w.setPreSolve({}); }), std::function<void()>([&] {
                  w.explode({.center = {0, 0}, .radius = 2.0f, .impulse = 100.0f});
              })}) {
            try {
                call();
            } catch (const Error&) {
                ++refused;
            }
        }
        return true;
    });
    w.step(1.0f / 60.0f);
    EXPECT_EQ(refused % 4, 0);
    EXPECT_GE(refused, 4);
    EXPECT_TRUE(w.isEnabled(box));
    // The refused explosion would have given the 1 kg box 100 m/s; the step
    // itself leaves it at rest to within a millimetre per second.
    EXPECT_LT(length(w.linearVelocity(box)), 1e-3f);
}

// A disabled body can be changed, destroyed or re-enabled as another type.
TEST(GameKitValidation, DisabledBodiesCanBeChangedAndDestroyed) {
    World w;
    test::makeGround(w);
    BodyId a = test::makeBox(w, {0.0f, 0.5f});
    BodyId b = test::makeBox(w, {3.0f, 0.5f});
    for (int i = 0; i < 10; ++i) w.step(1.0f / 60.0f);
    w.disableBody(a);
    w.disableBody(a);  // twice: nothing more
    w.disableBody(b);
    w.setBodyType(b, BodyType::kinematic_body);
    w.setTransform(b, {3.0f, 5.0f}, 0.0f);
    w.createCircleShape(b, {}, {{0.0f, 1.0f}, 0.25f});
    EXPECT_TRUE(w.queryPoint({3.0f, 6.0f}).empty());  // its new shape is not in the broadphase either
    w.destroyBody(a);
    w.step(1.0f / 60.0f);
    w.enableBody(b);
    EXPECT_EQ(w.queryPoint({3.0f, 6.0f}).size(), 1u);
    w.setLinearVelocity(b, {0.0f, -1.0f});
    for (int i = 0; i < 60; ++i) w.step(1.0f / 60.0f);
    EXPECT_NEAR(w.position(b).y, 4.0f, 1e-3f);  // a kinematic body moves by its velocity: 1 m in 1 s
    EXPECT_EQ(w.bodyCount(), 2);
}

}  // namespace
}  // namespace i2d
