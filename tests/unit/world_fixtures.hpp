// Small scene builders shared by the world tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <impulse2d/impulse2d.hpp>

namespace i2d::test {

/// Static ground whose top face is the line y = 0, from x = −halfWidth to +halfWidth.
inline BodyId makeGround(World& world, float halfWidth = 50.0f, float friction = 0.6f) {
    BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {.friction = friction}, makeOffsetBox(halfWidth, 1.0f, {0.0f, -1.0f}, 0.0f));
    return ground;
}

inline BodyId makeBox(World& world, Vec2 position, float halfExtent = 0.5f, float density = 1.0f,
                      float friction = 0.6f) {
    BodyId body = world.createBody({.type = BodyType::dynamic_body, .position = position});
    world.createPolygonShape(body, {.density = density, .friction = friction}, i2d::makeBox(halfExtent, halfExtent));
    return body;
}

/// Kinetic (linear and rotational) plus potential energy of `bodies` in
/// double precision (J), the potential in the world's gravity (along −y)
/// measured from the height `floorY`.
inline double totalEnergy(const World& world, const std::vector<BodyId>& bodies, double floorY = 0.0) {
    const double g = -world.settings().gravity.y;
    double e = 0.0;
    for (BodyId b : bodies) {
        const Vec2 v = world.linearVelocity(b);
        const double w = world.angularVelocity(b);
        e += 0.5 * world.mass(b) * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * world.rotationalInertia(b) * w * w +
             world.mass(b) * g * (double(world.worldCenterOfMass(b).y) - floorY);
    }
    return e;
}

/// The largest total energy of `bodies` over 5 s of stepping at 60 Hz,
/// relative to its start (the potential measured from `floorY`); a
/// non-finite energy stops the run and is returned.
inline double peakEnergyOver5s(World& world, const std::vector<BodyId>& bodies, double floorY) {
    const double start = totalEnergy(world, bodies, floorY);
    double peak = start;
    for (int i = 0; i < 300; ++i) {
        world.step(1.0f / 60.0f);
        peak = std::max(peak, totalEnergy(world, bodies, floorY));
        if (!std::isfinite(peak)) break;
    }
    return peak / start;
}

}  // namespace i2d::test
