// Testbed — one error figure per scene, for the speed-against-error sweep.
//
// Each benchmark scene has one number saying how far its simulation is from
// what it should do (a pyramid that should not move, a chain that should not
// stretch, a ball that should rebound to a known height). The metric is
// chosen by scene name (errorMetricFor); its definitions are in
// docs/performance.md and docs/scene-format.md ("testbed run --json", field
// `error`). Like every testbed measurement it reads tb::Simulation only, so
// the figure means the same in every engine.
#pragma once

#include <string>
#include <vector>

#include "simulation.hpp"

namespace tb {

enum class ErrorMetric {
    none,
    /// Largest distance (m) of any dynamic body's origin from its start,
    /// over the run: sway, sinking and collapse of stacks and pyramids.
    max_excursion,
    /// Largest sideways distance |x − x0| (m) of any dynamic body's origin
    /// from its start, over the run: for stacks that start with gaps, whose
    /// settling is not an error but whose sway and collapse are.
    max_sway,
    /// Largest penetration (m) over the touching contacts, over the run.
    max_penetration,
    /// Largest joint error (m, tb::maxJointError) over the run.
    joint_stretch,
    /// Largest |h − e²·d| (m) over the named dynamic bodies: d the drop from
    /// the start to the lowest point before the first rebound, h the height
    /// of the first rebound's apex above that lowest point, e the pair's
    /// restitution max(e_body, largest restitution of a static shape).
    rebound_error,
    /// Largest |E(t) − E(0)| over the run divided by the swing energy: for
    /// each dynamic body hung by a distance joint from a static body,
    /// m |g| (y0 − lowest y the joint allows). Dimensionless.
    energy_drift,
};

/// Name used in the JSON report and the sweep's CSV ("max_excursion", ...; "" for none).
const char* errorMetricName(ErrorMetric metric);
/// Unit of the metric's value ("m", "1").
const char* errorMetricUnit(ErrorMetric metric);

/// The metric of a scene, by name: pyramid100, many_pyramids,
/// many_pyramids_small, card_house → max_excursion; tall_stack20,
/// tall_stack50 → max_sway; rain1000, circle_pile1000 → max_penetration;
/// joint_grid, heavy_chain → joint_stretch; bounce → rebound_error;
/// pendulum_wave → energy_drift; any other scene → none.
ErrorMetric errorMetricFor(const std::string& sceneName);

struct ErrorValue {
    ErrorMetric metric = ErrorMetric::none;
    double value = 0.0;
    /// max_excursion and max_sway only (else false and not reported): at
    /// least max(1, 1%) of the dynamic bodies end more than
    /// kCollapseDistance sideways from their start. Sideways, because a soft
    /// solver's stack sinks without falling.
    bool collapsed = false;
    static constexpr float kCollapseDistance = 0.5f;
};

/// True when the metric reports `collapsed`.
bool errorMetricHasCollapse(ErrorMetric metric);

/// Follows one run step by step and computes the scene's error figure.
/// Call start() before the first step, observe() after each, then result()
/// with the simulation in its final state.
/// The penetration and joint figures are handed in by the caller, which
/// measures them anyway.
class ErrorTracker {
public:
    ErrorTracker(const SceneDesc& desc, ErrorMetric metric);

    void start(const Simulation& sim);
    void observe(const Simulation& sim, float penetration, float jointError);
    ErrorValue result(const Simulation& sim) const;

private:
    struct Ball {
        int index = 0;
        float restitution = 0.0f;
        float y0 = 0.0f;
        float lowest = 0.0f;  ///< lowest y before the rebound
        float apex = 0.0f;    ///< highest y after it
        int phase = 0;        ///< 0 falling, 1 rising, 2 apex passed
    };

    const SceneDesc& desc_;
    ErrorMetric metric_;
    double worst_ = 0.0;
    std::vector<BodySample> start_;       ///< max_excursion, max_sway: dynamic bodies' start
    std::vector<int> dynamic_;            ///< their indices
    std::vector<Ball> balls_;             ///< rebound_error
    double energy0_ = 0.0, swing_ = 0.0;  ///< energy_drift
};

}  // namespace tb
