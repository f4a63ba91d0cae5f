// testbed — command-line front end of the Impulse2D testbed: picks the
// command named by the first argument and hands it the rest.
//
//   testbed list                 shipped scenes and their descriptions
//   testbed run SCENE ...        step a scene headless, report timing/measurements (--json)
//   testbed render SCENE ...     render frames to PNG (renderer)
//   testbed view SCENE ...       interactive window (renderer)
//   testbed impact               evaluate the closed-form impact law on input lines
//   testbed plot TRACE.csv ...   traces of `run --trace` as PNG charts (gnuplot)
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "commands/impact_command.hpp"
#include "commands/list_command.hpp"
#include "commands/plot_command.hpp"
#include "commands/render_command.hpp"
#include "commands/run_command.hpp"
#include "commands/view_command.hpp"

namespace {

const char* const kHelp =
    "usage: testbed COMMAND [ARGS...]\n"
    "\n"
    "commands:\n"
    "  list      print the shipped scenes with their descriptions\n"
    "  run       step a scene without rendering; timing and measurements (--json for one JSON object)\n"
    "  render    render a scene to PNG frames\n"
    "  view      open a window and run a scene interactively\n"
    "  impact    resolve impacts read from standard input with the closed-form impact law\n"
    "  plot      draw traces of `run --trace` (one per engine) as PNG charts with gnuplot\n"
    "  help      this text\n"
    "\n"
    "`testbed COMMAND --help` describes each command.\n";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        std::cerr << kHelp;
        return 2;
    }
    const std::string cmd = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        if (cmd == "help" || cmd == "--help" || cmd == "-h") {
            std::cout << kHelp;
            return 0;
        }
        if (cmd == "list") return tb::runListCommand(rest, std::cout, std::cerr);
        if (cmd == "run") return tb::runRunCommand(rest, std::cout, std::cerr);
        if (cmd == "render") return tb::runRenderCommand(rest, std::cout, std::cerr);
        if (cmd == "view") return tb::runViewCommand(rest, std::cout, std::cerr);
        if (cmd == "plot") return tb::runPlotCommand(rest, std::cout, std::cerr);
        if (cmd == "impact") return tb::runImpactCommand(rest, std::cin, std::cout, std::cerr);
    } catch (const std::exception& e) {
        // Whatever a command did not catch itself (out of memory, a bug).
        std::cerr << "testbed " << cmd << ": " << e.what() << "\n";
        return 1;
    }
    std::cerr << "testbed: unknown command '" << cmd << "'\n\n" << kHelp;
    return 2;
}
