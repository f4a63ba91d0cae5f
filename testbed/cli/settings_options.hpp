// Testbed — the command-line options that override a scene's world settings
// (--velocity-iterations, --correction, --sleep, ...), read with ArgReader.
#pragma once

#include <impulse2d/impulse2d.hpp>

#include <optional>

#include "cli/arguments.hpp"
#include "simulation.hpp"

namespace tb {

/// Overrides of the scene's world settings given on the command line.
struct SettingsOverrides {
    std::optional<int> velocityIterations;
    std::optional<int> positionIterations;
    std::optional<int> substeps;
    std::optional<float> manifoldReuse;
    std::optional<float> exactJointMassRatio;
    std::optional<bool> exactColumnTilt;
    std::optional<float> contactHertz;
    std::optional<float> contactDampingRatio;
    std::optional<int> threads;
    std::optional<i2d::PositionCorrection> correction;
    std::optional<i2d::ImpactModel> impact;
    std::optional<bool> sleep;

    void applyTo(i2d::WorldSettings& settings) const;
    /// The world settings above and the run's worker count (--threads).
    void applyTo(SceneDesc& desc) const;
    /// Box2D's iteration counts: --velocity-iterations / --position-iterations
    /// when given, else Box2D's usual 8 and 3 (the scene's own iteration
    /// counts are Impulse2D's, per substep, and do not carry over).
    Box2DSettings box2dSettings() const;
};

/// Consume the reader's current option (and its value) if it is one of
/// --velocity-iterations N, --position-iterations N, --substeps N,
/// --correction soft_step|baumgarte|split, --impact closed_form|velocity_bias,
/// --sleep on|off, --manifold-reuse D, --exact-joint-mass-ratio R,
/// --exact-column-tilt on|off, --contact-hertz F,
/// --contact-damping-ratio Z, --threads N.
/// Returns false when it is none of them; throws UsageError
/// on a missing or bad value.
bool parseSettingsOption(ArgReader& reader, SettingsOverrides& overrides);
/// Help text for the options above.
const char* settingsOptionsHelp();

}  // namespace tb
