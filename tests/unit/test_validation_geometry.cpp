// Input validation of the world-free functions (docs/robustness.md,
// "Validation"): hull and polygon construction report degenerate input as an
// empty result, box and mass helpers and the impact law throw i2d::Error, ray
// casts with a non-finite or empty ray report no hit.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include <impulse2d/impulse2d.hpp>

namespace i2d {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ValidationGeometry, HullOfDegeneratePointSetsIsEmpty) {
    // Fewer than 3 points, too many points, non-finite points.
    EXPECT_EQ(computeHull(std::vector<Vec2>{}).count, 0);
    EXPECT_EQ(computeHull(std::vector<Vec2>{{0, 0}, {1, 0}}).count, 0);
    std::vector<Vec2> nine;
    for (int i = 0; i < 9; ++i) nine.push_back(rotate(makeRot(0.7f * static_cast<float>(i)), {1.0f, 0.0f}));
    EXPECT_EQ(computeHull(nine).count, 0);
    EXPECT_EQ(computeHull(std::vector<Vec2>{{0, 0}, {1, 0}, {kNan, 1}}).count, 0);
    EXPECT_EQ(computeHull(std::vector<Vec2>{{0, 0}, {1, 0}, {0, kInf}}).count, 0);
    // Fewer than 3 distinct points (within the weld distance kLinearSlop).
    EXPECT_EQ(computeHull(std::vector<Vec2>{{1, 1}, {1, 1}, {1, 1}}).count, 0);
    EXPECT_EQ(computeHull(std::vector<Vec2>{{0, 0}, {0.001f, 0}, {0, 0.001f}, {1, 1}}).count, 0);
    // Collinear, exactly and within kLinearSlop.
    EXPECT_EQ(computeHull(std::vector<Vec2>{{0, 0}, {1, 1}, {2, 2}, {3, 3}}).count, 0);
    EXPECT_EQ(computeHull(std::vector<Vec2>{{0, 0}, {5, 0.002f}, {10, 0}}).count, 0);
    // Far from the origin and huge extents still work when they make sense.
    EXPECT_EQ(computeHull(std::vector<Vec2>{{1.0e4f, 1.0e4f}, {1.0e4f + 1, 1.0e4f}, {1.0e4f, 1.0e4f + 1}}).count, 3);
    EXPECT_EQ(computeHull(std::vector<Vec2>{{-1.0e6f, -1.0e6f}, {1.0e6f, -1.0e6f}, {0, 1.0e6f}}).count, 3);
}

TEST(ValidationGeometry, MakePolygonRefusesDegenerateHullsAndRadii) {
    Hull empty;
    EXPECT_FALSE(makePolygon(empty));
    Hull tri = computeHull(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}});
    ASSERT_EQ(tri.count, 3);
    EXPECT_TRUE(makePolygon(tri));
    EXPECT_FALSE(makePolygon(tri, -1.0f));
    EXPECT_FALSE(makePolygon(tri, kNan));
    EXPECT_FALSE(makePolygon(tri, kInf));
    // A hand-edited hull: repeated point, clockwise order, too many points.
    Hull repeated = tri;
    repeated.points[2] = repeated.points[1];
    EXPECT_FALSE(makePolygon(repeated));
    Hull clockwise = tri;
    std::swap(clockwise.points[1], clockwise.points[2]);
    EXPECT_FALSE(makePolygon(clockwise));
    Hull tooMany = tri;
    tooMany.count = kMaxPolygonVertices + 1;
    EXPECT_FALSE(makePolygon(tooMany));
    Hull nonFinite = tri;
    nonFinite.points[0].x = kNan;
    EXPECT_FALSE(makePolygon(nonFinite));
}

TEST(ValidationGeometry, BoxAndMassHelpersThrow) {
    for (float bad : {0.0f, -1.0f, kNan, kInf}) {
        EXPECT_THROW(makeBox(bad, 1.0f), Error);
        EXPECT_THROW(makeBox(1.0f, bad), Error);
        EXPECT_THROW(makeOffsetBox(bad, 1.0f, {0, 0}, 0.0f), Error);
        EXPECT_THROW(computeMass(Circle{{0, 0}, 1.0f}, bad == 0.0f ? -2.0f : bad), Error);
    }
    EXPECT_THROW(makeOffsetBox(1.0f, 1.0f, {kNan, 0}, 0.0f), Error);
    EXPECT_THROW(makeOffsetBox(1.0f, 1.0f, {0, 0}, kInf), Error);
    EXPECT_THROW(makeRoundedBox(1.0f, 1.0f, -0.1f), Error);
    EXPECT_THROW(computeMass(Polygon{}, 1.0f), Error);
    EXPECT_THROW(computeMass(makeBox(1.0f, 1.0f), kNan), Error);
}

TEST(ValidationGeometry, RayCastsWithBadRaysMiss) {
    const Circle circle{{0, 0}, 1.0f};
    const Polygon box = makeBox(1.0f, 1.0f);
    const Capsule capsule{{-1, 0}, {1, 0}, 0.5f};
    const Segment segment{{-1, 0}, {1, 0}};
    for (RayCastInput in : {RayCastInput{{kNan, 5}, {0, -10}, 1.0f}, RayCastInput{{0, 5}, {0, -kInf}, 1.0f},
                            RayCastInput{{0, 5}, {0, 0}, 1.0f}, RayCastInput{{0, 5}, {0, -10}, kNan},
                            RayCastInput{{0, 5}, {0, -10}, -1.0f}}) {
        EXPECT_FALSE(rayCast(in, circle));
        EXPECT_FALSE(rayCast(in, box));
        EXPECT_FALSE(rayCast(in, capsule));
        EXPECT_FALSE(rayCast(in, segment));
    }
}

TEST(ValidationGeometry, ImpactLawRefusesBadInput) {
    ImpactInput ok;
    ok.restitution = 0.5;
    ok.friction = 0.3;
    ok.a = {.invMass = 1.0, .invInertia = 6.0, .r = {0.4, -0.5}, .v = {1.0, -2.0}, .w = 3.0};
    EXPECT_NO_THROW(resolveImpact(ok));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto refused = [&](auto edit) {
        ImpactInput in = ok;
        edit(in);
        EXPECT_THROW(resolveImpact(in), Error);
    };
    refused([&](ImpactInput& in) { in.restitution = nan; });
    refused([&](ImpactInput& in) { in.restitution = 1.5; });
    refused([&](ImpactInput& in) { in.friction = -0.1; });
    refused([&](ImpactInput& in) { in.normal = {0.0, 2.0}; });
    refused([&](ImpactInput& in) { in.normal = {0.0, 0.0}; });
    refused([&](ImpactInput& in) { in.a.v.x = std::numeric_limits<double>::infinity(); });
    refused([&](ImpactInput& in) { in.a.invMass = -1.0; });
    refused([&](ImpactInput& in) { in.b.invInertia = -1.0; });
    refused([&](ImpactInput& in) { in.a.invMass = 0.0, in.a.invInertia = 0.0; });
}

}  // namespace
}  // namespace i2d
