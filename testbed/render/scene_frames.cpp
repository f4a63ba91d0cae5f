// Testbed — rendering a scene's frames, sheet and GIF (see scene_frames.hpp).
#include "render/scene_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "game/platformer.hpp"
#include "render/frame_writer.hpp"
#include "scene.hpp"

namespace tb {

namespace {

std::string captionFor(const Scene& scene, int step) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s  t = %.2f s  step %d",
                  scene.desc.name.empty() ? "scene" : scene.desc.name.c_str(),
                  static_cast<double>(step) * static_cast<double>(scene.desc.dt), step);
    return buf;
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

    FrameWriter writer(options);
    OffscreenRenderer renderer(options.width, options.height, options.supersample);
    View2D view = sceneView(scene, options.width, options.height);

    ProgressBar progress(options.frames);
    for (int step = 0; step < options.frames; ++step) {
        if (step % options.every == 0)
            writer.add(renderer.renderWorld(*scene.world, view, options.flags,
                                            options.caption ? captionFor(scene, step) : std::string{}));
        stepScene(scene, scene.desc.dt);
        if (options.progress) progress.update(step + 1);
    }
    return writer.finish(scene.desc.dt);
}

}  // namespace tb
