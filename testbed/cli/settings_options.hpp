// Testbed — the command-line options that override a scene's world settings
// (--velocity-iterations, --correction, --sleep, ...), read with ArgReader.
#pragma once

#include <impulse2d/impulse2d.hpp>

#include <optional>

#include "cli/arguments.hpp"

namespace tb {

/// Overrides of the scene's world settings given on the command line.
struct SettingsOverrides {
    std::optional<int> velocityIterations;
    std::optional<int> positionIterations;
    std::optional<int> substeps;
    std::optional<i2d::PositionCorrection> correction;
    std::optional<i2d::ImpactModel> impact;
    std::optional<bool> sleep;

    void applyTo(i2d::WorldSettings& settings) const;
};

/// Consume the reader's current option (and its value) if it is one of
/// --velocity-iterations N, --position-iterations N, --substeps N,
/// --correction soft_step|baumgarte|split, --impact closed_form|velocity_bias,
/// --sleep on|off. Returns false when it is none of them; throws UsageError
/// on a missing or bad value.
bool parseSettingsOption(ArgReader& reader, SettingsOverrides& overrides);
/// Help text for the options above.
const char* settingsOptionsHelp();

}  // namespace tb
