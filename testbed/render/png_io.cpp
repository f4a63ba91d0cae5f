// Testbed renderer — implementation of png_io.hpp (see there).
#include "render/png_io.hpp"

#include <png.h>

#include <algorithm>

namespace tb {

Image::Image(int w, int h, std::uint32_t fillRgba) : width(w), height(h) {
    rgba.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    std::uint8_t c[4] = {static_cast<std::uint8_t>(fillRgba >> 24), static_cast<std::uint8_t>(fillRgba >> 16),
                         static_cast<std::uint8_t>(fillRgba >> 8), static_cast<std::uint8_t>(fillRgba)};
    for (std::size_t i = 0; i < rgba.size(); i += 4) std::copy(c, c + 4, &rgba[i]);
}

namespace {
void setError(std::string* error, const std::string& what) {
    if (error) *error = what;
}
}  // namespace

// The simplified libpng API (png_image) handles libpng's longjmp error
// reporting internally, so no C++ object lives across a setjmp here.
bool writePng(const std::string& path, const Image& image, std::string* error) {
    if (image.empty() || image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
        setError(error, path + ": empty or inconsistent image");
        return false;
    }
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
    for (std::size_t i = 0, n = static_cast<std::size_t>(image.width) * image.height; i < n; ++i) {
        rgb[3 * i + 0] = image.rgba[4 * i + 0];
        rgb[3 * i + 1] = image.rgba[4 * i + 1];
        rgb[3 * i + 2] = image.rgba[4 * i + 2];
    }
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&png, path.c_str(), 0, rgb.data(), 0, nullptr)) {
        setError(error, path + ": " + png.message);
        png_image_free(&png);
        return false;
    }
    return true;
}

bool readPng(const std::string& path, Image& image, std::string* error) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str())) {
        setError(error, path + ": " + png.message);
        png_image_free(&png);
        return false;
    }
    png.format = PNG_FORMAT_RGBA;
    Image out;
    out.width = static_cast<int>(png.width);
    out.height = static_cast<int>(png.height);
    out.rgba.resize(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, out.rgba.data(), 0, nullptr)) {
        setError(error, path + ": " + png.message);
        png_image_free(&png);
        return false;
    }
    image = std::move(out);
    return true;
}

void flipVertical(Image& image) {
    std::size_t stride = static_cast<std::size_t>(image.width) * 4;
    for (int y = 0; y < image.height / 2; ++y)
        std::swap_ranges(image.pixel(0, y), image.pixel(0, y) + stride, image.pixel(0, image.height - 1 - y));
}

Image downsample(const Image& src, int factor) {
    if (factor <= 1) return src;
    Image dst(src.width / factor, src.height / factor);
    int n = factor * factor;
    for (int y = 0; y < dst.height; ++y)
        for (int x = 0; x < dst.width; ++x) {
            unsigned sum[4] = {0, 0, 0, 0};
            for (int j = 0; j < factor; ++j)
                for (int i = 0; i < factor; ++i) {
                    const std::uint8_t* p = src.pixel(x * factor + i, y * factor + j);
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                }
            std::uint8_t* d = dst.pixel(x, y);
            for (int c = 0; c < 4; ++c) d[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
        }
    return dst;
}

Image resizeArea(const Image& src, int w, int h) {
    Image dst(std::max(1, w), std::max(1, h));
    if (src.empty()) return dst;
    // Integer source ranges per destination pixel: deterministic and simple.
    for (int y = 0; y < dst.height; ++y) {
        int y0 = static_cast<int>(static_cast<long long>(y) * src.height / dst.height);
        int y1 = std::max(y0 + 1, static_cast<int>(static_cast<long long>(y + 1) * src.height / dst.height));
        for (int x = 0; x < dst.width; ++x) {
            int x0 = static_cast<int>(static_cast<long long>(x) * src.width / dst.width);
            int x1 = std::max(x0 + 1, static_cast<int>(static_cast<long long>(x + 1) * src.width / dst.width));
            unsigned long sum[4] = {0, 0, 0, 0};
            for (int j = y0; j < y1; ++j)
                for (int i = x0; i < x1; ++i) {
                    const std::uint8_t* p = src.pixel(i, j);
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                }
            unsigned long n = static_cast<unsigned long>((y1 - y0) * (x1 - x0));
            std::uint8_t* d = dst.pixel(x, y);
            for (int c = 0; c < 4; ++c) d[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
        }
    }
    return dst;
}

Image contactSheet(const std::vector<Image>& frames, int columns, int thumbWidth, int gap,
                   std::uint32_t backgroundRgba) {
    if (frames.empty() || frames[0].empty()) return {};
    columns = std::max(1, std::min(columns, static_cast<int>(frames.size())));
    int rows = (static_cast<int>(frames.size()) + columns - 1) / columns;
    thumbWidth = std::max(8, thumbWidth);
    int thumbHeight = std::max(1, thumbWidth * frames[0].height / frames[0].width);
    Image sheet(gap + columns * (thumbWidth + gap), gap + rows * (thumbHeight + gap), backgroundRgba);
    for (std::size_t i = 0; i < frames.size(); ++i) {
        Image t = resizeArea(frames[i], thumbWidth, thumbHeight);
        int ox = gap + static_cast<int>(i % columns) * (thumbWidth + gap);
        int oy = gap + static_cast<int>(i / columns) * (thumbHeight + gap);
        for (int y = 0; y < thumbHeight; ++y)
            std::copy(t.pixel(0, y), t.pixel(0, y) + thumbWidth * 4, sheet.pixel(ox, oy + y));
    }
    return sheet;
}

}  // namespace tb
