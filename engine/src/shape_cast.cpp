// Shape casts and overlap tests of a convex proxy against one shape
// (shape_cast.hpp), on the GJK distance of distance.cpp: conservative
// advancement along a translation (Mirtich (1996), "Impulse-based Dynamic
// Simulation of Rigid Body Systems", PhD thesis; docs/references.md), sped
// up by the convexity of the gap along a line.
#include "shape_cast.hpp"

#include <algorithm>
#include <cmath>

#include "validation.hpp"

namespace i2d {

ShapeProxy makeProxy(const Circle& shape, const Transform& xf) {
    ShapeProxy p;
    p.points[0] = transformPoint(xf, shape.center);
    p.count = 1;
    p.radius = shape.radius;
    return p;
}

ShapeProxy makeProxy(const Capsule& shape, const Transform& xf) {
    ShapeProxy p;
    p.points[0] = transformPoint(xf, shape.center1);
    p.points[1] = transformPoint(xf, shape.center2);
    p.count = 2;
    p.radius = shape.radius;
    return p;
}

ShapeProxy makeProxy(const Polygon& shape, const Transform& xf) {
    ShapeProxy p;
    p.count = std::clamp(shape.count, 0, kMaxPolygonVertices);
    for (int i = 0; i < p.count; ++i) p.points[i] = transformPoint(xf, shape.vertices[i]);
    p.radius = shape.radius;
    return p;
}

ShapeProxy makeProxy(const Segment& shape, const Transform& xf) {
    ShapeProxy p;
    p.points[0] = transformPoint(xf, shape.point1);
    p.points[1] = transformPoint(xf, shape.point2);
    p.count = 2;
    return p;
}

namespace detail {

void validateProxy(const ShapeProxy& proxy) {
    if (proxy.count < 1 || proxy.count > kMaxPolygonVertices)
        fail("shape proxy must have 1 to 8 points (build it with makeProxy)");
    for (int i = 0; i < proxy.count; ++i) requireBounded(proxy.points[i], "shape proxy point");
    requireInRange(proxy.radius, 0.0f, kMaxRadius, "shape proxy radius");
}

AABB proxyAABB(const ShapeProxy& proxy) {
    AABB box{proxy.points[0], proxy.points[0]};
    for (int i = 1; i < proxy.count; ++i) {
        box.lower = min(box.lower, proxy.points[i]);
        box.upper = max(box.upper, proxy.points[i]);
    }
    const Vec2 r{proxy.radius, proxy.radius};
    return {box.lower - r, box.upper + r};
}

namespace {

ProxyGap gapAt(const ShapeProxy& proxy, Vec2 offset, const ShapeCore& core, const Transform& xf) {
    const Transform moved{offset, Rot{}};
    const DistanceResult d = shapeDistance(proxy.points, proxy.count, moved, core.points, core.count, xf);
    ProxyGap g;
    g.coreDistance = d.distance;
    g.gap = d.distance - proxy.radius - core.radius;
    g.pointOnShape = d.pointB;
    // Directions shorter than this are round-off of touching cores.
    if (d.distance > 1.0e-6f) g.normal = (1.0f / d.distance) * (d.pointA - d.pointB);
    return g;
}

}  // namespace

ProxyGap proxyGap(const ShapeProxy& proxy, const ShapeCore& core, const Transform& xf) {
    return gapAt(proxy, {}, core, xf);
}

CoreCast castProxy(const ShapeProxy& proxy, Vec2 translation, const ShapeCore& core, const Transform& xf,
                   float targetGap, float maxFraction) {
    CoreCast out;
    float t = 0.0f;
    // Newton steps on a convex function approach the root from one side;
    // slow only for grazing casts, which the cap ends conservatively.
    constexpr int kMaxSteps = 40;
    for (int step = 0; step < kMaxSteps; ++step) {
        const ProxyGap g = gapAt(proxy, t * translation, core, xf);
        const float closing = -dot(translation, g.normal);  // −gap′(t)
        if (g.gap <= targetGap + kCastTolerance) {
            out.atStart = step == 0;
            if (out.atStart && g.normal != Vec2{} && closing <= 0.0f) return out;  // touching but leaving
            out.hit = true;
            out.fraction = t;
            Vec2 n = g.normal;
            if (n == Vec2{}) n = -normalize(translation);  // cores overlap: no direction but the motion's
            out.normal = n;
            out.point = g.pointOnShape + core.radius * n;
            return out;
        }
        // Moving away, or not moving: the gap cannot close (convexity).
        if (closing <= 0.0f) return out;
        t += (g.gap - targetGap) / closing;
        if (t > maxFraction) return out;
    }
    // Not converged (a grazing cast): t is still before the touch.
    const ProxyGap g = gapAt(proxy, t * translation, core, xf);
    out.hit = true;
    out.fraction = t;
    out.normal = g.normal == Vec2{} ? -normalize(translation) : g.normal;
    out.point = g.pointOnShape + core.radius * out.normal;
    return out;
}

}  // namespace detail

}  // namespace i2d
