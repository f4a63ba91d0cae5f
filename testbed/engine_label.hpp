// Testbed — an engine and the settings it runs a scene with, in a few words,
// for the captions of rendered panels and the legends of trace plots
// ("impulse2d: soft_step, 4 substeps, closed_form, sleep on").
#pragma once

#include <impulse2d/impulse2d.hpp>

#include <string>

#include "simulation.hpp"

namespace tb {

/// Impulse2D's label reads `settings`; Box2D's reads `box2d` and the sleep flag.
std::string engineSettingsLabel(EngineKind engine, const i2d::WorldSettings& settings, const Box2DSettings& box2d);

}  // namespace tb
