// Testbed renderer — frames to files (see frame_writer.hpp).
#include "render/frame_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <unistd.h>

#include "render/gif_writer.hpp"

namespace tb {

ProgressBar::ProgressBar(int total) : total_(std::max(1, total)), tty_(::isatty(2) != 0) {}

void ProgressBar::update(int done) {
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

void savePng(const std::string& path, const Image& image) {
    std::string error;
    if (!writePng(path, image, &error)) throw std::runtime_error(error);
}

FrameWriter::FrameWriter(const RenderOptions& options, int thumbWidth, int gifWidth)
    : options_(options), dir_(options.outDir), thumbWidth_(thumbWidth), gifWidth_(gifWidth) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) throw std::runtime_error("cannot create " + dir_.string() + ": " + ec.message());
}

void FrameWriter::add(const Image& frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", static_cast<int>(result_.framePaths.size()));
    const std::string path = (dir_ / name).string();
    savePng(path, frame);
    result_.framePaths.push_back(path);
    if (options_.writeSheet) {
        int w = std::min(thumbWidth_, frame.width);
        thumbs_.push_back(resizeArea(frame, w, std::max(1, w * frame.height / frame.width)));
    }
}

RenderResult FrameWriter::finish(float dt) {
    if (options_.writeSheet && !thumbs_.empty()) {
        // At most 48 thumbnails: an even subset of the frames when there are more.
        std::vector<Image> chosen;
        int n = static_cast<int>(thumbs_.size());
        int count = std::min(n, 48);
        for (int i = 0; i < count; ++i) {
            int index = count == 1 ? 0 : static_cast<int>(static_cast<long long>(i) * (n - 1) / (count - 1));
            chosen.push_back(std::move(thumbs_[static_cast<std::size_t>(index)]));
        }
        int columns = sheetColumns(count, chosen[0].width, chosen[0].height);
        Image sheet = contactSheet(chosen, columns, chosen[0].width);
        result_.sheetPath = (dir_ / "sheet.png").string();
        savePng(result_.sheetPath, sheet);
        thumbs_.clear();
    }
    if (options_.writeGif) {
        int delay = static_cast<int>(std::lround(100.0 * dt * options_.every));
        std::string gif = (dir_ / "anim.gif").string();
        if (writeGifWithImageMagick(result_.framePaths, gif, std::max(delay, 2), gifWidth_, result_.gifMessage))
            result_.gifPath = gif;
    }
    return result_;
}

}  // namespace tb
