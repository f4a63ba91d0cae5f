// Narrowphase: contact manifolds for every shape pair, and GJK distance.
// Expected values are derived by hand from the configuration (distances
// between surfaces, face normals), never read back from the code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "impulse2d/collision.hpp"
#include "impulse2d/impulse2d.hpp"

using namespace i2d;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// Speculative distance used throughout (the world default, types.hpp).
constexpr float kSpec = 0.02f;
// Coordinates are O(1) m; each result goes through a transform, a few dot
// products and a midpoint, i.e. tens of ulps of 1.2e-7 at most. 1e-5 m is
// well above that and far below the millimetre scale of the cases tested.
constexpr float kTol = 1.0e-5f;

Transform at(float x, float y, float angle = 0.0f) { return Transform{{x, y}, makeRot(angle)}; }

void expectNormal(const Manifold& m, Vec2 n) {
    EXPECT_NEAR(m.normal.x, n.x, kTol);
    EXPECT_NEAR(m.normal.y, n.y, kTol);
}

float minSeparation(const Manifold& m) {
    float s = FLT_MAX;
    for (int i = 0; i < m.pointCount; ++i) s = std::min(s, m.points[i].separation);
    return s;
}

// Points sorted by x, for comparing two-point manifolds regardless of order.
std::vector<ManifoldPoint> sortedByX(const Manifold& m) {
    std::vector<ManifoldPoint> p(m.points, m.points + m.pointCount);
    std::sort(p.begin(), p.end(), [](const ManifoldPoint& a, const ManifoldPoint& b) { return a.point.x < b.point.x; });
    return p;
}

// Brute-force distance between two convex polygons (world), zero if they overlap.
float bruteDistance(const Polygon& a, const Transform& xa, const Polygon& b, const Transform& xb) {
    std::vector<Vec2> va, vb;
    for (int i = 0; i < a.count; ++i) va.push_back(transformPoint(xa, a.vertices[i]));
    for (int i = 0; i < b.count; ++i) vb.push_back(transformPoint(xb, b.vertices[i]));
    auto inside = [](const std::vector<Vec2>& poly, Vec2 p) {
        for (std::size_t i = 0; i < poly.size(); ++i)
            if (cross(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]) < 0.0f) return false;
        return true;
    };
    auto segSegIntersect = [](Vec2 p, Vec2 q, Vec2 r, Vec2 s) {
        float d1 = cross(q - p, r - p), d2 = cross(q - p, s - p);
        float d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
        return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
    };
    for (Vec2 p : va)
        if (inside(vb, p)) return 0.0f;
    for (Vec2 p : vb)
        if (inside(va, p)) return 0.0f;
    float best = FLT_MAX;
    auto pointSeg = [](Vec2 p, Vec2 a0, Vec2 a1) {
        Vec2 e = a1 - a0;
        float t = std::clamp(dot(p - a0, e) / dot(e, e), 0.0f, 1.0f);
        return distance(p, a0 + t * e);
    };
    for (std::size_t i = 0; i < va.size(); ++i)
        for (std::size_t j = 0; j < vb.size(); ++j) {
            Vec2 a0 = va[i], a1 = va[(i + 1) % va.size()];
            Vec2 b0 = vb[j], b1 = vb[(j + 1) % vb.size()];
            if (segSegIntersect(a0, a1, b0, b1)) return 0.0f;
            best = std::min({best, pointSeg(b0, a0, a1), pointSeg(a0, b0, b1)});
        }
    return best;
}

Polygon randomPolygon(std::mt19937& rng, float radius) {
    std::uniform_real_distribution<float> u(-0.6f, 0.6f);
    std::uniform_int_distribution<int> n(3, kMaxPolygonVertices);
    for (;;) {
        std::vector<Vec2> pts(n(rng));
        for (Vec2& p : pts) p = {u(rng), u(rng)};
        Hull h = computeHull(pts);
        if (h.count == 0) continue;
        if (auto poly = makePolygon(h, radius)) return *poly;
    }
}

}  // namespace

// ------------------------------------------------------------- circles ----

TEST(CircleCircle, SeparationTouchingOverlapAndSpeculative) {
    Circle a{{0, 0}, 0.5f};
    Circle b{{0, 0}, 0.25f};
    // Gap 0.25 m > speculative distance: nothing.
    EXPECT_EQ(collideCircles(a, at(0, 0), b, at(1.0f, 0), kSpec).pointCount, 0);
    // Gap 0.01 m: a speculative point with positive separation, midway in the gap.
    Manifold m = collideCircles(a, at(0, 0), b, at(0.76f, 0), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {1, 0});
    EXPECT_NEAR(m.points[0].separation, 0.01f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.505f, kTol);
    // Touching.
    m = collideCircles(a, at(0, 0), b, at(0.75f, 0), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, 0.0f, kTol);
    // Deep: centres 0.1 apart → separation 0.1 − 0.75; surfaces at x = 0.5 and −0.15.
    m = collideCircles(a, at(0, 0), b, at(0.1f, 0), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, -0.65f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.175f, kTol);
    expectNormal(m, {1, 0});
}

TEST(CircleCircle, NormalFromAToBAndCoincidentCentres) {
    Circle a{{0.2f, 0}, 0.5f};
    Circle b{{0, 0}, 0.5f};
    // A rotated by 90°: its local centre offset (0.2, 0) is at world (10, 10.2).
    Manifold m = collideCircles(a, at(10, 10, kPi / 2), b, at(10, 9.3f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, -1});
    EXPECT_NEAR(m.points[0].separation, 0.9f - 1.0f, 1e-4f);  // 1e-4: world coordinates ~10
    Manifold r = collideCircles(b, at(10, 9.3f), a, at(10, 10, kPi / 2), kSpec);
    expectNormal(r, {0, 1});

    m = collideCircles(b, at(3, 4), b, at(3, 4), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(length(m.normal), 1.0f, kTol);
    EXPECT_NEAR(m.points[0].separation, -1.0f, kTol);
    // Coincident centres: A's own up, turned with A (here by 90°: −x).
    m = collideCircles(b, at(3, 4, kPi / 2), b, at(3, 4), kSpec);
    expectNormal(m, {-1, 0});
}

TEST(CircleCircle, FarFromTheOriginAsPreciseAsNearIt) {
    // Two circles with offset centres on turned bodies about 1 cm apart, at the
    // origin and at (80000, −70000), where a float's spacing is 7.8 mm
    // (HARD_CASES's Far Recovery): world centres subtracted there would be
    // off by up to that; the bodies' origins subtracted first are exact
    // (Sterbenz), so the far pair's separation matches the near one's to the
    // rounding of the small offsets (kTol).
    const Circle a{{0.3f, 0.1f}, 0.5f};
    const Circle b{{-0.2f, 0.0f}, 0.25f};
    const float turnA = 0.7f, turnB = -1.1f;
    const Vec2 aCentre = rotate(makeRot(turnA), a.center);
    const Vec2 bCentre = rotate(makeRot(turnB), b.center);
    // B's origin 0.765625 m right of and 0.0625 m above A's: multiples of
    // the far spacing, so both bodies sit exactly where the test puts them.
    const Vec2 bOrigin{0.765625f, 0.0625f};
    const Vec2 d = bOrigin + bCentre - aCentre;
    const float separation = length(d) - 0.75f;  // 0.0118 m
    for (const Vec2 origin : {Vec2{0.0f, 0.0f}, Vec2{80000.0f, -70000.0f}}) {
        const Manifold m = collideCircles(a, at(origin.x, origin.y, turnA), b,
                                          at(origin.x + bOrigin.x, origin.y + bOrigin.y, turnB), kSpec);
        ASSERT_EQ(m.pointCount, 1);
        EXPECT_NEAR(m.points[0].separation, separation, kTol) << origin.x;
        expectNormal(m, normalize(d));
    }
}

// In a world the contact update writes two circles' manifold in place
// (engine/src/circle_manifold.hpp) when the bodies move, instead of taking
// collideCircles' result through the shape-pair table. Two circles of radius
// 0.5 m, centres 1.01 m apart along +x, moving together at 2 m/s without
// gravity: the step's manifold is that of their poses at the step's start
// (the narrowphase runs before they move), by hand one point 1 cm apart,
// normal +x, midway between the surfaces at x = 0.505; and it is exactly
// collideCircles' (the same arithmetic, so equal to the bit).
TEST(CircleCircle, AMovingPairInAWorldHoldsTheManifoldOfItsStartingPoses) {
    WorldSettings settings;
    settings.gravity = {0.0f, 0.0f};
    settings.enableSleep = false;
    World world(settings);
    const Circle disc{{0.0f, 0.0f}, 0.5f};
    const Transform xfA = at(0.0f, 0.0f), xfB = at(1.01f, 0.0f);
    for (const Transform& xf : {xfA, xfB}) {
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = xf.p, .linearVelocity = {2.0f, 0.0f}});
        world.createCircleShape(b, ShapeDef{.density = 1.0f}, disc);
    }
    world.step(1.0f / 60.0f);
    const std::vector<ContactData> contacts = world.contacts();
    ASSERT_EQ(contacts.size(), 1u);
    const Manifold& m = contacts[0].manifold;
    ASSERT_EQ(m.pointCount, 1);
    // Which body is A is the world's choice (both are circles): the normal
    // points from A to B, so compare along the pair's own direction.
    const float side = m.normal.x > 0.0f ? 1.0f : -1.0f;
    expectNormal(m, {side, 0.0f});
    EXPECT_NEAR(m.points[0].separation, 0.01f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.505f, kTol);
    EXPECT_NEAR(m.points[0].point.y, 0.0f, kTol);
    const Manifold direct = side > 0.0f ? collideCircles(disc, xfA, disc, xfB, world.settings().speculativeDistance)
                                        : collideCircles(disc, xfB, disc, xfA, world.settings().speculativeDistance);
    EXPECT_EQ(m.normal.x, direct.normal.x);
    EXPECT_EQ(m.normal.y, direct.normal.y);
    EXPECT_EQ(m.points[0].separation, direct.points[0].separation);
    EXPECT_EQ(m.points[0].point.x, direct.points[0].point.x);
    EXPECT_EQ(m.points[0].point.y, direct.points[0].point.y);
    EXPECT_EQ(m.points[0].id, direct.points[0].id);
}

// ------------------------------------------------------ capsule–circle ----

TEST(CapsuleCircle, FaceEndAndDegenerate) {
    Capsule cap{{-1, 0}, {1, 0}, 0.25f};
    Circle c{{0, 0}, 0.5f};
    Manifold m = collideCapsuleAndCircle(cap, at(0, 0), c, at(0.3f, 0.76f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, 0.01f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.3f, kTol);
    EXPECT_NEAR(m.points[0].point.y, 0.255f, kTol);
    // Beyond the end cap.
    m = collideCapsuleAndCircle(cap, at(0, 0), c, at(1.74f, 0), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {1, 0});
    EXPECT_NEAR(m.points[0].separation, -0.01f, kTol);
    EXPECT_EQ(collideCapsuleAndCircle(cap, at(0, 0), c, at(1.8f, 0), kSpec).pointCount, 0);
    // Centre on the core segment: normal is the left perpendicular (0, 1).
    m = collideCapsuleAndCircle(cap, at(0, 0), c, at(0.5f, 0), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, -0.75f, kTol);
}

// ----------------------------------------------------- capsule–capsule ----

TEST(CapsuleCapsule, ParallelGivesTwoPoints) {
    Capsule a{{-1, 0}, {1, 0}, 0.25f};
    Capsule b{{-0.5f, 0}, {1.5f, 0}, 0.25f};
    for (float gap : {0.0f, 0.01f, -0.02f}) {
        Manifold m = collideCapsules(a, at(0, 0), b, at(0, 0.5f + gap), kSpec);
        ASSERT_EQ(m.pointCount, 2) << gap;
        expectNormal(m, {0, 1});
        auto p = sortedByX(m);
        // Overlap of the cores along x is [−0.5, 1]; points midway between
        // the surfaces at y = 0.25 and 0.25 + gap.
        EXPECT_NEAR(p[0].point.x, -0.5f, kTol);
        EXPECT_NEAR(p[1].point.x, 1.0f, kTol);
        EXPECT_NEAR(p[0].point.y, 0.25f + 0.5f * gap, kTol);
        EXPECT_NEAR(p[0].separation, gap, kTol);
        EXPECT_NEAR(p[1].separation, gap, kTol);
        EXPECT_NE(p[0].id, p[1].id);
    }
    EXPECT_EQ(collideCapsules(a, at(0, 0), b, at(0, 0.55f), kSpec).pointCount, 0);
    // B below A: the normal flips.
    Manifold m = collideCapsules(a, at(0, 0), b, at(0, -0.49f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    expectNormal(m, {0, -1});
}

TEST(CapsuleCapsule, EndToEndTeeAndCrossing) {
    Capsule a{{-1, 0}, {1, 0}, 0.25f};
    // Collinear, end to end: 0.1 m apart (beyond speculative) then 0.01 m.
    Capsule b{{0, 0}, {2, 0}, 0.25f};
    EXPECT_EQ(collideCapsules(a, at(0, 0), b, at(1.6f, 0), kSpec).pointCount, 0);
    Manifold m = collideCapsules(a, at(0, 0), b, at(1.51f, 0), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {1, 0});
    EXPECT_NEAR(m.points[0].separation, 0.01f, kTol);
    // T: B upright, its lower end 0.5 above A's core → touching at x = 0.3.
    Capsule up{{0, 0}, {0, 2}, 0.25f};
    m = collideCapsules(a, at(0, 0), up, at(0.3f, 0.5f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].point.x, 0.3f, kTol);
    EXPECT_NEAR(m.points[0].point.y, 0.25f, kTol);
    EXPECT_NEAR(m.points[0].separation, 0.0f, kTol);
    // Crossing cores (an X): overlapping, normal perpendicular to A.
    m = collideCapsules(a, at(0, 0), b, at(-0.5f, -0.2f, 0.5f), kSpec);
    ASSERT_GE(m.pointCount, 1);
    EXPECT_LT(minSeparation(m), -0.25f);
    EXPECT_NEAR(std::fabs(m.normal.y), 1.0f, kTol);
}

TEST(CapsuleCapsule, TiltedEndRestsOnFace) {
    // B tilted by 30°, its lower end just touching A's top surface: one
    // point (the other end is far above), normal = A's face normal.
    Capsule a{{-2, 0}, {2, 0}, 0.1f};
    Capsule b{{0, 0}, {1, 0}, 0.1f};
    Manifold m = collideCapsules(a, at(0, 0), b, at(0.2f, 0.195f, kPi / 6), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, -0.005f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.2f, kTol);
}

TEST(CapsuleCapsule, FeatureIdsStableWhileSliding) {
    Capsule a{{-1, 0}, {1, 0}, 0.25f};
    Capsule b{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    Manifold m0 = collideCapsules(a, at(0, 0), b, at(0.0f, 0.499f), kSpec);
    ASSERT_EQ(m0.pointCount, 2);
    for (int k = 1; k <= 10; ++k) {
        Manifold m = collideCapsules(a, at(0, 0), b, at(0.01f * k, 0.499f, 0.001f * k), kSpec);
        ASSERT_EQ(m.pointCount, 2);
        for (int i = 0; i < 2; ++i) EXPECT_EQ(m.points[i].id, m0.points[i].id);
    }
}

// ------------------------------------------------------ polygon–circle ----

TEST(PolygonCircle, FaceVertexInsideAndRounded) {
    Polygon box = makeBox(0.5f, 0.5f);
    Manifold m = collidePolygonAndCircle(box, at(0, 0), Circle{{0, 0}, 0.5f}, at(0.2f, 1.01f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, 0.01f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.2f, kTol);
    EXPECT_NEAR(m.points[0].point.y, 0.505f, kTol);
    EXPECT_EQ(collidePolygonAndCircle(box, at(0, 0), Circle{{0, 0}, 0.5f}, at(0.2f, 1.03f), kSpec).pointCount, 0);
    // Vertex region: centre 0.5 m from the corner along (0.6, 0.8).
    m = collidePolygonAndCircle(box, at(0, 0), Circle{{0, 0}, 0.49f}, at(0.8f, 0.9f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0.6f, 0.8f});
    EXPECT_NEAR(m.points[0].separation, 0.01f, kTol);
    // Centre inside the box: the least-deep face (top: 0.3 inside) wins.
    m = collidePolygonAndCircle(box, at(0, 0), Circle{{0, 0}, 0.1f}, at(0.1f, 0.2f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, -0.4f, kTol);
    // Rounded box: the surface is 0.1 further out.
    m = collidePolygonAndCircle(makeRoundedBox(0.4f, 0.4f, 0.1f), at(0, 0), Circle{{0, 0}, 0.5f}, at(0, 1.0f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, 0.0f, kTol);
    EXPECT_NEAR(m.points[0].point.y, 0.5f, kTol);
}

// ----------------------------------------------------- polygon–polygon ----

TEST(PolygonPolygon, BoxRestingFlatOnBox) {
    Polygon ground = makeBox(2.0f, 0.5f);
    Polygon box = makeBox(0.5f, 0.5f);
    for (float gap : {-0.001f, 0.0f, 0.01f}) {
        Manifold m = collidePolygons(ground, at(0, 0), box, at(0.3f, 1.0f + gap), kSpec);
        ASSERT_EQ(m.pointCount, 2) << gap;
        expectNormal(m, {0, 1});
        auto p = sortedByX(m);
        EXPECT_NEAR(p[0].point.x, -0.2f, kTol);
        EXPECT_NEAR(p[1].point.x, 0.8f, kTol);
        for (auto& q : p) {
            EXPECT_NEAR(q.separation, gap, kTol);
            EXPECT_NEAR(q.point.y, 0.5f + 0.5f * gap, kTol);  // midway between the faces
        }
    }
    EXPECT_EQ(collidePolygons(ground, at(0, 0), box, at(0.3f, 1.03f), kSpec).pointCount, 0);
    // Far from the origin and with the pair swapped: normal still A → B.
    Manifold m = collidePolygons(box, at(1000.3f, 501.0f), ground, at(1000.0f, 500.0f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    // Float spacing at 1000 m is 6e-5 m, so positions carry ~1e-4 m error.
    EXPECT_NEAR(m.normal.y, -1.0f, kTol);
    EXPECT_NEAR(m.points[0].separation, 0.0f, 2e-4f);
}

TEST(PolygonPolygon, DeepIdenticalAndCorner) {
    Polygon box = makeBox(0.5f, 0.5f);
    // Exactly on top of each other: two points, full overlap depth 1 m.
    Manifold m = collidePolygons(box, at(2, 3), box, at(2, 3), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_NEAR(length(m.normal), 1.0f, kTol);
    EXPECT_NEAR(m.points[0].separation, -1.0f, kTol);
    EXPECT_NEAR(m.points[1].separation, -1.0f, kTol);
    // Box rotated 45°, corner 0.01 m into the top face of a wide box.
    Polygon ground = makeBox(2.0f, 0.5f);
    float h = 0.5f * std::sqrt(2.0f);
    m = collidePolygons(ground, at(0, 0), box, at(0.1f, 0.5f + h - 0.01f, kPi / 4), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, -0.01f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.1f, kTol);
    EXPECT_NEAR(m.points[0].point.y, 0.495f, kTol);
}

TEST(PolygonPolygon, SeparatedCornersUseVertexNormal) {
    Polygon box = makeBox(0.5f, 0.5f);
    // Corners (0.5,0.5) and (0.51,0.51): distance 0.01·√2 along the diagonal.
    Manifold m = collidePolygons(box, at(0, 0), box, at(1.01f, 1.01f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {std::sqrt(0.5f), std::sqrt(0.5f)});
    EXPECT_NEAR(m.points[0].separation, 0.01f * std::sqrt(2.0f), kTol);
    EXPECT_EQ(collidePolygons(box, at(0, 0), box, at(1.02f, 1.02f), kSpec).pointCount, 0);
}

TEST(PolygonPolygon, RoundedBoxes) {
    Polygon r = makeRoundedBox(0.4f, 0.4f, 0.1f);
    // Resting: cores 0.199 apart, surfaces overlap by 1 mm.
    Manifold m = collidePolygons(r, at(0, 0), r, at(0.2f, 0.999f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    expectNormal(m, {0, 1});
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.001f, kTol);
        EXPECT_NEAR(m.points[i].point.y, 0.4995f, kTol);
    }
    // Corner to corner, cores apart by 0.1·√2 < 2r: rounded diagonal normal.
    m = collidePolygons(r, at(0, 0), r, at(0.9f, 0.9f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {std::sqrt(0.5f), std::sqrt(0.5f)});
    EXPECT_NEAR(m.points[0].separation, 0.1f * std::sqrt(2.0f) - 0.2f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.45f, kTol);
}

TEST(PolygonPolygon, FeatureIdsStableUnderSliding) {
    Polygon ground = makeBox(5.0f, 0.5f);
    Polygon box = makeBox(0.5f, 0.5f);
    Manifold m0 = collidePolygons(ground, at(0, 0), box, at(0, 0.998f), kSpec);
    ASSERT_EQ(m0.pointCount, 2);
    auto p0 = sortedByX(m0);
    for (int k = 1; k <= 20; ++k) {
        // Slide 1 cm per step with a slight rocking rotation.
        Manifold m = collidePolygons(ground, at(0, 0), box, at(0.01f * k, 0.998f, 0.0005f * (k % 3 - 1)), kSpec);
        ASSERT_EQ(m.pointCount, 2);
        auto p = sortedByX(m);
        EXPECT_EQ(p[0].id, p0[0].id);
        EXPECT_EQ(p[1].id, p0[1].id);
    }
}

TEST(PolygonPolygon, RandomSeparatedPairsMatchDistance) {
    // For separated polygons, the deepest manifold point must report the
    // true surface distance (GJK-independent brute force). Tolerance: the
    // face/vertex classification tolerance 0.1·slop (a vertex just past a
    // face end may be reported along the face normal) plus round-off.
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> pos(-1.5f, 1.5f), ang(-kPi, kPi);
    int checked = 0, withPoints = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        Polygon a = randomPolygon(rng, 0.0f);
        Polygon b = randomPolygon(rng, 0.0f);
        Transform xa = at(pos(rng), pos(rng), ang(rng));
        Transform xb = at(pos(rng), pos(rng), ang(rng));
        float d = bruteDistance(a, xa, b, xb);
        Manifold m = collidePolygons(a, xa, b, xb, kSpec);
        if (d <= 0.0f) {
            EXPECT_GE(m.pointCount, 1);
            EXPECT_LE(minSeparation(m), 1e-5f);
            continue;
        }
        ++checked;
        if (d > kSpec + 1e-5f) {
            EXPECT_EQ(m.pointCount, 0) << trial;
            continue;
        }
        ASSERT_GE(m.pointCount, 1) << trial << " d=" << d;
        ++withPoints;
        EXPECT_NEAR(minSeparation(m), d, 0.1f * kLinearSlop + 1e-5f) << trial;
        EXPECT_NEAR(length(m.normal), 1.0f, kTol);
    }
    EXPECT_GT(checked, 1000);
    // Make the random close pairs actually exercise the speculative band.
    std::uniform_real_distribution<float> small(0.0f, kSpec);
    for (int trial = 0; trial < 2000; ++trial) {
        Polygon a = randomPolygon(rng, 0.0f);
        Polygon b = randomPolygon(rng, 0.0f);
        Transform xa = at(0, 0, ang(rng));
        Transform xb = at(2.0f, 0, ang(rng));
        // Move B towards A until it is inside the speculative band.
        float target = small(rng);
        float d = bruteDistance(a, xa, b, xb);
        // Each move reduces the gap by at most the move, so a few rounds converge.
        for (int k = 0; k < 4 && d > target + 1e-4f; ++k) {
            xb.p.x -= d - target;
            d = bruteDistance(a, xa, b, xb);
        }
        if (d <= 0.0f || d > kSpec) continue;
        Manifold m = collidePolygons(a, xa, b, xb, kSpec);
        ASSERT_GE(m.pointCount, 1) << trial;
        ++withPoints;
        EXPECT_NEAR(minSeparation(m), d, 0.1f * kLinearSlop + 1e-5f) << trial;
        EXPECT_GT(m.normal.x, 0.0f);  // B lies to the +x side of A
    }
    EXPECT_GT(withPoints, 1000);
}

// ---------------------------------------------------- polygon–capsule ----

TEST(PolygonCapsule, LyingAndStanding) {
    Polygon ground = makeBox(2.0f, 0.5f);
    Capsule cap{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    Manifold m = collidePolygonAndCapsule(ground, at(0, 0), cap, at(0.1f, 0.749f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    expectNormal(m, {0, 1});
    auto p = sortedByX(m);
    EXPECT_NEAR(p[0].point.x, -0.4f, kTol);
    EXPECT_NEAR(p[1].point.x, 0.6f, kTol);
    EXPECT_NEAR(p[0].separation, -0.001f, kTol);
    // Standing upright: one point under the lower cap.
    m = collidePolygonAndCapsule(ground, at(0, 0), cap, at(0.1f, 1.25f, kPi / 2), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, 0.0f, kTol);
    EXPECT_NEAR(m.points[0].point.x, 0.1f, kTol);
    EXPECT_EQ(collidePolygonAndCapsule(ground, at(0, 0), cap, at(0.1f, 0.8f), kSpec).pointCount, 0);
}

// ----------------------------------------------------------- segments ----

TEST(Segment, BoxRestingOnSegment) {
    Segment ground{{-5, 0}, {5, 0}};
    Polygon box = makeBox(0.5f, 0.5f);
    Manifold m = collideSegmentAndPolygon(ground, at(0, 0), box, at(1.0f, 0.498f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    expectNormal(m, {0, 1});
    auto p = sortedByX(m);
    EXPECT_NEAR(p[0].point.x, 0.5f, kTol);
    EXPECT_NEAR(p[1].point.x, 1.5f, kTol);
    for (auto& q : p) {
        EXPECT_NEAR(q.separation, -0.002f, kTol);
        EXPECT_NEAR(q.point.y, -0.001f, kTol);
    }
    // Hanging over the end of the segment: clipped at the segment's end.
    m = collideSegmentAndPolygon(ground, at(0, 0), box, at(5.0f, 0.5f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    p = sortedByX(m);
    EXPECT_NEAR(p[0].point.x, 4.5f, kTol);
    EXPECT_NEAR(p[1].point.x, 5.0f, kTol);
    // Below the segment: normal points down.
    m = collideSegmentAndPolygon(ground, at(0, 0), box, at(1.0f, -0.51f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    expectNormal(m, {0, -1});
    EXPECT_NEAR(m.points[0].separation, 0.01f, kTol);
    EXPECT_EQ(collideSegmentAndPolygon(ground, at(0, 0), box, at(1.0f, 0.53f), kSpec).pointCount, 0);
    // Sliding keeps the ids.
    Manifold m0 = collideSegmentAndPolygon(ground, at(0, 0), box, at(0.0f, 0.499f), kSpec);
    Manifold m1 = collideSegmentAndPolygon(ground, at(0, 0), box, at(0.05f, 0.499f), kSpec);
    ASSERT_EQ(m0.pointCount, 2);
    ASSERT_EQ(m1.pointCount, 2);
    EXPECT_EQ(sortedByX(m0)[0].id, sortedByX(m1)[0].id);
    EXPECT_EQ(sortedByX(m0)[1].id, sortedByX(m1)[1].id);
}

TEST(Segment, CircleAndCapsule) {
    Segment ground{{-5, 0}, {5, 0}};
    Manifold m = collideSegmentAndCircle(ground, at(0, 0), Circle{{0, 0}, 0.5f}, at(1.0f, 0.49f), kSpec);
    ASSERT_EQ(m.pointCount, 1);
    expectNormal(m, {0, 1});
    EXPECT_NEAR(m.points[0].separation, -0.01f, kTol);
    EXPECT_NEAR(m.points[0].point.y, -0.005f, kTol);
    EXPECT_EQ(collideSegmentAndCircle(ground, at(0, 0), Circle{{0, 0}, 0.5f}, at(1.0f, 0.53f), kSpec).pointCount, 0);

    Capsule cap{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    m = collideSegmentAndCapsule(ground, at(0, 0), cap, at(1.0f, 0.26f), kSpec);
    ASSERT_EQ(m.pointCount, 2);
    expectNormal(m, {0, 1});
    auto p = sortedByX(m);
    EXPECT_NEAR(p[0].point.x, 0.5f, kTol);
    EXPECT_NEAR(p[1].point.x, 1.5f, kTol);
    EXPECT_NEAR(p[0].separation, 0.01f, kTol);
    EXPECT_EQ(collideSegmentAndCapsule(ground, at(0, 0), cap, at(1.0f, 0.3f), kSpec).pointCount, 0);
}

// ---------------------------------------------------------------- GJK ----

TEST(Distance, RandomPolygonsMatchBruteForce) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> pos(-2.0f, 2.0f), ang(-kPi, kPi);
    int separated = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        Polygon a = randomPolygon(rng, 0.0f);
        Polygon b = randomPolygon(rng, 0.0f);
        Transform xa = at(pos(rng), pos(rng), ang(rng));
        Transform xb = at(pos(rng), pos(rng), ang(rng));
        DistanceResult r = shapeDistance(a.vertices, a.count, xa, b.vertices, b.count, xb);
        float d = bruteDistance(a, xa, b, xb);
        // 1e-4: GJK's barycentric solve loses a few digits when the simplex
        // is nearly degenerate; still 50x below the linear slop.
        EXPECT_NEAR(r.distance, d, 1e-4f) << trial;
        if (d > 0.0f) {
            ++separated;
            EXPECT_NEAR(distance(r.pointA, r.pointB), r.distance, 1e-4f);
        }
    }
    EXPECT_GT(separated, 500);
}

TEST(PolygonPolygon, RandomRoundedPairsMatchDistance) {
    // Rounded polygons: the deepest point's separation is the core distance
    // minus both radii, whenever the cores are apart. Same tolerance
    // reasoning as for sharp polygons.
    std::mt19937 rng(2024);
    std::uniform_real_distribution<float> pos(-1.2f, 1.2f), ang(-kPi, kPi), rad(0.02f, 0.2f);
    int withPoints = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        Polygon a = randomPolygon(rng, rad(rng));
        Polygon b = randomPolygon(rng, rad(rng));
        Transform xa = at(pos(rng), pos(rng), ang(rng));
        Transform xb = at(pos(rng), pos(rng), ang(rng));
        float core = bruteDistance(a, xa, b, xb);
        if (core <= 0.0f) continue;
        float d = core - a.radius - b.radius;
        Manifold m = collidePolygons(a, xa, b, xb, kSpec);
        if (d > kSpec + 1e-5f) {
            EXPECT_EQ(m.pointCount, 0) << trial;
            continue;
        }
        ASSERT_GE(m.pointCount, 1) << trial;
        ++withPoints;
        EXPECT_NEAR(minSeparation(m), d, 0.1f * kLinearSlop + 1e-5f) << trial;
    }
    EXPECT_GT(withPoints, 300);
}

TEST(CapsuleCapsule, RandomPairsMatchSegmentDistance) {
    // Brute-force core distance: minimum over a fine sampling of segment A
    // (2001 samples) of the exact point–segment distance to B; the sampling
    // error is at most half the sample spacing times the sine of the angle,
    // ≤ 1e-3 m for 2 m long segments, so that is the tolerance when the
    // sampled value is the reference. Separations beyond that must match
    // the point count rule (none beyond the speculative distance).
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> pos(-1.0f, 1.0f), ang(-kPi, kPi), rad(0.05f, 0.3f), len(0.0f, 1.0f);
    int withPoints = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        Capsule a{{-len(rng), 0}, {len(rng), 0}, rad(rng)};
        Capsule b{{-len(rng), 0}, {len(rng), 0}, rad(rng)};
        Transform xa = at(pos(rng), pos(rng), ang(rng));
        Transform xb = at(pos(rng), pos(rng), ang(rng));
        Vec2 a1 = transformPoint(xa, a.center1), a2 = transformPoint(xa, a.center2);
        Vec2 b1 = transformPoint(xb, b.center1), b2 = transformPoint(xb, b.center2);
        double best = 1e30;
        for (int k = 0; k <= 2000; ++k) {
            Vec2 p = lerp(a1, a2, k / 2000.0f);
            Vec2 e = b2 - b1;
            float t = std::clamp(dot(p - b1, e) / dot(e, e), 0.0f, 1.0f);
            best = std::min(best, double(distance(p, b1 + t * e)));
        }
        float d = float(best) - a.radius - b.radius;
        Manifold m = collideCapsules(a, xa, b, xb, kSpec);
        if (d > kSpec + 1e-3f) {
            EXPECT_EQ(m.pointCount, 0) << trial;
            continue;
        }
        if (d < kSpec - 1e-3f) {
            ASSERT_GE(m.pointCount, 1) << trial;
        }
        if (m.pointCount == 0) continue;
        EXPECT_NEAR(length(m.normal), 1.0f, kTol);
        if (best > 2e-3) {  // cores apart: the contact reports the true gap
            ++withPoints;
            // Face contacts within ~10° of parallel measure along the face
            // normal; the gap along it differs from the true gap by at most
            // the end-cap geometry, which the 1e-3 sampling bound dominates.
            EXPECT_NEAR(minSeparation(m), d, 1e-3f) << trial;
        } else {
            EXPECT_LT(minSeparation(m), 0.0f);
        }
    }
    EXPECT_GT(withPoints, 100);
}
