// Fuzz target: convex hull and polygon construction. For any point cloud
// computeHull returns either nothing or a convex counter-clockwise hull that
// contains every input point, makePolygon accepts it, its mass properties are
// finite and positive, and the world accepts the polygon as a shape.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"

using namespace i2d;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::ByteReader in(data, size);
    const bool raw = in.flag();
    // Scale: from sub-millimetre clouds to 1e4 m, optionally far from the origin.
    const float scale = in.real(1.0e-4f, 1.0e4f);
    const Vec2 offset{in.real(-1.0e4f, 1.0e4f), in.real(-1.0e4f, 1.0e4f)};
    const int n = in.integer(0, kMaxPolygonVertices + 2);
    std::vector<Vec2> points;
    for (int i = 0; i < n; ++i) {
        if (raw) {
            // Any float at all, NaN and infinities included.
            points.push_back({in.anyFloat(), in.anyFloat()});
        } else {
            points.push_back({offset.x + scale * in.real(-1.0f, 1.0f), offset.y + scale * in.real(-1.0f, 1.0f)});
        }
    }
    const Hull hull = computeHull(points);
    I2D_FUZZ_CHECK(hull.count == 0 || (hull.count >= 3 && hull.count <= kMaxPolygonVertices));
    if (hull.count == 0 || raw) return 0;

    // Convex and counter-clockwise, every input point inside (within the
    // weld and collinearity tolerance kLinearSlop, plus round-off at the
    // coordinates' magnitude).
    float extent = 0.0f;
    for (Vec2 p : points) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    const float tol = kLinearSlop + 1.0e-5f * extent;
    for (int i = 0; i < hull.count; ++i) {
        Vec2 a = hull.points[i];
        Vec2 b = hull.points[(i + 1) % hull.count];
        Vec2 e = normalize(b - a);
        for (Vec2 p : points) {
            if (cross(e, p - a) < -tol) {
                std::fprintf(stderr, "point (%.9g, %.9g) is %.9g outside edge (%.9g, %.9g)-(%.9g, %.9g); tol %.9g\n",
                             p.x, p.y, -cross(e, p - a), a.x, a.y, b.x, b.y, tol);
                for (Vec2 q : points) std::fprintf(stderr, "  input (%.9g, %.9g)\n", q.x, q.y);
                for (int k = 0; k < hull.count; ++k)
                    std::fprintf(stderr, "  hull (%.9g, %.9g)\n", hull.points[k].x, hull.points[k].y);
            }
            I2D_FUZZ_CHECK(cross(e, p - a) >= -tol);
        }
    }
    auto poly = makePolygon(hull);
    I2D_FUZZ_CHECK(poly.has_value());
    MassData md = computeMass(*poly, 1.0f);
    I2D_FUZZ_CHECK(isFinite(md.mass) && md.mass > 0.0f && isFinite(md.rotationalInertia) &&
                   md.rotationalInertia >= 0.0f);
    I2D_FUZZ_CHECK(isFinite(md.center) && containsPoint(*poly, md.center));

    // The world takes what makePolygon built unless it is thinner than its
    // documented minimum feature size; either way nothing breaks.
    World world;
    BodyId body = world.createBody({.type = BodyType::dynamic_body});
    try {
        world.createPolygonShape(body, {}, *poly);
        I2D_FUZZ_CHECK(world.shapeCount() == 1);
    } catch (const Error&) {
        I2D_FUZZ_CHECK(world.shapeCount() == 0);
    }
    world.step(1.0f / 60.0f);
    I2D_FUZZ_CHECK(fuzz::worldIsFinite(world));
    return 0;
}
