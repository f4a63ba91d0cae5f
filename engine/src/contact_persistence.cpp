// Persistent manifolds (contact_persistence.hpp says why and what).
#include "contact_persistence.hpp"

#include <algorithm>
#include <cmath>

#include "body.hpp"
#include "shape.hpp"

namespace i2d::detail {

namespace {

bool isFlat(ShapeType t) { return t == ShapeType::polygon || t == ShapeType::segment; }

/// Farthest point of the body's solid shapes from its origin (m).
float reachFromOrigin(const Body& b) { return std::max(b.reach, 0.0f) + length(b.localCenter); }

/// |sin| of the turn from q0 to q1.
float turnSine(Rot q0, Rot q1) { return std::abs(q0.c * q1.s - q0.s * q1.c); }

// Beyond a turn of B relative to A of about 11° (cos 0.98) a manifold is
// recomputed whatever the reach: the points would be too far from the faces.
constexpr float kMinTurnCosine = 0.98f;
// The normal is kept fixed in the world, so A's own turn since the manifold
// was computed is how far the normal is off its face: kept while that is
// under 2° (cos 0.99939). A body resting on a side of a drum turns with it
// and barely moves relative to it, so with the 11° above its manifold was
// kept through 2 steps of a drum turning at 5 rad/s, the rows pushed it
// along a normal 5 to 10° stale into a corner, and from there past the next
// side of a one-sided chain: 2 of 30 small bodies fell out of a kinematic
// chain drum at 5 rad/s, 1 at 1 rad/s (KeptManifolds test). A column's boxes
// lean by far less than 2°, and keep theirs.
constexpr float kMinWorldTurnCosine = 0.99939f;

// A kept point acts at the material points of A and B that touched when the
// manifold was computed. Where B slides along the face, the bodies really
// touch elsewhere: the load acts at a point of B as far from the true one as
// B slid, a moment W·(slide) that is not there. A unit box slid off a ledge
// at 0.2 m/s kept its support 3 mm behind its centre while its centre went
// on past the edge, and was held level until 5 cm past it, the reuse distance
// (recomputed every step it tips 3.7 cm past it); a rocking box's leaky
// solve had hidden this (contact_solver.cpp, solvePointPair). Slid 2 cm, the
// manifold is recomputed: the box tips 4.4 cm past the edge. Resting stacks,
// what keeping is for, slide far less (a tall stack's boxes at most a few
// millimetres), while a sliding box recomputes every 2 cm. (5 mm let a tall
// stack of boxes landing on each other with offsets sway past its bar.)
constexpr float kMaxKeptSlide = 0.02f;

}  // namespace

bool canPersist(const Shape& a, const Shape& b) {
    return !a.isSensor && !b.isSensor && isFlat(a.type) && isFlat(b.type);
}

void recordManifoldFrame(Contact& c, const Body& a, const Body& b) {
    ManifoldFrame& f = c.frame;
    f.relative = invMulTransforms(a.xf, b.xf);
    f.rotationA = a.xf.q;
    for (int j = 0; j < c.manifold.pointCount; ++j) {
        f.anchorA[j] = invTransformPoint(a.xf, c.manifold.points[j].point);
        f.separation[j] = c.manifold.points[j].separation;
    }
    // Kept only with two points: the manifold then holds both features that
    // can touch (the incident face's ends), and moving them is all a kept
    // manifold does. One point (a corner on a face) leaves out the corner a
    // turn brings down: a box rocking down from one corner onto a static
    // floor kept its pivot's manifold while its far corner, 2.4 cm above at
    // first, went 3.6 cm into the floor before the turn passed the reuse
    // distance (a 1.2 × 0.7 m box from 0.02 rad; 4.3 cm for a 2 × 1 m box),
    // and the soft row pushed it out over a quarter of a second.
    // A deep overlap is not at rest: its geometry changes as it separates.
    bool shallow = c.manifold.pointCount == 2;
    for (int j = 0; j < c.manifold.pointCount; ++j)
        shallow = shallow && c.manifold.points[j].separation > -deepOverlapOf(c);
    c.framed = shallow;
}

bool reuseManifold(Contact& c, const Body& a, const Body& b, float reuseDistance) {
    if (!c.framed || reuseDistance <= 0.0f) return false;
    const ManifoldFrame& f = c.frame;
    const Transform rel = invMulTransforms(a.xf, b.xf);
    // In A's frame, B's points moved by at most |Δp| + reach·|sin Δθ|. The
    // normal is fixed in the world: A's own turn is bounded by the 2° check
    // (and B's by both).
    const float relCos = dot(Vec2{rel.q.c, rel.q.s}, Vec2{f.relative.q.c, f.relative.q.s});
    const float absCos = dot(Vec2{a.xf.q.c, a.xf.q.s}, Vec2{f.rotationA.c, f.rotationA.s});
    if (relCos < kMinTurnCosine || absCos < kMinWorldTurnCosine) return false;
    const float moved = length(rel.p - f.relative.p) + reachFromOrigin(b) * turnSine(f.relative.q, rel.q);
    if (!(moved < reuseDistance)) return false;
    const Vec2 n = c.manifold.normal;
    // Nor may B have slid along the face by kMaxKeptSlide or more.
    if (!(std::abs(cross(rotate(a.xf.q, rel.p - f.relative.p), n)) < kMaxKeptSlide)) return false;
    for (int j = 0; j < c.manifold.pointCount; ++j) {
        const Vec2 pA = transformPoint(a.xf, f.anchorA[j]);
        const Vec2 pB = transformPoint(b.xf, invTransformPoint(f.relative, f.anchorA[j]));
        ManifoldPoint& mp = c.manifold.points[j];
        mp.separation = f.separation[j] + dot(pB - pA, n);
        mp.point = 0.5f * (pA + pB);
    }
    return true;
}

}  // namespace i2d::detail
