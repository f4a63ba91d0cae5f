// Impulse2D — shape geometry: convex hull, polygon construction, mass
// properties, bounding boxes, ray casts and point-in-shape tests.
//
// Everything here works on fixed-size arrays (at most kMaxPolygonVertices
// points) and never allocates.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>

#include "impulse2d/error.hpp"
#include "impulse2d/geometry.hpp"

namespace i2d {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// ---------------------------------------------------------------------------
// Convex hull (quickhull)
// ---------------------------------------------------------------------------

// Signed distance of p to the right of the directed line a→b (positive = right).
// The line direction is normalised so that the slop comparisons are in metres.
float rightDistance(Vec2 a, Vec2 b, Vec2 p) {
    Vec2 e = normalize(b - a);
    return cross(p - a, e);
}

// Quickhull recursion: appends to `out`, in order from a to b (exclusive of
// both), the hull vertices lying to the right of a→b among `pts`. Each level
// takes the farthest point c, which is certainly on the hull, and recurses on
// the points outside the two new edges a→c and c→b; points inside triangle
// a-c-b are discarded. Points within kLinearSlop of an edge are dropped as
// collinear. Depth is bounded by the point count (≤ 8).
void hullRecurse(Vec2 a, Vec2 b, const Vec2* pts, int count, Vec2* out, int& outCount) {
    if (count == 0) return;
    int best = -1;
    float bestDistance = kLinearSlop;
    for (int i = 0; i < count; ++i) {
        float d = rightDistance(a, b, pts[i]);
        if (d > bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    if (best < 0) return;
    Vec2 c = pts[best];
    Vec2 right1[kMaxPolygonVertices];
    Vec2 right2[kMaxPolygonVertices];
    int n1 = 0;
    int n2 = 0;
    for (int i = 0; i < count; ++i) {
        if (i == best) continue;
        if (rightDistance(a, c, pts[i]) > kLinearSlop) {
            right1[n1++] = pts[i];
        } else if (rightDistance(c, b, pts[i]) > kLinearSlop) {
            right2[n2++] = pts[i];
        }
    }
    hullRecurse(a, c, right1, n1, out, outCount);
    out[outCount++] = c;
    hullRecurse(c, b, right2, n2, out, outCount);
}

// Area-weighted integrals of a simple CCW polygon about the origin:
// area A = ½ Σ cᵢ, first moment S = ⅙ Σ cᵢ (pᵢ + pᵢ₊₁),
// polar second moment J = ∫|x|² dA = (1/12) Σ cᵢ (pᵢ·pᵢ + pᵢ·pᵢ₊₁ + pᵢ₊₁·pᵢ₊₁),
// with cᵢ = pᵢ × pᵢ₊₁ (Green's theorem / triangle fan from the origin).
struct AreaMoments {
    float area = 0.0f;
    Vec2 first{};
    float second = 0.0f;
};

AreaMoments polygonMoments(const Vec2* p, int count) {
    AreaMoments m;
    for (int i = 0; i < count; ++i) {
        Vec2 a = p[i];
        Vec2 b = p[i + 1 < count ? i + 1 : 0];
        float c = cross(a, b);
        m.area += 0.5f * c;
        m.first += (c / 6.0f) * (a + b);
        m.second += (c / 12.0f) * (dot(a, a) + dot(a, b) + dot(b, b));
    }
    return m;
}

void addMoments(AreaMoments& total, const AreaMoments& part) {
    total.area += part.area;
    total.first += part.first;
    total.second += part.second;
}

// First entry of the ray into the disk (center, radius); the ray origin is
// known to be outside. Solves |o + t d − c|² = r² for the smaller root.
std::optional<RayHit> rayCastDisk(const RayCastInput& in, Vec2 center, float radius) {
    Vec2 s = in.origin - center;
    Vec2 d = in.translation;
    float dd = dot(d, d);
    if (dd <= 0.0f) return std::nullopt;
    float b = dot(s, d);
    float c = dot(s, s) - radius * radius;
    float disc = b * b - dd * c;
    if (disc < 0.0f) return std::nullopt;
    float t = (-b - std::sqrt(disc)) / dd;
    if (t < 0.0f || t > in.maxFraction) return std::nullopt;
    RayHit hit;
    hit.fraction = t;
    hit.point = mulAdd(in.origin, t, d);
    hit.normal = normalize(hit.point - center);
    return hit;
}

// Ray against the segment a–b, seen from either side. The normal faces the
// ray (opposite to its direction). Parallel rays never hit.
std::optional<RayHit> rayCastSegmentImpl(const RayCastInput& in, Vec2 a, Vec2 b) {
    Vec2 d = in.translation;
    Vec2 e = b - a;
    float denom = cross(d, e);
    if (std::fabs(denom) <= FLT_EPSILON * length(d) * length(e)) return std::nullopt;
    Vec2 ao = a - in.origin;
    // o + t d = a + s e  ⇒  t = (a−o)×e / d×e,  s = (a−o)×d / d×e.
    float t = cross(ao, e) / denom;
    float s = cross(ao, d) / denom;
    if (t < 0.0f || t > in.maxFraction || s < 0.0f || s > 1.0f) return std::nullopt;
    RayHit hit;
    hit.fraction = t;
    hit.point = mulAdd(in.origin, t, d);
    Vec2 n = normalize(rightPerp(e));
    hit.normal = dot(n, d) > 0.0f ? -n : n;
    return hit;
}

void keepEarliest(std::optional<RayHit>& best, const std::optional<RayHit>& candidate) {
    if (candidate && (!best || candidate->fraction < best->fraction)) best = candidate;
}

// Squared distance from p to the segment a–b.
float segmentDistanceSquared(Vec2 a, Vec2 b, Vec2 p) {
    Vec2 e = b - a;
    float ee = dot(e, e);
    float t = ee > 0.0f ? clamp(dot(p - a, e) / ee, 0.0f, 1.0f) : 0.0f;
    return distanceSquared(mulAdd(a, t, e), p);
}

bool validRay(const RayCastInput& in) {
    return isFinite(in.origin) && isFinite(in.translation) && isFinite(in.maxFraction) && in.maxFraction >= 0.0f &&
           lengthSquared(in.translation) > 0.0f;
}

}  // namespace

Hull computeHull(std::span<const Vec2> points) {
    Hull hull;
    if (points.size() < 3 || points.size() > static_cast<std::size_t>(kMaxPolygonVertices)) return hull;

    // Weld: keep a point only if it is at least kLinearSlop from every kept point.
    Vec2 ps[kMaxPolygonVertices];
    int n = 0;
    const float weldSq = kLinearSlop * kLinearSlop;
    for (Vec2 p : points) {
        if (!isFinite(p)) return hull;
        bool unique = true;
        for (int j = 0; j < n; ++j) {
            if (distanceSquared(p, ps[j]) < weldSq) {
                unique = false;
                break;
            }
        }
        if (unique) ps[n++] = p;
    }
    if (n < 3) return hull;

    // Extreme points along the cloud's longer axis: lowest x (ties: lowest y)
    // and highest x (ties: highest y), or the same in y when the cloud is
    // taller than wide. Both are hull vertices, and the line between them
    // splits the cloud. Along the shorter axis a point within kLinearSlop of
    // that line could lie beyond its ends and be dropped as collinear (found
    // by fuzz_hull: a 0.2 m × 13 600 m sliver lost a corner 0.14 m outside).
    Vec2 lo = ps[0];
    Vec2 hi = ps[0];
    for (int i = 1; i < n; ++i) {
        lo = {std::min(lo.x, ps[i].x), std::min(lo.y, ps[i].y)};
        hi = {std::max(hi.x, ps[i].x), std::max(hi.y, ps[i].y)};
    }
    const bool alongY = hi.y - lo.y > hi.x - lo.x;
    auto before = [alongY](Vec2 a, Vec2 b) {
        if (alongY) return a.y < b.y || (a.y == b.y && a.x > b.x);
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    };
    int i1 = 0;
    int i2 = 0;
    for (int i = 1; i < n; ++i) {
        if (before(ps[i], ps[i1])) i1 = i;
        if (before(ps[i2], ps[i])) i2 = i;
    }
    Vec2 p1 = ps[i1];
    Vec2 p2 = ps[i2];
    Vec2 right[kMaxPolygonVertices];
    Vec2 left[kMaxPolygonVertices];
    int nr = 0;
    int nl = 0;
    for (int i = 0; i < n; ++i) {
        if (i == i1 || i == i2) continue;
        float d = rightDistance(p1, p2, ps[i]);
        if (d > kLinearSlop) {
            right[nr++] = ps[i];
        } else if (d < -kLinearSlop) {
            left[nl++] = ps[i];
        }
    }

    // Counter-clockwise: p1 → points right of p1→p2 → p2 → points right of p2→p1.
    Vec2 out[kMaxPolygonVertices];
    int m = 0;
    out[m++] = p1;
    hullRecurse(p1, p2, right, nr, out, m);
    out[m++] = p2;
    hullRecurse(p2, p1, left, nl, out, m);

    // Drop vertices within kLinearSlop of the line through their neighbours
    // (collinear within tolerance), repeating until none is removed.
    bool removed = true;
    while (removed && m >= 3) {
        removed = false;
        for (int i = 0; i < m; ++i) {
            Vec2 a = out[(i + m - 1) % m];
            Vec2 b = out[(i + 1) % m];
            if (rightDistance(a, b, out[i]) < kLinearSlop) {
                for (int j = i; j + 1 < m; ++j) out[j] = out[j + 1];
                --m;
                removed = true;
                break;
            }
        }
    }
    if (m < 3) return hull;
    for (int i = 0; i < m; ++i) hull.points[i] = out[i];
    hull.count = m;
    return hull;
}

std::optional<Polygon> makePolygon(const Hull& hull, float radius) {
    if (!isFinite(radius) || radius < 0.0f) return std::nullopt;
    const int n = hull.count;
    if (n < 3 || n > kMaxPolygonVertices) return std::nullopt;
    Polygon poly;
    poly.count = n;
    poly.radius = radius;
    for (int i = 0; i < n; ++i) {
        if (!isFinite(hull.points[i])) return std::nullopt;
        poly.vertices[i] = hull.points[i];
    }
    for (int i = 0; i < n; ++i) {
        Vec2 e = poly.vertices[i + 1 < n ? i + 1 : 0] - poly.vertices[i];
        float len = 0.0f;
        // Outward normal of a CCW edge is the clockwise perpendicular.
        poly.normals[i] = normalize(rightPerp(e), len);
        if (len <= 0.0f) return std::nullopt;
    }
    // Strict convexity: every other vertex lies strictly inside each edge.
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            if (j == i || j == (i + 1) % n) continue;
            if (dot(poly.normals[i], poly.vertices[j] - poly.vertices[i]) >= 0.0f) return std::nullopt;
        }
    }
    // Centroid of the core polygon, computed about the first vertex to keep
    // the products small (round-off) far from the body origin.
    Vec2 local[kMaxPolygonVertices];
    for (int i = 0; i < n; ++i) local[i] = poly.vertices[i] - poly.vertices[0];
    AreaMoments m = polygonMoments(local, n);
    if (!(m.area > 0.0f)) return std::nullopt;
    poly.centroid = poly.vertices[0] + (1.0f / m.area) * m.first;
    return poly;
}

Polygon makeOffsetBox(float hx, float hy, Vec2 center, float angle) {
    if (!isFinite(hx) || !isFinite(hy) || !(hx > 0.0f) || !(hy > 0.0f))
        throw Error("makeBox: half-extents must be finite and positive");
    if (!isFinite(center) || !isFinite(angle)) throw Error("makeOffsetBox: centre and angle must be finite");
    Rot q = makeRot(angle);
    Polygon box;
    box.count = 4;
    const Vec2 v[4] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    const Vec2 n[4] = {{0.0f, -1.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {-1.0f, 0.0f}};
    for (int i = 0; i < 4; ++i) {
        box.vertices[i] = rotate(q, v[i]) + center;
        box.normals[i] = rotate(q, n[i]);
    }
    box.centroid = center;
    return box;
}

Polygon makeBox(float hx, float hy) {
    if (!isFinite(hx) || !isFinite(hy) || !(hx > 0.0f) || !(hy > 0.0f))
        throw Error("makeBox: half-extents must be finite and positive");
    Polygon box;
    box.count = 4;
    box.vertices[0] = {-hx, -hy};
    box.vertices[1] = {hx, -hy};
    box.vertices[2] = {hx, hy};
    box.vertices[3] = {-hx, hy};
    box.normals[0] = {0.0f, -1.0f};
    box.normals[1] = {1.0f, 0.0f};
    box.normals[2] = {0.0f, 1.0f};
    box.normals[3] = {-1.0f, 0.0f};
    return box;
}

Polygon makeRoundedBox(float hx, float hy, float radius) {
    if (!isFinite(radius) || radius < 0.0f) throw Error("makeRoundedBox: radius must be finite and non-negative");
    Polygon box = makeBox(hx, hy);
    box.radius = radius;
    return box;
}

MassData computeMass(const Circle& shape, float density) {
    if (!isFinite(density) || density < 0.0f) throw Error("computeMass: density must be finite and non-negative");
    if (!(shape.radius >= 0.0f) || !isFinite(shape.radius) || !isFinite(shape.center))
        throw Error("computeMass: circle radius must be finite and non-negative, its centre finite");
    // Solid disk: m = ρπr², I = ½ m r² about its centre.
    float rr = shape.radius * shape.radius;
    MassData md;
    md.mass = density * kPi * rr;
    md.center = shape.center;
    md.rotationalInertia = 0.5f * md.mass * rr;
    return md;
}

MassData computeMass(const Capsule& shape, float density) {
    if (!isFinite(density) || density < 0.0f) throw Error("computeMass: density must be finite and non-negative");
    if (!(shape.radius >= 0.0f) || !isFinite(shape.radius) || !isFinite(shape.center1) || !isFinite(shape.center2))
        throw Error("computeMass: capsule radius must be finite and non-negative, its centres finite");
    // Rectangle L × 2r plus two half-disks of radius r at the ends.
    float r = shape.radius;
    float L = length(shape.center2 - shape.center1);
    float boxMass = density * (2.0f * r * L);
    float diskMass = density * kPi * r * r;  // both half-disks together
    MassData md;
    md.mass = boxMass + diskMass;
    md.center = lerp(shape.center1, shape.center2, 0.5f);
    // Rectangle about its centre: m (L² + (2r)²) / 12.
    float boxInertia = boxMass * (L * L + 4.0f * r * r) / 12.0f;
    // Each half-disk (mass mh = diskMass/2): inertia about the centre of its
    // flat side is ½ mh r²; its centroid lies d = 4r/(3π) from that side.
    // Parallel-axis theorem twice (to the half-disk centroid, then to the
    // capsule centre at distance L/2 + d): I = mh (½r² − d² + (L/2 + d)²).
    float d = 4.0f * r / (3.0f * kPi);
    float halfL = 0.5f * L;
    float capInertia = diskMass * (0.5f * r * r - d * d + (halfL + d) * (halfL + d));
    md.rotationalInertia = boxInertia + capInertia;
    return md;
}

MassData computeMass(const Polygon& shape, float density) {
    if (!isFinite(density) || density < 0.0f) throw Error("computeMass: density must be finite and non-negative");
    const int n = shape.count;
    if (n < 3 || n > kMaxPolygonVertices) throw Error("computeMass: polygon must have 3 to 8 vertices");
    // Integrate about a reference point inside the polygon (its first vertex
    // shifted to the vertex average) so the moments stay well conditioned for
    // shapes far from the body origin.
    Vec2 ref{};
    for (int i = 0; i < n; ++i) ref += shape.vertices[i];
    ref = (1.0f / static_cast<float>(n)) * ref;
    Vec2 v[kMaxPolygonVertices];
    for (int i = 0; i < n; ++i) v[i] = shape.vertices[i] - ref;

    // Core polygon: triangle fan (Green's theorem).
    AreaMoments total = polygonMoments(v, n);

    const float r = shape.radius;
    if (r > 0.0f) {
        // The rounded polygon is the core plus, for each edge, a rectangle of
        // width r swept outward along the edge normal, plus, at each vertex,
        // a circular sector of radius r between the normals of its two edges.
        // The sector angles sum to 2π, so together they form one disk.
        for (int i = 0; i < n; ++i) {
            int j = i + 1 < n ? i + 1 : 0;
            Vec2 off = r * shape.normals[i];
            Vec2 rect[4] = {v[i] + off, v[i], v[j], v[j] + off};
            // rect is listed clockwise (outer side first); reverse for CCW.
            Vec2 ccw[4] = {rect[3], rect[2], rect[1], rect[0]};
            addMoments(total, polygonMoments(ccw, 4));
        }
        for (int i = 0; i < n; ++i) {
            Vec2 nPrev = shape.normals[i > 0 ? i - 1 : n - 1];
            Vec2 nNext = shape.normals[i];
            // Sector angle θ between the adjacent outward normals.
            float theta = std::atan2(cross(nPrev, nNext), dot(nPrev, nNext));
            if (theta <= 0.0f) continue;
            float half = 0.5f * theta;
            float area = half * r * r;
            // Centroid of a sector: distance 2r sin(θ/2) / (3·θ/2) along the bisector.
            Vec2 bisector = normalize(nPrev + nNext);
            Vec2 c = mulAdd(v[i], 2.0f * r * std::sin(half) / (3.0f * half), bisector);
            // Polar moment about the apex: θ r⁴ / 4; shifted to the origin:
            // ∫|v + x|² = J_apex + 2 v·∫x + |v|² A.
            float jApex = 0.25f * theta * r * r * r * r;
            AreaMoments s;
            s.area = area;
            s.first = area * c;
            s.second = jApex + 2.0f * dot(v[i], area * (c - v[i])) + dot(v[i], v[i]) * area;
            addMoments(total, s);
        }
    }

    MassData md;
    if (!(total.area > 0.0f)) throw Error("computeMass: polygon has no area");
    Vec2 centerLocal = (1.0f / total.area) * total.first;
    md.mass = density * total.area;
    md.center = centerLocal + ref;
    // Inertia about the centre of mass: ρ (J_ref − A |c_ref|²).
    md.rotationalInertia = density * (total.second - total.area * dot(centerLocal, centerLocal));
    return md;
}

AABB computeAABB(const Circle& shape, const Transform& xf) {
    Vec2 p = transformPoint(xf, shape.center);
    Vec2 r{shape.radius, shape.radius};
    return {p - r, p + r};
}

AABB computeAABB(const Capsule& shape, const Transform& xf) {
    Vec2 a = transformPoint(xf, shape.center1);
    Vec2 b = transformPoint(xf, shape.center2);
    Vec2 r{shape.radius, shape.radius};
    return {min(a, b) - r, max(a, b) + r};
}

AABB computeAABB(const Polygon& shape, const Transform& xf) {
    Vec2 lo = transformPoint(xf, shape.vertices[0]);
    Vec2 hi = lo;
    for (int i = 1; i < shape.count; ++i) {
        Vec2 v = transformPoint(xf, shape.vertices[i]);
        lo = min(lo, v);
        hi = max(hi, v);
    }
    Vec2 r{shape.radius, shape.radius};
    return {lo - r, hi + r};
}

AABB computeAABB(const Segment& shape, const Transform& xf) {
    Vec2 a = transformPoint(xf, shape.point1);
    Vec2 b = transformPoint(xf, shape.point2);
    return {min(a, b), max(a, b)};
}

std::optional<RayHit> rayCast(const RayCastInput& input, const Circle& shape) {
    if (!validRay(input)) return std::nullopt;
    if (containsPoint(shape, input.origin)) return std::nullopt;
    return rayCastDisk(input, shape.center, shape.radius);
}

std::optional<RayHit> rayCast(const RayCastInput& input, const Capsule& shape) {
    if (!validRay(input)) return std::nullopt;
    if (containsPoint(shape, input.origin)) return std::nullopt;
    // The origin is outside the (convex) capsule, so the earliest contact of
    // the ray with any piece of it — the two end disks and the two flat sides
    // — is the entry point.
    std::optional<RayHit> best = rayCastDisk(input, shape.center1, shape.radius);
    keepEarliest(best, rayCastDisk(input, shape.center2, shape.radius));
    Vec2 e = shape.center2 - shape.center1;
    if (lengthSquared(e) > 0.0f) {
        Vec2 n = normalize(rightPerp(e));
        Vec2 off = shape.radius * n;
        keepEarliest(best, rayCastSegmentImpl(input, shape.center1 + off, shape.center2 + off));
        keepEarliest(best, rayCastSegmentImpl(input, shape.center1 - off, shape.center2 - off));
    }
    return best;
}

std::optional<RayHit> rayCast(const RayCastInput& input, const Polygon& shape) {
    if (!validRay(input)) return std::nullopt;
    const int n = shape.count;
    if (shape.radius > 0.0f) {
        if (containsPoint(shape, input.origin)) return std::nullopt;
        // Rounded polygon = offset edges + vertex disks; as for the capsule,
        // the earliest contact with any piece is the entry point.
        std::optional<RayHit> best;
        for (int i = 0; i < n; ++i) {
            int j = i + 1 < n ? i + 1 : 0;
            Vec2 off = shape.radius * shape.normals[i];
            keepEarliest(best, rayCastSegmentImpl(input, shape.vertices[i] + off, shape.vertices[j] + off));
            keepEarliest(best, rayCastDisk(input, shape.vertices[i], shape.radius));
        }
        return best;
    }
    // Sharp polygon: Cyrus–Beck clipping of the parameter interval
    // [lower, upper] against each half-plane n·(x − vᵢ) ≤ 0. The entry is the
    // last entering plane; when no plane is entering (origin inside or on the
    // boundary) there is no hit.
    float lower = 0.0f;
    float upper = input.maxFraction;
    int index = -1;
    for (int i = 0; i < n; ++i) {
        float numerator = dot(shape.normals[i], shape.vertices[i] - input.origin);
        float denominator = dot(shape.normals[i], input.translation);
        if (denominator == 0.0f) {
            if (numerator < 0.0f) return std::nullopt;  // parallel and outside this plane
        } else if (denominator < 0.0f && numerator < lower * denominator) {
            lower = numerator / denominator;  // entering: the interval starts later
            index = i;
        } else if (denominator > 0.0f && numerator < upper * denominator) {
            upper = numerator / denominator;  // leaving: the interval ends earlier
        }
        if (upper < lower) return std::nullopt;
    }
    if (index < 0) return std::nullopt;
    RayHit hit;
    hit.fraction = lower;
    hit.normal = shape.normals[index];
    hit.point = mulAdd(input.origin, lower, input.translation);
    return hit;
}

std::optional<RayHit> rayCast(const RayCastInput& input, const Segment& shape) {
    if (!validRay(input)) return std::nullopt;
    return rayCastSegmentImpl(input, shape.point1, shape.point2);
}

bool containsPoint(const Circle& shape, Vec2 p) {
    return distanceSquared(shape.center, p) <= shape.radius * shape.radius;
}

bool containsPoint(const Capsule& shape, Vec2 p) {
    return segmentDistanceSquared(shape.center1, shape.center2, p) <= shape.radius * shape.radius;
}

bool containsPoint(const Polygon& shape, Vec2 p) {
    const int n = shape.count;
    bool insideCore = true;
    for (int i = 0; i < n; ++i) {
        if (dot(shape.normals[i], p - shape.vertices[i]) > 0.0f) {
            insideCore = false;
            break;
        }
    }
    if (insideCore) return true;
    if (shape.radius <= 0.0f) return false;
    // Outside the core: inside the rounded shape iff within radius of the core
    // boundary, whose nearest point lies on one of the edges.
    float best = FLT_MAX;
    for (int i = 0; i < n; ++i) {
        best = std::min(best, segmentDistanceSquared(shape.vertices[i], shape.vertices[i + 1 < n ? i + 1 : 0], p));
    }
    return best <= shape.radius * shape.radius;
}

}  // namespace i2d
