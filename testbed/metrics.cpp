// Testbed — state measurements.
#include "metrics.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace tb {

double largestBodySpeed(const Simulation& sim) {
    double maxSpeed = 0.0;
    for (int i = 0, n = sim.bodyCount(); i < n; ++i) {
        const BodySample s = sim.sample(i);
        if (!s.dynamic) continue;
        const double speed = std::hypot(double(s.vx), double(s.vy));
        if (!(speed <= maxSpeed)) maxSpeed = speed;
    }
    return maxSpeed;
}

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

float jointError(const JointDesc& j, const BodySample& a, const BodySample& b) {
    return std::visit(
        [&](const auto& d) -> float {
            using D = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<D, i2d::DistanceJointDef>) {
                const float len = i2d::distance(worldPoint(a, d.localAnchorA), worldPoint(b, d.localAnchorB));
                if (!d.enableSpring) return std::abs(len - d.length);
                if (!d.enableLimit) return 0.0f;
                return std::max({0.0f, len - d.maxLength, d.minLength - len});
            } else if constexpr (std::is_same_v<D, i2d::RevoluteJointDef> || std::is_same_v<D, i2d::WeldJointDef>) {
                return i2d::distance(worldPoint(a, d.localAnchorA), worldPoint(b, d.localAnchorB));
            } else if constexpr (std::is_same_v<D, i2d::PrismaticJointDef> || std::is_same_v<D, i2d::WheelJointDef>) {
                // Off the axis, and beyond the translation limit when there is one.
                const i2d::Vec2 axis = i2d::normalize(worldPoint(a, d.localAxisA) - worldPoint(a, {}));
                const i2d::Vec2 gap = worldPoint(b, d.localAnchorB) - worldPoint(a, d.localAnchorA);
                const float along = i2d::dot(gap, axis);
                float err = std::abs(i2d::cross(axis, gap));
                if (d.enableLimit) err = std::max({err, along - d.upperTranslation, d.lowerTranslation - along});
                return err;
            } else if constexpr (std::is_same_v<D, i2d::PulleyJointDef>) {
                const float la = i2d::distance(d.groundAnchorA, worldPoint(a, d.localAnchorA));
                const float lb = i2d::distance(d.groundAnchorB, worldPoint(b, d.localAnchorB));
                return std::abs(la + d.ratio * lb - (d.lengthA + d.ratio * d.lengthB));
            } else {
                return 0.0f;  // motor and mouse joints are drives, a gear couples angles and translations
            }
        },
        j.def);
}

float maxJointError(const SceneDesc& desc, const Simulation& sim) {
    float worst = 0.0f;
    for (const JointDesc& j : desc.joints)
        worst = std::max(worst, jointError(j, sim.sample(j.bodyA), sim.sample(j.bodyB)));
    return worst;
}

}  // namespace tb
