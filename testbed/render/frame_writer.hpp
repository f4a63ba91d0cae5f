// Testbed renderer — where rendered frames go: numbered PNG files, a contact
// sheet of thumbnails and an animated GIF, with a progress bar on standard
// error. Shared by the single-engine and the two-engine renders.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "render/png_io.hpp"
#include "render/scene_frames.hpp"

namespace tb {

/// A progress bar on standard error: redrawn in place on a terminal (only
/// when it changes), one line per 10 % otherwise (logs, CI).
class ProgressBar {
public:
    explicit ProgressBar(int total);
    void update(int done);

private:
    int total_;
    bool tty_;
    int lastPercent_ = -100;
};

class FrameWriter {
public:
    /// Creates options.outDir. `thumbWidth` is a sheet thumbnail's width and
    /// `gifWidth` the animation's largest width (frames wider than one panel
    /// keep their proportions). Throws std::runtime_error when it cannot.
    FrameWriter(const RenderOptions& options, int thumbWidth = 320, int gifWidth = 640);

    /// Writes DIR/frame_NNNN.png (and keeps a thumbnail for the sheet).
    void add(const Image& frame);
    /// Writes the sheet (at most 48 thumbnails, evenly chosen) and the GIF
    /// (`dt` seconds per step); returns every path written.
    RenderResult finish(float dt);

private:
    RenderOptions options_;
    std::filesystem::path dir_;
    int thumbWidth_, gifWidth_;
    std::vector<Image> thumbs_;
    RenderResult result_;
};

/// Writes `image` as a PNG; throws std::runtime_error when it cannot.
void savePng(const std::string& path, const Image& image);

}  // namespace tb
