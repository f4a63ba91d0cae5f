// Testbed — `testbed render` (see render_command.hpp); the rendering itself
// is render/scene_frames.cpp.
#include "commands/render_command.hpp"

#include <climits>
#include <filesystem>
#include <ostream>
#include <tuple>

#include "cli/arguments.hpp"
#include "render/scene_frames.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace tb {

namespace {

const char* const kRenderUsage =
    "usage: testbed render SCENE --frames N [--every K] --out DIR [--size WxH]\n"
    "                      [--assets DIR] [--ssaa S] [--contacts] [--aabbs]\n"
    "                      [--no-gif] [--no-sheet] [--no-caption] [--quiet]\n"
    "  SCENE      scene name (from the assets directory) or path to a scene file\n"
    "  --frames   steps to simulate (default 120)\n"
    "  --every    write a frame every K steps (default 1)\n"
    "  --out      output directory (default out/SCENE)\n"
    "  --size     frame size in pixels (default 1280x720)\n"
    "  --ssaa     supersampling factor 1-4 for antialiasing (default 2)\n"
    "writes DIR/frame_0000.png..., DIR/sheet.png and DIR/anim.gif (needs ImageMagick convert)\n";

struct RenderArgs {
    RenderOptions options;
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
        if (r.is("--frames")) {
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
        Scene scene = buildScene(desc);
        std::string stem = !scene.desc.name.empty() ? scene.desc.name : std::filesystem::path(a.scene).stem().string();
        RenderOptions& options = a.options;
        options.outDir = a.outDir.empty() ? (std::filesystem::path("out") / stem).string() : a.outDir;
        RenderResult result = renderSceneFrames(scene, options);
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
