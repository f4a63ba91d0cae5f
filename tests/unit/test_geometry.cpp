// Shape geometry: hull, polygon construction, mass properties, AABBs, ray
// casts and point tests, checked against closed forms and brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "impulse2d/error.hpp"
#include "impulse2d/geometry.hpp"

using namespace i2d;

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Single-precision arithmetic on O(1) quantities: a handful of operations
// accumulate a few ulps of 1.2e-7 each, so 1e-5 relative is a safe bound for
// closed-form comparisons while still catching any formula error.
constexpr float kRel = 1.0e-5f;

float cross3(Vec2 o, Vec2 a, Vec2 b) { return cross(a - o, b - o); }

// Andrew's monotone chain, in double: an independent hull for comparison.
std::vector<Vec2> monotoneChain(std::vector<Vec2> p) {
    std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    std::vector<Vec2> h(2 * p.size());
    std::size_t k = 0;
    auto turn = [](Vec2 o, Vec2 a, Vec2 b) {
        return (double(a.x) - o.x) * (double(b.y) - o.y) - (double(a.y) - o.y) * (double(b.x) - o.x);
    };
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && turn(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}

double polygonArea(const Vec2* p, int n) {
    double a = 0.0;
    for (int i = 0; i < n; ++i) {
        Vec2 u = p[i];
        Vec2 v = p[(i + 1) % n];
        a += double(u.x) * v.y - double(u.y) * v.x;
    }
    return 0.5 * a;
}

// Independent inside test for a rounded convex polygon given by its CCW
// vertices: inside the core by half-planes, or within r of some edge.
bool insideRounded(const std::vector<Vec2>& v, float r, double x, double y) {
    const std::size_t n = v.size();
    bool core = true;
    double best = 1e300;
    for (std::size_t i = 0; i < n; ++i) {
        Vec2 a = v[i];
        Vec2 b = v[(i + 1) % n];
        double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
        double px = x - a.x, py = y - a.y;
        if (ex * py - ey * px < 0.0) core = false;
        double t = std::clamp((px * ex + py * ey) / (ex * ex + ey * ey), 0.0, 1.0);
        double dx = px - t * ex, dy = py - t * ey;
        best = std::min(best, dx * dx + dy * dy);
    }
    return core || best <= double(r) * r;
}

struct GridMass {
    double area = 0.0;
    double cx = 0.0;
    double cy = 0.0;
    double inertia = 0.0;  // about the centroid
    double cell = 0.0;
};

// Midpoint-rule integration over an n×n grid covering [lo, hi]².
template <class Inside>
GridMass gridIntegrate(Inside inside, double lo, double hi, int n) {
    GridMass g;
    double h = (hi - lo) / n;
    g.cell = h;
    double sx = 0, sy = 0, sxx = 0;
    for (int i = 0; i < n; ++i) {
        double x = lo + (i + 0.5) * h;
        for (int j = 0; j < n; ++j) {
            double y = lo + (j + 0.5) * h;
            if (!inside(x, y)) continue;
            g.area += h * h;
            sx += x * h * h;
            sy += y * h * h;
            sxx += (x * x + y * y) * h * h;
        }
    }
    g.cx = sx / g.area;
    g.cy = sy / g.area;
    g.inertia = sxx - g.area * (g.cx * g.cx + g.cy * g.cy);
    return g;
}

}  // namespace

// ---------------------------------------------------------------- hull ----

TEST(Hull, RandomCloudsAreConvexAndContainAllPoints) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> coord(-2.0f, 2.0f);
    std::uniform_int_distribution<int> countDist(3, kMaxPolygonVertices);
    int nonDegenerate = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<Vec2> pts(countDist(rng));
        for (Vec2& p : pts) p = {coord(rng), coord(rng)};
        Hull hull = computeHull(pts);
        if (hull.count == 0) continue;
        ++nonDegenerate;
        ASSERT_GE(hull.count, 3);
        // Strictly convex and counter-clockwise: every turn is to the left.
        for (int i = 0; i < hull.count; ++i) {
            Vec2 a = hull.points[i];
            Vec2 b = hull.points[(i + 1) % hull.count];
            Vec2 c = hull.points[(i + 2) % hull.count];
            EXPECT_GT(cross3(a, b, c), 0.0f) << "trial " << trial;
        }
        // Every hull vertex is an input point.
        for (int i = 0; i < hull.count; ++i) {
            bool found = std::any_of(pts.begin(), pts.end(), [&](Vec2 p) { return p == hull.points[i]; });
            EXPECT_TRUE(found);
        }
        // Brute-force containment: no input point is outside any hull edge by
        // more than the slop (points within kLinearSlop of an edge may be
        // dropped as collinear, which can leave them just outside). The 2x
        // allows for a vertex dropped between two such points.
        for (int i = 0; i < hull.count; ++i) {
            Vec2 a = hull.points[i];
            Vec2 b = hull.points[(i + 1) % hull.count];
            Vec2 n = normalize(rightPerp(b - a));
            for (Vec2 p : pts) EXPECT_LE(dot(n, p - a), 2.0f * kLinearSlop);
        }
        // Area agrees with an independent hull: the difference is bounded by
        // perimeter × 2·slop (only near-collinear points may be dropped).
        std::vector<Vec2> ref = monotoneChain(pts);
        double refArea = polygonArea(ref.data(), static_cast<int>(ref.size()));
        double area = polygonArea(hull.points, hull.count);
        double perimeter = 0.0;
        for (std::size_t i = 0; i < ref.size(); ++i) perimeter += distance(ref[i], ref[(i + 1) % ref.size()]);
        EXPECT_NEAR(area, refArea, perimeter * 2.0 * kLinearSlop + 1e-5);
    }
    // Random clouds of ≥ 3 points in a 4 m square are almost never degenerate.
    EXPECT_GT(nonDegenerate, 1900);
}

TEST(Hull, CollinearDuplicateTooManyAndNonFinite) {
    std::vector<Vec2> line = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
    EXPECT_EQ(computeHull(line).count, 0);
    // Collinear within the slop (2 mm off the line) is still degenerate.
    std::vector<Vec2> nearLine = {{0, 0}, {1, 0.002f}, {2, 0}};
    EXPECT_EQ(computeHull(nearLine).count, 0);

    std::vector<Vec2> dup = {{0, 0}, {0, 0}, {1, 0}, {1, 0}, {0, 1}, {0.001f, 1.0f}};
    Hull h = computeHull(dup);
    EXPECT_EQ(h.count, 3);

    // Square plus a point on an edge and a point welded to a corner.
    std::vector<Vec2> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.0f}, {1.002f, 1.001f}};
    h = computeHull(sq);
    EXPECT_EQ(h.count, 4);
    EXPECT_NEAR(polygonArea(h.points, h.count), 1.0, 0.01);

    std::vector<Vec2> nine(9);
    for (int i = 0; i < 9; ++i) nine[i] = {std::cos(0.7f * i), std::sin(0.7f * i)};
    EXPECT_EQ(computeHull(nine).count, 0);

    std::vector<Vec2> bad = {{0, 0}, {1, 0}, {0, std::numeric_limits<float>::quiet_NaN()}};
    EXPECT_EQ(computeHull(bad).count, 0);
    std::vector<Vec2> two = {{0, 0}, {1, 0}};
    EXPECT_EQ(computeHull(two).count, 0);
}

// ------------------------------------------------------------- polygon ----

TEST(Polygon, MakePolygonNormalsAndCentroid) {
    std::vector<Vec2> tri = {{0, 0}, {3, 0}, {0, 3}};
    Hull h = computeHull(tri);
    ASSERT_EQ(h.count, 3);
    auto poly = makePolygon(h, 0.1f);
    ASSERT_TRUE(poly.has_value());
    EXPECT_FLOAT_EQ(poly->radius, 0.1f);
    for (int i = 0; i < poly->count; ++i) {
        Vec2 n = poly->normals[i];
        EXPECT_NEAR(length(n), 1.0f, kRel);
        // Outward: the centroid is behind every face.
        EXPECT_LT(dot(n, poly->centroid - poly->vertices[i]), 0.0f);
        // Perpendicular to its edge.
        EXPECT_NEAR(dot(n, poly->vertices[(i + 1) % 3] - poly->vertices[i]), 0.0f, 1e-5f);
    }
    // Triangle centroid = vertex average.
    EXPECT_NEAR(poly->centroid.x, 1.0f, kRel);
    EXPECT_NEAR(poly->centroid.y, 1.0f, kRel);

    EXPECT_FALSE(makePolygon(h, -0.1f).has_value());
    EXPECT_FALSE(makePolygon(h, std::numeric_limits<float>::infinity()).has_value());
    EXPECT_FALSE(makePolygon(Hull{}, 0.0f).has_value());
    Hull cw = h;  // clockwise order is not a valid hull
    std::swap(cw.points[1], cw.points[2]);
    EXPECT_FALSE(makePolygon(cw, 0.0f).has_value());
}

TEST(Polygon, BoxesAndInvalidInput) {
    Polygon b = makeBox(2.0f, 0.5f);
    EXPECT_EQ(b.count, 4);
    EXPECT_FLOAT_EQ(b.radius, 0.0f);
    for (int i = 0; i < 4; ++i) {
        EXPECT_FLOAT_EQ(std::fabs(b.vertices[i].x), 2.0f);
        EXPECT_FLOAT_EQ(std::fabs(b.vertices[i].y), 0.5f);
        EXPECT_LT(dot(b.normals[i], -b.vertices[i]), 0.0f);
    }
    Polygon o = makeOffsetBox(1.0f, 0.5f, {3.0f, -1.0f}, kPi / 2);
    EXPECT_NEAR(o.centroid.x, 3.0f, kRel);
    EXPECT_NEAR(o.centroid.y, -1.0f, kRel);
    AABB box = computeAABB(o, Transform{});
    // Rotated a quarter turn, the 2×1 box becomes 1×2.
    EXPECT_NEAR(box.upper.x - box.lower.x, 1.0f, 1e-5f);
    EXPECT_NEAR(box.upper.y - box.lower.y, 2.0f, 1e-5f);

    Polygon r = makeRoundedBox(0.4f, 0.3f, 0.1f);
    EXPECT_FLOAT_EQ(r.radius, 0.1f);

    EXPECT_THROW(makeBox(0.0f, 1.0f), Error);
    EXPECT_THROW(makeBox(1.0f, -1.0f), Error);
    EXPECT_THROW(makeBox(std::numeric_limits<float>::quiet_NaN(), 1.0f), Error);
    EXPECT_THROW(makeRoundedBox(1.0f, 1.0f, -0.1f), Error);
    EXPECT_THROW(makeOffsetBox(1.0f, 1.0f, {0, 0}, std::numeric_limits<float>::infinity()), Error);
    // Card-house cards are 2 mm thick: thinner than the slop, still valid.
    EXPECT_NO_THROW(makeBox(0.001f, 0.2f));
}

// ---------------------------------------------------------------- mass ----

TEST(Mass, BoxClosedForm) {
    const float hx = 1.5f, hy = 0.25f, rho = 3.0f;
    MassData md = computeMass(makeBox(hx, hy), rho);
    float w = 2 * hx, h = 2 * hy;
    float m = rho * 4 * hx * hy;
    EXPECT_NEAR(md.mass, m, kRel * m);
    EXPECT_NEAR(md.center.x, 0.0f, 1e-6f);
    EXPECT_NEAR(md.center.y, 0.0f, 1e-6f);
    float I = m * (w * w + h * h) / 12.0f;
    EXPECT_NEAR(md.rotationalInertia, I, kRel * I);

    // Offset and rotated: same mass and central inertia, centre moved. The
    // offset of 10 m costs relative precision (moments of order 100 are
    // subtracted), hence the looser 1e-4 bound.
    MassData mo = computeMass(makeOffsetBox(hx, hy, {10.0f, -4.0f}, 0.6f), rho);
    EXPECT_NEAR(mo.mass, m, kRel * m);
    EXPECT_NEAR(mo.center.x, 10.0f, 1e-5f);
    EXPECT_NEAR(mo.center.y, -4.0f, 1e-5f);
    EXPECT_NEAR(mo.rotationalInertia, I, 1e-4f * I);
}

TEST(Mass, RightTriangleClosedForm) {
    // Legs a, b: area ab/2, centroid (a/3, b/3), central polar inertia m(a²+b²)/18.
    const float a = 2.0f, b = 1.0f, rho = 2.0f;
    std::vector<Vec2> pts = {{0, 0}, {a, 0}, {0, b}};
    auto poly = makePolygon(computeHull(pts));
    ASSERT_TRUE(poly);
    MassData md = computeMass(*poly, rho);
    float m = rho * a * b / 2;
    EXPECT_NEAR(md.mass, m, kRel * m);
    EXPECT_NEAR(md.center.x, a / 3, kRel);
    EXPECT_NEAR(md.center.y, b / 3, kRel);
    float I = m * (a * a + b * b) / 18.0f;
    EXPECT_NEAR(md.rotationalInertia, I, kRel * I);
}

TEST(Mass, CircleClosedForm) {
    Circle c{{0.5f, -2.0f}, 0.75f};
    MassData md = computeMass(c, 4.0f);
    float m = 4.0f * kPi * 0.75f * 0.75f;
    EXPECT_NEAR(md.mass, m, kRel * m);
    EXPECT_FLOAT_EQ(md.center.x, 0.5f);
    EXPECT_FLOAT_EQ(md.center.y, -2.0f);
    EXPECT_NEAR(md.rotationalInertia, 0.5f * m * 0.75f * 0.75f, kRel * m);
    EXPECT_THROW(computeMass(c, -1.0f), Error);
}

TEST(Mass, CapsuleDecomposition) {
    const float r = 0.3f, L = 2.0f, rho = 1.5f;
    Capsule cap{{-1.0f, 1.0f}, {1.0f, 1.0f}, r};
    MassData md = computeMass(cap, rho);
    // Independent derivation: rectangle L×2r, plus the two half-disks'
    // polar moment about the capsule centre computed directly:
    // ∫ over a half-disk centred at (L/2, 0) of (x'+L/2)² + y'² =
    //   πr⁴/4 + L·∫x' + (L²/4)·πr²/2, with ∫x' = 2r³/3 over the half-disk.
    double mRect = rho * 2.0 * r * L;
    double Irect = mRect * (double(L) * L + 4.0 * r * r) / 12.0;
    double Jcaps = 2.0 *
                   (kPi * std::pow(r, 4) / 4.0 + L * 2.0 * std::pow(r, 3) / 3.0 + L * L / 4.0 * kPi * r * r / 2.0);
    double m = mRect + rho * kPi * r * r;
    EXPECT_NEAR(md.mass, m, kRel * m);
    EXPECT_NEAR(md.center.x, 0.0f, 1e-6f);
    EXPECT_NEAR(md.center.y, 1.0f, 1e-6f);
    double I = Irect + rho * Jcaps;
    EXPECT_NEAR(md.rotationalInertia, I, kRel * I);

    // And against direct numerical integration (see RoundedPolygon for the bound).
    GridMass g = gridIntegrate(
        [&](double x, double y) {
            double dx = std::max(std::fabs(x) - 1.0, 0.0), dy = y - 1.0;
            return dx * dx + dy * dy <= double(r) * r;
        },
        -1.5, 1.5, 1500);
    double perimeter = 2.0 * L + 2.0 * kPi * r;
    EXPECT_NEAR(md.mass, rho * g.area, rho * perimeter * g.cell);
    EXPECT_NEAR(md.rotationalInertia, rho * g.inertia, rho * perimeter * g.cell * 1.3 * 1.3);
}

TEST(Mass, RoundedBoxExactArea) {
    const float hx = 0.5f, hy = 0.25f, r = 0.1f;
    MassData md = computeMass(makeRoundedBox(hx, hy, r), 1.0f);
    // Core + edge strips + one full disk from the four corner sectors.
    float area = 4 * hx * hy + 2 * (2 * hx + 2 * hy) * r + kPi * r * r;
    EXPECT_NEAR(md.mass, area, kRel * area);
    EXPECT_NEAR(md.center.x, 0.0f, 1e-6f);
    EXPECT_NEAR(md.center.y, 0.0f, 1e-6f);
}

TEST(Mass, RoundedPolygonMatchesNumericalIntegration) {
    // A rounded irregular pentagon: exact decomposition vs a 1500² midpoint
    // grid. A grid cell of size h can only be misclassified if it straddles
    // the boundary, so |area error| ≤ perimeter·h and |polar-moment error|
    // ≤ perimeter·h·ρ_max², ρ_max = farthest boundary point from the centroid.
    std::vector<Vec2> pts = {{-0.6f, -0.4f}, {0.7f, -0.5f}, {0.9f, 0.3f}, {0.1f, 0.8f}, {-0.7f, 0.4f}};
    const float r = 0.15f;
    auto poly = makePolygon(computeHull(pts), r);
    ASSERT_TRUE(poly);
    std::vector<Vec2> v(poly->vertices, poly->vertices + poly->count);
    MassData md = computeMass(*poly, 2.0f);
    GridMass g = gridIntegrate([&](double x, double y) { return insideRounded(v, r, x, y); }, -1.2, 1.2, 1500);
    double perimeter = 2 * kPi * r;
    for (int i = 0; i < poly->count; ++i) perimeter += distance(v[i], v[(i + 1) % v.size()]);
    double rmax = 1.4;
    EXPECT_NEAR(md.mass, 2.0 * g.area, 2.0 * perimeter * g.cell);
    EXPECT_NEAR(md.center.x, g.cx, perimeter * g.cell * rmax / g.area);
    EXPECT_NEAR(md.center.y, g.cy, perimeter * g.cell * rmax / g.area);
    EXPECT_NEAR(md.rotationalInertia, 2.0 * g.inertia, 2.0 * perimeter * g.cell * rmax * rmax);
    // The rounding matters: the core alone is clearly lighter than the grid says.
    MassData core = computeMass(*makePolygon(computeHull(pts), 0.0f), 2.0f);
    EXPECT_LT(core.mass, md.mass - 10.0 * 2.0 * perimeter * g.cell);
}

// ---------------------------------------------------------------- AABB ----

TEST(AABB, AllShapes) {
    Transform xf{{1.0f, 2.0f}, makeRot(kPi / 4)};
    AABB b = computeAABB(makeBox(0.5f, 0.5f), xf);
    float e = 0.5f * std::sqrt(2.0f);  // half-diagonal of the unit square
    EXPECT_NEAR(b.lower.x, 1.0f - e, 1e-5f);
    EXPECT_NEAR(b.upper.x, 1.0f + e, 1e-5f);
    EXPECT_NEAR(b.lower.y, 2.0f - e, 1e-5f);
    EXPECT_NEAR(b.upper.y, 2.0f + e, 1e-5f);

    AABB rb = computeAABB(makeRoundedBox(0.5f, 0.5f, 0.1f), Transform{});
    EXPECT_NEAR(rb.upper.x, 0.6f, 1e-6f);
    EXPECT_NEAR(rb.lower.y, -0.6f, 1e-6f);

    AABB c = computeAABB(Circle{{1.0f, 0.0f}, 0.5f}, xf);
    // The centre (1,0) rotated 45° about the body origin, then translated.
    EXPECT_NEAR(c.lower.x, 1.0f + std::sqrt(0.5f) - 0.5f, 1e-5f);
    EXPECT_NEAR(c.upper.y - c.lower.y, 1.0f, 1e-6f);

    AABB cap = computeAABB(Capsule{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.25f}, Transform{{0, 0}, makeRot(kPi / 2)});
    EXPECT_NEAR(cap.lower.x, -0.25f, 1e-6f);
    EXPECT_NEAR(cap.upper.y, 1.25f, 1e-6f);

    AABB s = computeAABB(Segment{{-2.0f, 1.0f}, {3.0f, -1.0f}}, Transform{});
    EXPECT_FLOAT_EQ(s.lower.x, -2.0f);
    EXPECT_FLOAT_EQ(s.upper.x, 3.0f);
    EXPECT_FLOAT_EQ(s.lower.y, -1.0f);
    EXPECT_FLOAT_EQ(s.upper.y, 1.0f);
}

// ----------------------------------------------------------- ray casts ----

TEST(RayCast, Circle) {
    Circle c{{1.0f, 0.0f}, 1.0f};
    auto hit = rayCast(RayCastInput{{-3.0f, 0.0f}, {6.0f, 0.0f}, 1.0f}, c);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->fraction, 3.0f / 6.0f, 1e-6f);  // surface at x = 0
    EXPECT_NEAR(hit->point.x, 0.0f, 1e-6f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-6f);
    // Too short, missing, starting inside.
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 0.0f}, {6.0f, 0.0f}, 0.4f}, c));
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 1.5f}, {6.0f, 0.0f}, 1.0f}, c));
    EXPECT_FALSE(rayCast(RayCastInput{{1.2f, 0.0f}, {6.0f, 0.0f}, 1.0f}, c));
    EXPECT_FALSE(rayCast(RayCastInput{{-3.0f, 0.0f}, {0.0f, 0.0f}, 1.0f}, c));
}

TEST(RayCast, BoxAndRoundedBox) {
    Polygon box = makeBox(0.5f, 0.5f);
    auto hit = rayCast(RayCastInput{{-2.0f, 0.25f}, {4.0f, 0.0f}, 1.0f}, box);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->fraction, 1.5f / 4.0f, 1e-6f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-6f);
    EXPECT_NEAR(hit->point.y, 0.25f, 1e-6f);
    EXPECT_FALSE(rayCast(RayCastInput{{0.0f, 0.0f}, {4.0f, 0.0f}, 1.0f}, box));   // inside
    EXPECT_FALSE(rayCast(RayCastInput{{-2.0f, 0.6f}, {4.0f, 0.0f}, 1.0f}, box));  // passes above

    Polygon rbox = makeRoundedBox(0.5f, 0.5f, 0.2f);
    hit = rayCast(RayCastInput{{-2.0f, 0.25f}, {4.0f, 0.0f}, 1.0f}, rbox);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->point.x, -0.7f, 1e-5f);  // flat side pushed out by r
    // Along the diagonal into the corner: the corner disk is hit at
    // (−0.5,−0.5) − 0.2·(1,1)/√2.
    hit = rayCast(RayCastInput{{-2.0f, -2.0f}, {3.0f, 3.0f}, 1.0f}, rbox);
    ASSERT_TRUE(hit);
    float k = 0.2f / std::sqrt(2.0f);
    EXPECT_NEAR(hit->point.x, -0.5f - k, 1e-5f);
    EXPECT_NEAR(hit->point.y, -0.5f - k, 1e-5f);
    EXPECT_NEAR(hit->normal.x, -std::sqrt(0.5f), 1e-5f);
    // Just beyond the sharp corner, still inside the rounding: no hit.
    EXPECT_FALSE(rayCast(RayCastInput{{-0.55f, -0.55f}, {-1.0f, 0.0f}, 1.0f}, rbox));
}

TEST(RayCast, CapsuleAndSegment) {
    Capsule cap{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    auto side = rayCast(RayCastInput{{0.3f, 2.0f}, {0.0f, -4.0f}, 1.0f}, cap);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->point.y, 0.5f, 1e-6f);
    EXPECT_NEAR(side->normal.y, 1.0f, 1e-6f);
    auto end = rayCast(RayCastInput{{3.0f, 0.0f}, {-4.0f, 0.0f}, 1.0f}, cap);
    ASSERT_TRUE(end);
    EXPECT_NEAR(end->point.x, 1.5f, 1e-6f);
    EXPECT_NEAR(end->normal.x, 1.0f, 1e-6f);
    EXPECT_FALSE(rayCast(RayCastInput{{1.2f, 0.1f}, {4.0f, 0.0f}, 1.0f}, cap));  // inside the cap

    Segment seg{{-1.0f, 0.0f}, {1.0f, 0.0f}};
    auto below = rayCast(RayCastInput{{0.0f, -1.0f}, {0.0f, 2.0f}, 1.0f}, seg);
    ASSERT_TRUE(below);
    EXPECT_NEAR(below->fraction, 0.5f, 1e-6f);
    EXPECT_NEAR(below->normal.y, -1.0f, 1e-6f);  // faces the ray origin
    auto above = rayCast(RayCastInput{{0.0f, 1.0f}, {0.0f, -2.0f}, 1.0f}, seg);
    ASSERT_TRUE(above);
    EXPECT_NEAR(above->normal.y, 1.0f, 1e-6f);
    EXPECT_FALSE(rayCast(RayCastInput{{2.0f, -1.0f}, {0.0f, 2.0f}, 1.0f}, seg));
    EXPECT_FALSE(rayCast(RayCastInput{{-2.0f, 0.0f}, {4.0f, 0.0f}, 1.0f}, seg));  // parallel
}

TEST(RayCast, RandomHitsLieOnTheSurface) {
    // For every hit the point is on the boundary: inside (boundary counts)
    // and a step of 1e-4 m back along the ray is outside. 1e-4 m is far
    // above float round-off at these O(1) coordinates (~1e-7).
    std::vector<Vec2> pts = {{-0.6f, -0.4f}, {0.7f, -0.5f}, {0.9f, 0.3f}, {0.1f, 0.8f}, {-0.7f, 0.4f}};
    Polygon sharp = *makePolygon(computeHull(pts), 0.0f);
    Polygon round = *makePolygon(computeHull(pts), 0.2f);
    Capsule cap{{-0.5f, -0.2f}, {0.6f, 0.4f}, 0.3f};
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-3.0f, 3.0f);
    int hits = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        RayCastInput in{{u(rng), u(rng)}, {u(rng), u(rng)}, 1.0f};
        auto check = [&](auto const& shape) {
            auto h = rayCast(in, shape);
            if (!h) return;
            ++hits;
            Vec2 dir = normalize(in.translation);
            EXPECT_TRUE(containsPoint(shape, h->point + 1e-5f * (-h->normal)));
            EXPECT_FALSE(containsPoint(shape, h->point - 1e-4f * dir));
            EXPECT_LT(dot(h->normal, in.translation), 0.0f);
        };
        check(sharp);
        check(round);
        check(cap);
        check(Circle{{0.2f, 0.1f}, 0.7f});
    }
    EXPECT_GT(hits, 1000);
}

// ------------------------------------------------------- containsPoint ----

TEST(ContainsPoint, BoundariesAndRounding) {
    EXPECT_TRUE(containsPoint(Circle{{0, 0}, 1.0f}, {1.0f, 0.0f}));
    EXPECT_FALSE(containsPoint(Circle{{0, 0}, 1.0f}, {1.001f, 0.0f}));
    Capsule cap{{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
    EXPECT_TRUE(containsPoint(cap, {1.3f, 0.3f}));
    EXPECT_FALSE(containsPoint(cap, {1.4f, 0.4f}));
    Polygon box = makeBox(0.5f, 0.5f);
    EXPECT_TRUE(containsPoint(box, {0.5f, 0.5f}));
    EXPECT_FALSE(containsPoint(box, {0.51f, 0.0f}));
    Polygon rbox = makeRoundedBox(0.5f, 0.5f, 0.1f);
    EXPECT_TRUE(containsPoint(rbox, {0.59f, 0.0f}));
    EXPECT_TRUE(containsPoint(rbox, {0.55f, 0.55f}));   // 0.0707 from the corner
    EXPECT_FALSE(containsPoint(rbox, {0.58f, 0.58f}));  // 0.113 from the corner
}
