// Testbed — `testbed run` (step a scene without rendering and report
// measurements, as text or one JSON object) and `testbed list`.
#pragma once

#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "error_metric.hpp"
#include "scene.hpp"
#include "simulation.hpp"

namespace tb {

/// Bad command-line arguments; what() is the message shown before the usage hint.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

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

/// Consume args[i] (and its value, advancing i) if it is one of
/// --velocity-iterations N, --position-iterations N, --substeps N,
/// --correction soft_step|baumgarte|split, --impact closed_form|velocity_bias,
/// --sleep on|off. Returns false when args[i] is none of them; throws
/// UsageError on a missing or bad value. Shared with render/view.
bool parseSettingsOption(const std::vector<std::string>& args, std::size_t& i, SettingsOverrides& overrides);
/// Help text for the options above.
const char* settingsOptionsHelp();

struct RunOptions {
    std::string scene;      ///< shipped scene name or path to a file
    std::string assetsDir;  ///< empty: defaultAssetsDir()
    std::optional<long> steps;
    std::optional<double> seconds;
    bool json = false;
    EngineKind engine = EngineKind::impulse2d;
    SettingsOverrides overrides;

    /// Box2D's iteration counts: --velocity-iterations / --position-iterations
    /// when given, else Box2D's usual 8 and 3 (the scene's own iteration
    /// counts are Impulse2D's, per substep, and do not carry over).
    Box2DSettings box2dSettings() const;
};

/// Parse `run` arguments (after the word "run"). Throws UsageError.
RunOptions parseRunOptions(const std::vector<std::string>& args);

/// Measurements of one run (see docs/scene-format.md, "testbed run --json").
struct RunReport {
    std::string scene;
    EngineKind engine = EngineKind::impulse2d;
    std::vector<std::string> notes;  ///< what the engine could not express of the scene
    i2d::WorldSettings settings;     ///< Impulse2D's settings of the run
    Box2DSettings box2d;             ///< Box2D's iteration counts of the run
    long steps = 0;            ///< steps requested
    long stepsCompleted = 0;   ///< fewer when a state went non-finite
    float dt = 0.0f;
    double msMedian = 0.0, msMin = 0.0, msMax = 0.0;
    int bodies = 0;
    int joints = 0;
    int contacts = 0;          ///< touching contacts after the last step
    int maxContacts = 0;
    int awakeBodies = 0;
    float maxPenetration = 0.0f;
    double energyInitial = 0.0, energyFinal = 0.0, energyMax = 0.0;
    bool nan = false;
    /// Dynamic bodies whose origin ends more than kDisplacedDistance from its start.
    int displaced = 0;
    static constexpr float kDisplacedDistance = 0.5f;
    float jointErrorMax = 0.0f;    ///< largest tb::maxJointError over the run (m)
    float jointErrorFinal = 0.0f;  ///< after the last step (m)
    struct Named {
        std::string name;
        float x0, y0, angle0, x, y, angle, vx, vy, w;
        float maxDx = 0;           ///< largest |x − x0| over the run
        float minY = 0, maxY = 0;  ///< lowest and highest y over the run (including the start)
    };
    std::vector<Named> named;  ///< sorted by name
    /// The scene's error figure (tb::errorMetricFor; metric none for scenes without one).
    ErrorValue error;
};

/// Build and step a scene in the given engine (with the overrides already in
/// desc.settings; `box2d` only matters for EngineKind::box2d).
RunReport runScene(const SceneDesc& desc, long steps, EngineKind engine = EngineKind::impulse2d,
                   const Box2DSettings& box2d = {});

/// The report as one JSON object (field names are relied on by other tools).
std::string reportToJson(const RunReport& report);

/// `testbed run ...`; returns the process exit code.
int runRunCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
/// `testbed list ...`; returns the process exit code.
int runListCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

extern const char* const kRunHelp;
extern const char* const kListHelp;

}  // namespace tb
