// Testbed — a run's report as JSON or text (see report_format.hpp).
#include "report_format.hpp"

#include <nlohmann/json.hpp>

#include <iomanip>
#include <ostream>

#include "enum_names.hpp"

namespace tb {

std::string reportToJson(const RunReport& r) {
    using json = nlohmann::ordered_json;
    // nlohmann writes non-finite numbers as null; the "nan" field says why.
    json j;
    j["scene"] = r.scene;
    j["engine"] = engineName(r.engine);
    j["steps"] = r.steps;
    j["steps_completed"] = r.stepsCompleted;
    j["dt"] = r.dt;
    j["ms_per_step"] = {{"median", r.msMedian}, {"min", r.msMin}, {"max", r.msMax}};
    json stages = nullptr;  // an engine without its own stage timing
    for (const auto& [name, value] : r.stageMedians) stages[name] = value;
    j["profile"] = stages;
    j["bodies"] = r.bodies;
    j["awake_bodies"] = r.awakeBodies;
    j["joints"] = r.joints;
    j["contacts"] = r.contacts;
    j["max_contacts"] = r.maxContacts;
    j["max_penetration"] = r.maxPenetration;
    j["final_penetration"] = r.finalPenetration;
    j["max_speed"] = r.maxSpeed;
    j["energy"] = {{"initial", r.energyInitial}, {"final", r.energyFinal}, {"max", r.energyMax}};
    j["nan"] = r.nan;
    j["displaced"] = r.displaced;
    j["tunnelled"] = r.tunnelled;
    j["snagged"] = r.snagged;
    j["driven"] = {{"bodies", r.driven}, {"max_vertical_speed", r.drivenMaxVerticalSpeed}};
    j["joint_error"] = {{"max", r.jointErrorMax}, {"final", r.jointErrorFinal}};
    json named = json::object();
    for (const auto& n : r.named)
        named[n.name] = {{"x0", n.x0}, {"y0", n.y0},        {"angle0", n.angle0}, {"x", n.x},
                         {"y", n.y},   {"angle", n.angle},  {"vx", n.vx},         {"vy", n.vy},
                         {"w", n.w},   {"max_dx", n.maxDx}, {"min_y", n.minY},    {"max_y", n.maxY}};
    j["named"] = named;
    if (r.engine == EngineKind::box2d) {
        j["settings"] = {{"velocity_iterations", r.box2d.velocityIterations},
                         {"position_iterations", r.box2d.positionIterations},
                         {"sleep", r.settings.enableSleep}};
    } else {
        const i2d::WorldSettings& s = r.settings;
        j["settings"] = {{"correction", enumName(s.positionCorrection)},
                         {"impact", enumName(s.impactModel)},
                         {"velocity_iterations", s.velocityIterations},
                         {"position_iterations", s.positionIterations},
                         {"substeps", s.substeps},
                         {"contact_hertz", s.contactHertz},
                         {"contact_damping_ratio", s.contactDampingRatio},
                         {"exact_column_tilt", s.exactColumnTilt},
                         {"sleep", s.enableSleep}};
    }
    j["notes"] = r.notes;
    if (r.error.metric == ErrorMetric::none) {
        j["error"] = nullptr;
    } else {
        j["error"] = {{"metric", errorMetricName(r.error.metric)},
                      {"value", r.error.value},
                      {"unit", errorMetricUnit(r.error.metric)}};
        if (errorMetricHasCollapse(r.error.metric)) j["error"]["collapsed"] = r.error.collapsed;
    }
    return j.dump();
}

void printReportText(const RunReport& r, std::ostream& out) {
    out << "scene " << r.scene << " (" << engineName(r.engine) << "): " << r.stepsCompleted << "/" << r.steps
        << " steps of " << r.dt << " s, " << r.bodies << " bodies, " << r.joints << " joints\n";
    out << std::fixed << std::setprecision(3);
    out << "  ms/step  median " << r.msMedian << "  min " << r.msMin << "  max " << r.msMax << "\n";
    out << "  contacts " << r.contacts << " (max " << r.maxContacts << "), max penetration " << std::setprecision(5)
        << r.maxPenetration << " m, awake " << r.awakeBodies << "\n";
    out << std::setprecision(3) << "  energy   initial " << r.energyInitial << "  final " << r.energyFinal << "  max "
        << r.energyMax << " J\n";
    out << "  displaced (> 0.5 m) " << r.displaced << ", joint error max " << std::setprecision(5) << r.jointErrorMax
        << " m, final " << r.jointErrorFinal << " m\n"
        << std::setprecision(3);
    out << "  tunnelled " << r.tunnelled << ", snagged " << r.snagged << " of " << r.driven << " driven (largest |vy| "
        << std::setprecision(4) << r.drivenMaxVerticalSpeed << " m/s)\n"
        << std::setprecision(3);
    if (r.error.metric != ErrorMetric::none)
        out << "  error: " << errorMetricName(r.error.metric) << " " << std::setprecision(5) << r.error.value << " "
            << errorMetricUnit(r.error.metric) << (r.error.collapsed ? " (collapsed)" : "") << "\n"
            << std::setprecision(3);
    if (r.nan) out << "  NON-FINITE STATE after step " << r.stepsCompleted << "\n";
    for (const auto& n : r.notes) out << "  note: " << n << "\n";
    for (const auto& n : r.named)
        out << "  " << n.name << ": (" << n.x0 << ", " << n.y0 << ", " << n.angle0 << ") -> (" << n.x << ", " << n.y
            << ", " << n.angle << "), v (" << n.vx << ", " << n.vy << "), w " << n.w << "\n";
    out.unsetf(std::ios::floatfield);
}

}  // namespace tb
