// Testbed — the per-step trace of a run (see trace_writer.hpp).
#include "trace_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "metrics.hpp"

namespace tb {

std::vector<std::string> traceColumns(const std::vector<std::string>& namedBodies) {
    std::vector<std::string> columns{
        "step[count]",        "time[s]",        "total_energy[J]",     "kinetic_energy[J]", "potential_energy[J]",
        "max_penetration[m]", "max_speed[m/s]", "awake_bodies[count]", "contacts[count]",   "joint_error[m]"};
    for (const std::string& name : namedBodies) {
        columns.push_back(name + ".x[m]");
        columns.push_back(name + ".y[m]");
        columns.push_back(name + ".angle[rad]");
    }
    return columns;
}

TraceWriter::TraceWriter(std::string path) : path_(std::move(path)) {
    out_.open(path_, std::ios::out | std::ios::trunc);
    if (!out_) throw TraceError("cannot write '" + path_ + "': " + std::strerror(errno));
}

TraceWriter::~TraceWriter() {
    if (out_.is_open()) out_.flush();
}

void TraceWriter::check() {
    if (!out_) throw TraceError("writing '" + path_ + "' failed");
}

void TraceWriter::begin(const SceneDesc& desc) {
    dt_ = desc.dt;
    gravity_ = desc.settings.gravity;
    joints_ = desc.joints;
    named_.clear();
    for (std::size_t i = 0; i < desc.bodies.size(); ++i)
        if (!desc.bodies[i].name.empty()) named_.emplace_back(desc.bodies[i].name, static_cast<int>(i));
    std::sort(named_.begin(), named_.end());
    std::vector<std::string> names;
    for (const auto& n : named_) names.push_back(n.first);
    const std::vector<std::string> columns = traceColumns(names);
    for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << columns[i];
    out_ << "\n";
    check();
}

void TraceWriter::afterStep(long step, const Simulation& sim) {
    const Energy e = computeEnergy(sim, gravity_);
    const double maxSpeed = largestBodySpeed(sim);
    int awake = 0;
    for (int i = 0, n = sim.bodyCount(); i < n; ++i) {
        const BodySample s = sim.sample(i);
        if (s.dynamic && s.awake) ++awake;
    }
    float jointErr = 0.0f;
    for (const JointDesc& j : joints_) {
        const float err = jointError(j, sim.sample(j.bodyA), sim.sample(j.bodyB));
        if (!(err <= jointErr)) jointErr = err;
    }
    char buf[512];
    std::snprintf(buf, sizeof buf, "%ld,%.6f,%.10g,%.10g,%.10g,%.6g,%.6g,%d,%d,%.6g", step,
                  static_cast<double>(step) * static_cast<double>(dt_), e.total(), e.kinetic, e.potential,
                  static_cast<double>(sim.maxPenetration()), maxSpeed, awake, sim.touchingContactCount(),
                  static_cast<double>(jointErr));
    out_ << buf;
    for (const auto& n : named_) {
        const BodySample s = sim.sample(n.second);
        std::snprintf(buf, sizeof buf, ",%.8g,%.8g,%.8g", static_cast<double>(s.x), static_cast<double>(s.y),
                      static_cast<double>(s.angle));
        out_ << buf;
    }
    out_ << "\n";
    lastStep_ = step;
    check();
}

void TraceWriter::finish(const RunReport& report, const std::string& engineLabel) {
    if (closed_) return;
    closed_ = true;
    char buf[256];
    const double t = static_cast<double>(report.stepsCompleted) * static_cast<double>(report.dt);
    out_ << "# scene: " << report.scene << "\n# engine: " << engineLabel << "\n";
    if (report.nan) {
        std::snprintf(buf, sizeof buf,
                      "# stopped: non-finite state after step %ld of %ld (t = %.4f s); the run ends there\n",
                      report.stepsCompleted, report.steps, t);
    } else {
        std::snprintf(buf, sizeof buf, "# end: %ld of %ld steps (t = %.4f s)\n", report.stepsCompleted, report.steps,
                      t);
    }
    out_ << buf;
    out_.flush();
    check();
}

void TraceWriter::abort(const std::string& why) {
    if (closed_) return;
    closed_ = true;
    out_ << "# stopped: after step " << lastStep_ << ": " << why << "\n";
    out_.flush();
}

}  // namespace tb
