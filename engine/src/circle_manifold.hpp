// The manifold of two circles, written in place: the narrowphase of a pile
// of circles calls it for every contact (computeManifold, contact.cpp), and
// collideCircles (manifold.cpp) is the same function returning its result.
#pragma once

#include "impulse2d/collision.hpp"

namespace i2d::detail {

/// collideCircles into `m`, every field written (all zero when the circles
/// are further apart than speculativeDistance).
///
/// In world axes: two circles have no direction of their own, so nothing is
/// gained by A's frame, and the transforms into it and back were most of the
/// work (a third of each circle contact's update in a pile of circles). The
/// difference of the two origins is taken first, as the frame would take it,
/// so nearby bodies far from the world's origin lose no precision.
inline void writeCircleManifold(const Circle& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                                float speculativeDistance, Manifold& m) {
    const Vec2 offsetA = rotate(xfA.q, a.center);
    const Vec2 d = (xfB.p - xfA.p) + (rotate(xfB.q, b.center) - offsetA);
    float dist = 0.0f;
    Vec2 n = normalize(d, dist);
    m.points[1] = ManifoldPoint{};
    if (dist - a.radius - b.radius > speculativeDistance) {
        m.normal = Vec2{};
        m.points[0] = ManifoldPoint{};
        m.pointCount = 0;
        return;
    }
    if (n.x == 0.0f && n.y == 0.0f) {
        n = rotate(xfA.q, Vec2{0.0f, 1.0f});  // coincident centres: A's up
        dist = 0.0f;
    }
    m.normal = n;
    const float separation = dist - a.radius - b.radius;
    // Midway between the two surfaces along n.
    m.points[0].point = xfA.p + mulAdd(offsetA, a.radius + 0.5f * separation, n);
    m.points[0].separation = separation;
    m.points[0].id = 0;
    m.pointCount = 1;
}

}  // namespace i2d::detail
