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

#if __has_include("render_command.hpp")
#include "render_command.hpp"
#define TB_HAVE_RENDER 1
#endif
#if __has_include("impact_command.hpp")
#include "impact_command.hpp"
#define TB_HAVE_IMPACT 1
#endif

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

int notBuilt(const char* what) {
    std::cerr << "testbed: the '" << what << "' command is not part of this build\n";
    return 2;
}

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
#ifdef TB_HAVE_RENDER
            return runRenderCommand(rest);
#else
            return notBuilt("render");
#endif
        }
        if (cmd == "view") {
#ifdef TB_HAVE_RENDER
            return runViewCommand(rest);
#else
            return notBuilt("view");
#endif
        }
        if (cmd == "impact") {
#ifdef TB_HAVE_IMPACT
            for (const auto& a : rest)
                if (a == "--help" || a == "-h") {
                    std::cout << "usage: testbed impact < INPUT\n\n"
                                 "Resolve impacts read from standard input with the closed-form impact law;\n"
                                 "see the impact law's documentation for the line format.\n";
                    return 0;
                }
            return runImpactCommand(std::cin, std::cout, std::cerr);
#else
            return notBuilt("impact");
#endif
        }
    } catch (const std::exception& e) {
        std::cerr << "testbed " << cmd << ": " << e.what() << "\n";
        return 1;
    }
    std::cerr << "testbed: unknown command '" << cmd << "'\n\n" << kHelp;
    return 2;
}
