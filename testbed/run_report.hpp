// Testbed — one headless run of a scene and what it measures: timing,
// contacts, penetration, energy, named bodies, joint error and the scene's
// error figure. Shared by `testbed run`, the validation cases and the sweep.
#pragma once

#include <string>
#include <vector>

#include "error_metric.hpp"
#include "scene.hpp"
#include "simulation.hpp"

namespace tb {

/// Measurements of one run (see docs/scene-format.md, "testbed run --json").
struct RunReport {
    std::string scene;
    EngineKind engine = EngineKind::impulse2d;
    std::vector<std::string> notes;  ///< what the engine could not express of the scene
    i2d::WorldSettings settings;     ///< Impulse2D's settings of the run
    Box2DSettings box2d;             ///< Box2D's iteration counts of the run
    long steps = 0;                  ///< steps requested
    long stepsCompleted = 0;         ///< fewer when a state went non-finite
    float dt = 0.0f;
    double msMedian = 0.0, msMin = 0.0, msMax = 0.0;
    int bodies = 0;
    int joints = 0;
    int contacts = 0;  ///< touching contacts after the last step
    int maxContacts = 0;
    int awakeBodies = 0;
    float maxPenetration = 0.0f;
    float finalPenetration = 0.0f;  ///< deepest contact after the last step (m)
    double maxSpeed = 0.0;          ///< largest body speed over the run (m/s)
    double energyInitial = 0.0, energyFinal = 0.0, energyMax = 0.0;
    bool nan = false;
    /// Dynamic bodies whose origin ends more than kDisplacedDistance from its start.
    int displaced = 0;
    static constexpr float kDisplacedDistance = 0.5f;
    /// Dynamic bodies that tunnelled into or through a static shape (or, for
    /// a bullet, a non-bullet dynamic body); driven bodies that snagged; how
    /// many bodies were driven and their largest vertical speed (m/s) after
    /// the 5th step (tb::CrossingCheck).
    int tunnelled = 0;
    int snagged = 0;
    int driven = 0;
    float drivenMaxVerticalSpeed = 0.0f;
    float jointErrorMax = 0.0f;    ///< largest tb::maxJointError over the run (m)
    float jointErrorFinal = 0.0f;  ///< after the last step (m)
    struct Named {
        std::string name;
        float x0, y0, angle0, x, y, angle, vx, vy, w;
        float maxDx = 0;           ///< largest |x − x0| over the run
        float minY = 0, maxY = 0;  ///< lowest and highest y over the run (including the start)
    };
    std::vector<Named> named;  ///< sorted by name
    /// The median over the steps of each stage's time as the engine measures
    /// it (ms; Simulation::stageTimes), in stage order; empty for Box2D.
    std::vector<std::pair<std::string, double>> stageMedians;
    /// The scene's error figure (tb::errorMetricFor; metric none for scenes without one).
    ErrorValue error;
};

/// Told about the state after every step of runScene (outside the timing),
/// including the step that left a non-finite state, after which the run stops.
class StepObserver {
public:
    virtual ~StepObserver() = default;
    /// `step` counts from 1.
    virtual void afterStep(long step, const Simulation& sim) = 0;
};

/// Build and step a scene in the given engine (with the overrides already in
/// desc.settings; `box2d` only matters for EngineKind::box2d). `observer`, if
/// given, sees the state after every step (testbed run --trace). With
/// `checkCrossings` false the tunnelled/snagged counts stay 0: the check
/// reads every body after every step, which is outside the timing but leaves
/// the caches colder for the next step (about 8 µs per step for the 22,000
/// sleeping bodies of many_pyramids); the speed sweeps turn it off.
RunReport runScene(const SceneDesc& desc, long steps, EngineKind engine = EngineKind::impulse2d,
                   const Box2DSettings& box2d = {}, StepObserver* observer = nullptr, bool checkCrossings = true);

}  // namespace tb
