// Testbed — measurements of a world's state used by `testbed run` and tests.
#pragma once

#include <impulse2d/impulse2d.hpp>

namespace tb {

/// Mechanical energy of the dynamic bodies (J): kinetic ½ m |v|² + ½ I ω²
/// (v of the centre of mass, I about it) plus gravitational potential
/// −m (s g)·x_com, with s the body's gravity scale and x_com its world centre
/// of mass. Static and kinematic bodies contribute nothing.
struct Energy {
    double kinetic = 0.0;
    double potential = 0.0;
    double total() const { return kinetic + potential; }
};
Energy computeEnergy(const i2d::World& world);

/// Largest penetration (−separation, m) over the points of the touching
/// contacts, 0 when nothing overlaps.
float maxPenetration(const i2d::World& world);

/// True when every body's position, angle and velocities are finite.
bool allFinite(const i2d::World& world);

/// State of one body, as reported per named body by `testbed run`.
struct BodyState {
    float x = 0, y = 0, angle = 0, vx = 0, vy = 0, w = 0;
};
BodyState bodyState(const i2d::World& world, i2d::BodyId id);

}  // namespace tb
