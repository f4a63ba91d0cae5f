// Testbed — run a scene offscreen and write its frames as PNG files, a
// contact sheet and an animated GIF (what `testbed render` does).
//
// Frame i (0-based) is the state after i·K steps: DIR/frame_0000.png is the
// initial state; N steps are simulated and ceil(N / K) frames written.
#pragma once

#include <string>
#include <vector>

#include "render/offscreen.hpp"

namespace tb {

struct Scene;

struct RenderOptions {
    int frames = 120;  ///< steps to simulate
    int every = 1;     ///< write one frame per this many steps
    int width = 1280;
    int height = 720;
    int supersample = 2;  ///< antialiasing: render at this multiple, then average
    std::string outDir = "out";
    bool writeSheet = true;
    bool writeGif = true;
    bool caption = true;   ///< scene name, time and step on each frame
    bool progress = true;  ///< progress bar on standard error
    WorldDrawFlags flags{};
};

struct RenderResult {
    std::vector<std::string> framePaths;
    std::string sheetPath;   ///< empty when not written
    std::string gifPath;     ///< empty when not written
    std::string gifMessage;  ///< why the GIF is missing, or how it was made
};

/// Steps `scene` and writes the frames, sheet and GIF into options.outDir
/// (created if needed). The camera is chosen once, before the first step.
/// Throws std::runtime_error when a file cannot be written or OSMesa fails.
RenderResult renderSceneFrames(Scene& scene, const RenderOptions& options);

/// Columns of the contact sheet for `count` frames (about 16:9 overall).
int sheetColumns(int count, int frameWidth, int frameHeight);

}  // namespace tb
