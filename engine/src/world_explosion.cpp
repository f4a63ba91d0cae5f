// World: the explosion helper (World::explode) — impulses away from a point
// for the dynamic bodies near it, computed and checked for every body before
// any is applied, so a refused explosion changes nothing.
#include <algorithm>
#include <cmath>

#include "impulse2d/world.hpp"
#include "shape_cast.hpp"
#include "validation.hpp"
#include "world_state.hpp"

namespace i2d {

void World::explode(const ExplosionDef& def) {
    auto& w = state();
    w.checkUnlocked();
    detail::requireBounded(def.center, "explosion centre");
    detail::requireInRange(def.radius, 0.0f, 1.0e7f, "explosion radius");
    detail::requireInRange(def.falloff, 0.0f, 1.0e7f, "explosion falloff");
    detail::requireInRange(def.impulse, 0.0f, 1.0e7f, "explosion impulse");
    const float reach = def.radius + def.falloff;
    const AABB box{def.center - Vec2{reach, reach}, def.center + Vec2{reach, reach}};
    const std::vector<ShapeId> near = overlapAABB(box, def.filter);

    // The centre as a point proxy: the gap to a shape is the distance from the
    // centre to its surface (negative inside).
    ShapeProxy centre;
    centre.points[0] = def.center;
    centre.count = 1;
    struct Push {
        int body;
        Vec2 impulse, point;
    };
    std::vector<Push> pushes;
    for (ShapeId id : near) {
        const int s = w.shapeIndex(id);
        const detail::Shape& sh = w.shapes[s];
        const detail::Body& body = w.bodies[sh.body];
        if (body.type != BodyType::dynamic_body || sh.isSensor) continue;
        const detail::ProxyGap g = detail::proxyGap(centre, detail::shapeCore(sh), body.xf);
        const float d = std::max(g.gap, 0.0f);
        if (d > reach) continue;
        const float scale = d <= def.radius || def.falloff == 0.0f ? 1.0f : 1.0f - (d - def.radius) / def.falloff;
        // Outwards from the centre through the nearest surface point; from a
        // centre inside the shape, through the body's centre of mass.
        Vec2 dir = -g.normal;
        Vec2 point = def.center + g.gap * dir;
        if (g.gap <= 0.0f) {
            dir = normalize(body.center - def.center);
            point = body.center;
        }
        if (dir == Vec2{}) continue;  // the centre is the centre of mass: no direction to push in
        pushes.push_back({sh.body, (scale * def.impulse) * dir, point});
    }
    // The velocities each body would have, checked as applyLinearImpulse
    // checks them, before any change (pushes are grouped by body: stable sort).
    std::stable_sort(pushes.begin(), pushes.end(), [](const Push& a, const Push& b) { return a.body < b.body; });
    struct Result {
        int body;
        Vec2 v;
        float w;
    };
    std::vector<Result> results;
    for (const Push& p : pushes) {
        const detail::Body& body = w.bodies[p.body];
        if (results.empty() || results.back().body != p.body) results.push_back({p.body, body.v, body.w});
        results.back().v += body.invMass * p.impulse;
        results.back().w += body.invInertia * cross(p.point - body.center, p.impulse);
    }
    for (const Result& r : results) {
        detail::requireBounded(r.v, "velocity after the explosion");
        detail::requireBounded(r.w, "angular velocity after the explosion");
    }
    for (const Result& r : results) {
        detail::wakeBody(w, r.body);
        w.bodies[r.body].v = r.v;
        w.bodies[r.body].w = r.w;
        detail::noteMotionSet(w, r.body);
    }
}

}  // namespace i2d
