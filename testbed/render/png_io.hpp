// Testbed renderer — RGBA images in memory, PNG files through libpng, and the
// few image operations the renderer needs (downsampling, contact sheets).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tb {

/// 8-bit RGBA pixels, rows from the top, no padding.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;

    Image() = default;
    Image(int w, int h, std::uint32_t fillRgba = 0x000000FFu);
    bool empty() const { return width <= 0 || height <= 0; }
    std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
    const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

/// Writes an 8-bit RGB PNG (alpha dropped: frames are opaque). The file holds
/// no time stamp or other varying chunk, so equal images give equal bytes.
/// Returns false and fills `error` when the file cannot be written.
bool writePng(const std::string& path, const Image& image, std::string* error = nullptr);

/// Reads any PNG libpng understands, expanded to 8-bit RGBA.
bool readPng(const std::string& path, Image& image, std::string* error = nullptr);

/// Reverses the row order (OpenGL reads rows bottom-up).
void flipVertical(Image& image);

/// Box-filter reduction by an integer factor (supersampling resolve).
Image downsample(const Image& src, int factor);

/// Resize to exactly w × h by area averaging (for thumbnails).
Image resizeArea(const Image& src, int w, int h);

/// A grid of thumbnails, `columns` per row, each `thumbWidth` wide with the
/// source aspect, separated by `gap` pixels of background colour.
Image contactSheet(const std::vector<Image>& frames, int columns, int thumbWidth, int gap = 4,
                   std::uint32_t backgroundRgba = 0x202020FFu);

}  // namespace tb
