// Fuzz target: every collider pair of the narrowphase (circle, capsule,
// polygon, rounded polygon; segment as shape A) and the GJK distance. For
// any finite shapes and transforms a manifold has 0–2 finite points, a unit
// normal, separations no larger than the speculative distance; the distance
// is finite and non-negative.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"

using namespace i2d;

namespace {

enum Kind { kCircle, kCapsule, kPolygon, kSegment };

struct AnyShape {
    Kind kind = kCircle;
    Circle circle{};
    Capsule capsule{};
    Polygon polygon{};
    Segment segment{};
};

float size(fuzz::ByteReader& in) { return in.real(0.01f, 5.0f); }
Vec2 point(fuzz::ByteReader& in, float r) { return {in.real(-r, r), in.real(-r, r)}; }

AnyShape makeShape(fuzz::ByteReader& in, Kind kind) {
    AnyShape s;
    s.kind = kind;
    switch (kind) {
        case kCircle: s.circle = {point(in, 2.0f), size(in)}; break;
        case kCapsule: {
            Vec2 c1 = point(in, 3.0f);
            Vec2 c2 = point(in, 3.0f);
            if (distance(c1, c2) < 2.0f * kLinearSlop) c2 = c1 + Vec2{1.0f, 0.0f};
            s.capsule = {c1, c2, size(in)};
            break;
        }
        case kPolygon: {
            std::vector<Vec2> pts;
            int n = in.integer(3, kMaxPolygonVertices);
            for (int i = 0; i < n; ++i) pts.push_back(point(in, 3.0f));
            float radius = in.flag() ? in.real(0.0f, 1.0f) : 0.0f;
            auto poly = makePolygon(computeHull(pts), radius);
            s.polygon = poly ? *poly : makeRoundedBox(size(in), size(in), radius);
            break;
        }
        case kSegment: {
            Vec2 p1 = point(in, 5.0f);
            Vec2 p2 = point(in, 5.0f);
            if (distance(p1, p2) < 2.0f * kLinearSlop) p2 = p1 + Vec2{1.0f, 0.0f};
            s.segment = {p1, p2};
            break;
        }
    }
    return s;
}

// The shape as GJK sees it: core points and radius.
int corePoints(const AnyShape& s, Vec2* out, float& radius) {
    switch (s.kind) {
        case kCircle:
            out[0] = s.circle.center;
            radius = s.circle.radius;
            return 1;
        case kCapsule:
            out[0] = s.capsule.center1;
            out[1] = s.capsule.center2;
            radius = s.capsule.radius;
            return 2;
        case kSegment:
            out[0] = s.segment.point1;
            out[1] = s.segment.point2;
            radius = 0.0f;
            return 2;
        case kPolygon:
            for (int i = 0; i < s.polygon.count; ++i) out[i] = s.polygon.vertices[i];
            radius = s.polygon.radius;
            return s.polygon.count;
    }
    return 0;
}

Manifold collide(const AnyShape& a, const Transform& xa, const AnyShape& b, const Transform& xb, float spec) {
    if (a.kind == kSegment) {
        if (b.kind == kCircle) return collideSegmentAndCircle(a.segment, xa, b.circle, xb, spec);
        if (b.kind == kCapsule) return collideSegmentAndCapsule(a.segment, xa, b.capsule, xb, spec);
        return collideSegmentAndPolygon(a.segment, xa, b.polygon, xb, spec);
    }
    if (a.kind == kCircle) return collideCircles(a.circle, xa, b.circle, xb, spec);
    if (a.kind == kCapsule) {
        if (b.kind == kCircle) return collideCapsuleAndCircle(a.capsule, xa, b.circle, xb, spec);
        return collideCapsules(a.capsule, xa, b.capsule, xb, spec);
    }
    if (b.kind == kCircle) return collidePolygonAndCircle(a.polygon, xa, b.circle, xb, spec);
    if (b.kind == kCapsule) return collidePolygonAndCapsule(a.polygon, xa, b.capsule, xb, spec);
    return collidePolygons(a.polygon, xa, b.polygon, xb, spec);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::ByteReader in(data, size);
    // The pairs the narrowphase dispatches: A's kind ≥ B's kind (circle <
    // capsule < polygon), segments only as A and never against segments.
    static constexpr Kind kPairs[][2] = {{kCircle, kCircle},  {kCapsule, kCircle},  {kCapsule, kCapsule},
                                         {kPolygon, kCircle}, {kPolygon, kCapsule}, {kPolygon, kPolygon},
                                         {kSegment, kCircle}, {kSegment, kCapsule}, {kSegment, kPolygon}};
    const auto& pair = kPairs[in.integer<int>(0, 8)];
    const AnyShape a = makeShape(in, pair[0]);
    const AnyShape b = makeShape(in, pair[1]);
    // Bodies anywhere within 1e4 m (the documented far-world range), the
    // second near the first so that the shapes often touch.
    const float far = in.flag() ? 1.0e4f : 10.0f;
    const Transform xa{point(in, far), makeRot(in.real(-10.0f, 10.0f))};
    const Transform xb{xa.p + point(in, 8.0f), makeRot(in.real(-10.0f, 10.0f))};
    const float spec = in.real(0.0f, 0.1f);

    const Manifold m = collide(a, xa, b, xb, spec);
    I2D_FUZZ_CHECK(m.pointCount >= 0 && m.pointCount <= 2);
    if (m.pointCount > 0) {
        I2D_FUZZ_CHECK(isFinite(m.normal) && std::abs(length(m.normal) - 1.0f) < 1.0e-3f);
        for (int i = 0; i < m.pointCount; ++i) {
            I2D_FUZZ_CHECK(isFinite(m.points[i].point) && std::isfinite(m.points[i].separation));
            // Reported only up to the speculative distance; slack for float
            // round-off at coordinates up to 1e4 m (spacing ~1e-3 m there).
            I2D_FUZZ_CHECK(m.points[i].separation <= spec + 0.01f);
        }
    }

    Vec2 pa[kMaxPolygonVertices];
    Vec2 pb[kMaxPolygonVertices];
    float ra = 0.0f;
    float rb = 0.0f;
    const int na = corePoints(a, pa, ra);
    const int nb = corePoints(b, pb, rb);
    const DistanceResult d = shapeDistance(pa, na, xa, pb, nb, xb);
    I2D_FUZZ_CHECK(std::isfinite(d.distance) && d.distance >= 0.0f && isFinite(d.pointA) && isFinite(d.pointB));
    // Cores further apart than the radii and the speculative distance (with
    // the same round-off slack) make no contact.
    if (d.distance > ra + rb + spec + 0.01f) I2D_FUZZ_CHECK(m.pointCount == 0);
    return 0;
}
