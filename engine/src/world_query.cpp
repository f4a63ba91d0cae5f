// World: the public API facade for queries — ray casts, shape casts, box,
// shape and point overlap over the broadphase's trees.
#include <algorithm>

#include "impulse2d/world.hpp"
#include "query_lock.hpp"
#include "shape_cast.hpp"
#include "validation.hpp"
#include "world_state.hpp"

namespace i2d {

namespace {

bool passesBits(const Filter& f, const QueryFilter& q) {
    return (f.categoryBits & q.maskBits) != 0 && (f.maskBits & q.categoryBits) != 0;
}

using detail::QueryLock;

bool passes(const detail::WorldState& w, int s, const QueryFilter& q) {
    if (!passesBits(w.shapes[s].filter, q)) return false;
    return !q.accept || q.accept(w.shapeHandle(s));
}

std::optional<RayHit> castRayAt(const detail::Shape& sh, const Transform& xf, Vec2 origin, Vec2 translation,
                                float maxFraction) {
    RayCastInput in{invTransformPoint(xf, origin), invRotate(xf.q, translation), maxFraction};
    std::optional<RayHit> hit = detail::shapeRayCast(sh, in);
    if (hit) {
        hit->point = transformPoint(xf, hit->point);
        hit->normal = rotate(xf.q, hit->normal);
    }
    return hit;
}

// Shapes of the three trees whose fat box overlaps `box`, that pass the filter and
// the exact test `accept`, as handles in slot order (independent of tree shape).
template <class Exact>
std::vector<ShapeId> shapesInBox(const detail::WorldState& w, const AABB& box, const QueryFilter& filter, Exact exact) {
    std::vector<int> found;
    auto visit = [&](int s) {
        if (passes(w, s, filter) && exact(w.shapes[s])) found.push_back(s);
        return true;
    };
    w.broadPhase.queryAll(box, visit);
    std::sort(found.begin(), found.end());
    std::vector<ShapeId> out;
    out.reserve(found.size());
    for (int s : found) out.push_back(w.shapeHandle(s));
    return out;
}

void checkRay(Vec2 origin, Vec2 translation) {
    detail::requireBounded(origin, "ray origin");
    detail::requireBounded(translation, "ray translation");
}

}  // namespace

std::optional<RayResult> World::rayCastClosest(Vec2 origin, Vec2 translation, const QueryFilter& filter) const {
    checkRay(origin, translation);
    auto& w = state();
    QueryLock lock(w, filter);
    std::optional<RayResult> best;
    auto visit = [&](int s, float maxFraction) -> float {
        const detail::Shape& sh = w.shapes[s];
        if (sh.isSensor) return maxFraction;
        auto hit = castRayAt(sh, w.bodies[sh.body].xf, origin, translation, maxFraction);
        if (!hit || hit->fraction > maxFraction) return maxFraction;
        // Ties resolved by the lower slot, so the answer does not depend on tree order.
        if (best && hit->fraction == best->fraction && s > static_cast<int>(best->shape.index1) - 1) return maxFraction;
        if (!passes(w, s, filter)) return maxFraction;
        best = RayResult{w.shapeHandle(s), hit->point, hit->normal, hit->fraction};
        return hit->fraction;
    };
    for (const detail::DynamicTree* tree : w.broadPhase.trees())
        tree->rayCast(origin, translation, best ? best->fraction : 1.0f, visit);
    return best;
}

std::optional<RayResult> World::rayCastAny(Vec2 origin, Vec2 translation, const QueryFilter& filter) const {
    checkRay(origin, translation);
    auto& w = state();
    QueryLock lock(w, filter);
    std::optional<RayResult> found;
    // A negative fraction ends the tree walk at the first accepted hit.
    auto visit = [&](int s, float maxFraction) -> float {
        const detail::Shape& sh = w.shapes[s];
        if (sh.isSensor) return maxFraction;
        auto hit = castRayAt(sh, w.bodies[sh.body].xf, origin, translation, maxFraction);
        if (!hit || !passes(w, s, filter)) return maxFraction;
        found = RayResult{w.shapeHandle(s), hit->point, hit->normal, hit->fraction};
        return -1.0f;
    };
    for (const detail::DynamicTree* tree : w.broadPhase.trees())
        if (!found) tree->rayCast(origin, translation, 1.0f, visit);
    return found;
}

std::vector<RayResult> World::rayCastAll(Vec2 origin, Vec2 translation, const QueryFilter& filter) const {
    checkRay(origin, translation);
    auto& w = state();
    QueryLock lock(w, filter);
    std::vector<RayResult> out;
    auto visit = [&](int s, float maxFraction) -> float {
        const detail::Shape& sh = w.shapes[s];
        if (sh.isSensor) return maxFraction;
        auto hit = castRayAt(sh, w.bodies[sh.body].xf, origin, translation, 1.0f);
        if (hit && passes(w, s, filter)) out.push_back({w.shapeHandle(s), hit->point, hit->normal, hit->fraction});
        return maxFraction;
    };
    for (const detail::DynamicTree* tree : w.broadPhase.trees()) tree->rayCast(origin, translation, 1.0f, visit);
    std::sort(out.begin(), out.end(), [](const RayResult& a, const RayResult& b) {
        return a.fraction != b.fraction ? a.fraction < b.fraction : a.shape.index1 < b.shape.index1;
    });
    return out;
}

std::vector<ShapeId> World::overlapAABB(const AABB& box, const QueryFilter& filter) const {
    detail::requireBounded(box.lower, "box lower");
    detail::requireBounded(box.upper, "box upper");
    auto& w = state();
    QueryLock lock(w, filter);
    return shapesInBox(w, box, filter, [&](const detail::Shape& sh) {
        return overlaps(detail::shapeAABB(sh, w.bodies[sh.body].xf), box);
    });
}

std::vector<ShapeId> World::queryPoint(Vec2 p, const QueryFilter& filter) const {
    detail::requireBounded(p, "point");
    auto& w = state();
    QueryLock lock(w, filter);
    return shapesInBox(w, AABB{p, p}, filter, [&](const detail::Shape& sh) {
        return detail::shapeContains(sh, invTransformPoint(w.bodies[sh.body].xf, p));
    });
}

std::optional<ShapeCastResult> World::castShape(const ShapeProxy& proxy, Vec2 translation,
                                                const QueryFilter& filter) const {
    detail::validateProxy(proxy);
    detail::requireBounded(translation, "cast translation");
    auto& w = state();
    QueryLock lock(w, filter);
    const AABB start = detail::proxyAABB(proxy);
    const AABB swept = unionOf(start, {start.lower + translation, start.upper + translation});
    std::vector<int> candidates;
    auto visit = [&](int s) {
        if (!w.shapes[s].isSensor) candidates.push_back(s);
        return true;
    };
    w.broadPhase.queryAll(swept, visit);
    // Slot order: the lower slot wins a tie whatever the trees' shape.
    std::sort(candidates.begin(), candidates.end());
    std::optional<ShapeCastResult> best;
    for (int s : candidates) {
        const detail::Shape& sh = w.shapes[s];
        const float maxFraction = best ? best->fraction : 1.0f;
        const detail::CoreCast c = detail::castProxy(proxy, translation, detail::shapeCore(sh), w.bodies[sh.body].xf,
                                                     0.0f, maxFraction);
        if (!c.hit || (best && c.fraction >= best->fraction) || !passes(w, s, filter)) continue;
        best = ShapeCastResult{w.shapeHandle(s), c.point, c.normal, c.fraction};
    }
    return best;
}

std::vector<ShapeId> World::overlapShape(const ShapeProxy& proxy, const QueryFilter& filter) const {
    detail::validateProxy(proxy);
    auto& w = state();
    QueryLock lock(w, filter);
    return shapesInBox(w, detail::proxyAABB(proxy), filter, [&](const detail::Shape& sh) {
        return detail::proxyGap(proxy, detail::shapeCore(sh), w.bodies[sh.body].xf).gap <= 0.0f;
    });
}

}  // namespace i2d
