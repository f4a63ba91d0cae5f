// Testbed — `testbed run`: step a scene without rendering and report the
// measurements, as text or one JSON object.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/arguments.hpp"
#include "cli/settings_options.hpp"
#include "simulation.hpp"

namespace tb {

struct RunOptions {
    std::string scene;      ///< shipped scene name or path to a file
    std::string assetsDir;  ///< empty: defaultAssetsDir()
    std::optional<long> steps;
    std::optional<double> seconds;
    bool json = false;
    std::string tracePath;  ///< --trace FILE.csv; empty: no trace
    EngineKind engine = EngineKind::impulse2d;
    SettingsOverrides overrides;

    /// Box2D's iteration counts: --velocity-iterations / --position-iterations
    /// when given, else Box2D's usual 8 and 3 (the scene's own iteration
    /// counts are Impulse2D's, per substep, and do not carry over).
    Box2DSettings box2dSettings() const;
};

/// Parse `run` arguments (after the word "run"). Throws UsageError.
RunOptions parseRunOptions(const std::vector<std::string>& args);

/// `testbed run ...`; returns the process exit code (2 for bad arguments,
/// 1 for a bad scene or a non-finite state).
int runRunCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

extern const char* const kRunHelp;

}  // namespace tb
