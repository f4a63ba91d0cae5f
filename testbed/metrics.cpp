// Testbed — state measurements.
#include "metrics.hpp"

#include <algorithm>
#include <cmath>

namespace tb {

Energy computeEnergy(const i2d::World& world) {
    Energy e;
    const i2d::Vec2 g = world.gravity();
    for (i2d::BodyId id : world.bodies()) {
        if (world.bodyType(id) != i2d::BodyType::dynamic_body) continue;
        // Accumulate in double: large scenes sum tens of thousands of terms.
        double m = world.mass(id);
        double inertia = world.rotationalInertia(id);
        i2d::Vec2 v = world.linearVelocity(id);
        double w = world.angularVelocity(id);
        i2d::Vec2 c = world.worldCenterOfMass(id);
        double s = world.gravityScale(id);
        e.kinetic += 0.5 * m * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * inertia * w * w;
        e.potential -= m * s * (double(g.x) * c.x + double(g.y) * c.y);
    }
    return e;
}

float maxPenetration(const i2d::World& world) {
    float worst = 0.0f;
    for (const i2d::ContactData& c : world.contacts())
        for (int i = 0; i < c.manifold.pointCount; ++i) worst = std::max(worst, -c.manifold.points[i].separation);
    return worst;
}

bool allFinite(const i2d::World& world) {
    for (i2d::BodyId id : world.bodies()) {
        if (!i2d::isFinite(world.position(id)) || !std::isfinite(world.angle(id)) ||
            !i2d::isFinite(world.linearVelocity(id)) || !std::isfinite(world.angularVelocity(id)))
            return false;
    }
    return true;
}

BodyState bodyState(const i2d::World& world, i2d::BodyId id) {
    i2d::Vec2 p = world.position(id);
    i2d::Vec2 v = world.linearVelocity(id);
    return {p.x, p.y, world.angle(id), v.x, v.y, world.angularVelocity(id)};
}

}  // namespace tb
