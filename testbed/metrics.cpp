// Testbed — state measurements.
#include "metrics.hpp"

#include <algorithm>
#include <cmath>

namespace tb {

Energy computeEnergy(const Simulation& sim, i2d::Vec2 g) {
    Energy e;
    for (int i = 0, n = sim.bodyCount(); i < n; ++i) {
        const BodySample s = sim.sample(i);
        if (!s.dynamic) continue;
        // Accumulate in double: large scenes sum tens of thousands of terms.
        const double m = s.mass;
        e.kinetic += 0.5 * m * (double(s.vx) * s.vx + double(s.vy) * s.vy) + 0.5 * double(s.inertia) * s.w * s.w;
        e.potential -= m * s.gravityScale * (double(g.x) * s.cx + double(g.y) * s.cy);
    }
    return e;
}

bool allFinite(const Simulation& sim) {
    for (int i = 0, n = sim.bodyCount(); i < n; ++i) {
        const BodySample s = sim.sample(i);
        for (float v : {s.x, s.y, s.angle, s.vx, s.vy, s.w})
            if (!std::isfinite(v)) return false;
    }
    return true;
}

namespace {

i2d::Vec2 worldPoint(const BodySample& s, i2d::Vec2 local) {
    const float c = std::cos(s.angle), sn = std::sin(s.angle);
    return {s.x + c * local.x - sn * local.y, s.y + sn * local.x + c * local.y};
}

}  // namespace

float jointError(const DistanceJointDesc& j, const BodySample& a, const BodySample& b) {
    const float d = i2d::distance(worldPoint(a, j.def.localAnchorA), worldPoint(b, j.def.localAnchorB));
    if (!j.def.enableSpring) return std::abs(d - j.def.length);
    if (!j.def.enableLimit) return 0.0f;
    return std::max({0.0f, d - j.def.maxLength, j.def.minLength - d});
}

float maxJointError(const SceneDesc& desc, const Simulation& sim) {
    float worst = 0.0f;
    for (const DistanceJointDesc& j : desc.joints)
        worst = std::max(worst, jointError(j, sim.sample(j.bodyA), sim.sample(j.bodyB)));
    return worst;
}

}  // namespace tb
