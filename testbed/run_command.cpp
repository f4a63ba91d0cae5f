// Testbed — `testbed run` and `testbed list`.
#include "run_command.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <ostream>

#include "metrics.hpp"
#include "scene_loader.hpp"

namespace tb {

const char* const kRunHelp =
    "usage: testbed run SCENE [--steps N | --seconds S] [--json] [--engine impulse2d|box2d] [--assets DIR]\n"
    "                  [settings options]\n"
    "\n"
    "Step a scene without rendering and report timing and measurements.\n"
    "SCENE is a shipped scene name (see `testbed list`) or a path to a .json scene file.\n"
    "\n"
    "  --steps N       number of steps (default 600)\n"
    "  --seconds S     simulated time instead of --steps (steps = round(S / dt))\n"
    "  --json          print one JSON object: scene, steps, dt, ms_per_step {median,min,max},\n"
    "                  bodies, contacts, max_contacts, max_penetration, energy {initial,final,max},\n"
    "                  nan, named {NAME: {x0,y0,angle0,x,y,angle,vx,vy,w,max_dx,min_y,max_y}},\n"
    "                  engine, notes, settings, displaced, joint_error {max,final},\n"
    "                  error {metric,value,unit} (the scene's error figure, null if none) and a few more\n"
    "  --engine E      impulse2d (default) or box2d: the same scene in Box2D 2.4.1, same report;\n"
    "                  --velocity-iterations / --position-iterations then set Box2D's counts\n"
    "                  (default 8 and 3) and the other settings options do not apply\n"
    "  --assets DIR    assets directory holding scenes/ (default: next to the executable or the source tree)\n";

const char* const kListHelp =
    "usage: testbed list [--assets DIR]\n"
    "\n"
    "Print the shipped scenes, one per line: NAME, then its description.\n";

const char* settingsOptionsHelp() {
    return "settings options (override the scene's world settings):\n"
           "  --velocity-iterations N   velocity iterations per step (baumgarte, split; soft_step has one\n"
           "                            solve and one relax pass per substep); Box2D's with --engine box2d\n"
           "  --position-iterations N   position iterations (split); Box2D's with --engine box2d\n"
           "  --substeps N              substeps per step (soft_step)\n"
           "  --correction MODE         soft_step | baumgarte | split\n"
           "  --impact MODEL            closed_form | velocity_bias\n"
           "  --sleep on|off            enable or disable sleeping\n";
}

void SettingsOverrides::applyTo(i2d::WorldSettings& s) const {
    if (velocityIterations) s.velocityIterations = *velocityIterations;
    if (positionIterations) s.positionIterations = *positionIterations;
    if (substeps) s.substeps = *substeps;
    if (correction) s.positionCorrection = *correction;
    if (impact) s.impactModel = *impact;
    if (sleep) s.enableSleep = *sleep;
}

namespace {

const std::string& value(const std::vector<std::string>& args, std::size_t& i) {
    if (i + 1 >= args.size()) throw UsageError(args[i] + " needs a value");
    return args[++i];
}

long parseLong(const std::string& opt, const std::string& s, long lo, long hi) {
    char* end = nullptr;
    errno = 0;
    long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
        throw UsageError(opt + ": expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "], got '" + s + "'");
    return v;
}

double parseDouble(const std::string& opt, const std::string& s, double lo, double hi) {
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
        throw UsageError(opt + ": expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "], got '" + s + "'");
    return v;
}

}  // namespace

bool parseSettingsOption(const std::vector<std::string>& args, std::size_t& i, SettingsOverrides& o) {
    const std::string& a = args[i];
    if (a == "--velocity-iterations") {
        o.velocityIterations = static_cast<int>(parseLong(a, value(args, i), 1, 1000));
    } else if (a == "--position-iterations") {
        o.positionIterations = static_cast<int>(parseLong(a, value(args, i), 0, 1000));
    } else if (a == "--substeps") {
        o.substeps = static_cast<int>(parseLong(a, value(args, i), 1, 1000));
    } else if (a == "--correction") {
        const std::string& v = value(args, i);
        if (v == "soft_step") o.correction = i2d::PositionCorrection::soft_step;
        else if (v == "baumgarte") o.correction = i2d::PositionCorrection::baumgarte;
        else if (v == "split") o.correction = i2d::PositionCorrection::split;
        else throw UsageError("--correction: expected soft_step, baumgarte or split, got '" + v + "'");
    } else if (a == "--impact") {
        const std::string& v = value(args, i);
        if (v == "closed_form") o.impact = i2d::ImpactModel::closed_form;
        else if (v == "velocity_bias") o.impact = i2d::ImpactModel::velocity_bias;
        else throw UsageError("--impact: expected closed_form or velocity_bias, got '" + v + "'");
    } else if (a == "--sleep") {
        const std::string& v = value(args, i);
        if (v == "on") o.sleep = true;
        else if (v == "off") o.sleep = false;
        else throw UsageError("--sleep: expected on or off, got '" + v + "'");
    } else {
        return false;
    }
    return true;
}

RunOptions parseRunOptions(const std::vector<std::string>& args) {
    RunOptions r;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (parseSettingsOption(args, i, r.overrides)) continue;
        if (a == "--steps") {
            r.steps = parseLong(a, value(args, i), 0, 100000000L);
        } else if (a == "--seconds") {
            r.seconds = parseDouble(a, value(args, i), 0.0, 1.0e6);
        } else if (a == "--json") {
            r.json = true;
        } else if (a == "--engine") {
            const std::string& v = value(args, i);
            if (v == "impulse2d") r.engine = EngineKind::impulse2d;
            else if (v == "box2d") r.engine = EngineKind::box2d;
            else throw UsageError("--engine: expected impulse2d or box2d, got '" + v + "'");
        } else if (a == "--assets") {
            r.assetsDir = value(args, i);
        } else if (a.size() > 1 && a[0] == '-') {
            throw UsageError("unknown option '" + a + "'");
        } else if (r.scene.empty()) {
            r.scene = a;
        } else {
            throw UsageError("unexpected argument '" + a + "' (one scene per run)");
        }
    }
    if (r.scene.empty()) throw UsageError("no scene given");
    if (r.steps && r.seconds) throw UsageError("give --steps or --seconds, not both");
    return r;
}

Box2DSettings RunOptions::box2dSettings() const {
    Box2DSettings b;
    if (overrides.velocityIterations) b.velocityIterations = *overrides.velocityIterations;
    if (overrides.positionIterations) b.positionIterations = *overrides.positionIterations;
    return b;
}

RunReport runScene(const SceneDesc& desc, long steps, EngineKind engine, const Box2DSettings& box2d) {
    std::unique_ptr<Simulation> sim = makeSimulation(desc, engine, box2d);
    RunReport rep;
    rep.scene = desc.name;
    rep.engine = engine;
    rep.notes = sim->notes();
    rep.settings = desc.settings;
    rep.box2d = box2d;
    rep.steps = steps;
    rep.dt = desc.dt;
    rep.bodies = sim->bodyCount();
    rep.joints = sim->jointCount();

    std::vector<std::pair<std::string, int>> named;
    for (std::size_t i = 0; i < desc.bodies.size(); ++i)
        if (!desc.bodies[i].name.empty()) named.emplace_back(desc.bodies[i].name, static_cast<int>(i));
    std::sort(named.begin(), named.end());
    for (const auto& [name, index] : named) {
        BodySample s = sim->sample(index);
        rep.named.push_back({name, s.x, s.y, s.angle, s.x, s.y, s.angle, s.vx, s.vy, s.w, 0.0f, s.y, s.y});
    }
    std::vector<BodySample> start;
    start.reserve(static_cast<std::size_t>(rep.bodies));
    for (int i = 0; i < rep.bodies; ++i) start.push_back(sim->sample(i));

    const i2d::Vec2 g = desc.settings.gravity;
    rep.energyInitial = rep.energyMax = rep.energyFinal = computeEnergy(*sim, g).total();
    rep.nan = !allFinite(*sim);
    rep.jointErrorMax = rep.jointErrorFinal = maxJointError(desc, *sim);
    ErrorTracker tracker(desc, errorMetricFor(desc.name));
    tracker.start(*sim);

    std::vector<double> ms;
    ms.reserve(static_cast<std::size_t>(steps));
    for (long i = 0; i < steps && !rep.nan; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        sim->step(desc.dt);
        auto t1 = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        ++rep.stepsCompleted;

        rep.maxContacts = std::max(rep.maxContacts, sim->touchingContactCount());
        const float penetration = sim->maxPenetration();
        rep.maxPenetration = std::max(rep.maxPenetration, penetration);
        if (!allFinite(*sim)) {
            rep.nan = true;
            break;
        }
        double e = computeEnergy(*sim, g).total();
        rep.energyMax = std::max(rep.energyMax, e);
        rep.energyFinal = e;
        rep.jointErrorFinal = maxJointError(desc, *sim);
        rep.jointErrorMax = std::max(rep.jointErrorMax, rep.jointErrorFinal);
        tracker.observe(*sim, penetration, rep.jointErrorFinal);
        for (std::size_t k = 0; k < named.size(); ++k) {
            BodySample s = sim->sample(named[k].second);
            RunReport::Named& nb = rep.named[k];
            nb.maxDx = std::max(nb.maxDx, std::abs(s.x - nb.x0));
            nb.minY = std::min(nb.minY, s.y);
            nb.maxY = std::max(nb.maxY, s.y);
        }
    }
    rep.error = tracker.result(*sim);
    rep.contacts = sim->touchingContactCount();
    for (int i = 0; i < rep.bodies; ++i) {
        BodySample s = sim->sample(i);
        if (s.awake && s.dynamic) ++rep.awakeBodies;
        const BodySample& s0 = start[static_cast<std::size_t>(i)];
        if (s.dynamic && std::hypot(s.x - s0.x, s.y - s0.y) > RunReport::kDisplacedDistance) ++rep.displaced;
    }
    if (!ms.empty()) {
        std::vector<double> sorted = ms;
        std::sort(sorted.begin(), sorted.end());
        std::size_t n = sorted.size();
        rep.msMedian = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        rep.msMin = sorted.front();
        rep.msMax = sorted.back();
    }
    for (std::size_t k = 0; k < named.size(); ++k) {
        BodySample s = sim->sample(named[k].second);
        RunReport::Named& nb = rep.named[k];
        nb.x = s.x;
        nb.y = s.y;
        nb.angle = s.angle;
        nb.vx = s.vx;
        nb.vy = s.vy;
        nb.w = s.w;
    }
    return rep;
}

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
    j["bodies"] = r.bodies;
    j["awake_bodies"] = r.awakeBodies;
    j["joints"] = r.joints;
    j["contacts"] = r.contacts;
    j["max_contacts"] = r.maxContacts;
    j["max_penetration"] = r.maxPenetration;
    j["energy"] = {{"initial", r.energyInitial}, {"final", r.energyFinal}, {"max", r.energyMax}};
    j["nan"] = r.nan;
    j["displaced"] = r.displaced;
    j["joint_error"] = {{"max", r.jointErrorMax}, {"final", r.jointErrorFinal}};
    json named = json::object();
    for (const auto& n : r.named)
        named[n.name] = {{"x0", n.x0},       {"y0", n.y0},     {"angle0", n.angle0}, {"x", n.x},
                         {"y", n.y},         {"angle", n.angle}, {"vx", n.vx},       {"vy", n.vy},
                         {"w", n.w},         {"max_dx", n.maxDx}, {"min_y", n.minY}, {"max_y", n.maxY}};
    j["named"] = named;
    if (r.engine == EngineKind::box2d) {
        j["settings"] = {{"velocity_iterations", r.box2d.velocityIterations},
                         {"position_iterations", r.box2d.positionIterations},
                         {"sleep", r.settings.enableSleep}};
    } else {
        static const char* const kCorrection[] = {"baumgarte", "split", "soft_step"};
        static const char* const kImpact[] = {"closed_form", "velocity_bias"};
        const i2d::WorldSettings& s = r.settings;
        j["settings"] = {{"correction", kCorrection[static_cast<int>(s.positionCorrection)]},
                         {"impact", kImpact[static_cast<int>(s.impactModel)]},
                         {"velocity_iterations", s.velocityIterations},
                         {"position_iterations", s.positionIterations},
                         {"substeps", s.substeps},
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

namespace {

void printText(const RunReport& r, std::ostream& out) {
    out << "scene " << r.scene << " (" << engineName(r.engine) << "): " << r.stepsCompleted << "/" << r.steps << " steps of " << r.dt << " s, "
        << r.bodies << " bodies, " << r.joints << " joints\n";
    out << std::fixed << std::setprecision(3);
    out << "  ms/step  median " << r.msMedian << "  min " << r.msMin << "  max " << r.msMax << "\n";
    out << "  contacts " << r.contacts << " (max " << r.maxContacts << "), max penetration " << std::setprecision(5)
        << r.maxPenetration << " m, awake " << r.awakeBodies << "\n";
    out << std::setprecision(3) << "  energy   initial " << r.energyInitial << "  final " << r.energyFinal << "  max "
        << r.energyMax << " J\n";
    out << "  displaced (> 0.5 m) " << r.displaced << ", joint error max " << std::setprecision(5) << r.jointErrorMax
        << " m, final " << r.jointErrorFinal << " m\n" << std::setprecision(3);
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

}  // namespace

int runRunCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    for (const auto& a : args)
        if (a == "--help" || a == "-h") {
            out << kRunHelp << "\n" << settingsOptionsHelp();
            return 0;
        }
    RunOptions opt;
    try {
        opt = parseRunOptions(args);
    } catch (const UsageError& e) {
        err << "testbed run: " << e.what() << "\n(see `testbed run --help`)\n";
        return 2;
    }
    try {
        SceneDesc desc = loadSceneDesc(opt.scene, opt.assetsDir);
        opt.overrides.applyTo(desc.settings);
        long steps = 600;
        if (opt.steps) steps = *opt.steps;
        if (opt.seconds) steps = std::lround(*opt.seconds / static_cast<double>(desc.dt));
        RunReport rep = runScene(desc, steps, opt.engine, opt.box2dSettings());
        if (opt.json) {
            out << reportToJson(rep) << "\n";
        } else {
            printText(rep, out);
        }
        return rep.nan ? 1 : 0;
    } catch (const SceneError& e) {
        err << "testbed run: " << e.what() << "\n";
        return 1;
    } catch (const i2d::Error& e) {
        err << "testbed run: engine error: " << e.what() << "\n";
        return 1;
    }
}

int runListCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    std::string assets;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--help" || args[i] == "-h") {
            out << kListHelp;
            return 0;
        } else if (args[i] == "--assets" && i + 1 < args.size()) {
            assets = args[++i];
        } else {
            err << "testbed list: unexpected argument '" << args[i] << "'\n(see `testbed list --help`)\n";
            return 2;
        }
    }
    std::string dir = assets.empty() ? defaultAssetsDir() : assets;
    if (dir.empty()) {
        err << "testbed list: no assets directory found (give --assets DIR)\n";
        return 1;
    }
    auto scenes = listScenes(dir);
    if (scenes.empty()) {
        err << "testbed list: no scenes in " << dir << "\n";
        return 1;
    }
    std::size_t width = 0;
    for (const auto& s : scenes) width = std::max(width, s.first.size());
    for (const auto& [name, description] : scenes)
        out << std::left << std::setw(static_cast<int>(width)) << name << "  " << description << "\n";
    return 0;
}

}  // namespace tb
