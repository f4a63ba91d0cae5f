// Shape casts and overlap tests of a convex proxy against one shape: the
// geometry behind World::castShape, World::overlapShape, World::explode and
// the character mover (mover.cpp).
#pragma once

#include "impulse2d/types.hpp"
#include "shape.hpp"

namespace i2d::detail {

/// Stopping band of a cast (m): a cast ends once the gap between the surfaces
/// is within this of the gap it aims at.
inline constexpr float kCastTolerance = 0.1f * kLinearSlop;

/// Gap between a proxy (world) and a shape's core placed by xf: the distance
/// between the surfaces (negative: overlap, down to −(radii) when the cores
/// meet), with the closest points of the cores and the unit direction from
/// the shape to the proxy (zero when the cores meet).
struct ProxyGap {
    float gap = 0.0f;
    Vec2 pointOnShape{};  ///< closest point of the shape's core (world)
    Vec2 normal{};        ///< from the shape towards the proxy; zero when the cores overlap
    float coreDistance = 0.0f;
};
ProxyGap proxyGap(const ShapeProxy& proxy, const ShapeCore& core, const Transform& xf);

/// Sweeps the proxy along `translation` until its gap to the shape is within
/// kCastTolerance above `targetGap` (targetGap > −(sum of radii)). The gap is
/// a convex function of the fraction t (the distance from a point moving on
/// a line to a convex set), so each Newton step t += (gap − target)/(−gap′)
/// lands before the root: the cast never passes the first touch.
struct CoreCast {
    bool hit = false;
    bool atStart = false;  ///< within the band already at t = 0
    float fraction = 1.0f;
    Vec2 point{};   ///< on the shape's surface (world)
    Vec2 normal{};  ///< the shape's outward normal there
};
CoreCast castProxy(const ShapeProxy& proxy, Vec2 translation, const ShapeCore& core, const Transform& xf,
                   float targetGap, float maxFraction);

/// The proxy's bounding box (world).
AABB proxyAABB(const ShapeProxy& proxy);

/// Throws i2d::Error unless the proxy has 1 to kMaxPolygonVertices bounded
/// points and a radius in [0, 1e5] m.
void validateProxy(const ShapeProxy& proxy);

}  // namespace i2d::detail
