// Testbed — `testbed list` (see list_command.hpp).
#include "commands/list_command.hpp"

#include <algorithm>
#include <iomanip>
#include <ostream>

#include "cli/arguments.hpp"
#include "scene_loader.hpp"

namespace tb {

const char* const kListHelp = "usage: testbed list [--assets DIR]\n"
                              "\n"
                              "Print the shipped scenes, one per line: NAME, then its description.\n";

int runListCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (wantsHelp(args)) {
        out << kListHelp;
        return 0;
    }
    std::string assets;
    try {
        ArgReader r(args);
        while (r.next()) {
            if (r.is("--assets")) {
                assets = r.value();
            } else if (r.isOption()) {
                r.rejectUnknownOption();
            } else {
                throw UsageError("unexpected argument '" + r.current() + "'");
            }
        }
    } catch (const UsageError& e) {
        return reportUsageError(err, "list", e, "(see `testbed list --help`)\n");
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
