// Testbed — `testbed run` (see run_command.hpp).
#include "commands/run_command.hpp"

#include <cmath>
#include <ostream>

#include <memory>

#include "engine_label.hpp"
#include "report_format.hpp"
#include "run_report.hpp"
#include "scene_loader.hpp"
#include "trace_writer.hpp"

namespace tb {

const char* const kRunHelp =
    "usage: testbed run SCENE [--steps N | --seconds S] [--json] [--engine impulse2d|box2d] [--assets DIR]\n"
    "                  [--trace FILE.csv] [settings options]\n"
    "\n"
    "Step a scene without rendering and report timing and measurements.\n"
    "SCENE is a shipped scene name (see `testbed list`) or a path to a .json scene file.\n"
    "\n"
    "  --steps N       number of steps (default 600)\n"
    "  --seconds S     simulated time instead of --steps (steps = round(S / dt))\n"
    "  --json          print one JSON object: scene, steps, dt, ms_per_step {median,min,max},\n"
    "                  bodies, contacts, max_contacts, max_penetration, final_penetration,\n"
    "                  max_speed, energy {initial,final,max},\n"
    "                  nan, named {NAME: {x0,y0,angle0,x,y,angle,vx,vy,w,max_dx,min_y,max_y}},\n"
    "                  engine, notes, settings, displaced, joint_error {max,final},\n"
    "                  error {metric,value,unit} (the scene's error figure, null if none) and a few more\n"
    "  --engine E      impulse2d (default) or box2d: the same scene in Box2D 2.4.1, same report;\n"
    "                  --velocity-iterations / --position-iterations then set Box2D's counts\n"
    "                  (default 8 and 3) and the other settings options do not apply\n"
    "  --trace FILE    write one CSV row per step: step, time (s), total, kinetic and potential energy (J),\n"
    "                  deepest contact (m), largest body speed (m/s), awake bodies, contacts, joint error (m),\n"
    "                  then x (m), y (m), angle (rad) of each named body; the header names each column\n"
    "                  with its unit; comment lines at the end give the engine and where the run ended\n"
    "                  (also when it stopped on a non-finite state). Plot traces with `testbed plot`\n"
    "  --assets DIR    assets directory holding scenes/ (default: next to the executable or the source tree)\n";

RunOptions parseRunOptions(const std::vector<std::string>& args) {
    RunOptions o;
    ArgReader r(args);
    while (r.next()) {
        if (parseSettingsOption(r, o.overrides)) continue;
        if (r.is("--steps")) {
            o.steps = r.integer(0, 100000000L);
        } else if (r.is("--seconds")) {
            o.seconds = r.number(0.0, 1.0e6);
        } else if (r.is("--json")) {
            o.json = true;
        } else if (r.is("--engine")) {
            o.engine = r.choice<EngineKind>();
        } else if (r.is("--assets")) {
            o.assetsDir = r.value();
        } else if (r.is("--trace")) {
            o.tracePath = r.value();
            if (o.tracePath.empty()) throw UsageError("--trace: expected a file path, got ''");
        } else if (r.is("--compare") || r.is("--overlay")) {
            throw UsageError(r.current() + " is an option of `testbed render`; `testbed run` runs one engine "
                                           "(--engine), and --trace records it over time for `testbed plot`");
        } else if (r.isOption()) {
            r.rejectUnknownOption();
        } else if (o.scene.empty()) {
            o.scene = r.current();
        } else {
            throw UsageError("unexpected argument '" + r.current() + "' (one scene per run)");
        }
    }
    if (o.scene.empty()) throw UsageError("no scene given");
    if (o.steps && o.seconds) throw UsageError("give --steps or --seconds, not both");
    return o;
}

Box2DSettings RunOptions::box2dSettings() const { return overrides.box2dSettings(); }

int runRunCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (wantsHelp(args)) {
        out << kRunHelp << "\n" << settingsOptionsHelp();
        return 0;
    }
    RunOptions opt;
    try {
        opt = parseRunOptions(args);
    } catch (const UsageError& e) {
        return reportUsageError(err, "run", e, "(see `testbed run --help`)\n");
    }
    // A trace path that cannot be written is refused before anything runs.
    std::unique_ptr<TraceWriter> trace;
    if (!opt.tracePath.empty()) {
        try {
            trace = std::make_unique<TraceWriter>(opt.tracePath);
        } catch (const TraceError& e) {
            return reportUsageError(err, "run", UsageError(std::string("--trace: ") + e.what()),
                                    "(see `testbed run --help`)\n");
        }
    }
    try {
        SceneDesc desc = loadSceneDesc(opt.scene, opt.assetsDir);
        opt.overrides.applyTo(desc);
        long steps = 600;
        if (opt.steps) steps = *opt.steps;
        if (opt.seconds) steps = std::lround(*opt.seconds / static_cast<double>(desc.dt));
        if (trace) trace->begin(desc);
        RunReport rep = runScene(desc, steps, opt.engine, opt.box2dSettings(), trace.get());
        if (trace) {
            trace->finish(rep, engineSettingsLabel(opt.engine, desc.settings, rep.box2d));
            if (rep.nan)
                err << "testbed run: non-finite state after step " << rep.stepsCompleted << "; the trace "
                    << trace->path() << " ends there\n";
        }
        if (opt.json) {
            out << reportToJson(rep) << "\n";
        } else {
            printReportText(rep, out);
        }
        return rep.nan ? 1 : 0;
    } catch (const SceneError& e) {
        if (trace) trace->abort(e.what());
        err << "testbed run: " << e.what() << "\n";
        return 1;
    } catch (const i2d::Error& e) {
        if (trace) trace->abort(std::string("engine error: ") + e.what());
        err << "testbed run: engine error: " << e.what() << "\n";
        return 1;
    } catch (const TraceError& e) {
        err << "testbed run: --trace: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace tb
