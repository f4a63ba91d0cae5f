// The character mover (impulse2d/mover.hpp): the plane solver, velocity
// clipping, the World's collide and cast queries for a capsule, and the
// collide-solve-cast loop that moves it.
//
// The approach is the one of Catto's Box2D v3.1 mover (docs/references.md):
// the capsule keeps a small overlap (kLinearSlop) with what it rests on, so
// that those surfaces are found again as planes by the next collide and the
// cast, which ignores them, never stalls on them; the plane solver keeps the
// motion from going deeper than that slop.
#include <algorithm>
#include <cmath>

#include "impulse2d/world.hpp"
#include "query_lock.hpp"
#include "shape_cast.hpp"
#include "validation.hpp"
#include "world_state.hpp"

namespace i2d {

PlaneSolution solvePlanes(Vec2 targetDelta, std::span<CollisionPlane> planes) {
    for (CollisionPlane& p : planes) p.push = 0.0f;
    PlaneSolution out{targetDelta, 0};
    constexpr int kMaxSweeps = 20;
    for (out.iterations = 0; out.iterations < kMaxSweeps; ++out.iterations) {
        float change = 0.0f;
        for (CollisionPlane& p : planes) {
            // The gap to this plane after moving by delta, with the slop
            // allowed: positive means nothing to do.
            const float gap = dot(p.normal, out.delta) - p.offset + kLinearSlop;
            // Accumulated push never negative: a plane pushes out, never pulls in.
            const float total = std::max(p.push - gap, 0.0f);
            const float step = total - p.push;
            p.push = total;
            out.delta += step * p.normal;
            change += std::abs(step);
        }
        if (change < kLinearSlop) break;
    }
    return out;
}

Vec2 clipVector(Vec2 v, std::span<const CollisionPlane> planes) {
    for (const CollisionPlane& p : planes) {
        if (p.push <= 0.0f) continue;
        const float into = dot(v, p.normal);
        if (into < 0.0f) v -= into * p.normal;
    }
    return v;
}

namespace {

ShapeProxy capsuleProxy(const Capsule& c) {
    detail::requireBounded(c.center1, "mover centre1");
    detail::requireBounded(c.center2, "mover centre2");
    detail::requireFinite(c.radius, "mover radius");
    if (!(c.radius > 0.0f) || c.radius > detail::kMaxRadius) detail::fail("mover radius must be in (0, 1e5]");
    ShapeProxy p;
    p.points[0] = c.center1;
    p.points[1] = c.center2;
    p.count = 2;
    p.radius = c.radius;
    return p;
}

bool passesQuery(const detail::WorldState& w, int s, const QueryFilter& q) {
    const Filter& f = w.shapes[s].filter;
    if ((f.categoryBits & q.maskBits) == 0 || (f.maskBits & q.categoryBits) == 0) return false;
    return !q.accept || q.accept(w.shapeHandle(s));
}

// Non-sensor shapes whose fat boxes overlap `box` and pass the filter, in slot order.
std::vector<int> candidates(detail::WorldState& w, const AABB& box, const QueryFilter& q) {
    std::vector<int> found;
    auto visit = [&](int s) {
        if (!w.shapes[s].isSensor) found.push_back(s);
        return true;
    };
    w.broadPhase.queryAll(box, visit);
    std::sort(found.begin(), found.end());
    // The game's accept function runs with the world locked, released
    // however it ends (an exception from it left the world locked for good).
    const detail::QueryLock lock(w, q);
    std::erase_if(found, [&](int s) { return !passesQuery(w, s, q); });
    return found;
}

}  // namespace

std::vector<CollisionPlane> World::collideMover(const Capsule& mover, const QueryFilter& filter) const {
    const ShapeProxy proxy = capsuleProxy(mover);
    auto& w = state();
    std::vector<CollisionPlane> planes;
    for (int s : candidates(w, detail::proxyAABB(proxy), filter)) {
        const detail::Shape& sh = w.shapes[s];
        const detail::ShapeCore core = detail::shapeCore(sh);
        const detail::ProxyGap g = detail::proxyGap(proxy, core, w.bodies[sh.body].xf);
        if (g.gap > 0.0f || g.normal == Vec2{}) continue;
        planes.push_back({g.normal, -g.gap, w.shapeHandle(s), g.pointOnShape + core.radius * g.normal, 0.0f});
    }
    return planes;
}

float World::castMover(const Capsule& mover, Vec2 translation, const QueryFilter& filter) const {
    const ShapeProxy proxy = capsuleProxy(mover);
    detail::requireBounded(translation, "mover translation");
    auto& w = state();
    const AABB start = detail::proxyAABB(proxy);
    const AABB swept = unionOf(start, {start.lower + translation, start.upper + translation});
    float fraction = 1.0f;
    for (int s : candidates(w, swept, filter)) {
        const detail::Shape& sh = w.shapes[s];
        // Aim at an overlap of the slop: the depth the plane solver lets the
        // mover rest at, so the shape is a plane at the next collide.
        const detail::CoreCast c = detail::castProxy(proxy, translation, detail::shapeCore(sh), w.bodies[sh.body].xf,
                                                     -kLinearSlop, fraction);
        if (c.hit && !c.atStart) fraction = std::min(fraction, c.fraction);
    }
    return fraction;
}

MoverResult moveCharacter(const World& world, const Capsule& capsule, Vec2 position, Vec2 delta, Vec2 velocity,
                          const QueryFilter& filter) {
    detail::requireBounded(position, "mover position");
    detail::requireBounded(delta, "mover delta");
    detail::requireBounded(velocity, "mover velocity");
    auto placed = [&](Vec2 p) { return Capsule{capsule.center1 + p, capsule.center2 + p, capsule.radius}; };
    MoverResult out;
    out.position = position;
    const Vec2 target = position + delta;
    constexpr int kMaxRounds = 5;
    constexpr float kDoneDistance = 0.01f;  // m: a round that moves less ends the move
    for (out.iterations = 1; out.iterations <= kMaxRounds; ++out.iterations) {
        out.planes = world.collideMover(placed(out.position), filter);
        const PlaneSolution solved = solvePlanes(target - out.position, out.planes);
        const float fraction = world.castMover(placed(out.position), solved.delta, filter);
        const Vec2 moved = fraction * solved.delta;
        out.position += moved;
        if (lengthSquared(moved) < kDoneDistance * kDoneDistance) break;
    }
    out.iterations = std::min(out.iterations, kMaxRounds);
    out.velocity = clipVector(velocity, out.planes);
    return out;
}

}  // namespace i2d
