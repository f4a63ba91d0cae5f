// Testbed — rendering a scene's frames, sheet and GIF (see scene_frames.hpp).
#include "render/scene_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <stdexcept>

#include <unistd.h>

#include "render/gif_writer.hpp"
#include "scene.hpp"

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
    if (!scene.world) throw std::runtime_error("the scene has no world");
    if (options.frames < 1) throw std::runtime_error("--frames must be at least 1");
    if (options.every < 1) throw std::runtime_error("--every must be at least 1");
    if (options.width < 16 || options.height < 16 || options.width > 8192 || options.height > 8192)
        throw std::runtime_error("--size must be between 16x16 and 8192x8192");

    std::filesystem::path dir(options.outDir);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create " + dir.string() + ": " + ec.message());

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

}  // namespace tb
