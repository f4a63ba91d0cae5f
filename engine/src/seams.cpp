// Seams between separate static shapes.
//
// A floor of adjacent boxes, of segments laid end to end or of boxes in
// different bodies is flat, but each piece is collided on its own. At a seam
// the narrowphase of the next piece can report a normal that the floor as a
// whole does not have: the side face of the next box (hidden by the box
// before it), or the rounded normal of the next segment's end vertex. Such a
// ghost normal, in a speculative contact, stops a sliding box at the seam or
// kicks a rolling circle upwards (Catto, 2020, "Ghost Collisions", Box2D
// blog).
//
// The manifold of a static shape S and a moving shape is kept as computed,
// except for the points whose normal n (from S to the moving shape) is a
// ghost. With p the point's witness on S's core:
// - n is a face normal of S, and p is near an end of that face: the face is
//   internal when another static polygon T has a coincident face of opposite
//   normal that spans p (two boxes side by side). No body can touch an
//   internal face from outside the union, so the point is a ghost.
// - n is a vertex normal of S (strictly between S's face normals at a vertex
//   v, or at a segment's end): when another static shape T has a face that
//   passes through v, and n leans over that face (n·u > 0 for u the unit
//   direction from v along T's face), then the body lies over T's face,
//   whose own contact supports it: the point is a ghost. At a convex corner
//   of the union the vertex normals between the two faces do not lean over
//   either face and are kept; at a flat or concave seam every vertex normal
//   leans over the neighbour's face and is dropped. This is the vertex-region
//   rule of a chain's ghost vertices (Catto, 2025, Box2D v3.1, manifold.c,
//   the chain segment colliders), with the neighbour found through the
//   broadphase instead of stored.
// - of a flat face resting across a flat seam, the point each piece reports
//   at the seam's vertex (dropFlatSeamPoints, below).
// A chain's segment (World::createChain) keeps its neighbours' far points
// (ghost vertices) and applies the vertex rule with them, whatever its body,
// and collides on its right side only.
// A two-sided segment (any body) pushes a body only towards the side its
// centroid is on: a manifold whose normal points across the line, for a body
// whose centroid projects onto the segment, is dropped.
// Only static shapes that would collide with the moving shape count as
// neighbours, and only polygons and segments (a static circle or capsule
// has no face to continue a floor). Cost: a broadphase query of a
// slop-sized box for vertex normals, and for face normals within the
// speculative distance of a face's end; none for a body resting inside a face.
#include <cmath>

#include "contact.hpp"
#include "seams.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

constexpr float kShareTolerance = kLinearSlop;  ///< vertices and faces closer than this are shared
constexpr float kFaceAlignment = 0.9999f;       ///< cos 0.8°: a normal this close to a face normal is it
constexpr float kLean = 1.0e-4f;                ///< n·u above this leans over the face (at 20 m/s: 2 mm/s towards it)

/// Whether n is the face normal `face` of S, for a contact with `moving`.
/// A polygon or capsule touches with a face of its own, so a normal within
/// 0.8° of S's face is that face, tilted by the mover's own lean. A circle's
/// normal is either S's face normal or a vertex normal (from S's vertex to
/// its centre), tilted by the centre's distance past the vertex over the
/// radius: a disc of radius 0.5 whose centre was 6 mm short of a seam had
/// one tilted 0.67°, which the 0.8° test took for the face, and at 10 m/s
/// its row saw the disc approach the vertex at 0.12 m/s and lifted it 2 mm.
/// For a circle the face normal is only the one that leans over neither side
/// by more than kLean, the bound of the vertex rule below.
bool isFaceNormal(Vec2 n, Vec2 face, const Shape& moving) {
    if (moving.type != ShapeType::circle) return dot(n, face) >= kFaceAlignment;
    return dot(n, face) > 0.0f && std::abs(cross(n, face)) <= kLean;
}

/// A static shape's core in world space: a polygon's vertices and normals, or a segment's two points.
struct Outline {
    Vec2 vertices[kMaxPolygonVertices];
    Vec2 normals[kMaxPolygonVertices];
    int count = 0;
    float radius = 0.0f;
    bool segment = false;
};

bool outlineOf(const Shape& s, const Transform& xf, Outline& o) {
    if (s.type == ShapeType::polygon) {
        const Polygon& p = s.geometry.polygon;
        o.count = p.count;
        o.radius = p.radius;
        for (int i = 0; i < p.count; ++i) {
            o.vertices[i] = transformPoint(xf, p.vertices[i]);
            o.normals[i] = rotate(xf.q, p.normals[i]);
        }
        return true;
    }
    if (s.type == ShapeType::segment) {
        o.count = 2;
        o.segment = true;
        o.vertices[0] = transformPoint(xf, s.geometry.segment.point1);
        o.vertices[1] = transformPoint(xf, s.geometry.segment.point2);
        const Vec2 n = leftPerp(normalize(o.vertices[1] - o.vertices[0]));
        o.normals[0] = n;
        o.normals[1] = -n;
        return true;
    }
    return false;
}

/// The faces of an outline as (start, end) pairs: a polygon's edges, a segment once.
int faceCount(const Outline& o) { return o.segment ? 1 : o.count; }
Vec2 faceEnd(const Outline& o, int i) { return o.vertices[(i + 1) % o.count]; }

/// Calls visit(outline) for every static polygon or segment near `box`
/// other than `self` that collides with the moving shape.
template <class Visit>
void forNeighbours(const WorldState& w, int self, const Shape& moving, const AABB& box, Visit&& visit) {
    w.broadPhase.staticTree.query(box, [&](int other) {
        if (other == self) return true;
        const Shape& t = w.shapes[other];
        if (t.isSensor || !shouldCollide(t.filter, moving.filter)) return true;
        Outline o;
        if (!outlineOf(t, w.bodies[t.body].xf, o)) return true;
        return visit(o);
    });
}

AABB around(Vec2 p, float r) { return {p - Vec2{r, r}, p + Vec2{r, r}}; }

/// True when face `face` of S (outward normal m) is hidden at p by a
/// coincident, opposite face of a neighbouring polygon.
bool faceIsInternal(const WorldState& w, int self, const Shape& moving, const Outline& s, int face, Vec2 p) {
    const Vec2 m = s.normals[face];
    bool internal = false;
    forNeighbours(w, self, moving, around(p, kShareTolerance), [&](const Outline& t) {
        if (t.segment) return true;
        for (int j = 0; j < t.count; ++j) {
            if (dot(t.normals[j], m) > -kFaceAlignment) continue;
            const Vec2 a = t.vertices[j], b = faceEnd(t, j);
            // On the same line (S's face through p), and spanning p.
            if (std::abs(dot(a - p, m)) > kShareTolerance + t.radius + s.radius) continue;
            const Vec2 e = b - a;
            const float len = length(e);
            if (len <= 0.0f) continue;
            const float along = dot(p - a, e) / len;
            if (along < -kShareTolerance || along > len + kShareTolerance) continue;
            internal = true;
            return false;
        }
        return true;
    });
    return internal;
}

/// True when a neighbouring static shape has a face through v over which n leans.
bool leansOverNeighbour(const WorldState& w, int self, const Shape& moving, Vec2 v, Vec2 n) {
    bool leans = false;
    forNeighbours(w, self, moving, around(v, kShareTolerance), [&](const Outline& t) {
        for (int j = 0; j < faceCount(t); ++j) {
            const Vec2 a = t.vertices[j], b = faceEnd(t, j);
            float len = 0.0f;
            const Vec2 u = normalize(b - a, len);
            if (len <= 0.0f) continue;
            // Does the face pass through v?
            const float along = clamp(dot(v - a, u), 0.0f, len);
            if (distance(v, a + along * u) > kShareTolerance + t.radius) continue;
            const bool atA = distance(v, a) <= kShareTolerance, atB = distance(v, b) <= kShareTolerance;
            // Directions from v along the face: into it from an end, both ways from inside.
            const float lean = atA ? dot(n, u) : atB ? -dot(n, u) : std::abs(dot(n, u));
            if (lean > kLean) {
                leans = true;
                return false;
            }
        }
        return true;
    });
    return leans;
}

bool isGhost(const WorldState& w, int self, const Shape& moving, const Outline& s, Vec2 p, Vec2 n, float reach) {
    // A face normal of S?
    for (int i = 0; i < (s.segment ? 2 : s.count); ++i) {
        if (!isFaceNormal(n, s.normals[i], moving)) continue;
        if (s.segment) return false;  // a segment's side: never hidden
        const Vec2 a = s.vertices[i], b = faceEnd(s, i);
        if (distance(p, a) > reach && distance(p, b) > reach) return false;  // well inside the face
        return faceIsInternal(w, self, moving, s, i, p);
    }
    // A vertex normal: at which vertex?
    int vertex = -1;
    for (int i = 0; i < s.count; ++i)
        if (distance(p, s.vertices[i]) <= kShareTolerance) vertex = i;
    if (vertex < 0) return false;
    return leansOverNeighbour(w, self, moving, s.vertices[vertex], n);
}

/// Whether a static neighbour's face continues S's flat face past its end v:
/// a face with S's outward normal n (either side of a segment), on S's line
/// through v, reaching from v onwards along uOut (the direction out of S's
/// face at v).
bool faceContinuesPast(const WorldState& w, int self, const Shape& moving, Vec2 v, Vec2 uOut, Vec2 n, float radius) {
    bool continues = false;
    forNeighbours(w, self, moving, around(v, kShareTolerance), [&](const Outline& t) {
        for (int j = 0; j < faceCount(t); ++j) {
            const bool facesUp = dot(t.normals[j], n) >= kFaceAlignment ||
                                 (t.segment && -dot(t.normals[j], n) >= kFaceAlignment);
            if (!facesUp) continue;
            const Vec2 a = t.vertices[j], b = faceEnd(t, j);
            // On S's surface line (the same thickness) through v ...
            if (std::abs(dot(a - v, n) + radius - t.radius) > kShareTolerance) continue;
            // ... from v onwards.
            const float ta = dot(a - v, uOut), tb = dot(b - v, uOut);
            if (std::min(ta, tb) > kShareTolerance || std::max(ta, tb) <= kShareTolerance) continue;
            continues = true;
            return false;
        }
        return true;
    });
    return continues;
}

/// Whether the moving shape reaches past v along uOut no higher above S's
/// surface line (outward normal n through S's core point v, S's radius
/// `radius`) than `gap`, the gap of its point at v: a polygon's or capsule's
/// corner beyond v as low as the face at v.
bool liesFlatPast(const WorldState& w, const Shape& moving, Vec2 v, Vec2 uOut, Vec2 n, float radius, float gap) {
    const Transform& xf = w.bodies[moving.body].xf;
    Vec2 corners[kMaxPolygonVertices];
    int count = 0;
    float own = 0.0f;
    if (moving.type == ShapeType::polygon) {
        const Polygon& p = moving.geometry.polygon;
        for (int i = 0; i < p.count; ++i) corners[count++] = transformPoint(xf, p.vertices[i]);
        own = p.radius;
    } else if (moving.type == ShapeType::capsule) {
        corners[count++] = transformPoint(xf, moving.geometry.capsule.center1);
        corners[count++] = transformPoint(xf, moving.geometry.capsule.center2);
        own = moving.geometry.capsule.radius;
    }
    for (int i = 0; i < count; ++i) {
        const Vec2 d = corners[i] - v;
        if (dot(d, uOut) > kShareTolerance && dot(d, n) - radius - own <= gap + kShareTolerance) return true;
    }
    return false;
}

/// A flat face resting across a flat seam (two static pieces in line: a
/// chain's segments, segments end to end, boxes side by side): each piece's
/// manifold clips the moving face at the piece's end, so both report a point
/// at the seam's vertex v, beside the moving face's own corner on their side.
/// The floor as a whole holds the face at its two corners; the extra point
/// at v, held twice, puts a third support off the face's middle, so a loaded
/// box sinks more on its far side (a column of 50 boxes on a chain, its axis
/// 0.3 m from a vertex, leaned 10 cm) and a box landing flat there is struck
/// off its centre and spins. Of a two-point face manifold, a point at an end v
/// of S's face is dropped when the floor continues flat past v
/// (`continuesPast`) and the moving shape lies there as low as at v, so the
/// neighbour's manifold holds it beyond v; a shape tilted up past v keeps it,
/// being held at v indeed. `p[k]` are the points' witnesses on S's core.
template <class ContinuesPast>
void dropFlatSeamPoints(const WorldState& w, const Shape& moving, Vec2 a, Vec2 b, Vec2 n, float radius, const Vec2 p[2],
                        Manifold& m, ContinuesPast&& continuesPast) {
    if (m.pointCount != 2 || moving.type == ShapeType::circle) return;
    bool drop[2] = {false, false};
    for (int k = 0; k < 2; ++k) {
        for (const Vec2 v : {a, b}) {
            if (distance(p[k], v) > kShareTolerance || distance(p[1 - k], v) <= kShareTolerance) continue;
            const Vec2 uOut = normalize(v == a ? a - b : b - a);
            drop[k] = liesFlatPast(w, moving, v, uOut, n, radius, m.points[k].separation) && continuesPast(v, uOut);
        }
    }
    int kept = 0;
    for (int k = 0; k < 2; ++k)
        if (!drop[k]) m.points[kept++] = m.points[k];
    m.pointCount = kept;
}

/// The centroid of a shape in its body frame.
Vec2 localCentroid(const Shape& s) {
    switch (s.type) {
        case ShapeType::circle: return s.geometry.circle.center;
        case ShapeType::capsule: return 0.5f * (s.geometry.capsule.center1 + s.geometry.capsule.center2);
        case ShapeType::segment: return 0.5f * (s.geometry.segment.point1 + s.geometry.segment.point2);
        case ShapeType::polygon: return s.geometry.polygon.centroid;
    }
    return {};
}

/// The manifold of `moving` against the front face of chain segment
/// `chain` alone: the segment's line extended past both ends (so that no end
/// is a feature and the normal is the face's), keeping the points that lie
/// along the segment itself (those beyond an end are the neighbour's to
/// make). Ids are set apart from the segment's own manifolds'.
Manifold faceOnlyManifold(const WorldState& w, const Shape& chain, const Shape& moving, float margin) {
    const Transform& xfChain = w.bodies[chain.body].xf;
    const Transform& xfMoving = w.bodies[moving.body].xf;
    const Segment& seg = chain.geometry.segment;
    const float span = distance(seg.point1, seg.point2);
    Manifold f;
    if (!(span > 0.0f)) return f;
    const Vec2 d = (1.0f / span) * (seg.point2 - seg.point1);
    // Past the whole of the moving shape (its box's diagonal), so that no end is within its reach.
    const AABB box = shapeAABB(moving, xfMoving);
    const float reach = length(box.upper - box.lower);
    Shape line = chain;
    line.geometry.segment = Segment{seg.point1 - reach * d, seg.point2 + reach * d};
    f = collideShapes(line, xfChain, moving, xfMoving, margin);
    const Vec2 p1 = transformPoint(xfChain, seg.point1), dw = rotate(xfChain.q, d);
    int kept = 0;
    for (int i = 0; i < f.pointCount; ++i) {
        const float along = dot(f.points[i].point - p1, dw);
        if (along < -kShareTolerance || along > span + kShareTolerance) continue;
        f.points[kept] = f.points[i];
        f.points[kept].id = static_cast<std::uint16_t>(f.points[kept].id | 0x8000u);
        ++kept;
    }
    f.pointCount = kept;
    return f;
}

/// A chain segment's rule, with its stored ghost vertices as the
/// neighbours: one-sided (nothing whose centroid is behind the segment's
/// line collides with it, nor any point whose normal points behind it), and
/// the vertex rule above at each end that has a neighbour.
void applyChainRule(const WorldState& w, const Shape& chain, const Shape& moving, Vec2 n, Manifold& m) {
    const Transform& xf = w.bodies[chain.body].xf;
    const Vec2 p1 = transformPoint(xf, chain.geometry.segment.point1);
    const Vec2 p2 = transformPoint(xf, chain.geometry.segment.point2);
    const Vec2 front = rightPerp(normalize(p2 - p1));
    const Vec2 c = transformPoint(w.bodies[moving.body].xf, localCentroid(moving));
    if (dot(front, c - p1) < 0.0f || dot(n, front) < 0.0f) {
        m.pointCount = 0;
        return;
    }
    const Vec2 g1 = transformPoint(xf, chain.ghost1), g2 = transformPoint(xf, chain.ghost2);
    if (isFaceNormal(n, front, moving)) {
        if (m.pointCount != 2) return;
        // The neighbour continues the face flat past an end when its far
        // point (the ghost vertex) lies straight on.
        const Vec2 witness[2] = {m.points[0].point - 0.5f * m.points[0].separation * n,
                                 m.points[1].point - 0.5f * m.points[1].separation * n};
        dropFlatSeamPoints(w, moving, p1, p2, front, 0.0f, witness, m, [&](Vec2 v, Vec2 uOut) {
            const Vec2 g = v == p1 ? g1 : g2;
            return distance(g, v) > 0.0f && dot(normalize(g - v), uOut) >= kFaceAlignment;
        });
        return;
    }
    // The manifold has one normal: a ghost at one end is a ghost for the
    // whole segment. A body's face reaching over the segment (the box's
    // front face sliding along a flat chain) clips both of its ends; the far
    // one, kept by a fast body's speculative margin, carried the ghost normal
    // past the near end's rule and stopped the box.
    //
    // A neighbour rising in front of the segment (a concave corner, as
    // inside a drum) makes a point at the shared vertex no ghost but a body
    // pressed into the corner, against both sides: dropped by both segments,
    // a box carried round the inside of a chain drum lost both contacts at
    // once and left through the corner. Such a point's manifold is taken
    // against the segment's face alone (faceOnlyManifold). Kept with its own
    // normal instead, the normal of the body's side, a box driven across a
    // chain's shallow valley stopped dead at its first vertex.
    float margin = w.settings.speculativeDistance;
    for (int i = 0; i < m.pointCount; ++i) margin = std::max(margin, m.points[i].separation);
    for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& pt = m.points[i];
        const Vec2 p = pt.point - 0.5f * pt.separation * n;
        Vec2 v{}, g{};
        if (distance(p, p1) <= kShareTolerance && distance(g1, p1) > 0.0f)
            v = p1, g = g1;
        else if (distance(p, p2) <= kShareTolerance && distance(g2, p2) > 0.0f)
            v = p2, g = g2;
        else
            continue;
        const Vec2 u = normalize(g - v);
        if (!(dot(n, u) > kLean)) continue;
        if (dot(front, u) > kLean) {  // concave: the face alone
            // (faceOnlyManifold's normal points from the chain to `moving`, as n does.)
            const bool chainIsA = dot(m.normal, n) > 0.0f;
            m = faceOnlyManifold(w, chain, moving, margin);
            if (!chainIsA) m.normal = -m.normal;
            return;
        }
        // A body pressed deeper into the segment than the speculative
        // distance is no body sliding across a seam: its deep points make the
        // separating axis test pick its own faces against the segment's ends
        // (a flat box 15 cm thick under a box 800 times its mass, tilted 5°
        // and 7 cm deep over a chain's vertex: its side face against the
        // vertex, and its tilted bottom face). Both segments under it dropped
        // theirs as ghosts, the contact let go of a body still in front of
        // the chain, and it fell through. Its manifold is taken against the
        // segment's face alone instead, which pushes it out in front. (A body
        // resting or sliding on a chain stays within the penetration slop of
        // its face, 5 mm, and its sag under load.)
        if (deepestSeparation(m) < -w.settings.speculativeDistance) {
            const bool chainIsA = dot(m.normal, n) > 0.0f;
            m = faceOnlyManifold(w, chain, moving, w.settings.speculativeDistance);
            if (!chainIsA) m.normal = -m.normal;
            return;
        }
        m.pointCount = 0;
        return;
    }
}

}  // namespace

/// A two-sided segment pushes a body towards the side its centroid is on,
/// never across its line: when the centroid projects onto the segment and
/// the normal points to the other side (a thin body straddling the segment,
/// whose own face won the separating axis test), the manifold is dropped.
/// Without this, a sliver stopped across a segment by continuous collision
/// was pushed through it at less than the speculative distance per step.
void keepSegmentSide(const WorldState& w, const Shape& segment, const Shape& other, Vec2 n, Manifold& m) {
    const Transform& xf = w.bodies[segment.body].xf;
    const Vec2 p1 = transformPoint(xf, segment.geometry.segment.point1);
    const Vec2 e = transformPoint(xf, segment.geometry.segment.point2) - p1;
    const Vec2 c = transformPoint(w.bodies[other.body].xf, localCentroid(other)) - p1;
    const float t = dot(c, e);
    if (t < 0.0f || t > dot(e, e)) return;
    const float side = cross(e, c);  // > 0: the centroid is on the left
    if (side == 0.0f) return;
    if ((side > 0.0f ? 1.0f : -1.0f) * cross(e, n) < 0.0f) m.pointCount = 0;
}

bool hasSeamRule(const Shape& a, const Shape& b, bool aStatic, bool bStatic) {
    if (a.isSensor || b.isSensor) return false;
    return a.type == ShapeType::segment || a.chainSegment || b.chainSegment || aStatic != bStatic;
}

void dropSeamGhosts(const WorldState& w, const Contact& c, Manifold& m) {
    if (m.pointCount == 0 || c.isSensor) return;
    const Shape& shapeA = w.shapes[c.shapeA];
    const Shape& shapeB = w.shapes[c.shapeB];
    // Segments come first in a contact (contact.cpp), and two never collide.
    if (shapeA.type == ShapeType::segment && !shapeA.chainSegment) {
        keepSegmentSide(w, shapeA, shapeB, m.normal, m);
        if (m.pointCount == 0) return;
    }
    if (shapeA.chainSegment || shapeB.chainSegment) {
        // Two segments never collide, so one side is the chain's.
        const bool aChain = shapeA.chainSegment;
        applyChainRule(w, aChain ? shapeA : shapeB, aChain ? shapeB : shapeA, aChain ? m.normal : -m.normal, m);
        return;
    }
    const bool aStatic = w.bodies[c.bodyA].type == BodyType::static_body;
    const bool bStatic = w.bodies[c.bodyB].type == BodyType::static_body;
    if (aStatic == bStatic) return;
    const int self = aStatic ? c.shapeA : c.shapeB;
    const Shape& fixed = w.shapes[self];
    const Shape& moving = w.shapes[aStatic ? c.shapeB : c.shapeA];
    Outline s;
    if (!outlineOf(fixed, w.bodies[fixed.body].xf, s)) return;
    const Vec2 n = aStatic ? m.normal : -m.normal;  // from the static shape to the moving one
    // How near a face's end a face contact may be a seam's: the speculative
    // distance (how far above a surface a point is reported) and the slop
    // (how deep a resting point sinks).
    const float reach = w.settings.speculativeDistance + kLinearSlop;
    int kept = 0;
    for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& pt = m.points[i];
        // The point is midway between the surfaces: S's core is half the
        // separation and S's radius behind it.
        const Vec2 p = pt.point - (0.5f * pt.separation + s.radius) * n;
        if (!isGhost(w, self, moving, s, p, n, reach)) m.points[kept++] = pt;
    }
    m.pointCount = kept;
    if (m.pointCount != 2) return;
    for (int i = 0; i < faceCount(s) + (s.segment ? 1 : 0); ++i) {
        if (!isFaceNormal(n, s.normals[i], moving)) continue;
        const Vec2 a = s.segment ? s.vertices[0] : s.vertices[i], b = s.segment ? s.vertices[1] : faceEnd(s, i);
        Vec2 witness[2];
        for (int k = 0; k < 2; ++k) witness[k] = m.points[k].point - (0.5f * m.points[k].separation + s.radius) * n;
        dropFlatSeamPoints(w, moving, a, b, n, s.radius, witness, m,
                           [&](Vec2 v, Vec2 uOut) { return faceContinuesPast(w, self, moving, v, uOut, n, s.radius); });
        return;
    }
}

}  // namespace i2d::detail
