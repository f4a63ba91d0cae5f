// Impulse2D — shape geometry: primitives, convex hull, mass properties,
// bounding boxes, ray casts and point tests. Everything here is pure
// geometry, independent of worlds and bodies, and usable on its own.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "impulse2d/math.hpp"

namespace i2d {

/// Most vertices a convex polygon may have.
inline constexpr int kMaxPolygonVertices = 8;

/// Smallest distance between two hull vertices (metres). Points closer than
/// this are welded when a hull is built; a polygon needs three vertices that
/// are at least this far apart and not collinear within it.
inline constexpr float kLinearSlop = 0.005f;

/// A solid circle in its body's frame.
struct Circle {
    Vec2 center{};
    float radius = 0.5f;
};

/// A solid capsule: the points within `radius` of the segment center1–center2.
struct Capsule {
    Vec2 center1{};
    Vec2 center2{1.0f, 0.0f};
    float radius = 0.25f;
};

/// A line segment with no thickness (typically static ground).
struct Segment {
    Vec2 point1{};
    Vec2 point2{1.0f, 0.0f};
};

/// A segment of a chain with its neighbours' far points (ghost vertices);
/// a ghost equal to the segment's own point means that end has no neighbour.
struct ChainSegment {
    Segment segment{};
    Vec2 ghost1{};  ///< the point before point1
    Vec2 ghost2{};  ///< the point after point2
};

/// A solid convex polygon, counter-clockwise, with an optional rounding
/// radius (the Minkowski sum of the polygon and a disk). Build it with
/// makePolygon / makeBox so that normals and centroid are consistent.
struct Polygon {
    Vec2 vertices[kMaxPolygonVertices]{};
    Vec2 normals[kMaxPolygonVertices]{};  ///< outward unit normal of edge i → i+1
    Vec2 centroid{};
    float radius = 0.0f;
    int count = 0;
};

/// A convex hull of at most kMaxPolygonVertices points, counter-clockwise.
struct Hull {
    Vec2 points[kMaxPolygonVertices]{};
    int count = 0;  ///< 0 when the hull is degenerate
};

/// Convex hull of a point cloud (quickhull). Welds points closer than
/// kLinearSlop and drops collinear points. Returns count == 0 when fewer
/// than 3 points remain, when the points are collinear, when any point is
/// non-finite, or when more than kMaxPolygonVertices points are given.
Hull computeHull(std::span<const Vec2> points);

/// Polygon from a hull (count must be ≥ 3) with a rounding radius ≥ 0 (m):
/// computes the outward edge normals and the centroid. Returns std::nullopt
/// for a degenerate hull (too few or too many points, non-finite, repeated,
/// clockwise or non-convex points, no area) or a negative or non-finite
/// radius. Never throws.
std::optional<Polygon> makePolygon(const Hull& hull, float radius = 0.0f);

/// Axis-aligned box with half-extents hx, hy (m) centred on the body origin.
/// Throws i2d::Error unless hx and hy are finite and > 0.
Polygon makeBox(float hx, float hy);
/// Box with half-extents hx, hy (m) centred at `center` (m), rotated by
/// `angle` (radians). Throws i2d::Error unless hx, hy are finite and > 0 and
/// center and angle are finite.
Polygon makeOffsetBox(float hx, float hy, Vec2 center, float angle);
/// Box with rounded corners: the square part has half-extents hx, hy (m), the
/// corners the rounding radius (m), so the whole box measures 2(hx + radius)
/// by 2(hy + radius). Throws i2d::Error as makeBox, or when radius is
/// negative or non-finite.
Polygon makeRoundedBox(float hx, float hy, float radius);

/// Mass, centre of mass (body frame) and rotational inertia about the centre of mass.
struct MassData {
    float mass = 0.0f;
    Vec2 center{};
    float rotationalInertia = 0.0f;
};

/// Mass properties of a shape of uniform density (kg/m², in the shape's own
/// frame). Throws i2d::Error when density is negative or non-finite, and for
/// a polygon with fewer than 3 or more than 8 vertices or no area.
MassData computeMass(const Circle& shape, float density);
MassData computeMass(const Capsule& shape, float density);
MassData computeMass(const Polygon& shape, float density);

/// Tight world bounding box of a shape placed by the transform xf (m).
AABB computeAABB(const Circle& shape, const Transform& xf);
AABB computeAABB(const Capsule& shape, const Transform& xf);
AABB computeAABB(const Polygon& shape, const Transform& xf);
AABB computeAABB(const Segment& shape, const Transform& xf);

/// A ray (or swept point) in the shape's local frame: origin + t·translation, t ∈ [0, maxFraction].
struct RayCastInput {
    Vec2 origin{};
    Vec2 translation{};
    float maxFraction = 1.0f;
};

/// Where a ray first enters a shape: point and outward normal in the same frame
/// as the input, and the fraction t along the translation.
struct RayHit {
    Vec2 point{};
    Vec2 normal{};
    float fraction = 0.0f;
};

/// Ray casts in the shape's local frame. A ray starting inside a solid shape
/// does not hit it (it reports no entry point). A ray with a non-finite or
/// zero translation, a non-finite origin, or a negative or non-finite
/// maxFraction hits nothing. Never throws.
std::optional<RayHit> rayCast(const RayCastInput& input, const Circle& shape);
std::optional<RayHit> rayCast(const RayCastInput& input, const Capsule& shape);
std::optional<RayHit> rayCast(const RayCastInput& input, const Polygon& shape);
std::optional<RayHit> rayCast(const RayCastInput& input, const Segment& shape);

/// Point-in-shape tests in the shape's local frame (boundary counts as inside).
bool containsPoint(const Circle& shape, Vec2 p);
bool containsPoint(const Capsule& shape, Vec2 p);
bool containsPoint(const Polygon& shape, Vec2 p);

}  // namespace i2d
