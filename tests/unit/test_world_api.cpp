// The public World API: handles, mass properties, forces, events, queries,
// and the error policy (a refused call throws i2d::Error and changes nothing).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "world_fixtures.hpp"

using namespace i2d;

TEST(WorldApi, StaleHandlesAreDetected) {
    World world;
    BodyId a = world.createBody({.type = BodyType::dynamic_body});
    EXPECT_TRUE(world.isValid(a));
    world.destroyBody(a);
    EXPECT_FALSE(world.isValid(a));
    EXPECT_THROW(world.position(a), Error);
    EXPECT_THROW(world.destroyBody(a), Error);  // destroying twice is refused
    // The slot is reused with a new generation: the old handle stays stale.
    BodyId b = world.createBody({.type = BodyType::dynamic_body});
    EXPECT_EQ(a.index1, b.index1);
    EXPECT_NE(a.generation, b.generation);
    EXPECT_FALSE(world.isValid(a));
    EXPECT_THROW(world.setLinearVelocity(a, {1, 0}), Error);
    EXPECT_EQ(world.linearVelocity(b).x, 0.0f);
    EXPECT_THROW(world.position(BodyId{}), Error);
    EXPECT_FALSE(world.isValid(ShapeId{}));
}

TEST(WorldApi, DestroyingABodyRemovesItsShapesAndJoints) {
    World world;
    BodyId a = world.createBody({.type = BodyType::dynamic_body});
    BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {2, 0}});
    ShapeId s = world.createCircleShape(a, {}, {{0, 0}, 0.5f});
    JointId j = world.createDistanceJoint({.bodyA = a, .bodyB = b, .length = 2.0f});
    world.destroyBody(a);
    EXPECT_FALSE(world.isValid(s));
    EXPECT_FALSE(world.isValid(j));
    EXPECT_EQ(world.jointCount(), 0);
    EXPECT_TRUE(world.isValid(b));
    world.step(1.0f / 60.0f);
}

// A body's joints are a list through the joints (engine/src/joint.hpp,
// bodyJoints): in creation order, whichever side of each joint the body is,
// through removals at its head, middle and tail and a body destroyed with
// its joints.
TEST(WorldApi, ABodysJointsStayInCreationOrder) {
    World world;
    const BodyId a = world.createBody({.type = BodyType::dynamic_body});
    const BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {2, 0}});
    const BodyId c = world.createBody({.type = BodyType::dynamic_body, .position = {0, 2}});
    auto joint = [&](BodyId x, BodyId y) {
        return world.createDistanceJoint({.bodyA = x, .bodyB = y, .length = 2.0f});
    };
    auto same = [](const std::vector<JointId>& got, const std::vector<JointId>& want) {
        if (got.size() != want.size()) return false;
        for (std::size_t i = 0; i < got.size(); ++i)
            if (got[i].index1 != want[i].index1 || got[i].generation != want[i].generation) return false;
        return true;
    };
    const JointId j1 = joint(a, b), j2 = joint(a, c), j3 = joint(b, a), j4 = joint(a, b);
    EXPECT_TRUE(same(world.bodyJoints(a), {j1, j2, j3, j4}));
    EXPECT_TRUE(same(world.bodyJoints(b), {j1, j3, j4}));
    EXPECT_TRUE(same(world.bodyJoints(c), {j2}));
    world.destroyJoint(j2);  // the middle of a's list, the whole of c's
    EXPECT_TRUE(same(world.bodyJoints(a), {j1, j3, j4}));
    EXPECT_TRUE(world.bodyJoints(c).empty());
    world.destroyJoint(j1);  // the head of a's and b's
    world.destroyJoint(j4);  // the tail of a's and b's
    EXPECT_TRUE(same(world.bodyJoints(a), {j3}));
    EXPECT_TRUE(same(world.bodyJoints(b), {j3}));
    const JointId j5 = joint(c, a);  // appended after the removals (it may take a freed slot)
    EXPECT_TRUE(same(world.bodyJoints(a), {j3, j5}));
    world.destroyBody(b);  // takes j3 with it
    EXPECT_FALSE(world.isValid(j3));
    EXPECT_TRUE(same(world.bodyJoints(a), {j5}));
    EXPECT_TRUE(same(world.bodyJoints(c), {j5}));
    EXPECT_EQ(world.jointCount(), 1);
    world.step(1.0f / 60.0f);
}

TEST(WorldApi, MassPropertiesFromShapes) {
    World world;
    BodyId b = world.createBody({.type = BodyType::dynamic_body});
    // Box 2 × 1 m at density 3: m = 6 kg, I = m (w² + h²)/12 = 6·5/12 = 2.5 kg·m².
    world.createPolygonShape(b, {.density = 3.0f}, i2d::makeBox(1.0f, 0.5f));
    EXPECT_NEAR(world.mass(b), 6.0f, 1e-4f);
    EXPECT_NEAR(world.rotationalInertia(b), 2.5f, 1e-4f);
    // Add a 1 kg-ish disk off centre: centre of mass shifts by m₂d/(m₁+m₂).
    world.createCircleShape(b, {.density = 1.0f / 3.14159265f}, {{3.0f, 0.0f}, 1.0f});
    float m = world.mass(b);
    EXPECT_NEAR(m, 7.0f, 1e-3f);
    EXPECT_NEAR(world.localCenterOfMass(b).x, 3.0f / 7.0f, 1e-4f);
    // Parallel axes: I = 2.5 + 6·(3/7)² + (1·1²/2) + 1·(3 − 3/7)².
    float c = 3.0f / 7.0f;
    EXPECT_NEAR(world.rotationalInertia(b), 2.5f + 6 * c * c + 0.5f + (3 - c) * (3 - c), 1e-3f);
    // Override and reset.
    world.setMassData(b, {.mass = 10.0f, .center = {0, 0}, .rotationalInertia = 4.0f});
    EXPECT_FLOAT_EQ(world.mass(b), 10.0f);
    EXPECT_THROW(world.setMassData(b, {.mass = 0.0f}), Error);
    EXPECT_THROW(world.setMassData(b, {.mass = -1.0f}), Error);
    EXPECT_FLOAT_EQ(world.mass(b), 10.0f);  // refused calls change nothing
    world.resetMassData(b);
    EXPECT_NEAR(world.mass(b), 7.0f, 1e-3f);
}

TEST(WorldApi, RefusesBadInputWithoutChangingTheWorld) {
    World world;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {1, 2}});
    world.createCircleShape(b, {}, {{0, 0}, 0.5f});
    EXPECT_THROW(world.createBody({.position = {nan, 0}}), Error);
    EXPECT_THROW(world.createBody({.linearVelocity = {inf, 0}}), Error);
    EXPECT_THROW(world.createBody({.position = {1e30f, 0}}), Error);
    EXPECT_THROW(world.setTransform(b, {nan, 0}, 0), Error);
    EXPECT_THROW(world.applyForce(b, {inf, 0}, {0, 0}), Error);
    EXPECT_THROW(world.applyLinearImpulse(b, {0, nan}, {0, 0}), Error);
    EXPECT_THROW(world.setGravity({0, nan}), Error);
    EXPECT_THROW(world.step(0.0f), Error);
    EXPECT_THROW(world.step(-1.0f), Error);
    EXPECT_THROW(world.step(nan), Error);
    EXPECT_THROW(world.createCircleShape(b, {}, {{0, 0}, 0.0f}), Error);
    EXPECT_THROW(world.createCircleShape(b, {}, {{0, 0}, -1.0f}), Error);
    EXPECT_THROW(world.createCircleShape(b, {.density = -1.0f}, {{0, 0}, 1.0f}), Error);
    EXPECT_THROW(world.createCircleShape(b, {.restitution = 2.0f}, {{0, 0}, 1.0f}), Error);
    EXPECT_THROW(world.createCapsuleShape(b, {}, {{0, 0}, {0, 0}, 0.5f}), Error);
    EXPECT_THROW(world.createSegmentShape(b, {}, {{1, 1}, {1, 1}}), Error);
    EXPECT_THROW(world.createPolygonShape(b, {}, Polygon{}), Error);
    EXPECT_THROW(world.createDistanceJoint({.bodyA = b, .bodyB = b}), Error);
    WorldSettings bad;
    bad.velocityIterations = 0;
    EXPECT_THROW(world.setSettings(bad), Error);
    EXPECT_THROW(World{bad}, Error);
    // Nothing of the above changed the one body.
    EXPECT_EQ(world.bodyCount(), 1);
    EXPECT_EQ(world.shapeCount(), 1);
    EXPECT_EQ(world.position(b).x, 1.0f);
    EXPECT_EQ(world.position(b).y, 2.0f);
    EXPECT_EQ(world.linearVelocity(b).x, 0.0f);
    EXPECT_EQ(world.settings().velocityIterations, WorldSettings{}.velocityIterations);
}

TEST(WorldApi, ImpulseAtAPointChangesLinearAndAngularVelocity) {
    World world({.gravity = {0, 0}});
    BodyId b = world.createBody({.type = BodyType::dynamic_body});
    world.createPolygonShape(b, {.density = 1.0f}, i2d::makeBox(0.5f, 0.5f));  // m = 1, I = 1/6
    world.applyLinearImpulse(b, {0, 2}, {0.5f, 0});
    // Δv = p/m = (0, 2); Δω = (r × p)/I = (0.5·2)·6 = 6.
    EXPECT_NEAR(world.linearVelocity(b).y, 2.0f, 1e-5f);
    EXPECT_NEAR(world.angularVelocity(b), 6.0f, 1e-4f);
    // A force acts for one step: Δv = F Δt/m.
    world.applyForceToCenter(b, {60.0f, 0});
    world.step(1.0f / 60.0f);
    EXPECT_NEAR(world.linearVelocity(b).x, 1.0f, 1e-5f);
    world.step(1.0f / 60.0f);
    EXPECT_NEAR(world.linearVelocity(b).x, 1.0f, 1e-5f);  // cleared after the step
}

TEST(WorldApi, ContactEventsBeginAndEnd) {
    World world;
    test::makeGround(world);
    BodyId ball = world.createBody({.type = BodyType::dynamic_body, .position = {0, 2}});
    ShapeId s = world.createCircleShape(ball, {.restitution = 0.0f}, {{0, 0}, 0.5f});
    int begins = 0;
    for (int i = 0; i < 120; ++i) {
        world.step(1.0f / 60.0f);
        for (const auto& e : world.contactBeginEvents()) {
            EXPECT_TRUE(e.shapeA == s || e.shapeB == s);
            ++begins;
        }
    }
    EXPECT_EQ(begins, 1);
    world.setTransform(ball, {0, 10}, 0);
    world.step(1.0f / 60.0f);
    EXPECT_EQ(world.contactEndEvents().size(), 1u);
}

TEST(WorldApi, SensorEventsReportOverlapOnly) {
    World world({.gravity = {0, 0}});
    BodyId zone = world.createBody({});
    ShapeId sensor = world.createPolygonShape(zone, {.isSensor = true}, i2d::makeBox(1.0f, 1.0f));
    BodyId ball = world.createBody({.type = BodyType::dynamic_body, .position = {-3, 0}, .linearVelocity = {3, 0}});
    ShapeId visitor = world.createCircleShape(ball, {}, {{0, 0}, 0.25f});
    int begins = 0, ends = 0;
    for (int i = 0; i < 180; ++i) {
        world.step(1.0f / 60.0f);
        for (const auto& e : world.sensorBeginEvents()) {
            EXPECT_EQ(e.sensor, sensor);
            EXPECT_EQ(e.visitor, visitor);
            ++begins;
        }
        ends += static_cast<int>(world.sensorEndEvents().size());
    }
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 1);
    // A sensor does not stop the ball: it moved on at its speed.
    EXPECT_NEAR(world.linearVelocity(ball).x, 3.0f, 1e-5f);
}

TEST(WorldApi, RayCastsAndQueries) {
    World world({.gravity = {0, 0}});
    BodyId a = world.createBody({.position = {5, 0}});
    ShapeId sa = world.createPolygonShape(a, {}, i2d::makeBox(1.0f, 1.0f));
    BodyId b = world.createBody({.position = {10, 0}});
    ShapeId sb = world.createCircleShape(b, {.filter = {.categoryBits = 2}}, {{0, 0}, 1.0f});
    auto hit = world.rayCastClosest({0, 0}, {20, 0});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->shape, sa);
    EXPECT_NEAR(hit->point.x, 4.0f, 1e-4f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-4f);
    EXPECT_NEAR(hit->fraction, 0.2f, 1e-5f);
    auto all = world.rayCastAll({0, 0}, {20, 0});
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].shape, sa);
    EXPECT_EQ(all[1].shape, sb);
    EXPECT_NEAR(all[1].point.x, 9.0f, 1e-4f);
    // Filter: only category 2.
    auto filtered = world.rayCastClosest({0, 0}, {20, 0}, {.categoryBits = 0xFFFF, .maskBits = 2});
    ASSERT_TRUE(filtered.has_value());
    EXPECT_EQ(filtered->shape, sb);
    EXPECT_FALSE(world.rayCastClosest({0, 5}, {20, 0}).has_value());
    auto box = world.overlapAABB({{3, -0.5f}, {4.5f, 0.5f}});
    ASSERT_EQ(box.size(), 1u);
    EXPECT_EQ(box[0], sa);
    EXPECT_EQ(world.queryPoint({10.5f, 0.5f}).size(), 1u);
    EXPECT_TRUE(world.queryPoint({7.5f, 0.0f}).empty());
}

TEST(WorldApi, FilteredShapesDoNotCollide) {
    World world;
    BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {.filter = {.categoryBits = 1, .maskBits = 0xFFFF}},
                             makeOffsetBox(10, 1, {0, -1}, 0));
    BodyId ghost = world.createBody({.type = BodyType::dynamic_body, .position = {0, 1}});
    world.createCircleShape(ghost, {.filter = {.categoryBits = 2, .maskBits = 0xFFFF & ~1u}}, {{0, 0}, 0.5f});
    for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f);
    EXPECT_LT(world.position(ghost).y, -1.0f);  // fell through the ground
}
