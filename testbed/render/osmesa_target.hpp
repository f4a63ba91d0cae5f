// Testbed renderer — an offscreen OpenGL context in system memory (OSMesa):
// no display, no GPU. Mesa's software rasteriser gives the same pixels for
// the same drawing on one machine, which makes rendered frames reproducible.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render/gl_api.hpp"
#include "render/png_io.hpp"

namespace tb {

class OsmesaTarget {
public:
    /// Creates a width × height RGBA context. Throws std::runtime_error when
    /// OSMesa cannot create it or lacks a needed GL entry point.
    OsmesaTarget(int width, int height);
    ~OsmesaTarget();
    OsmesaTarget(const OsmesaTarget&) = delete;
    OsmesaTarget& operator=(const OsmesaTarget&) = delete;

    /// Makes this context current on the calling thread (done by the constructor).
    void makeCurrent();
    const GlApi& gl() const { return gl_; }
    int width() const { return width_; }
    int height() const { return height_; }
    /// Finishes drawing and returns the pixels, rows from the top.
    Image readImage();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    GlApi gl_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace tb
