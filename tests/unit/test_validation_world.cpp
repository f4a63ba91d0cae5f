// Input validation of the World's public entry points (docs/robustness.md,
// "Validation"): every refused call throws i2d::Error whose message names
// the problem, and leaves the world exactly as it was — checked here by
// comparing a full snapshot of the world before and after, then stepping.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "world_fixtures.hpp"

namespace i2d {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Everything a refused call could have touched, compared bit for bit.
struct Snapshot {
    int bodies = 0, shapes = 0, joints = 0, awake = 0;
    std::vector<float> values;
    WorldSettings settings;

    static Snapshot of(const World& world) {
        Snapshot s;
        s.bodies = world.bodyCount();
        s.shapes = world.shapeCount();
        s.joints = world.jointCount();
        s.awake = world.awakeBodyCount();
        s.settings = world.settings();
        for (BodyId b : world.bodies()) {
            Transform xf = world.transform(b);
            MassData md = world.massData(b);
            Vec2 v = world.linearVelocity(b);
            s.values.insert(s.values.end(), {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, world.angularVelocity(b),
                                             md.mass, md.center.x, md.center.y, md.rotationalInertia,
                                             world.linearDamping(b), world.angularDamping(b), world.gravityScale(b),
                                             static_cast<float>(world.bodyType(b)), world.isAwake(b) ? 1.0f : 0.0f});
            for (ShapeId sh : world.bodyShapes(b))
                s.values.insert(s.values.end(), {world.density(sh), world.friction(sh), world.restitution(sh)});
            for (JointId j : world.bodyJoints(b)) s.values.push_back(world.distanceJointDef(j).length);
        }
        return s;
    }
    bool operator==(const Snapshot& o) const {
        return bodies == o.bodies && shapes == o.shapes && joints == o.joints && awake == o.awake &&
               values.size() == o.values.size() &&
               std::memcmp(values.data(), o.values.data(), values.size() * sizeof(float)) == 0 &&
               std::memcmp(&settings, &o.settings, sizeof(WorldSettings)) == 0;
    }
};

// A small world with something of everything: ground, a resting box, a
// falling circle, a capsule, a joint, a sleeping body.
struct Scene {
    World world;
    BodyId ground, box, ball, pill, sleeper;
    ShapeId boxShape, groundShape;
    JointId joint;

    Scene() {
        ground = test::makeGround(world);
        groundShape = world.bodyShapes(ground)[0];
        box = test::makeBox(world, {0.0f, 0.5f});
        boxShape = world.bodyShapes(box)[0];
        ball = world.createBody({.type = BodyType::dynamic_body, .position = {3.0f, 2.0f}});
        world.createCircleShape(ball, {}, {{0.0f, 0.0f}, 0.3f});
        pill = world.createBody({.type = BodyType::dynamic_body, .position = {-3.0f, 2.0f}});
        world.createCapsuleShape(pill, {}, {{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.2f});
        joint = world.createDistanceJoint({.bodyA = ball, .bodyB = pill, .length = 6.0f});
        sleeper = world.createBody({.type = BodyType::dynamic_body, .position = {10.0f, 0.5f}, .isAwake = false});
        world.createPolygonShape(sleeper, {}, makeBox(0.5f, 0.5f));
        for (int i = 0; i < 10; ++i) world.step(1.0f / 60.0f);
    }
};

// The call must throw i2d::Error mentioning `fragment`, change nothing, and
// the world must step on normally afterwards.
void expectRefused(Scene& s, const std::function<void()>& call, const std::string& fragment) {
    Snapshot before = Snapshot::of(s.world);
    try {
        call();
        ADD_FAILURE() << "no i2d::Error for a call that should mention '" << fragment << "'";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
            << "message '" << e.what() << "' does not mention '" << fragment << "'";
    }
    EXPECT_TRUE(Snapshot::of(s.world) == before) << "a refused call changed the world ('" << fragment << "')";
    // Stepping on a copy of the check: nothing became non-finite.
    s.world.step(1.0f / 60.0f);
    for (BodyId b : s.world.bodies()) {
        EXPECT_TRUE(isFinite(s.world.position(b)));
        EXPECT_TRUE(isFinite(s.world.linearVelocity(b)));
    }
}

TEST(ValidationWorld, NonFiniteAndOutOfRangeNumbers) {
    Scene s;
    World& w = s.world;
    for (float bad : {kNan, kInf, -kInf, 1.0e30f}) {
        expectRefused(
            s,
            [&] {
                w.createBody({.position = {bad, 0.0f}});
            },
            "body position");
        expectRefused(
            s, [&] { w.createBody({.angle = bad}); }, "body angle");
        expectRefused(
            s,
            [&] {
                w.createBody({.linearVelocity = {0.0f, bad}});
            },
            "body linear velocity");
        expectRefused(
            s, [&] { w.createBody({.angularVelocity = bad}); }, "body angular velocity");
        expectRefused(
            s, [&] { w.createBody({.gravityScale = bad}); }, "gravity scale");
        expectRefused(
            s,
            [&] {
                w.setTransform(s.box, {bad, 0.0f}, 0.0f);
            },
            "position");
        expectRefused(
            s,
            [&] {
                w.setTransform(s.box, {0.0f, 0.0f}, bad);
            },
            "angle");
        expectRefused(
            s,
            [&] {
                w.setLinearVelocity(s.box, {bad, 0.0f});
            },
            "linear velocity");
        expectRefused(
            s, [&] { w.setAngularVelocity(s.box, bad); }, "angular velocity");
        expectRefused(
            s,
            [&] {
                w.applyForce(s.box, {bad, 0.0f}, {0.0f, 0.0f});
            },
            "force");
        expectRefused(
            s,
            [&] {
                w.applyForce(s.box, {1.0f, 0.0f}, {0.0f, bad});
            },
            "point");
        expectRefused(
            s,
            [&] {
                w.applyForceToCenter(s.box, {0.0f, bad});
            },
            "force");
        expectRefused(
            s, [&] { w.applyTorque(s.box, bad); }, "torque");
        expectRefused(
            s,
            [&] {
                w.applyLinearImpulse(s.box, {bad, 0.0f}, {0.0f, 0.0f});
            },
            "impulse");
        expectRefused(
            s,
            [&] {
                w.applyLinearImpulseToCenter(s.box, {0.0f, bad});
            },
            "impulse");
        expectRefused(
            s, [&] { w.applyAngularImpulse(s.box, bad); }, "angular impulse");
        expectRefused(
            s,
            [&] {
                w.setGravity({0.0f, bad});
            },
            "gravity");
        expectRefused(
            s, [&] { w.setGravityScale(s.box, bad); }, "gravity scale");
        if (!std::isfinite(bad))
            expectRefused(
                s, [&] { w.setMassData(s.box, {.mass = bad}); }, "mass");
        expectRefused(
            s,
            [&] {
                w.setMassData(s.box, {.mass = 1.0f, .center = {bad, 0.0f}});
            },
            "centre of mass");
        expectRefused(
            s, [&] { w.setDistanceJointLength(s.joint, bad); }, "joint length");
        expectRefused(
            s,
            [&] {
                w.rayCastClosest({bad, 0.0f}, {1.0f, 0.0f});
            },
            "ray origin");
        expectRefused(
            s,
            [&] {
                w.rayCastAll({0.0f, 0.0f}, {0.0f, bad});
            },
            "ray translation");
        expectRefused(
            s,
            [&] {
                w.overlapAABB({{bad, 0.0f}, {1.0f, 1.0f}});
            },
            "box lower");
        expectRefused(
            s,
            [&] {
                w.queryPoint({bad, bad});
            },
            "point");
    }
    for (float bad : {kNan, kInf, -1.0f}) {
        expectRefused(
            s, [&] { w.createBody({.linearDamping = bad}); }, "linear damping");
        expectRefused(
            s, [&] { w.createBody({.angularDamping = bad}); }, "angular damping");
        expectRefused(
            s, [&] { w.setLinearDamping(s.box, bad); }, "linear damping");
        expectRefused(
            s, [&] { w.setAngularDamping(s.box, bad); }, "angular damping");
        expectRefused(
            s, [&] { w.setMassData(s.box, {.mass = 1.0f, .rotationalInertia = bad}); }, "inertia");
        expectRefused(
            s, [&] { w.setFriction(s.boxShape, bad); }, "friction");
        expectRefused(
            s, [&] { w.setRestitution(s.boxShape, bad); }, "restitution");
        expectRefused(
            s, [&] { w.setDensity(s.boxShape, bad); }, "density");
    }
}

TEST(ValidationWorld, TimeStep) {
    Scene s;
    // Below 1 µs the solver's 1/h stops being safe: a denormal step (found by
    // fuzz_world) made it infinite and a moving kinematic body's position NaN.
    for (float dt :
         {0.0f, -0.0f, -1.0f / 60.0f, kNan, kInf, -kInf, 2.0f, std::numeric_limits<float>::denorm_min(), 1.0e-7f})
        expectRefused(
            s, [&] { s.world.step(dt); }, "time step");
    EXPECT_NO_THROW(s.world.step(1.0e-6f));
}

TEST(ValidationWorld, MassAndDensity) {
    Scene s;
    World& w = s.world;
    // The free mass functions check their shapes as the shape constructors do
    // (a NaN radius gave a NaN mass, a negative one a positive mass).
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW((void)computeMass(Circle{{0.0f, 0.0f}, nan}, 1.0f), Error);
    EXPECT_THROW((void)computeMass(Circle{{0.0f, 0.0f}, -1.0f}, 1.0f), Error);
    EXPECT_THROW((void)computeMass(Capsule{{0.0f, 0.0f}, {1.0f, 0.0f}, -0.5f}, 1.0f), Error);
    EXPECT_THROW((void)computeMass(Capsule{{nan, 0.0f}, {1.0f, 0.0f}, 0.5f}, 1.0f), Error);
    EXPECT_THROW((void)w.velocityAtPoint(s.box, {nan, nan}), Error);
    expectRefused(
        s, [&] { w.setMassData(s.box, {.mass = 0.0f}); }, "mass must be > 0");
    expectRefused(
        s, [&] { w.setMassData(s.box, {.mass = -1.0f}); }, "mass must be > 0");
    // 1e-40 is positive but its inverse is not finite in single precision.
    expectRefused(
        s, [&] { w.setMassData(s.box, {.mass = 1.0e-40f}); }, "mass");
    expectRefused(
        s, [&] { w.setMassData(s.box, {.mass = 1.0f, .rotationalInertia = 1.0e-40f}); }, "inertia");
    expectRefused(
        s, [&] { w.setMassData(s.ground, {.mass = 1.0f}); }, "only dynamic bodies");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {.density = -1.0f}, {{0.0f, 0.0f}, 0.5f});
        },
        "density");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {.density = 1.0e30f}, {{0.0f, 0.0f}, 0.5f});
        },
        "density");
    expectRefused(
        s, [&] { w.setDensity(s.boxShape, 1.0e30f); }, "density");
    expectRefused(
        s, [&] { w.setFriction(s.boxShape, 1.0e30f); }, "friction");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {.friction = 1.0e30f}, {{0.0f, 0.0f}, 0.5f});
        },
        "friction");
    // Documented safe behaviour: density 0 is allowed; a dynamic body
    // without any mass moves as 1 kg without rotation.
    BodyId massless = w.createBody({.type = BodyType::dynamic_body, .position = {20.0f, 5.0f}});
    w.createCircleShape(massless, {.density = 0.0f}, {{0.0f, 0.0f}, 0.5f});
    EXPECT_EQ(w.mass(massless), 1.0f);
    EXPECT_EQ(w.rotationalInertia(massless), 0.0f);
}

// Found by fuzz_world: a shape whose density is the smallest positive float
// gave its body a positive mass with an infinite inverse, a NaN centre of
// mass, and NaN velocities once a second shape was added.
TEST(ValidationWorld, DenormalDensityCountsAsNoMass) {
    World world;
    BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 10.0f}});
    world.createCircleShape(b, {.density = std::numeric_limits<float>::denorm_min()}, {{0.3f, 0.0f}, 0.5f});
    EXPECT_EQ(world.mass(b), 1.0f);  // the documented massless fallback
    EXPECT_TRUE(isFinite(world.worldCenterOfMass(b)));
    world.createCircleShape(b, {.density = 1.0f}, {{0.0f, 0.0f}, 0.5f});
    world.step(1.0f / 60.0f);
    EXPECT_TRUE(isFinite(world.position(b)));
    EXPECT_TRUE(isFinite(world.linearVelocity(b)));
    ShapeId s = world.bodyShapes(b)[1];
    world.setDensity(s, std::numeric_limits<float>::denorm_min());
    world.step(1.0f / 60.0f);
    EXPECT_TRUE(isFinite(world.position(b)));
    EXPECT_EQ(world.mass(b), 1.0f);
}

TEST(ValidationWorld, DegenerateGeometry) {
    Scene s;
    World& w = s.world;
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {}, {{0.0f, 0.0f}, 0.0f});
        },
        "radius");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {}, {{0.0f, 0.0f}, -1.0f});
        },
        "radius");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {}, {{0.0f, 0.0f}, kNan});
        },
        "radius");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {}, {{0.0f, 0.0f}, 1.0e6f});
        },
        "radius");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(s.box, {}, {{kNan, 0.0f}, 1.0f});
        },
        "circle centre");
    // Zero-length (and shorter than the linear slop) capsules and segments.
    expectRefused(
        s,
        [&] {
            w.createCapsuleShape(s.box, {}, {{1.0f, 1.0f}, {1.0f, 1.0f}, 0.5f});
        },
        "capsule centres");
    expectRefused(
        s,
        [&] {
            w.createCapsuleShape(s.box, {}, {{0.0f, 0.0f}, {0.001f, 0.0f}, 0.5f});
        },
        "capsule centres");
    expectRefused(
        s,
        [&] {
            w.createCapsuleShape(s.box, {}, {{0.0f, 0.0f}, {1.0f, 0.0f}, 0.0f});
        },
        "capsule radius");
    expectRefused(
        s,
        [&] {
            w.createSegmentShape(s.ground, {}, {{2.0f, 2.0f}, {2.0f, 2.0f}});
        },
        "segment points");
    expectRefused(
        s,
        [&] {
            w.createSegmentShape(s.ground, {}, {{2.0f, 2.0f}, {kInf, 2.0f}});
        },
        "segment point2");

    // Polygons: the world refuses what makePolygon would never build.
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, Polygon{}); }, "3 to 8 vertices");
    Polygon tooMany = makeBox(1.0f, 1.0f);
    tooMany.count = kMaxPolygonVertices + 1;
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, tooMany); }, "3 to 8 vertices");
    // Three copies of one point with plausible unit normals: zero area.
    Polygon point{};
    point.count = 3;
    point.normals[0] = {0.0f, -1.0f};
    point.normals[1] = {1.0f, 0.0f};
    point.normals[2] = {-1.0f, 0.0f};
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, point); }, "polygon");
    // Collinear vertices.
    Polygon line = makeBox(1.0f, 1.0f);
    line.count = 3;
    line.vertices[2] = {3.0f, -1.0f};
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, line); }, "polygon");
    // Tiny: edges shorter than 0.5 mm, a tenth of the linear slop; a 2 mm
    // card (card_house) is still accepted.
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, makeBox(1.0e-4f, 1.0e-4f)); }, "polygon edge");
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, makeBox(1.0f, 1.0e-4f)); }, "polygon");
    EXPECT_NO_THROW(w.destroyShape(w.createPolygonShape(s.box, {}, makeBox(0.001f, 0.2f))));
    // Huge: beyond the coordinate limit.
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, makeBox(1.0e8f, 1.0f)); }, "polygon vertex");
    // Rounding radius not finite or absurd.
    Polygon round = makeBox(1.0f, 1.0f);
    round.radius = kInf;
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, round); }, "polygon radius");
    round.radius = 1.0e30f;
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, round); }, "polygon radius");
    // Normals that do not belong to the edges, and a clockwise polygon.
    Polygon wrongNormals = makeBox(1.0f, 1.0f);
    std::swap(wrongNormals.normals[0], wrongNormals.normals[2]);
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, wrongNormals); }, "polygon");
    Polygon clockwise = makeBox(1.0f, 1.0f);
    std::swap(clockwise.vertices[1], clockwise.vertices[3]);
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, clockwise); }, "polygon");
    Polygon badCentroid = makeBox(1.0f, 1.0f);
    badCentroid.centroid = {kNan, 0.0f};
    expectRefused(
        s, [&] { w.createPolygonShape(s.box, {}, badCentroid); }, "polygon centroid");
}

TEST(ValidationWorld, HandlesInvalidStaleAndForged) {
    Scene s;
    World& w = s.world;
    BodyId gone = w.createBody({.type = BodyType::dynamic_body});
    ShapeId goneShape = w.createCircleShape(gone, {}, {{0.0f, 0.0f}, 0.5f});
    w.destroyBody(gone);
    // Destroying twice, and any use of the stale handles.
    expectRefused(
        s, [&] { w.destroyBody(gone); }, "stale");
    expectRefused(
        s, [&] { w.position(gone); }, "stale");
    expectRefused(
        s, [&] { w.destroyShape(goneShape); }, "stale");
    // The slot is reused by the next body; the old handle still names nothing.
    BodyId reused = w.createBody({.type = BodyType::dynamic_body, .position = {30.0f, 5.0f}});
    EXPECT_EQ(reused.index1, gone.index1);
    EXPECT_FALSE(w.isValid(gone));
    expectRefused(
        s,
        [&] {
            w.applyForceToCenter(gone, {1.0f, 0.0f});
        },
        "stale");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(gone, {}, {{0.0f, 0.0f}, 0.5f});
        },
        "stale");
    // Null handles.
    expectRefused(
        s, [&] { w.destroyBody(BodyId{}); }, "null body");
    expectRefused(
        s, [&] { w.destroyShape(ShapeId{}); }, "null shape");
    expectRefused(
        s, [&] { w.destroyJoint(JointId{}); }, "null joint");
    // Forged handles: indices far beyond any slot, including ones that do
    // not fit a signed int, with this world's id and without one.
    for (std::uint32_t world : {s.box.world, 0u})
        for (std::uint32_t index1 : {2u, 1000u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFFFFu}) {
            BodyId fb{index1, 0, world};
            ShapeId fs{index1, 0, world};
            JointId fj{index1, 0, world};
            if (index1 == 2u) fb.generation = 12345;  // a live slot with the wrong generation
            EXPECT_FALSE(w.isValid(fb));
            EXPECT_FALSE(w.isValid(fs));
            EXPECT_FALSE(w.isValid(fj));
            expectRefused(
                s, [&] { w.destroyBody(fb); }, "invalid body");
            expectRefused(
                s,
                [&] {
                    w.setLinearVelocity(fb, {1.0f, 0.0f});
                },
                "invalid body");
            expectRefused(
                s, [&] { w.destroyShape(fs); }, "invalid shape");
            expectRefused(
                s, [&] { w.friction(fs); }, "invalid shape");
            expectRefused(
                s, [&] { w.destroyJoint(fj); }, "invalid joint");
            expectRefused(
                s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = fb}); }, "invalid body");
        }
    // A shape handle asked for another type.
    expectRefused(
        s, [&] { w.shapeCircle(s.boxShape); }, "another type");
    // A joint's handle after its body died.
    w.destroyBody(s.pill);
    EXPECT_FALSE(w.isValid(s.joint));
    expectRefused(
        s, [&] { w.destroyJoint(s.joint); }, "stale");
}

// A handle names an object of the world that made it: another world refuses
// it even where that world has a live object in the same slot with the same
// generation, and says why.
TEST(ValidationWorld, HandlesOfAnotherWorldAreRefused) {
    Scene s;
    Scene other;  // built by the same calls: the same slots and generations
    World& w = s.world;
    ASSERT_EQ(other.box.index1, s.box.index1);
    ASSERT_EQ(other.box.generation, s.box.generation);
    ASSERT_NE(other.box.world, s.box.world);
    EXPECT_FALSE(w.isValid(other.box));
    EXPECT_FALSE(w.isValid(other.boxShape));
    EXPECT_FALSE(w.isValid(other.joint));
    expectRefused(
        s, [&] { w.position(other.box); }, "another world");
    expectRefused(
        s, [&] { w.destroyBody(other.box); }, "another world");
    expectRefused(
        s,
        [&] {
            w.setLinearVelocity(other.box, {1.0f, 0.0f});
        },
        "another world");
    expectRefused(
        s,
        [&] {
            w.createCircleShape(other.box, {}, {{0.0f, 0.0f}, 0.5f});
        },
        "another world");
    expectRefused(
        s, [&] { w.destroyShape(other.boxShape); }, "another world");
    expectRefused(
        s, [&] { w.setFriction(other.boxShape, 0.1f); }, "another world");
    expectRefused(
        s, [&] { w.destroyJoint(other.joint); }, "another world");
    expectRefused(
        s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = other.ball}); }, "another world");
    // The other world's own handles still work there.
    EXPECT_TRUE(other.world.isValid(other.box));
    EXPECT_NO_THROW(other.world.position(other.box));
}

// A World that was moved from has no state: every call on it is refused
// with i2d::Error instead of dereferencing nothing.
TEST(ValidationWorld, MovedFromWorldRefusesCalls) {
    World a;
    BodyId body = a.createBody({.type = BodyType::dynamic_body});
    World b = std::move(a);
    EXPECT_TRUE(b.isValid(body));
    EXPECT_THROW(a.step(1.0f / 60.0f), Error);  // NOLINT(bugprone-use-after-move): the case under test
    EXPECT_THROW(a.createBody({}), Error);
    EXPECT_THROW(a.isValid(body), Error);
    EXPECT_THROW(a.bodyCount(), Error);
    b.step(1.0f / 60.0f);
    EXPECT_EQ(b.bodyCount(), 1);
}

// A bounded impulse on a body of tiny mass (a denormal density is accepted)
// would give it a velocity beyond any bound: refused, nothing changes.
TEST(ValidationWorld, ImpulseThatWouldOverflowIsRefused) {
    Scene s;
    World& w = s.world;
    BodyId dust = w.createBody({.type = BodyType::dynamic_body, .position = {20.0f, 5.0f}});
    w.createPolygonShape(dust, {.density = 1.0e-36f}, makeBox(0.5f, 0.5f));
    ASSERT_GT(w.mass(dust), 0.0f);
    ASSERT_LT(w.mass(dust), 1.0e-30f);
    expectRefused(
        s,
        [&] {
            w.applyLinearImpulseToCenter(dust, {10.0f, 0.0f});
        },
        "velocity after the impulse");
    expectRefused(
        s, [&] { w.applyAngularImpulse(dust, 10.0f); }, "angular velocity after the impulse");
    // An impulse the body can take still works.
    w.applyLinearImpulseToCenter(dust, {1.0e-36f, 0.0f});
    EXPECT_GT(w.linearVelocity(dust).x, 0.0f);
}

TEST(ValidationWorld, JointsAndSettings) {
    Scene s;
    World& w = s.world;
    expectRefused(
        s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = s.box}); }, "two different bodies");
    expectRefused(
        s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = s.ball, .length = 0.0f}); }, "joint length");
    expectRefused(
        s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = s.ball, .length = -1.0f}); }, "joint length");
    expectRefused(
        s,
        [&] {
            w.createDistanceJoint({.bodyA = s.box, .bodyB = s.ball, .localAnchorA = {kNan, 0.0f}});
        },
        "localAnchorA");
    expectRefused(
        s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = s.ball, .hertz = kInf}); }, "hertz");
    expectRefused(
        s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = s.ball, .hertz = 1.0e30f}); }, "hertz");
    expectRefused(
        s, [&] { w.createDistanceJoint({.bodyA = s.box, .bodyB = s.ball, .dampingRatio = 1.0e30f}); }, "damping ratio");
    expectRefused(
        s,
        [&] {
            w.createDistanceJoint(
                {.bodyA = s.box, .bodyB = s.ball, .enableLimit = true, .minLength = 2.0f, .maxLength = 1.0f});
        },
        "minLength");
    expectRefused(
        s, [&] { w.setDistanceJointLength(s.joint, 0.0f); }, "joint length");

    auto badSettings = [&](auto edit, const char* fragment) {
        WorldSettings bad = w.settings();
        edit(bad);
        expectRefused(
            s, [&] { w.setSettings(bad); }, fragment);
        EXPECT_THROW(World{bad}, Error);
    };
    badSettings([](WorldSettings& x) { x.gravity = {kNan, 0.0f}; }, "gravity");
    badSettings([](WorldSettings& x) { x.substeps = 0; }, "substeps");
    badSettings([](WorldSettings& x) { x.velocityIterations = -3; }, "velocityIterations");
    badSettings([](WorldSettings& x) { x.pushFactor = 1.5f; }, "pushFactor");
    badSettings([](WorldSettings& x) { x.contactHertz = kInf; }, "contactHertz");
    badSettings([](WorldSettings& x) { x.contactHertz = 1.0e30f; }, "contactHertz");
    badSettings([](WorldSettings& x) { x.jointDampingRatio = 1.0e30f; }, "jointDampingRatio");
    badSettings([](WorldSettings& x) { x.maxLinearSpeed = 0.0f; }, "maxLinearSpeed");
    badSettings([](WorldSettings& x) { x.maxLinearSpeed = 1.0e30f; }, "maxLinearSpeed");
    badSettings([](WorldSettings& x) { x.timeToSleep = kNan; }, "timeToSleep");
    badSettings([](WorldSettings& x) { x.positionCorrection = static_cast<PositionCorrection>(7); },
                "positionCorrection");
    badSettings([](WorldSettings& x) { x.impactModel = static_cast<ImpactModel>(9); }, "impactModel");
    expectRefused(
        s, [&] { w.createBody({.type = static_cast<BodyType>(5)}); }, "body type");
    expectRefused(
        s, [&] { w.setBodyType(s.box, static_cast<BodyType>(5)); }, "body type");
}

// The world reports events as buffers read after step(), so no user code runs
// while it steps. The one callback interface is DebugDraw: a drawer that
// tries to change the world from inside draw() is refused.
struct MeddlingDrawer : DebugDraw {
    World* world = nullptr;
    int refusals = 0;
    void meddle() {
        try {
            world->createBody({.type = BodyType::dynamic_body});
        } catch (const Error&) {
            ++refusals;
        }
        try {
            world->destroyBody(world->bodies().front());
        } catch (const Error&) {
            ++refusals;
        }
    }
    void drawSolidPolygon(const Transform&, const Vec2*, int, float, Color) override { meddle(); }
    void drawSolidCircle(Vec2, float, Vec2, Color) override { meddle(); }
    void drawSolidCapsule(Vec2, Vec2, float, Color) override { meddle(); }
    void drawSegment(Vec2, Vec2, Color) override { meddle(); }
    void drawPoint(Vec2, float, Color) override {}
};

TEST(ValidationWorld, ChangesFromInsideDrawAreRefused) {
    Scene s;
    Snapshot before = Snapshot::of(s.world);
    MeddlingDrawer drawer;
    drawer.world = &s.world;
    s.world.draw(drawer);
    EXPECT_GT(drawer.refusals, 0);
    EXPECT_TRUE(Snapshot::of(s.world) == before);
    // After draw() returns the world can be changed again.
    EXPECT_NO_THROW(s.world.createBody({}));
}

TEST(ValidationWorld, DestroyEverythingInAnyOrderKeepsTheWorldConsistent) {
    Scene s;
    World& w = s.world;
    w.destroyJoint(s.joint);
    w.destroyShape(s.boxShape);
    w.destroyBody(s.sleeper);
    w.destroyBody(s.ground);
    for (int i = 0; i < 30; ++i) w.step(1.0f / 60.0f);
    for (BodyId b : w.bodies()) w.destroyBody(b);
    EXPECT_EQ(w.bodyCount(), 0);
    EXPECT_EQ(w.shapeCount(), 0);
    EXPECT_EQ(w.jointCount(), 0);
    EXPECT_EQ(w.contactCount(), 0);
    EXPECT_NO_THROW(w.step(1.0f / 60.0f));
}

}  // namespace
}  // namespace i2d
