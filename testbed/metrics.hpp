// Testbed — measurements of a simulation's state, the same formulas for every
// engine (they read tb::Simulation, never an engine directly).
#pragma once

#include <vector>

#include "simulation.hpp"

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
Energy computeEnergy(const Simulation& sim, i2d::Vec2 gravity);

/// True when every body's position, angle and velocities are finite.
bool allFinite(const Simulation& sim);

/// Largest speed |v| of a dynamic body (m/s); a non-finite speed is returned
/// as such rather than lost to the comparison.
double largestBodySpeed(const Simulation& sim);

/// How far a joint is from what it asks (m), from the world anchors computed
/// from the body samples: for a rigid distance joint |d − L|, for a length
/// range the amount d lies outside [min, max] (springs without a range count
/// 0); revolute and weld joints: the distance between the anchors; prismatic
/// and wheel joints: anchor B's distance from the axis line, or how far it
/// lies beyond the translation limit, whichever is larger; pulley joints:
/// |lengthA + ratio·lengthB − its rest value|. Motor, mouse and gear joints
/// count 0 (drives, and a coupling of angles with translations).
float jointError(const JointDesc& joint, const BodySample& a, const BodySample& b);
/// Largest jointError over the scene's joints (0 when it has none).
float maxJointError(const SceneDesc& desc, const Simulation& sim);

}  // namespace tb
