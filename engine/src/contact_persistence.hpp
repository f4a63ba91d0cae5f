// Persistent manifolds: a touching contact between flat shapes keeps its
// manifold while its two bodies have barely moved relative to each other,
// instead of recomputing it from the geometry every step.
//
// Why. With soft contacts a column of boxes is a column of springs: each
// contact compresses by its load / (m_eff·ω²), about 0.5 mm per 10 N at the
// default 50 Hz (1.4 mm at 30 Hz). A manifold recomputed from the geometry every step puts its
// points where the faces overlap now, so a box displaced sideways by δ moves
// the load of everything above towards one point: the gravity moment W·δ of
// a leaning column (its "P-delta" moment) is fed back into the contact
// compression, which leans it further. A column of such springs buckles under
// its own weight once q·L³ > 7.84·EI (Greenhill's self-weight buckling), with
// EI = 2·k·b² per metre: about 14 boxes of 1 m at 30 Hz, 20 at the default
// 50 Hz (L grows as k^(1/3)). A column of 20 at 30 Hz therefore fell within
// 10 s whatever the substep count, and Box2D 2.4.1 and
// Box2D v3 with its contact recycling off fall the same way (measured). The
// first asymmetry that started the lean was the order in which the first
// step's Gauss-Seidel sweep met a manifold's two points; with the feedback
// it grew by e every 1.4 s. (That seed is gone too: contact_solver.cpp now
// solves a manifold's two points together. This file removes the feedback,
// which any other seed, a column built leaning, would still drive.)
//
// What. While the two bodies' relative pose stays within `reuseDistance`
// (the largest distance any point of B has moved in A's frame), B has slid
// along the face by less than 2 cm (kMaxKeptSlide) and neither
// A nor B relative to A has turned by more than about 11°, the manifold keeps its normal (fixed
// in the world) and its points stay fixed in the bodies: each point is a
// material point of A and one of B, which coincided when the manifold was
// computed; its separation is the one computed then plus their relative
// motion along the normal, the same update the substeps make within a step.
// A displaced box then keeps pressing on the same material points, the load
// split between them no longer follows the displacement, and the column
// stands. It is the "contact recycling" of Catto (2025), Box2D v3.2, in
// the tradition of persistent contact manifolds (docs/references.md).
//
// Only flat pairs persist (polygons and segments): a point fixed in a round
// shape would roll away from the true contact (a rolling disc would sink).
// Deep overlaps (kDeepOverlap) never persist: bodies created inside each
// other change their closest features as they separate, and a stale normal
// threw such a pile of 100 boxes at 23 m/s instead of 15.
#pragma once

#include "body.hpp"
#include "contact.hpp"

namespace i2d::detail {

struct Body;
struct Shape;

/// True when the contact of these shapes may keep its manifold.
bool canPersist(const Shape& a, const Shape& b);

/// Records the frame of a manifold just computed (its points in A's frame and
/// the relative pose of the bodies) so later steps can reuse it.
void recordManifoldFrame(Contact& c, const Body& a, const Body& b);

/// Reuses the contact's manifold when its bodies moved less than
/// `reuseDistance` relative to each other since it was computed: updates the
/// points' separations and positions and returns true. False otherwise (the
/// caller recomputes the manifold).
bool reuseManifold(Contact& c, const Body& a, const Body& b, float reuseDistance);

/// Lever arms from the centres of mass of A and B to manifold point j. For a
/// reused manifold these are the two material points of the point, which have
/// drifted apart by the bodies' relative motion; otherwise both arms end at
/// the manifold point.
template <class BodyA, class BodyB>  // Body, or anything with its center and localCenter (RowBody)
inline void contactArms(const Contact& c, const BodyA& a, const BodyB& b, int j, Vec2& rA, Vec2& rB) {
    if (!c.framed) {
        const Vec2 p = c.manifold.points[j].point;
        rA = p - a.center;
        rB = p - b.center;
        return;
    }
    // The arms as they were when the manifold was computed, in the world's
    // orientation of that moment: they do not turn with the bodies. A box
    // that tilts by θ under a load W would otherwise carry that load between
    // two points offset sideways by θ·(its height), a moment W·θ that tilts
    // it further: the same feedback as above, from the turn of the arms.
    const ManifoldFrame& f = c.frame;
    const Vec2 anchor = f.anchorA[j];
    rA = rotate(f.rotationA, anchor - a.localCenter);
    rB = rotate(mulRot(f.rotationA, f.relative.q), invTransformPoint(f.relative, anchor) - b.localCenter);
}

}  // namespace i2d::detail
