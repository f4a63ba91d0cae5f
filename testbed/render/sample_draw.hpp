// Testbed renderer — a scene drawn from any engine: the scene description's
// shapes and joints at the transforms tb::Simulation::sample() reads back.
// Both panels of a comparison go through this one code path, so a difference
// on screen is a difference of state, not of drawing.
#pragma once

#include <optional>

#include <impulse2d/debug_draw.hpp>

#include "scene.hpp"
#include "simulation.hpp"

namespace tb {

/// Draws every body of `desc` (shapes in the colours World::draw uses:
/// static, kinematic, awake, asleep) at its sampled pose, then the joints
/// when `dd.drawJoints`. `colour`, when given, replaces the body colours.
/// Bodies whose pose is not finite are skipped.
void drawSimulation(i2d::DebugDraw& dd, const SceneDesc& desc, const Simulation& sim,
                    std::optional<i2d::Color> colour = std::nullopt);

}  // namespace tb
