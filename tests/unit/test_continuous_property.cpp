// Continuous collision, property test: random shapes at random angles,
// spins and speeds, fired at a thin static wall or a static segment, some of
// them already touching it when the first step begins. None may end a step
// behind the wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <impulse2d/impulse2d.hpp>

namespace {

using namespace i2d;

constexpr float kWallFront = 0.0f;      ///< the wall's (or segment's) face the shots come from: the line x = 0
constexpr float kWallThickness = 0.1f;  ///< the wall of the issue (m)
constexpr float kHalfHeight = 400.0f;   ///< tall enough that no shot can go round it in the steps run

enum class ShapeKind { circle, capsule, box, polygon, rounded_polygon, count };
enum class TargetKind { wall, segment, count };

struct Case {
    ShapeKind shape{};
    TargetKind target{};
    float size = 0.0f;      ///< half-extent scale (m)
    float angle = 0.0f;     ///< rad
    float spin = 0.0f;      ///< rad/s
    float speed = 0.0f;     ///< m/s
    float heading = 0.0f;   ///< direction of flight, rad from +x
    bool touching = false;  ///< starts touching the front face
    float gap = 0.0f;       ///< start distance of the nearest point to the front face (m)
    int settings = 0;       ///< which position correction and impact model
    unsigned seed = 0;

    std::string describe() const {
        return "shape " + std::to_string(static_cast<int>(shape)) + " target " +
               std::to_string(static_cast<int>(target)) + " size " + std::to_string(size) + " angle " +
               std::to_string(angle) + " spin " + std::to_string(spin) + " speed " + std::to_string(speed) +
               " heading " + std::to_string(heading) + " gap " + std::to_string(gap) + " settings " +
               std::to_string(settings) + " seed " + std::to_string(seed);
    }
};

Case randomCase(std::mt19937& rng, unsigned seed) {
    auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
    Case c;
    c.seed = seed;
    c.shape = static_cast<ShapeKind>(
        std::uniform_int_distribution<int>(0, static_cast<int>(ShapeKind::count) - 1)(rng));
    c.target = static_cast<TargetKind>(
        std::uniform_int_distribution<int>(0, static_cast<int>(TargetKind::count) - 1)(rng));
    c.size = uniform(0.05f, 0.5f);
    c.angle = uniform(-3.14159f, 3.14159f);
    c.spin = uniform(-100.0f, 100.0f);
    c.speed = uniform(1.0f, 400.0f);
    c.heading = uniform(-1.0f, 1.0f);  // up to 57° off the wall's normal
    c.touching = uniform(0.0f, 1.0f) < 0.5f;
    // Touching: up to the contact's allowed penetration (0.005 m) into the
    // face, or up to the speculative distance (0.02 m) in front of it.
    c.gap = c.touching ? uniform(-0.005f, 0.02f) : uniform(0.05f, 20.0f);
    c.settings = std::uniform_int_distribution<int>(0, 3)(rng);
    return c;
}

Polygon shapeOutline(ShapeKind kind, float size, std::mt19937& rng) {
    auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
    switch (kind) {
        case ShapeKind::box: return makeBox(size, uniform(0.2f, 1.0f) * size);
        case ShapeKind::polygon:
        case ShapeKind::rounded_polygon: {
            // A random convex hull of 3 to 8 points on an ellipse.
            for (;;) {
                Vec2 points[kMaxPolygonVertices];
                const int n = std::uniform_int_distribution<int>(3, kMaxPolygonVertices)(rng);
                const float ry = uniform(0.3f, 1.0f) * size;
                for (int i = 0; i < n; ++i) {
                    const float a = uniform(0.0f, 6.2831853f);
                    points[i] = {size * std::cos(a), ry * std::sin(a)};
                }
                const Hull hull = computeHull(std::span<const Vec2>(points, static_cast<std::size_t>(n)));
                const float radius = kind == ShapeKind::rounded_polygon ? 0.2f * size : 0.0f;
                if (auto p = makePolygon(hull, radius)) return *p;
            }
        }
        default: break;
    }
    return makeBox(size, size);
}

struct Result {
    bool crossed = false;  ///< the centre of mass ended a step behind the front face
    bool passed = false;   ///< some point of the body ended a step beyond the far face
    int step = -1;
};

// Whether the body's centre or all of it got behind the face, after each step.
Result run(const Case& c, bool continuous = true) {
    std::mt19937 rng(c.seed * 7919u + 13u);
    WorldSettings s;
    s.gravity = {0.0f, 0.0f};
    s.enableSleep = false;
    s.enableContinuous = continuous;
    s.positionCorrection = (c.settings & 1) ? PositionCorrection::soft_step : PositionCorrection::baumgarte;
    s.impactModel = (c.settings & 2) ? ImpactModel::closed_form : ImpactModel::velocity_bias;
    World world(s);
    BodyId wall = world.createBody({});
    if (c.target == TargetKind::wall)
        world.createPolygonShape(
            wall, {},
            makeOffsetBox(0.5f * kWallThickness, kHalfHeight, {kWallFront + 0.5f * kWallThickness, 0.0f}, 0.0f));
    else
        world.createSegmentShape(wall, {}, {{kWallFront, -kHalfHeight}, {kWallFront, kHalfHeight}});

    // The body as a polygon core plus a radius (circle: one point; capsule: two).
    Polygon core{};
    float radius = 0.0f;
    BodyId body = world.createBody({.type = BodyType::dynamic_body, .angle = c.angle});
    switch (c.shape) {
        case ShapeKind::circle:
            world.createCircleShape(body, {}, {{0.0f, 0.0f}, c.size});
            core.count = 1;
            radius = c.size;
            break;
        case ShapeKind::capsule: {
            const Capsule cap{{-c.size, 0.0f}, {c.size, 0.0f}, 0.3f * c.size};
            world.createCapsuleShape(body, {}, cap);
            core.vertices[0] = cap.center1;
            core.vertices[1] = cap.center2;
            core.count = 2;
            radius = cap.radius;
            break;
        }
        default:
            core = shapeOutline(c.shape, c.size, rng);
            radius = core.radius;
            world.createPolygonShape(body, {}, core);
            break;
    }
    auto extentX = [&](Transform xf) {
        float m = -1.0e30f;
        for (int i = 0; i < core.count; ++i) m = std::max(m, transformPoint(xf, core.vertices[i]).x);
        return m + radius;
    };
    // Place the body so that its nearest point is `gap` in front of the face.
    const Transform xf0{{0.0f, 0.0f}, makeRot(c.angle)};
    const float shift = kWallFront - c.gap - extentX(xf0);
    world.setTransform(body, {shift, 0.0f}, c.angle);
    world.setLinearVelocity(body, {c.speed * std::cos(c.heading), c.speed * std::sin(c.heading)});
    world.setAngularVelocity(body, c.spin);

    Result r;
    for (int step = 0; step < 30 && !r.crossed && !r.passed; ++step) {
        world.step(1.0f / 60.0f);
        const Transform xf{world.position(body), world.rotation(body)};
        r.crossed = world.worldCenterOfMass(body).x > kWallFront;
        // Wholly beyond the far face: through the wall (a segment has no
        // thickness; the same line 0.1 m behind it is used, which the
        // centre test above already makes unreachable).
        const float far = kWallFront + kWallThickness;
        float nearest = 1.0e30f;
        for (int i = 0; i < core.count; ++i) nearest = std::min(nearest, transformPoint(xf, core.vertices[i]).x);
        r.passed = nearest - radius > far;
        r.step = step;
    }
    return r;
}

// 4000 random shots, half of them starting in contact with the face. The
// property is exact, with no tolerance: the centre of mass of a body that
// came from in front of the face never ends a step behind it (a body
// stopped with its centre in front of a 0.1 m wall is pushed back out by
// the contact, not through), and no body ends a step wholly beyond the far
// face. Without continuous collision the same shots fail (the test below),
// so this can fail.
TEST(ContinuousProperty, NoShotEndsBehindTheWall) {
    int failures = 0, touchingCases = 0;
    constexpr unsigned kCases = 4000;
    for (unsigned seed = 1; seed <= kCases; ++seed) {
        std::mt19937 rng(seed);
        const Case c = randomCase(rng, seed);
        touchingCases += c.touching;
        const Result r = run(c);
        if (r.crossed || r.passed) {
            ++failures;
            if (failures <= 10)
                ADD_FAILURE() << (r.crossed ? "centre crossed" : "passed") << " at step " << r.step << ": "
                              << c.describe();
        }
    }
    EXPECT_EQ(failures, 0);
    // The random draw covers both starts (half of each expected; the bound
    // only checks the draw is not degenerate).
    EXPECT_GT(touchingCases, static_cast<int>(kCases) / 3);
}

TEST(ContinuousProperty, WithoutItShotsEndBehindTheWall) {
    int failures = 0;
    for (unsigned seed = 1; seed <= 200; ++seed) {
        std::mt19937 rng(seed);
        const Result r = run(randomCase(rng, seed), false);
        failures += r.crossed || r.passed;
    }
    // Most shots move several times the wall's thickness per step. Without
    // the sweep, speculative contacts, whose margin follows how far the body
    // can close in the step (contact.cpp), stop the shots whose nearest
    // feature at the step's start is the one that hits; spinning shapes that
    // turn another feature into the wall within the step still cross it: 24
    // of these 200 (more than 50 with the fixed 0.02 m margin).
    EXPECT_GT(failures, 10);
}

// Two shots of a run over seeds 1-40000 that ended behind a segment: thin
// polygons (15 mm and 4 mm across) left straddling it, which the contact
// then pushed through at less than the speculative distance per step until
// a segment kept its push on the side of the body's centroid (seams.cpp).
TEST(ContinuousProperty, SliversStraddlingASegmentAreNotPushedThrough) {
    for (unsigned seed : {5552u, 34960u}) {
        std::mt19937 rng(seed);
        const Case c = randomCase(rng, seed);
        ASSERT_EQ(c.target, TargetKind::segment) << seed;
        const Result r = run(c);
        EXPECT_FALSE(r.crossed || r.passed) << c.describe();
    }
}

}  // namespace
