#include "render/render_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <tuple>

#include <unistd.h>

#include "render/cli_args.hpp"
#include "render/gif_writer.hpp"
#include "scene.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace tb {

namespace {

/// A progress bar on standard error: redrawn in place on a terminal (only
/// when it changes), one line per 10 % otherwise (logs, CI).
class ProgressBar {
public:
    explicit ProgressBar(int total) : total_(std::max(1, total)), tty_(::isatty(2) != 0) {}
    void update(int done) {
        constexpr int kWidth = 40;
        int percent = static_cast<int>(100LL * done / total_);
        if (tty_) {
            int filled = static_cast<int>(static_cast<long long>(done) * kWidth / total_);
            if (percent == lastPercent_ && done != total_) return;
            std::string bar(static_cast<std::size_t>(filled), '#');
            bar.append(static_cast<std::size_t>(kWidth - filled), '.');
            std::fprintf(stderr, "\r[%s] %3d%% %d/%d steps", bar.c_str(), percent, done, total_);
            if (done >= total_) std::fputc('\n', stderr);
        } else {
            if (percent / 10 == lastPercent_ / 10 && done != total_) return;
            std::fprintf(stderr, "render: %3d%% (%d/%d steps)\n", percent, done, total_);
        }
        lastPercent_ = percent;
        std::fflush(stderr);
    }

private:
    int total_;
    bool tty_;
    int lastPercent_ = -100;
};

std::string framePath(const std::filesystem::path& dir, int index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", index);
    return (dir / name).string();
}

std::string captionFor(const Scene& scene, int step) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s  t = %.2f s  step %d", scene.desc.name.empty() ? "scene" : scene.desc.name.c_str(),
                  static_cast<double>(step) * static_cast<double>(scene.desc.dt), step);
    return buf;
}

void save(const std::string& path, const Image& image) {
    std::string error;
    if (!writePng(path, image, &error)) throw std::runtime_error(error);
}

}  // namespace

int sheetColumns(int count, int frameWidth, int frameHeight) {
    if (count <= 1) return 1;
    // Choose c so that the sheet (c columns × ceil(count/c) rows) is closest to 16:9.
    double best = 1e9;
    int bestC = 1;
    for (int c = 1; c <= count; ++c) {
        int rows = (count + c - 1) / c;
        double aspect = static_cast<double>(c * frameWidth) / static_cast<double>(rows * frameHeight);
        double score = std::fabs(std::log(aspect / (16.0 / 9.0)));
        if (score < best - 1e-9) {
            best = score;
            bestC = c;
        }
    }
    return bestC;
}

RenderResult renderSceneFrames(Scene& scene, const RenderOptions& options) {
    if (!scene.world) throw std::runtime_error("render: the scene has no world");
    if (options.frames < 1) throw std::runtime_error("render: --frames must be at least 1");
    if (options.every < 1) throw std::runtime_error("render: --every must be at least 1");
    if (options.width < 16 || options.height < 16 || options.width > 8192 || options.height > 8192)
        throw std::runtime_error("render: --size must be between 16x16 and 8192x8192");

    std::filesystem::path dir(options.outDir);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("render: cannot create " + dir.string() + ": " + ec.message());

    OffscreenRenderer renderer(options.width, options.height, options.supersample);
    View2D view = sceneView(scene, options.width, options.height);
    RenderResult result;
    std::vector<Image> thumbs;
    const int thumbWidth = 320;

    ProgressBar progress(options.frames);
    for (int step = 0; step < options.frames; ++step) {
        if (step % options.every == 0) {
            Image frame = renderer.renderWorld(*scene.world, view, options.flags,
                                               options.caption ? captionFor(scene, step) : std::string{});
            std::string path = framePath(dir, static_cast<int>(result.framePaths.size()));
            save(path, frame);
            result.framePaths.push_back(path);
            if (options.writeSheet) {
                int w = std::min(thumbWidth, frame.width);
                thumbs.push_back(resizeArea(frame, w, std::max(1, w * frame.height / frame.width)));
            }
        }
        scene.world->step(scene.desc.dt);
        if (options.progress) progress.update(step + 1);
    }

    if (options.writeSheet && !thumbs.empty()) {
        // At most 48 thumbnails: an even subset of the frames when there are more.
        std::vector<Image> chosen;
        int n = static_cast<int>(thumbs.size());
        int count = std::min(n, 48);
        for (int i = 0; i < count; ++i) {
            int index = count == 1 ? 0 : static_cast<int>(static_cast<long long>(i) * (n - 1) / (count - 1));
            chosen.push_back(std::move(thumbs[static_cast<std::size_t>(index)]));
        }
        int columns = sheetColumns(count, chosen[0].width, chosen[0].height);
        Image sheet = contactSheet(chosen, columns, chosen[0].width);
        result.sheetPath = (dir / "sheet.png").string();
        save(result.sheetPath, sheet);
    }

    if (options.writeGif) {
        int delay = static_cast<int>(std::lround(100.0 * scene.desc.dt * options.every));
        std::string gif = (dir / "anim.gif").string();
        if (writeGifWithImageMagick(result.framePaths, gif, std::max(delay, 2), 640, result.gifMessage))
            result.gifPath = gif;
    }
    return result;
}

namespace {

void printRenderUsage(std::ostream& out) {
    out << "usage: testbed render SCENE --frames N [--every K] --out DIR [--size WxH]\n"
           "                      [--assets DIR] [--ssaa S] [--contacts] [--aabbs]\n"
           "                      [--no-gif] [--no-sheet] [--no-caption] [--quiet]\n"
           "  SCENE      scene name (from the assets directory) or path to a scene file\n"
           "  --frames   steps to simulate (default 120)\n"
           "  --every    write a frame every K steps (default 1)\n"
           "  --out      output directory (default out/SCENE)\n"
           "  --size     frame size in pixels (default 1280x720)\n"
           "  --ssaa     supersampling factor 1-4 for antialiasing (default 2)\n"
           "writes DIR/frame_0000.png..., DIR/sheet.png and DIR/anim.gif (needs ImageMagick convert)\n";
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& args) {
    RenderOptions options;
    std::string sceneName, assetsDir, outDir;
    try {
        for (std::size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            auto value = [&]() -> const std::string& { return optionValue(args, i); };
            if (a == "-h" || a == "--help") {
                printRenderUsage(std::cout);
                return 0;
            } else if (a == "--frames") {
                options.frames = parseIntArg(a, value());
            } else if (a == "--every") {
                options.every = parseIntArg(a, value());
            } else if (a == "--out") {
                outDir = value();
            } else if (a == "--size") {
                std::tie(options.width, options.height) = parseSizeArg(a, value(), 1);
            } else if (a == "--assets") {
                assetsDir = value();
            } else if (a == "--ssaa") {
                options.supersample = parseIntArg(a, value());
                if (options.supersample < 1 || options.supersample > 4)
                    throw std::invalid_argument("--ssaa: expected 1 to 4");
            } else if (a == "--contacts") {
                options.flags.contacts = true;
            } else if (a == "--aabbs") {
                options.flags.aabbs = true;
            } else if (a == "--no-gif") {
                options.writeGif = false;
            } else if (a == "--no-sheet") {
                options.writeSheet = false;
            } else if (a == "--no-caption") {
                options.caption = false;
            } else if (a == "--quiet") {
                options.progress = false;
            } else if (!a.empty() && a[0] == '-') {
                throw std::invalid_argument("unknown option " + a);
            } else if (sceneName.empty()) {
                sceneName = a;
            } else {
                throw std::invalid_argument("more than one scene given ('" + sceneName + "', '" + a + "')");
            }
        }
        if (sceneName.empty()) throw std::invalid_argument("no scene given");
    } catch (const std::invalid_argument& e) {
        std::cerr << "testbed render: " << e.what() << "\n";
        printRenderUsage(std::cerr);
        return 2;
    }

    try {
        if (assetsDir.empty()) assetsDir = defaultAssetsDir();
        SceneDesc desc = loadSceneDesc(sceneName, assetsDir);
        Scene scene = buildScene(desc);
        std::string stem = !scene.desc.name.empty() ? scene.desc.name : std::filesystem::path(sceneName).stem().string();
        options.outDir = outDir.empty() ? (std::filesystem::path("out") / stem).string() : outDir;
        RenderResult r = renderSceneFrames(scene, options);
        std::cerr << "wrote " << r.framePaths.size() << " frames to " << options.outDir << "\n";
        if (!r.sheetPath.empty()) std::cerr << "contact sheet: " << r.sheetPath << "\n";
        if (!r.gifPath.empty())
            std::cerr << "animation: " << r.gifPath << "\n";
        else if (options.writeGif)
            std::cerr << "warning: anim.gif not written: " << r.gifMessage << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "testbed render: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace tb
