// Fuzz target: chains (World::createChain). Random point lists — too few,
// coincident, non-finite, out of range, folding back, crossing, open or
// looped — on static, kinematic or dynamic bodies, then fast bodies and
// bullets thrown at whatever was built, stepped. Checks: a refused chain
// changes nothing; an accepted one has a segment per pair of points with
// its neighbours as ghosts; the world stays finite; everything can be
// destroyed.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"

using namespace i2d;

namespace {

std::vector<float> snapshot(const World& w) {
    std::vector<float> s{static_cast<float>(w.bodyCount()), static_cast<float>(w.shapeCount()),
                         static_cast<float>(w.contactCount())};
    return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::ByteReader in(data, size);
    WorldSettings settings;
    settings.positionCorrection = static_cast<PositionCorrection>(in.integer(0, 2));
    settings.impactModel = static_cast<ImpactModel>(in.integer(0, 1));
    World world(settings);
    auto range = [&](float lo, float hi) { return in.real(lo, hi); };
    auto maybeBad = [&](float lo, float hi) { return in.integer(0, 7) == 0 ? in.anyFloat() : range(lo, hi); };
    std::vector<BodyId> bodies;
    int steps = 0;
    while (in.remaining() > 0 && steps < 120) {
        switch (in.integer(0, 3)) {
            case 0: {  // a chain
                const int t = in.integer(0, 5);
                BodyId b = world.createBody({.type = t == 0   ? BodyType::kinematic_body
                                                     : t == 1 ? BodyType::dynamic_body
                                                              : BodyType::static_body,
                                             .position = {range(-10, 10), range(-10, 10)},
                                             .angle = range(-3, 3)});
                bodies.push_back(b);
                std::vector<Vec2> points(static_cast<std::size_t>(in.integer(0, 12)));
                for (Vec2& p : points) p = {maybeBad(-8, 8), maybeBad(-8, 8)};
                // Sometimes a repeated point, or a tiny step.
                if (!points.empty() && in.integer(0, 5) == 0) points.push_back(points.back());
                if (!points.empty() && in.integer(0, 5) == 0) points.push_back(points.back() + Vec2{0.001f, 0.0f});
                const bool loop = in.flag();
                const std::vector<float> before = snapshot(world);
                try {
                    const std::vector<ShapeId> segments = world.createChain(
                        b, {.points = points, .isLoop = loop, .friction = maybeBad(0, 1), .restitution = range(0, 1)});
                    I2D_FUZZ_CHECK(segments.size() == (loop ? points.size() : points.size() - 1));
                    for (std::size_t i = 0; i < segments.size(); ++i) {
                        const ChainSegment c = world.shapeChainSegment(segments[i]);
                        I2D_FUZZ_CHECK(c.segment.point1 == points[i]);
                        I2D_FUZZ_CHECK(c.segment.point2 == points[(i + 1) % points.size()]);
                    }
                } catch (const Error&) {
                    I2D_FUZZ_CHECK(before == snapshot(world));
                }
                break;
            }
            case 1: {  // a fast body, maybe a bullet, maybe spinning
                BodyId b = world.createBody({.type = BodyType::dynamic_body,
                                             .position = {range(-12, 12), range(-12, 12)},
                                             .angle = range(-3, 3),
                                             .linearVelocity = {range(-400, 400), range(-400, 400)},
                                             .angularVelocity = range(-100, 100),
                                             .isBullet = in.flag()});
                bodies.push_back(b);
                const float r = range(0.02f, 0.5f);
                switch (in.integer(0, 2)) {
                    case 0: world.createCircleShape(b, {}, {{0, 0}, r}); break;
                    case 1: world.createCapsuleShape(b, {}, {{-r, 0}, {r, 0}, 0.5f * r}); break;
                    default: world.createPolygonShape(b, {}, makeBox(r, range(0.02f, 0.5f))); break;
                }
                break;
            }
            case 2:
                if (!bodies.empty()) {
                    const std::size_t i = in.integer<std::size_t>(0, bodies.size() - 1);
                    world.destroyBody(bodies[i]);
                    bodies.erase(bodies.begin() + static_cast<std::ptrdiff_t>(i));
                }
                break;
            default:
                world.step(1.0f / 60.0f);
                ++steps;
                I2D_FUZZ_CHECK(fuzz::worldIsFinite(world));
                break;
        }
    }
    for (int i = 0; i < 5; ++i) world.step(1.0f / 60.0f);
    I2D_FUZZ_CHECK(fuzz::worldIsFinite(world));
    for (BodyId b : bodies) world.destroyBody(b);
    I2D_FUZZ_CHECK(world.bodyCount() == 0 && world.shapeCount() == 0 && world.contactCount() == 0);
    return 0;
}
