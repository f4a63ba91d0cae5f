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
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace tb {

const char* const kRunHelp =
    "usage: testbed run SCENE [--steps N | --seconds S] [--json] [--assets DIR] [settings options]\n"
    "\n"
    "Step a scene without rendering and report timing and measurements.\n"
    "SCENE is a shipped scene name (see `testbed list`) or a path to a .json scene file.\n"
    "\n"
    "  --steps N       number of steps (default 600)\n"
    "  --seconds S     simulated time instead of --steps (steps = round(S / dt))\n"
    "  --json          print one JSON object: scene, steps, dt, ms_per_step {median,min,max},\n"
    "                  bodies, contacts, max_contacts, max_penetration, energy {initial,final,max},\n"
    "                  nan, named {NAME: {x0,y0,angle0,x,y,angle,vx,vy,w}} (and a few extra fields)\n"
    "  --assets DIR    assets directory holding scenes/ (default: next to the executable or the source tree)\n";

const char* const kListHelp =
    "usage: testbed list [--assets DIR]\n"
    "\n"
    "Print the shipped scenes, one per line: NAME, then its description.\n";

const char* settingsOptionsHelp() {
    return "settings options (override the scene's world settings):\n"
           "  --velocity-iterations N   velocity iterations per step (per substep in soft_step)\n"
           "  --position-iterations N   position iterations (split) / relax iterations (soft_step)\n"
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

RunReport runScene(const SceneDesc& desc, long steps) {
    Scene scene = buildScene(desc);
    i2d::World& world = *scene.world;
    RunReport rep;
    rep.scene = desc.name;
    rep.steps = steps;
    rep.dt = desc.dt;
    rep.bodies = world.bodyCount();
    rep.joints = world.jointCount();

    for (const auto& [name, id] : scene.named) {
        BodyState s = bodyState(world, id);
        rep.named.push_back({name, s.x, s.y, s.angle, 0, 0, 0, 0, 0, 0});
    }
    Energy e0 = computeEnergy(world);
    rep.energyInitial = rep.energyMax = rep.energyFinal = e0.total();
    rep.nan = !allFinite(world);

    std::vector<double> ms;
    ms.reserve(static_cast<std::size_t>(steps));
    for (long i = 0; i < steps && !rep.nan; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        world.step(desc.dt);
        auto t1 = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        ++rep.stepsCompleted;

        rep.maxContacts = std::max(rep.maxContacts, world.contactCount());
        rep.maxPenetration = std::max(rep.maxPenetration, maxPenetration(world));
        if (!allFinite(world)) {
            rep.nan = true;
            break;
        }
        double e = computeEnergy(world).total();
        rep.energyMax = std::max(rep.energyMax, e);
        rep.energyFinal = e;
    }
    rep.contacts = world.contactCount();
    rep.awakeBodies = world.awakeBodyCount();
    if (!ms.empty()) {
        std::vector<double> sorted = ms;
        std::sort(sorted.begin(), sorted.end());
        std::size_t n = sorted.size();
        rep.msMedian = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        rep.msMin = sorted.front();
        rep.msMax = sorted.back();
    }
    for (auto& nb : rep.named) {
        BodyState s = bodyState(world, scene.named.at(nb.name));
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
    json named = json::object();
    for (const auto& n : r.named)
        named[n.name] = {{"x0", n.x0}, {"y0", n.y0}, {"angle0", n.angle0}, {"x", n.x},   {"y", n.y},
                         {"angle", n.angle}, {"vx", n.vx}, {"vy", n.vy}, {"w", n.w}};
    j["named"] = named;
    return j.dump();
}

namespace {

void printText(const RunReport& r, std::ostream& out) {
    out << "scene " << r.scene << ": " << r.stepsCompleted << "/" << r.steps << " steps of " << r.dt << " s, "
        << r.bodies << " bodies, " << r.joints << " joints\n";
    out << std::fixed << std::setprecision(3);
    out << "  ms/step  median " << r.msMedian << "  min " << r.msMin << "  max " << r.msMax << "\n";
    out << "  contacts " << r.contacts << " (max " << r.maxContacts << "), max penetration " << std::setprecision(5)
        << r.maxPenetration << " m, awake " << r.awakeBodies << "\n";
    out << std::setprecision(3) << "  energy   initial " << r.energyInitial << "  final " << r.energyFinal << "  max "
        << r.energyMax << " J\n";
    if (r.nan) out << "  NON-FINITE STATE after step " << r.stepsCompleted << "\n";
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
        RunReport rep = runScene(desc, steps);
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
