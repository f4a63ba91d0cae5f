// Testbed — `testbed plot` (see plot_command.hpp); the charts themselves are
// trace_plot.cpp's gnuplot script.
#include "commands/plot_command.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <tuple>

#include <spawn.h>
#include <sys/wait.h>

#include "cli/arguments.hpp"
#include "trace_plot.hpp"

extern char** environ;

namespace tb {

const char* const kPlotHelp =
    "usage: testbed plot TRACE.csv [TRACE.csv ...] [--out DIR] [--body NAME] [--title TEXT]\n"
    "                    [--label TEXT ...] [--size WxH]\n"
    "\n"
    "Draw traces written by `testbed run --trace` as PNG charts with gnuplot, one line per trace\n"
    "(e.g. the same scene in impulse2d and in box2d), time in seconds on the horizontal axis:\n"
    "  DIR/energy.png        total energy less its value at step 1 (J), kinetic energy (J) dashed\n"
    "  DIR/penetration.png   deepest contact (mm)\n"
    "  DIR/speed.png         largest body speed (m/s)\n"
    "  DIR/joint_error.png   largest joint error (mm)\n"
    "  DIR/body_NAME.png     the named body's x and y (m)\n"
    "  DIR/summary.png       energy, deepest contact, largest speed and the body's y (or the joint error)\n"
    "  DIR/plot.gp           the gnuplot script that drew them\n"
    "\n"
    "  --out DIR      output directory (default out/plots)\n"
    "  --body NAME    named body to plot (default: the first trace's first named body that moves)\n"
    "  --title TEXT   title before every chart's own (default: the traces' scene)\n"
    "  --label TEXT   legend entry of the next trace, once per trace in order (default: the engine and its\n"
    "                 settings from the trace, with \"(stopped at t = T s)\" for a run that went non-finite)\n"
    "  --size WxH     size of one chart in pixels (default 800x450; the summary is 1.5 times larger)\n"
    "Needs gnuplot (with the pngcairo terminal) on the PATH.\n";

namespace {

struct PlotArgs {
    std::vector<std::string> traces;
    std::vector<std::string> labels;
    std::string outDir = "out/plots";
    std::string body;
    bool bodyGiven = false;
    std::string title;
    bool titleGiven = false;
    int width = 800, height = 450;
};

PlotArgs parsePlotArgs(const std::vector<std::string>& args) {
    PlotArgs a;
    ArgReader r(args);
    while (r.next()) {
        if (r.is("--out")) {
            a.outDir = r.value();
        } else if (r.is("--body")) {
            a.body = r.value();
            a.bodyGiven = true;
        } else if (r.is("--title")) {
            a.title = r.value();
            a.titleGiven = true;
        } else if (r.is("--label")) {
            a.labels.push_back(r.value());
        } else if (r.is("--size")) {
            std::tie(a.width, a.height) = r.size(100, 4096);
        } else if (r.is("--compare") || r.is("--engine")) {
            throw UsageError(r.current() + " does not apply: `testbed plot` draws traces already written; run each "
                                           "engine with `testbed run SCENE --engine E --trace FILE.csv`");
        } else if (r.isOption()) {
            r.rejectUnknownOption();
        } else {
            a.traces.push_back(r.current());
        }
    }
    if (a.traces.empty()) throw UsageError("no trace given (write one with `testbed run SCENE --trace FILE.csv`)");
    if (!a.labels.empty() && a.labels.size() != a.traces.size())
        throw UsageError("--label given " + std::to_string(a.labels.size()) + " times for " +
                         std::to_string(a.traces.size()) + " traces (once per trace, or not at all)");
    return a;
}

/// Runs `gnuplot SCRIPT`; returns its exit status, or -1 when it cannot be started.
int runGnuplot(const std::string& script) {
    std::string prog = "gnuplot";
    std::vector<char*> argv{prog.data(), const_cast<char*>(script.c_str()), nullptr};
    pid_t pid = 0;
    if (posix_spawnp(&pid, "gnuplot", nullptr, nullptr, argv.data(), environ) != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return -1;
    if (!WIFEXITED(status)) return -1;
    // posix_spawnp may report a missing program only through the child's exit code 127.
    return WEXITSTATUS(status) == 127 ? -1 : WEXITSTATUS(status);
}

}  // namespace

int runPlotCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (wantsHelp(args)) {
        out << kPlotHelp;
        return 0;
    }
    PlotRequest req;
    try {
        PlotArgs a = parsePlotArgs(args);
        for (const std::string& path : a.traces) {
            try {
                req.traces.push_back(readTraceInfo(path));
            } catch (const TraceReadError& e) {
                throw UsageError(e.what());
            }
        }
        req.labels = a.labels.empty() ? defaultLabels(req.traces) : a.labels;
        req.body = a.bodyGiven ? a.body : "";
        if (!a.bodyGiven) {
            req.body = req.traces.front().movingBody();
        } else {
            for (const TraceInfo& t : req.traces) {
                const auto bodies = t.bodies();
                if (std::find(bodies.begin(), bodies.end(), a.body) == bodies.end())
                    throw UsageError("--body: '" + t.path + "' has no named body '" + a.body + "'");
            }
        }
        req.title = a.titleGiven ? a.title : req.traces.front().scene;
        req.outDir = a.outDir;
        req.width = a.width;
        req.height = a.height;
    } catch (const UsageError& e) {
        return reportUsageError(err, "plot", e, "(see `testbed plot --help`)\n");
    }

    std::error_code ec;
    std::filesystem::create_directories(req.outDir, ec);
    if (ec) {
        err << "testbed plot: cannot create " << req.outDir << ": " << ec.message() << "\n";
        return 1;
    }
    const std::string scriptPath = (std::filesystem::path(req.outDir) / "plot.gp").string();
    {
        std::ofstream script(scriptPath);
        script << plotScript(req);
        if (!script) {
            err << "testbed plot: cannot write " << scriptPath << "\n";
            return 1;
        }
    }
    const int status = runGnuplot(scriptPath);
    if (status < 0) {
        err << "testbed plot: gnuplot not found on the PATH (install gnuplot, e.g. Debian's gnuplot-nox); the "
               "script is "
            << scriptPath << "\n";
        return 1;
    }
    if (status != 0) {
        err << "testbed plot: gnuplot failed (exit code " << status << ") on " << scriptPath << "\n";
        return 1;
    }
    for (const PlotChart& c : plotCharts(req))
        err << "wrote " << (std::filesystem::path(req.outDir) / c.file).string() << "  (" << c.what << ")\n";
    return 0;
}

}  // namespace tb
