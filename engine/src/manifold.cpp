// Impulse2D — narrowphase: contact manifolds for every pair of shape types.
//
// Method. Round shapes (circle, capsule, rounded polygon, segment) are a core
// (point, segment, convex polygon) plus a radius. Closest features of the
// cores give a normal; the surfaces are the cores pushed out by their radii.
// Polygon pairs use the separating axis test (SAT) on both polygons' edge
// normals to choose a reference face, then clip the most anti-parallel
// (incident) edge of the other polygon against the side planes of the
// reference face (Sutherland–Hodgman with two planes), giving up to two
// points. Capsules and segments become two-vertex polygons where that is
// exact (against a real polygon, SAT on the polygon's normals plus the
// segment's normal is complete). Every pair is computed in A's frame shifted
// to one of A's vertices, so the arithmetic stays small far from the origin.
// Nothing allocates; the only loops are over ≤ 8 vertices.
//
// Degenerate cases (what each pair returns):
// - circle–circle, coincident centres: normal = A's local +y axis (in world),
//   separation = −(rA + rB), point at A's centre.
// - capsule–circle (also segment–circle): circle centre exactly on the core
//   segment: normal = left perpendicular of the segment (center1→center2);
//   zero-length core: treated as a circle (A's +y when centres coincide).
// - capsule–capsule (also segment–capsule): when the closest-point direction
//   is within ~10° of one segment's normal and the projections overlap, the
//   other segment is clipped against that one (two points when nearly
//   parallel, e.g. one lying on the other); otherwise (end-to-end, crossing
//   at an angle with separated cores, or a clip that cut away the closest
//   point) one point at the closest points.
//   Crossing/intersecting cores: reference = A, normal = A's perpendicular
//   on the side of B's midpoint (+left perpendicular when exactly centred).
//   Parallel collinear segments overlapping end to end: two points.
//   Zero-length cores fall back to the circle formulas above.
// - polygon–circle: centre inside the polygon: normal of the least-deep
//   face (first such face on ties), point at the face projection midpoint;
//   centre exactly at a vertex/edge: face normal of the max-separation face.
// - polygon–polygon (also polygon–capsule, segment–polygon): identical
//   polygons exactly on top of each other: every axis ties, A's face 0 is the
//   reference (normal = A's normals[0]), two points with separation
//   −(full overlap depth along that normal). Cores separated but within
//   radius + speculative distance: if the exact core distance equals the SAT
//   separation (face contact) the clip above is used; otherwise the closest
//   features are vertex–vertex and one point with the vertex-to-vertex normal
//   is returned. Incident edge entirely outside the reference face's side
//   planes: one point at its nearest vertex.
// - segment–polygon / polygon–capsule with a zero-length segment: polygon–
//   circle with the roles swapped and the normal negated.
#include <cfloat>
#include <cmath>

#include "impulse2d/collision.hpp"

#include "circle_manifold.hpp"

namespace i2d {

namespace {

// Relative tolerance for keeping the reference face of polygon A: B's face is
// only preferred when it separates by clearly more, so the reference face,
// and with it the feature ids, do not flicker between nearly equal axes from
// one step to the next (Box2D uses the same 0.1·linear slop).
constexpr float kReferenceTolerance = 0.1f * kLinearSlop;

// cos(≈10°): capsule pairs use a face (clipped, up to two points) manifold
// when the closest-point direction is this close to one segment's normal.
constexpr float kCapsuleFaceAlignment = 0.985f;

Manifold toWorld(const Manifold& local, const Transform& frame) {
    Manifold m = local;
    m.normal = rotate(frame.q, local.normal);
    for (int i = 0; i < m.pointCount; ++i) m.points[i].point = transformPoint(frame, local.points[i].point);
    return m;
}

// One contact between core points pA, pB (distance `dist` apart along the
// unit normal n, A → B) of shapes with radii rA, rB: the surfaces are at
// pA + rA n and pB − rB n, the point midway, separation dist − rA − rB.
Manifold singlePoint(Vec2 pA, Vec2 pB, Vec2 n, float dist, float rA, float rB, std::uint16_t id) {
    Manifold m;
    m.normal = n;
    Vec2 cA = mulAdd(pA, rA, n);
    Vec2 cB = mulSub(pB, rB, n);
    m.points[0].point = lerp(cA, cB, 0.5f);
    m.points[0].separation = dist - rA - rB;
    m.points[0].id = id;
    m.pointCount = 1;
    return m;
}

// singlePoint computed in `frame` and put in world space, as
// toWorld(singlePoint(...), frame) with the same operations in the same
// order, but written once into the result: the local manifold copied into
// the world one (and that into the contact) was written in 4-byte pieces and
// read back in 16-byte ones, a store-forwarding stall per circle contact.
Manifold singlePointInWorld(Vec2 pA, Vec2 pB, Vec2 n, float dist, float rA, float rB, std::uint16_t id,
                            const Transform& frame) {
    Manifold m;
    m.normal = rotate(frame.q, n);
    const Vec2 cA = mulAdd(pA, rA, n);
    const Vec2 cB = mulSub(pB, rB, n);
    m.points[0].point = transformPoint(frame, lerp(cA, cB, 0.5f));
    m.points[0].separation = dist - rA - rB;
    m.points[0].id = id;
    m.pointCount = 1;
    return m;
}

// Clips the incident segment inc1–inc2 (radius rad2) against the side planes
// of the reference segment ref1–ref2 (radius rad1). `n` is the reference
// normal pointing towards the incident shape and ref2 − ref1 must point along
// leftPerp(n) (true for a CCW polygon edge and its outward normal). Points
// are reported at the midpoint between the surfaces; separation is measured
// along n. `flip` means the reference belongs to B: the manifold normal is
// then −n and ids are written in (A feature, B feature) order.
//
// When the incident segment projects entirely outside the reference range,
// `allowDisjoint` decides between one point at the nearest incident vertex
// (polygons, whose SAT already committed to this face) and no point (the
// capsule caller then falls back to closest points).
void clipSegments(Vec2 ref1, Vec2 ref2, Vec2 n, float rad1, int idRef1, int idRef2, Vec2 inc1, Vec2 inc2, float rad2,
                  int idInc1, int idInc2, bool flip, bool allowDisjoint, float speculativeDistance, Manifold& m) {
    m.pointCount = 0;
    m.normal = flip ? -n : n;
    const Vec2 t = leftPerp(n);
    const float lower1 = 0.0f;
    const float upper1 = dot(ref2 - ref1, t);
    float s1 = dot(inc1 - ref1, t);
    float s2 = dot(inc2 - ref1, t);
    if (s1 > s2) {  // order the incident vertices along the tangent
        Vec2 tv = inc1;
        inc1 = inc2;
        inc2 = tv;
        float ts = s1;
        s1 = s2;
        s2 = ts;
        int ti = idInc1;
        idInc1 = idInc2;
        idInc2 = ti;
    }
    const float radius = rad1 + rad2;
    auto emit = [&](Vec2 v, int idR, int idI) {
        float sep = dot(v - ref1, n);
        if (sep - radius > speculativeDistance) return;
        ManifoldPoint& mp = m.points[m.pointCount++];
        // Midway between the reference surface (ref plane + rad1) and the
        // incident surface (v − rad2 n).
        mp.point = mulAdd(v, 0.5f * (rad1 - rad2 - sep), n);
        mp.separation = sep - radius;
        mp.id = flip ? makeFeatureId(idI, idR) : makeFeatureId(idR, idI);
    };
    if (s2 < lower1 || s1 > upper1) {
        if (!allowDisjoint) return;
        if (s2 < lower1) {
            emit(inc2, idRef1, idInc2);
        } else {
            emit(inc1, idRef2, idInc1);
        }
        return;
    }
    // Sutherland–Hodgman against the two side planes t·x = lower1, upper1.
    Vec2 vLower = inc1;
    Vec2 vUpper = inc2;
    const float span = s2 - s1;
    if (s1 < lower1 && span > FLT_EPSILON) vLower = lerp(inc1, inc2, (lower1 - s1) / span);
    if (s2 > upper1 && span > FLT_EPSILON) vUpper = lerp(inc1, inc2, (upper1 - s1) / span);
    emit(vLower, idRef1, idInc1);
    emit(vUpper, idRef2, idInc2);
}

// Largest separation of poly2 from poly1 over poly1's face normals:
// max_i min_j nᵢ·(v2ⱼ − v1ᵢ). Positive means the face normal separates.
float findMaxSeparation(const Polygon& poly1, const Polygon& poly2, int& edge) {
    float best = -FLT_MAX;
    edge = 0;
    for (int i = 0; i < poly1.count; ++i) {
        Vec2 n = poly1.normals[i];
        Vec2 v = poly1.vertices[i];
        float si = FLT_MAX;
        for (int j = 0; j < poly2.count; ++j) {
            float sij = dot(n, poly2.vertices[j] - v);
            if (sij < si) si = sij;
        }
        if (si > best) {
            best = si;
            edge = i;
        }
    }
    return best;
}

// Exact closest points of two disjoint convex cores: the minimum over every
// (edge, vertex) pair of both polygons of the point–segment distance. Used
// only when SAT has shown the cores are apart; ≤ 2·8·8 cheap tests.
struct ClosestFeatures {
    Vec2 pA{};
    Vec2 pB{};
    float distanceSquared = FLT_MAX;
    int vertexA = 0;
    int vertexB = 0;
};

void closestEdgeVertex(const Polygon& edges, const Polygon& verts, bool edgesAreA, ClosestFeatures& out) {
    for (int i = 0; i < edges.count; ++i) {
        int i2 = i + 1 < edges.count ? i + 1 : 0;
        Vec2 a = edges.vertices[i];
        Vec2 e = edges.vertices[i2] - a;
        float ee = dot(e, e);
        for (int j = 0; j < verts.count; ++j) {
            Vec2 p = verts.vertices[j];
            float t = ee > 0.0f ? clamp(dot(p - a, e) / ee, 0.0f, 1.0f) : 0.0f;
            Vec2 q = mulAdd(a, t, e);
            float dsq = distanceSquared(q, p);
            if (dsq < out.distanceSquared) {
                out.distanceSquared = dsq;
                int edgeVertex = t < 0.5f ? i : i2;
                if (edgesAreA) {
                    out.pA = q;
                    out.pB = p;
                    out.vertexA = edgeVertex;
                    out.vertexB = j;
                } else {
                    out.pA = p;
                    out.pB = q;
                    out.vertexA = j;
                    out.vertexB = edgeVertex;
                }
            }
        }
    }
}

// Smallest distance from a vertex of `verts` to face `edge` of `face` (its
// segment, not its line): an upper bound of the distance between the cores.
float faceDistanceBound(const Polygon& face, int edge, const Polygon& verts) {
    const Vec2 n = face.normals[edge];
    const Vec2 r1 = face.vertices[edge];
    const Vec2 tangent = leftPerp(n);
    const float length = dot(face.vertices[edge + 1 < face.count ? edge + 1 : 0] - r1, tangent);
    float bound = FLT_MAX;
    for (int j = 0; j < verts.count; ++j) {
        const Vec2 d = verts.vertices[j] - r1;
        const float u = dot(d, tangent);
        const float over = u < 0.0f ? -u : (u > length ? u - length : 0.0f);
        const float sn = dot(d, n);
        bound = std::fmin(bound, over == 0.0f ? std::fabs(sn) : std::sqrt(sn * sn + over * over));
    }
    return bound;
}

// Polygon–polygon in A's shifted frame (localA, localB both expressed there).
Manifold collidePolygonsLocal(const Polygon& polyA, const Polygon& polyB, float speculativeDistance) {
    Manifold m;
    int edgeA = 0;
    int edgeB = 0;
    const float separationA = findMaxSeparation(polyA, polyB, edgeA);
    const float separationB = findMaxSeparation(polyB, polyA, edgeB);
    const float radius = polyA.radius + polyB.radius;
    if (separationA > speculativeDistance + radius || separationB > speculativeDistance + radius) return m;

    const bool flip = separationB > separationA + kReferenceTolerance;
    const float separation = flip ? separationB : std::fmax(separationA, separationB);

    // Cores apart: SAT gives a lower bound of their distance; it is the exact
    // distance for a face contact (a vertex over a face) and an underestimate
    // when the closest features are two vertices.
    const bool disjoint = separation > kReferenceTolerance;

    // Reference face and incident edge (the incident edge's normal is the
    // most anti-parallel to the reference normal).
    const Polygon& ref = flip ? polyB : polyA;
    const Polygon& inc = flip ? polyA : polyB;
    const int edgeRef = flip ? edgeB : edgeA;
    const Vec2 n = ref.normals[edgeRef];

    ClosestFeatures cf;
    bool haveClosest = false;
    float dist = 0.0f;
    if (disjoint) {
        // Face contact test first: the distance of any vertex of one polygon
        // to a face segment of the other is an upper bound of the core
        // distance, SAT's separation a lower bound. When a vertex projects onto
        // either polygon's best SAT face (a box on a box, boxes side by side)
        // the two meet and the exact closest features are not needed: 2·4
        // cheap tests for two boxes instead of the 2·4·4 edge–vertex pairs below.
        const float upper = std::fmin(faceDistanceBound(polyA, edgeA, polyB), faceDistanceBound(polyB, edgeB, polyA));
        // Within a millionth: equal for every use below (tolerances of 0.1 slop).
        if (upper <= separation + 1.0e-6f * separation) {
            dist = upper;
        } else {
            closestEdgeVertex(polyA, polyB, true, cf);
            closestEdgeVertex(polyB, polyA, false, cf);
            haveClosest = true;
            dist = std::sqrt(cf.distanceSquared);
        }
        if (dist > speculativeDistance + radius) return m;
    }
    auto vertexContact = [&]() {
        if (!haveClosest) {
            closestEdgeVertex(polyA, polyB, true, cf);
            closestEdgeVertex(polyB, polyA, false, cf);
            dist = std::sqrt(cf.distanceSquared);
        }
        Vec2 nv = (1.0f / dist) * (cf.pB - cf.pA);
        return singlePoint(cf.pA, cf.pB, nv, dist, polyA.radius, polyB.radius, makeFeatureId(cf.vertexA, cf.vertexB));
    };
    if (disjoint && dist > separation + kReferenceTolerance) return vertexContact();
    int edgeInc = 0;
    float minDot = FLT_MAX;
    for (int i = 0; i < inc.count; ++i) {
        float d = dot(n, inc.normals[i]);
        if (d < minDot) {
            minDot = d;
            edgeInc = i;
        }
    }
    const int r1 = edgeRef;
    const int r2 = edgeRef + 1 < ref.count ? edgeRef + 1 : 0;
    const int i1 = edgeInc;
    const int i2 = edgeInc + 1 < inc.count ? edgeInc + 1 : 0;
    clipSegments(ref.vertices[r1], ref.vertices[r2], n, ref.radius, r1, r2, inc.vertices[i1], inc.vertices[i2],
                 inc.radius, i1, i2, flip, true, speculativeDistance, m);
    if (disjoint) {
        // A vertex just past the end of the reference face (within the
        // classification tolerance) can be clipped away, leaving points that
        // overstate the gap; then the exact closest-vertex contact is better.
        float minSep = FLT_MAX;
        for (int i = 0; i < m.pointCount; ++i) minSep = std::fmin(minSep, m.points[i].separation);
        if (m.pointCount == 0 || minSep > dist - radius + kReferenceTolerance) return vertexContact();
    }
    return m;
}

// Shifts polygon A so its first vertex is the origin and maps B into that
// frame; returns the shifted frame used to bring the result back to world.
Transform shiftedPair(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB, Polygon& localA,
                      Polygon& localB) {
    const Vec2 origin = a.vertices[0];
    const Transform frame{xfA.p + rotate(xfA.q, origin), xfA.q};
    const Transform xf = invMulTransforms(frame, xfB);
    localA = a;
    for (int i = 0; i < a.count; ++i) localA.vertices[i] = a.vertices[i] - origin;
    localA.centroid = a.centroid - origin;
    localB = b;
    for (int i = 0; i < b.count; ++i) {
        localB.vertices[i] = transformPoint(xf, b.vertices[i]);
        localB.normals[i] = rotate(xf.q, b.normals[i]);
    }
    localB.centroid = transformPoint(xf, b.centroid);
    return frame;
}

Manifold collidePolygonsImpl(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                             float speculativeDistance) {
    Polygon localA;
    Polygon localB;
    const Transform frame = shiftedPair(a, xfA, b, xfB, localA, localB);
    return toWorld(collidePolygonsLocal(localA, localB, speculativeDistance), frame);
}

// A segment p1–p2 with a radius as a two-vertex polygon: edge 0 (p1→p2) and
// edge 1 (p2→p1) with opposite normals. Requires p1 ≠ p2.
Polygon makeCapsulePolygon(Vec2 p1, Vec2 p2, float radius) {
    Polygon poly;
    poly.count = 2;
    poly.vertices[0] = p1;
    poly.vertices[1] = p2;
    poly.normals[0] = normalize(rightPerp(p2 - p1));
    poly.normals[1] = -poly.normals[0];
    poly.centroid = lerp(p1, p2, 0.5f);
    poly.radius = radius;
    return poly;
}

bool isDegenerateSegment(Vec2 p1, Vec2 p2) {
    // normalize() treats lengths below 1e-12 as zero; stay well above that.
    return lengthSquared(p2 - p1) < 1.0e-12f;
}

// Closest points between segments p1–q1 and p2–q2 (Ericson, Real-Time
// Collision Detection §5.1.9): minimise |p1 + s d1 − p2 − t d2|² over the
// unit square, clamping s then recomputing t (and s again if t clamps).
struct SegmentDistanceResult {
    Vec2 closest1{};
    Vec2 closest2{};
    float distanceSquared = 0.0f;
};

SegmentDistanceResult segmentDistance(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2) {
    Vec2 d1 = q1 - p1;
    Vec2 d2 = q2 - p2;
    Vec2 r = p1 - p2;
    float a = dot(d1, d1);
    float e = dot(d2, d2);
    float f = dot(d2, r);
    float s = 0.0f;
    float t = 0.0f;
    constexpr float kEps = 1.0e-12f;
    if (a <= kEps && e <= kEps) {
        // both points
    } else if (a <= kEps) {
        t = clamp(f / e, 0.0f, 1.0f);
    } else {
        float c = dot(d1, r);
        if (e <= kEps) {
            s = clamp(-c / a, 0.0f, 1.0f);
        } else {
            float b = dot(d1, d2);
            float denom = a * e - b * b;
            s = denom > 0.0f ? clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
            t = (b * s + f) / e;
            if (t < 0.0f) {
                t = 0.0f;
                s = clamp(-c / a, 0.0f, 1.0f);
            } else if (t > 1.0f) {
                t = 1.0f;
                s = clamp((b - c) / a, 0.0f, 1.0f);
            }
        }
    }
    SegmentDistanceResult res;
    res.closest1 = mulAdd(p1, s, d1);
    res.closest2 = mulAdd(p2, t, d2);
    res.distanceSquared = distanceSquared(res.closest1, res.closest2);
    return res;
}

// Capsule–capsule in A's frame (segments p1–q1 radius rA, p2–q2 radius rB).
Manifold collideCapsulesLocal(Vec2 p1, Vec2 q1, float rA, Vec2 p2, Vec2 q2, float rB, float speculativeDistance) {
    Manifold m;
    const SegmentDistanceResult sd = segmentDistance(p1, q1, p2, q2);
    const float maxDistance = rA + rB + speculativeDistance;
    if (sd.distanceSquared > maxDistance * maxDistance) return m;
    const float dist = std::sqrt(sd.distanceSquared);

    const Vec2 e1 = q1 - p1;
    const Vec2 e2 = q2 - p2;
    const bool segA = !isDegenerateSegment(p1, q1);
    const bool segB = !isDegenerateSegment(p2, q2);

    // Normal for the closest-point contact; when the cores touch or cross it
    // is undefined, so take a segment perpendicular on the side of the other
    // shape's centre (see the degenerate-case list at the top).
    Vec2 nClosest{};
    bool haveClosest = dist > kReferenceTolerance;
    if (haveClosest) {
        nClosest = (1.0f / dist) * (sd.closest2 - sd.closest1);
    } else if (segA) {
        Vec2 n = normalize(leftPerp(e1));
        nClosest = dot(n, lerp(p2, q2, 0.5f) - p1) >= 0.0f ? n : -n;
    } else if (segB) {
        Vec2 n = normalize(leftPerp(e2));
        nClosest = dot(n, lerp(p1, q1, 0.5f) - p2) <= 0.0f ? n : -n;
    } else {
        nClosest = {0.0f, 1.0f};
    }

    if (segA && segB) {
        const Vec2 nA = normalize(leftPerp(e1));
        const Vec2 nB = normalize(leftPerp(e2));
        float alignA = dot(nClosest, nA);
        float alignB = dot(nClosest, nB);
        if (!haveClosest) {
            alignA = alignA >= 0.0f ? 1.0f : -1.0f;  // crossing: A is the reference
            alignB = 0.0f;
        }
        if (std::fmax(std::fabs(alignA), std::fabs(alignB)) >= kCapsuleFaceAlignment) {
            // Face contact: clip the other segment against the better-aligned
            // one; A is preferred within a small tolerance for stable ids.
            if (std::fabs(alignA) >= std::fabs(alignB) - 1.0e-3f) {
                Vec2 n = alignA >= 0.0f ? nA : -nA;  // A → B
                // ref2 − ref1 must point along leftPerp(n).
                bool forward = dot(e1, leftPerp(n)) > 0.0f;
                clipSegments(forward ? p1 : q1, forward ? q1 : p1, n, rA, forward ? 0 : 1, forward ? 1 : 0, p2, q2, rB,
                             0, 1, false, false, speculativeDistance, m);
            } else {
                Vec2 n = alignB >= 0.0f ? -nB : nB;  // B → A (reference is B)
                bool forward = dot(e2, leftPerp(n)) > 0.0f;
                clipSegments(forward ? p2 : q2, forward ? q2 : p2, n, rB, forward ? 0 : 1, forward ? 1 : 0, p1, q1, rA,
                             0, 1, true, false, speculativeDistance, m);
            }
            // Keep the clipped manifold only if its deepest point agrees with
            // the exact closest-point gap; the clip can cut away the closest
            // point when it lies just past the end of the reference segment.
            float minSep = FLT_MAX;
            for (int i = 0; i < m.pointCount; ++i) minSep = std::fmin(minSep, m.points[i].separation);
            if (m.pointCount > 0 && minSep <= dist - rA - rB + kReferenceTolerance) return m;
            m.pointCount = 0;
        }
    }
    return singlePoint(sd.closest1, sd.closest2, nClosest, dist, rA, rB, 0);
}

}  // namespace

Manifold collideCircles(const Circle& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                        float speculativeDistance) {
    Manifold m;
    detail::writeCircleManifold(a, xfA, b, xfB, speculativeDistance, m);
    return m;
}

Manifold collideCapsuleAndCircle(const Capsule& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                                 float speculativeDistance) {
    const Transform xf = invMulTransforms(xfA, xfB);
    const Vec2 c = transformPoint(xf, b.center);
    const Vec2 e = a.center2 - a.center1;
    const float ee = dot(e, e);
    // Closest point of the core segment to the circle centre.
    const float t = ee > 0.0f ? clamp(dot(c - a.center1, e) / ee, 0.0f, 1.0f) : 0.0f;
    const Vec2 pA = mulAdd(a.center1, t, e);
    float dist = 0.0f;
    Vec2 n = normalize(c - pA, dist);
    if (dist - a.radius - b.radius > speculativeDistance) return {};
    if (n.x == 0.0f && n.y == 0.0f) {
        n = isDegenerateSegment(a.center1, a.center2) ? Vec2{0.0f, 1.0f} : normalize(leftPerp(e));
        dist = 0.0f;
    }
    return singlePointInWorld(pA, c, n, dist, a.radius, b.radius, 0, xfA);
}

Manifold collideCapsules(const Capsule& a, const Transform& xfA, const Capsule& b, const Transform& xfB,
                         float speculativeDistance) {
    const Vec2 origin = a.center1;
    const Transform frame{xfA.p + rotate(xfA.q, origin), xfA.q};
    const Transform xf = invMulTransforms(frame, xfB);
    const Vec2 p1{};
    const Vec2 q1 = a.center2 - origin;
    const Vec2 p2 = transformPoint(xf, b.center1);
    const Vec2 q2 = transformPoint(xf, b.center2);
    return toWorld(collideCapsulesLocal(p1, q1, a.radius, p2, q2, b.radius, speculativeDistance), frame);
}

Manifold collidePolygonAndCircle(const Polygon& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                                 float speculativeDistance) {
    const Transform xf = invMulTransforms(xfA, xfB);
    const Vec2 c = transformPoint(xf, b.center);
    const float radius = a.radius + b.radius;

    // Face of maximum separation of the centre.
    int normalIndex = 0;
    float separation = -FLT_MAX;
    for (int i = 0; i < a.count; ++i) {
        float s = dot(a.normals[i], c - a.vertices[i]);
        if (s > separation) {
            separation = s;
            normalIndex = i;
        }
    }
    if (separation - radius > speculativeDistance) return {};

    const int i1 = normalIndex;
    const int i2 = i1 + 1 < a.count ? i1 + 1 : 0;
    const Vec2 v1 = a.vertices[i1];
    const Vec2 v2 = a.vertices[i2];
    // Voronoi regions of the face's end vertices (only meaningful with the
    // centre outside the core; inside, the face itself is the answer).
    const float u1 = dot(c - v1, v2 - v1);
    const float u2 = dot(c - v2, v1 - v2);
    if ((u1 < 0.0f || u2 < 0.0f) && separation > FLT_EPSILON) {
        const Vec2 v = u1 < 0.0f ? v1 : v2;
        float dist = 0.0f;
        Vec2 n = normalize(c - v, dist);
        if (dist - radius > speculativeDistance) return {};
        return singlePointInWorld(v, c, n, dist, a.radius, b.radius, 0, xfA);
    }
    // Face region: the core point is the projection of the centre on the face.
    const Vec2 n = a.normals[i1];
    const Vec2 pA = mulSub(c, separation, n);
    return singlePointInWorld(pA, c, n, separation, a.radius, b.radius, 0, xfA);
}

Manifold collidePolygonAndCapsule(const Polygon& a, const Transform& xfA, const Capsule& b, const Transform& xfB,
                                  float speculativeDistance) {
    if (isDegenerateSegment(b.center1, b.center2)) {
        return collidePolygonAndCircle(a, xfA, Circle{b.center1, b.radius}, xfB, speculativeDistance);
    }
    return collidePolygonsImpl(a, xfA, makeCapsulePolygon(b.center1, b.center2, b.radius), xfB, speculativeDistance);
}

Manifold collidePolygons(const Polygon& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                         float speculativeDistance) {
    return collidePolygonsImpl(a, xfA, b, xfB, speculativeDistance);
}

Manifold collideSegmentAndCircle(const Segment& a, const Transform& xfA, const Circle& b, const Transform& xfB,
                                 float speculativeDistance) {
    return collideCapsuleAndCircle(Capsule{a.point1, a.point2, 0.0f}, xfA, b, xfB, speculativeDistance);
}

Manifold collideSegmentAndCapsule(const Segment& a, const Transform& xfA, const Capsule& b, const Transform& xfB,
                                  float speculativeDistance) {
    return collideCapsules(Capsule{a.point1, a.point2, 0.0f}, xfA, b, xfB, speculativeDistance);
}

Manifold collideSegmentAndPolygon(const Segment& a, const Transform& xfA, const Polygon& b, const Transform& xfB,
                                  float speculativeDistance) {
    if (isDegenerateSegment(a.point1, a.point2)) {
        // Polygon against a point (circle of radius 0), then swap A and B.
        Manifold m = collidePolygonAndCircle(b, xfB, Circle{a.point1, 0.0f}, xfA, speculativeDistance);
        m.normal = -m.normal;
        return m;
    }
    return collidePolygonsImpl(makeCapsulePolygon(a.point1, a.point2, 0.0f), xfA, b, xfB, speculativeDistance);
}

}  // namespace i2d
