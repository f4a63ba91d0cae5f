// testbed — command-line front end of the Impulse2D testbed.
//
//   testbed list                 shipped scenes and their descriptions
//   testbed run SCENE ...        step a scene headless, report timing/measurements (--json)
//   testbed render SCENE ...     render frames to PNG (renderer)
//   testbed view SCENE ...       interactive window (renderer)
//   testbed impact               evaluate the closed-form impact law on input lines
#include <iostream>
#include <string>
#include <vector>

#include "run_command.hpp"

#include "render_command.hpp"
#include "impact_command.hpp"

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
    "  help      this text\n"
    "\n"
    "`testbed COMMAND --help` describes each command.\n";

}  // namespace

int main(int argc, char** argv) {
    // The render and impact entry points may be declared in tb:: or globally.
    using namespace tb;
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        std::cerr << kHelp;
        return 2;
    }
    std::string cmd = args.front();
    std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        if (cmd == "help" || cmd == "--help" || cmd == "-h") {
            std::cout << kHelp;
            return 0;
        }
        if (cmd == "list") return tb::runListCommand(rest, std::cout, std::cerr);
        if (cmd == "run") return tb::runRunCommand(rest, std::cout, std::cerr);
        if (cmd == "render") {
            return runRenderCommand(rest);
        }
        if (cmd == "view") {
            return runViewCommand(rest);
        }
        if (cmd == "impact") {
            for (const auto& a : rest)
                if (a == "--help" || a == "-h") {
                    std::cout << "usage: testbed impact < INPUT\n\n"
                                 "Resolve impacts read from standard input with the closed-form impact law;\n"
                                 "see the impact law's documentation for the line format.\n";
                    return 0;
                }
            return runImpactCommand(std::cin, std::cout, std::cerr);
        }
    } catch (const std::exception& e) {
        std::cerr << "testbed " << cmd << ": " << e.what() << "\n";
        return 1;
    }
    std::cerr << "testbed: unknown command '" << cmd << "'\n\n" << kHelp;
    return 2;
}
