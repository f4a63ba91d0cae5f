// Impulse2D — closest points between two convex point clouds (GJK).
//
// Gilbert–Johnson–Keerthi distance on the Minkowski difference B − A, with
// Johnson's sub-algorithm for the closest point of a 1-, 2- or 3-vertex
// simplex to the origin, solved by Voronoi regions using barycentric
// coordinates (as in Ericson, "Real-Time Collision Detection" §9.5, and
// Catto's GDC 2010 "Computing Distance" talk). Everything is done in A's
// frame; B's points are mapped on the fly, so nothing is allocated.
#include <cfloat>

#include "impulse2d/collision.hpp"
#include "impulse2d/error.hpp"

namespace i2d {

namespace {

struct SimplexVertex {
    Vec2 wA;  // support point of A (A's frame)
    Vec2 wB;  // support point of B (A's frame)
    Vec2 w;   // wB − wA, a point of the Minkowski difference
    float a;  // barycentric weight of this vertex in the closest point
    int indexA;
    int indexB;
};

struct Simplex {
    SimplexVertex v[3];
    int count = 0;

    // Closest point of the segment v0–v1 to the origin. Regions: beyond v0
    // (weight of v1 would be negative), beyond v1, or the segment interior
    // with weights proportional to the opposite sub-lengths.
    void solve2() {
        Vec2 w1 = v[0].w;
        Vec2 w2 = v[1].w;
        Vec2 e12 = w2 - w1;
        float d12_2 = -dot(w1, e12);
        if (d12_2 <= 0.0f) {
            v[0].a = 1.0f;
            count = 1;
            return;
        }
        float d12_1 = dot(w2, e12);
        if (d12_1 <= 0.0f) {
            v[1].a = 1.0f;
            v[0] = v[1];
            count = 1;
            return;
        }
        float inv = 1.0f / (d12_1 + d12_2);
        v[0].a = d12_1 * inv;
        v[1].a = d12_2 * inv;
        count = 2;
    }

    // Closest point of the triangle v0 v1 v2 to the origin: test the vertex,
    // edge and interior Voronoi regions with unnormalised barycentric
    // coordinates (edge ones from projections, interior ones from signed areas).
    void solve3() {
        Vec2 w1 = v[0].w;
        Vec2 w2 = v[1].w;
        Vec2 w3 = v[2].w;

        Vec2 e12 = w2 - w1;
        float d12_1 = dot(w2, e12);
        float d12_2 = -dot(w1, e12);
        Vec2 e13 = w3 - w1;
        float d13_1 = dot(w3, e13);
        float d13_2 = -dot(w1, e13);
        Vec2 e23 = w3 - w2;
        float d23_1 = dot(w3, e23);
        float d23_2 = -dot(w2, e23);

        float n123 = cross(e12, e13);
        float d123_1 = n123 * cross(w2, w3);
        float d123_2 = n123 * cross(w3, w1);
        float d123_3 = n123 * cross(w1, w2);

        if (d12_2 <= 0.0f && d13_2 <= 0.0f) {  // vertex 1
            v[0].a = 1.0f;
            count = 1;
            return;
        }
        if (d12_1 > 0.0f && d12_2 > 0.0f && d123_3 <= 0.0f) {  // edge 12
            float inv = 1.0f / (d12_1 + d12_2);
            v[0].a = d12_1 * inv;
            v[1].a = d12_2 * inv;
            count = 2;
            return;
        }
        if (d13_1 > 0.0f && d13_2 > 0.0f && d123_2 <= 0.0f) {  // edge 13
            float inv = 1.0f / (d13_1 + d13_2);
            v[0].a = d13_1 * inv;
            v[2].a = d13_2 * inv;
            v[1] = v[2];
            count = 2;
            return;
        }
        if (d12_1 <= 0.0f && d23_2 <= 0.0f) {  // vertex 2
            v[1].a = 1.0f;
            v[0] = v[1];
            count = 1;
            return;
        }
        if (d13_1 <= 0.0f && d23_1 <= 0.0f) {  // vertex 3
            v[2].a = 1.0f;
            v[0] = v[2];
            count = 1;
            return;
        }
        if (d23_1 > 0.0f && d23_2 > 0.0f && d123_1 <= 0.0f) {  // edge 23
            float inv = 1.0f / (d23_1 + d23_2);
            v[1].a = d23_1 * inv;
            v[2].a = d23_2 * inv;
            v[0] = v[2];
            count = 2;
            return;
        }
        // Interior: the origin is inside the triangle (overlap).
        float inv = 1.0f / (d123_1 + d123_2 + d123_3);
        v[0].a = d123_1 * inv;
        v[1].a = d123_2 * inv;
        v[2].a = d123_3 * inv;
        count = 3;
    }

    // Direction from the current simplex towards the origin.
    Vec2 searchDirection() const {
        if (count == 1) return -v[0].w;
        Vec2 e12 = v[1].w - v[0].w;
        float sgn = cross(e12, -v[0].w);
        return sgn > 0.0f ? leftPerp(e12) : rightPerp(e12);
    }
};

int support(const Vec2* points, int count, Vec2 d) {
    int best = 0;
    float bestValue = dot(points[0], d);
    for (int i = 1; i < count; ++i) {
        float value = dot(points[i], d);
        if (value > bestValue) {
            bestValue = value;
            best = i;
        }
    }
    return best;
}

}  // namespace

DistanceResult shapeDistance(const Vec2* pointsA, int countA, const Transform& xfA, const Vec2* pointsB, int countB,
                             const Transform& xfB) {
    if (pointsA == nullptr || pointsB == nullptr || countA < 1 || countB < 1)
        throw Error("shapeDistance: both point sets must be non-empty");

    // B relative to A.
    const Transform xf = invMulTransforms(xfA, xfB);

    Simplex s;
    auto makeVertex = [&](int iA, int iB) {
        SimplexVertex sv;
        sv.indexA = iA;
        sv.indexB = iB;
        sv.wA = pointsA[iA];
        sv.wB = transformPoint(xf, pointsB[iB]);
        sv.w = sv.wB - sv.wA;
        sv.a = 1.0f;
        return sv;
    };
    s.v[0] = makeVertex(0, 0);
    s.count = 1;

    // Each iteration adds a vertex that is strictly closer in the search
    // direction; the loop ends when the support points repeat (convergence),
    // the origin is enclosed (overlap) or the direction vanishes (origin on
    // the simplex). The cap guards against cycling from round-off.
    constexpr int kMaxIterations = 30;
    for (int iter = 0; iter < kMaxIterations; ++iter) {
        int savedA[3];
        int savedB[3];
        int savedCount = s.count;
        for (int i = 0; i < savedCount; ++i) {
            savedA[i] = s.v[i].indexA;
            savedB[i] = s.v[i].indexB;
        }
        if (s.count == 2) s.solve2();
        if (s.count == 3) s.solve3();
        if (s.count == 3) break;

        Vec2 d = s.searchDirection();
        if (lengthSquared(d) < FLT_EPSILON * FLT_EPSILON) break;

        int iA = support(pointsA, countA, -d);
        int iB = support(pointsB, countB, invRotate(xf.q, d));
        bool duplicate = false;
        for (int i = 0; i < savedCount; ++i) {
            if (savedA[i] == iA && savedB[i] == iB) {
                duplicate = true;
                break;
            }
        }
        if (duplicate) break;
        s.v[s.count++] = makeVertex(iA, iB);
    }

    Vec2 pA{};
    Vec2 pB{};
    for (int i = 0; i < s.count; ++i) {
        pA += s.v[i].a * s.v[i].wA;
        pB += s.v[i].a * s.v[i].wB;
    }
    if (s.count == 3) pB = pA;  // origin enclosed: the shapes overlap

    DistanceResult result;
    result.pointA = transformPoint(xfA, pA);
    result.pointB = transformPoint(xfA, pB);
    result.distance = s.count == 3 ? 0.0f : length(pB - pA);
    return result;
}

}  // namespace i2d
