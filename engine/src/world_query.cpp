// World: the public API facade for queries — ray casts, box overlap and
// point tests over both broadphase trees.
#include <algorithm>

#include "impulse2d/world.hpp"
#include "validation.hpp"
#include "world_state.hpp"

namespace i2d {

namespace {

bool passes(const Filter& f, const QueryFilter& q) {
    return (f.categoryBits & q.maskBits) != 0 && (f.maskBits & q.categoryBits) != 0;
}

std::optional<RayHit> castShape(const detail::Shape& sh, const Transform& xf, Vec2 origin, Vec2 translation,
                                float maxFraction) {
    RayCastInput in{invTransformPoint(xf, origin), invRotate(xf.q, translation), maxFraction};
    std::optional<RayHit> hit = detail::shapeRayCast(sh, in);
    if (hit) {
        hit->point = transformPoint(xf, hit->point);
        hit->normal = rotate(xf.q, hit->normal);
    }
    return hit;
}

// Shapes of both trees whose fat box overlaps `box`, that pass the filter and
// the exact test `accept`, as handles in slot order (independent of tree shape).
template <class Accept>
std::vector<ShapeId> shapesInBox(const detail::WorldState& w, const AABB& box, const QueryFilter& filter,
                                 Accept accept) {
    std::vector<int> found;
    auto visit = [&](int s) {
        const detail::Shape& sh = w.shapes[s];
        if (passes(sh.filter, filter) && accept(sh)) found.push_back(s);
        return true;
    };
    w.broadPhase.staticTree.query(box, visit);
    w.broadPhase.movingTree.query(box, visit);
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
    const auto& w = state();
    std::optional<RayResult> best;
    auto visit = [&](int s, float maxFraction) -> float {
        const detail::Shape& sh = w.shapes[s];
        if (sh.isSensor || !passes(sh.filter, filter)) return maxFraction;
        auto hit = castShape(sh, w.bodies[sh.body].xf, origin, translation, maxFraction);
        if (!hit || hit->fraction > maxFraction) return maxFraction;
        // Ties resolved by the lower slot, so the answer does not depend on tree order.
        if (best && hit->fraction == best->fraction && s > static_cast<int>(best->shape.index1) - 1) return maxFraction;
        best = RayResult{w.shapeHandle(s), hit->point, hit->normal, hit->fraction};
        return hit->fraction;
    };
    float maxFraction = 1.0f;
    w.broadPhase.staticTree.rayCast(origin, translation, maxFraction, visit);
    if (best) maxFraction = best->fraction;
    w.broadPhase.movingTree.rayCast(origin, translation, maxFraction, visit);
    return best;
}

std::vector<RayResult> World::rayCastAll(Vec2 origin, Vec2 translation, const QueryFilter& filter) const {
    checkRay(origin, translation);
    const auto& w = state();
    std::vector<RayResult> out;
    auto visit = [&](int s, float maxFraction) -> float {
        const detail::Shape& sh = w.shapes[s];
        if (sh.isSensor || !passes(sh.filter, filter)) return maxFraction;
        auto hit = castShape(sh, w.bodies[sh.body].xf, origin, translation, 1.0f);
        if (hit) out.push_back({w.shapeHandle(s), hit->point, hit->normal, hit->fraction});
        return maxFraction;
    };
    w.broadPhase.staticTree.rayCast(origin, translation, 1.0f, visit);
    w.broadPhase.movingTree.rayCast(origin, translation, 1.0f, visit);
    std::sort(out.begin(), out.end(), [](const RayResult& a, const RayResult& b) {
        return a.fraction != b.fraction ? a.fraction < b.fraction : a.shape.index1 < b.shape.index1;
    });
    return out;
}

std::vector<ShapeId> World::overlapAABB(const AABB& box, const QueryFilter& filter) const {
    detail::requireBounded(box.lower, "box lower");
    detail::requireBounded(box.upper, "box upper");
    const auto& w = state();
    return shapesInBox(w, box, filter, [&](const detail::Shape& sh) {
        return overlaps(detail::shapeAABB(sh, w.bodies[sh.body].xf), box);
    });
}

std::vector<ShapeId> World::queryPoint(Vec2 p, const QueryFilter& filter) const {
    detail::requireBounded(p, "point");
    const auto& w = state();
    return shapesInBox(w, AABB{p, p}, filter, [&](const detail::Shape& sh) {
        return detail::shapeContains(sh, invTransformPoint(w.bodies[sh.body].xf, p));
    });
}

}  // namespace i2d
