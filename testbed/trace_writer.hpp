// Testbed — `testbed run --trace FILE.csv`: the run's figures after every
// step, one CSV row per step, so that two engines (or two settings) can be
// compared over time rather than only at the end.
//
// Columns (each header names its unit in brackets):
//   step[count], time[s], total_energy[J], kinetic_energy[J], potential_energy[J],
//   max_penetration[m], max_speed[m/s], awake_bodies[count], contacts[count],
//   joint_error[m], then NAME.x[m], NAME.y[m], NAME.angle[rad] per named body
//   (sorted by name).
// Row k is the state after step k (k = 1 .. steps); the figures are those of
// `testbed run --json` (energy: metrics.hpp; the deepest touching contact;
// the largest centre-of-mass speed of a dynamic body; awake dynamic bodies).
// After the rows come comment lines (starting with '#'): "# scene: NAME",
// "# engine: LABEL" (engine_label.hpp),
// then "# end: ..." or, when the run stopped on a non-finite state,
// "# stopped: ..." naming the step and time; that row holds "nan" or "inf".
#pragma once

#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "run_report.hpp"

namespace tb {

/// A trace file that cannot be opened or written; what() names the path.
class TraceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The column names of a trace for the given named bodies (in that order).
std::vector<std::string> traceColumns(const std::vector<std::string>& namedBodies);

class TraceWriter final : public StepObserver {
public:
    /// Opens (creates or truncates) `path`; throws TraceError when it cannot.
    explicit TraceWriter(std::string path);
    ~TraceWriter() override;

    /// Writes the header for `desc` (its named bodies); once, before the run.
    void begin(const SceneDesc& desc);
    void afterStep(long step, const Simulation& sim) override;
    /// The closing lines: the engine label, then where the run ended
    /// (`report.nan`: the step and time it stopped at). Flushes the file.
    void finish(const RunReport& report, const std::string& engineLabel);
    /// Closing line for a run broken off by an error; flushes the file.
    void abort(const std::string& why);

    const std::string& path() const { return path_; }

private:
    void check();

    std::string path_;
    std::ofstream out_;
    float dt_ = 0.0f;
    i2d::Vec2 gravity_{};
    std::vector<JointDesc> joints_;
    std::vector<std::pair<std::string, int>> named_;  ///< name, body index; sorted by name
    long lastStep_ = 0;
    bool closed_ = false;
};

}  // namespace tb
