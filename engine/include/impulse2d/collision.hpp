// Impulse2D — narrowphase: contact manifolds between pairs of shapes.
//
// Conventions (every function below):
// - Shapes are given in their body frames with the bodies' transforms.
// - The manifold normal is a world-space unit vector pointing from shape A to shape B.
// - Each point lies midway between the two surfaces, in world space.
// - separation < 0 means overlap (penetration depth = −separation); points
//   are reported up to `speculativeDistance` of positive separation so the
//   solver can stop an approach before it becomes an overlap.
// - Point ids name the features (vertex/edge indices) that produced the
//   point; they stay the same while the same features touch, which is what
//   lets the solver warm-start from the previous step.
#pragma once

#include <cstdint>

#include "impulse2d/geometry.hpp"

namespace i2d {

struct ManifoldPoint {
    Vec2 point{};             ///< world position of the contact point
    float separation = 0.0f;  ///< signed distance between the surfaces along the normal
    std::uint16_t id = 0;     ///< feature id, stable while the contact persists
};

struct Manifold {
    Vec2 normal{};  ///< unit normal from A to B (world)
    ManifoldPoint points[2]{};
    int pointCount = 0;  ///< 0 (no contact), 1 or 2
};

/// Builds a feature id from the reference/incident features.
constexpr std::uint16_t makeFeatureId(int a, int b) {
    return static_cast<std::uint16_t>(((a & 0xFF) << 8) | (b & 0xFF));
}

// One function per pair of shape types (the first shape is A). Each returns
// pointCount 0 when the shapes are further apart than speculativeDistance (m).
// None of them validates its input or throws.
Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                        float speculativeDistance);
Manifold collideCapsuleAndCircle(const Capsule& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                                 float speculativeDistance);
Manifold collideCapsules(const Capsule& a, const Transform& xfA, const Capsule& b, const Transform& xfB,
                         float speculativeDistance);
Manifold collidePolygonAndCircle(const Polygon& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                                 float speculativeDistance);
Manifold collidePolygonAndCapsule(const Polygon& a, const Transform& xfA, const Capsule& b, const Transform& xfB,
                                  float speculativeDistance);
Manifold collidePolygons(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                         float speculativeDistance);
Manifold collideSegmentAndCircle(const Segment& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                                 float speculativeDistance);
Manifold collideSegmentAndCapsule(const Segment& a, const Transform& xfA, const Capsule& b, const Transform& xfB,
                                  float speculativeDistance);
Manifold collideSegmentAndPolygon(const Segment& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                                  float speculativeDistance);

/// Closest points between the convex hulls of two point sets (GJK), each
/// placed by its transform; the shapes' radii are not included: subtract
/// them from `distance`. Used by continuous collision. Throws i2d::Error
/// when a point set is null or empty.
struct DistanceResult {
    Vec2 pointA{};          ///< closest point on A's core (before radius), world
    Vec2 pointB{};          ///< closest point on B's core, world
    float distance = 0.0f;  ///< distance between the cores (0 when they overlap)
};
DistanceResult shapeDistance(const Vec2* pointsA, int countA, const Transform& xfA, const Vec2* pointsB, int countB,
                             const Transform& xfB);

}  // namespace i2d
