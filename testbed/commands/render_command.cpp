// Testbed — `testbed render` (see render_command.hpp); the rendering itself
// is render/scene_frames.cpp.
#include "commands/render_command.hpp"

#include <climits>
#include <filesystem>
#include <optional>
#include <ostream>
#include <tuple>

#include "cli/arguments.hpp"
#include "cli/settings_options.hpp"
#include "render/compare_frames.hpp"
#include "render/scene_frames.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace tb {

namespace {

const char* const kRenderUsage =
    "usage: testbed render SCENE --frames N [--every K] --out DIR [--size WxH]\n"
    "                      [--assets DIR] [--ssaa S] [--contacts] [--aabbs]\n"
    "                      [--no-gif] [--no-sheet] [--no-caption] [--quiet]\n"
    "                      [--compare ENGINE [--overlay]] [settings options]\n"
    "  SCENE      scene name (from the assets directory) or path to a scene file\n"
    "  --frames   steps to simulate (default 120)\n"
    "  --every    write a frame every K steps (default 1)\n"
    "  --out      output directory (default out/SCENE)\n"
    "  --size     frame size in pixels (default 1280x720)\n"
    "  --ssaa     supersampling factor 1-4 for antialiasing (default 2)\n"
    "  --compare  box2d: the same scene in Impulse2D (left) and in Box2D 2.4.1 (right) at the same step,\n"
    "             same camera and scale, each panel captioned with its engine and settings, a scale bar\n"
    "             in metres; frames are twice as wide as --size (not with --contacts or --aabbs)\n"
    "  --overlay  with --compare: one panel, Impulse2D filled and the other engine as blue outlines\n"
    "  settings options (see `testbed run --help`) override the scene's settings; with --compare,\n"
    "  --velocity-iterations and --position-iterations also set Box2D's (default 8 and 3)\n"
    "writes DIR/frame_0000.png..., DIR/sheet.png and DIR/anim.gif (needs ImageMagick convert)\n";

struct RenderArgs {
    RenderOptions options;
    SettingsOverrides overrides;
    std::optional<EngineKind> compare;
    bool overlay = false;
    std::string scene;
    std::string assetsDir;
    std::string outDir;
};

// Every limit renderSceneFrames checks is checked here too, so that a bad
// value is a usage error (exit 2) rather than a failed render (exit 1).
RenderArgs parseRenderArgs(const std::vector<std::string>& args) {
    RenderArgs a;
    RenderOptions& o = a.options;
    ArgReader r(args);
    while (r.next()) {
        if (parseSettingsOption(r, a.overrides)) continue;
        if (r.is("--compare")) {
            a.compare = r.choice<EngineKind>();
            if (*a.compare == EngineKind::impulse2d)
                throw UsageError("--compare: the left panel is impulse2d already; expected box2d");
        } else if (r.is("--overlay")) {
            a.overlay = true;
        } else if (r.is("--trace")) {
            throw UsageError("--trace is an option of `testbed run` (one engine per trace; see `testbed plot`)");
        } else if (r.is("--frames")) {
            o.frames = static_cast<int>(r.integer(1, INT_MAX));
        } else if (r.is("--every")) {
            o.every = static_cast<int>(r.integer(1, INT_MAX));
        } else if (r.is("--out")) {
            a.outDir = r.value();
        } else if (r.is("--size")) {
            std::tie(o.width, o.height) = r.size(16, 8192);
        } else if (r.is("--assets")) {
            a.assetsDir = r.value();
        } else if (r.is("--ssaa")) {
            o.supersample = static_cast<int>(r.integer(1, 4));
        } else if (r.is("--contacts")) {
            o.flags.contacts = true;
        } else if (r.is("--aabbs")) {
            o.flags.aabbs = true;
        } else if (r.is("--no-gif")) {
            o.writeGif = false;
        } else if (r.is("--no-sheet")) {
            o.writeSheet = false;
        } else if (r.is("--no-caption")) {
            o.caption = false;
        } else if (r.is("--quiet")) {
            o.progress = false;
        } else if (r.isOption()) {
            r.rejectUnknownOption();
        } else if (a.scene.empty()) {
            a.scene = r.current();
        } else {
            throw UsageError("more than one scene given ('" + a.scene + "', '" + r.current() + "')");
        }
    }
    if (a.scene.empty()) throw UsageError("no scene given");
    if (a.overlay && !a.compare) throw UsageError("--overlay needs --compare ENGINE");
    if (a.compare && (o.flags.contacts || o.flags.aabbs))
        throw UsageError("--contacts and --aabbs show Impulse2D's own contacts and boxes; not with --compare");
    return a;
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (wantsHelp(args)) {
        out << kRenderUsage;
        return 0;
    }
    RenderArgs a;
    try {
        a = parseRenderArgs(args);
    } catch (const UsageError& e) {
        return reportUsageError(err, "render", e, kRenderUsage);
    }
    try {
        if (a.assetsDir.empty()) a.assetsDir = defaultAssetsDir();
        SceneDesc desc = loadSceneDesc(a.scene, a.assetsDir);
        a.overrides.applyTo(desc);
        std::string stem = !desc.name.empty() ? desc.name : std::filesystem::path(a.scene).stem().string();
        if (a.compare) stem += "_compare";
        RenderOptions& options = a.options;
        options.outDir = a.outDir.empty() ? (std::filesystem::path("out") / stem).string() : a.outDir;
        RenderResult result;
        if (a.compare) {
            result = renderCompareFrames(desc, options, {*a.compare, a.overrides.box2dSettings(), a.overlay});
        } else {
            Scene scene = buildScene(desc);
            result = renderSceneFrames(scene, options);
        }
        err << "wrote " << result.framePaths.size() << " frames to " << options.outDir << "\n";
        if (!result.sheetPath.empty()) err << "contact sheet: " << result.sheetPath << "\n";
        if (!result.gifPath.empty())
            err << "animation: " << result.gifPath << "\n";
        else if (options.writeGif)
            err << "warning: anim.gif not written: " << result.gifMessage << "\n";
        return 0;
    } catch (const std::exception& e) {
        err << "testbed render: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace tb
