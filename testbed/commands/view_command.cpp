// Testbed — `testbed view` (see view_command.hpp): the scene cycle handed to
// the viewer is every shipped scene, starting at the one asked for.
#include "commands/view_command.hpp"

#include <algorithm>
#include <climits>
#include <ostream>
#include <tuple>

#include "cli/arguments.hpp"
#include "render/viewer.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace tb {

namespace {

const char* const kViewUsage =
    "usage: testbed view [SCENE] [--assets DIR] [--size WxH] [--paused] [--screenshot FILE --frames N]\n"
    "keys: space pause, s/right step, r restart, n/p (page down/up) next/previous scene,\n"
    "      m position correction, i impact model, z sleep, +/- velocity iterations, ./, substeps,\n"
    "      c contacts, a AABBs, j joints, h help, q/escape quit; mouse: drag bodies, wheel zoom;\n"
    "      platformer scenes: left/right arrows run, up jumps\n";

struct ViewArgs {
    ViewerOptions options;
    std::string scene;  ///< empty: the first shipped scene
    std::string assetsDir;
};

ViewArgs parseViewArgs(const std::vector<std::string>& args) {
    ViewArgs a;
    bool framesGiven = false;
    ArgReader r(args);
    while (r.next()) {
        if (r.is("--assets")) {
            a.assetsDir = r.value();
        } else if (r.is("--size")) {
            std::tie(a.options.width, a.options.height) = r.size(16, INT_MAX);
        } else if (r.is("--screenshot")) {
            a.options.screenshot = r.value();
        } else if (r.is("--frames")) {
            a.options.frames = static_cast<int>(r.integer(1, INT_MAX));
            framesGiven = true;
        } else if (r.is("--paused")) {
            a.options.paused = true;
        } else if (r.isOption()) {
            r.rejectUnknownOption();
        } else if (a.scene.empty()) {
            a.scene = r.current();
        } else {
            throw UsageError("more than one scene given ('" + a.scene + "', '" + r.current() + "')");
        }
    }
    if (framesGiven && a.options.screenshot.empty()) throw UsageError("--frames needs --screenshot FILE");
    return a;
}

}  // namespace

int runViewCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (wantsHelp(args)) {
        out << kViewUsage;
        return 0;
    }
    ViewArgs a;
    try {
        a = parseViewArgs(args);
    } catch (const UsageError& e) {
        return reportUsageError(err, "view", e, kViewUsage);
    }
    try {
        const std::string assetsDir = a.assetsDir.empty() ? defaultAssetsDir() : a.assetsDir;
        std::vector<ViewerScene> scenes;
        for (const auto& entry : listScenes(assetsDir)) {
            std::string name = entry.first;
            scenes.push_back({name, [name, assetsDir] { return buildScene(loadSceneDesc(name, assetsDir)); }});
        }
        int start = 0;
        if (!a.scene.empty()) {
            const std::string& wanted = a.scene;
            auto it = std::find_if(scenes.begin(), scenes.end(),
                                   [&](const ViewerScene& s) { return s.name == wanted; });
            if (it != scenes.end()) {
                start = static_cast<int>(it - scenes.begin());
            } else {
                // A file path or a scene outside the list: first in the cycle.
                loadSceneDesc(wanted, assetsDir);  // report a bad name before opening a window
                scenes.insert(scenes.begin(),
                              {wanted, [wanted, assetsDir] { return buildScene(loadSceneDesc(wanted, assetsDir)); }});
            }
        }
        if (scenes.empty()) {
            err << "testbed view: no scenes found in " << assetsDir << "\n";
            return 1;
        }
        return runViewer(scenes, start, a.options);
    } catch (const std::exception& e) {
        err << "testbed view: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace tb
