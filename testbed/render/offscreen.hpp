// Testbed renderer — rendering frames offscreen into images: an OSMesa target
// at `supersample` times the output size, the GL debug drawer, an optional
// text line, and a box-filter resolve to the output size (antialiasing).
#pragma once

#include <functional>
#include <string>

#include "render/camera.hpp"
#include "render/gl_draw.hpp"
#include "render/osmesa_target.hpp"
#include "render/png_io.hpp"

namespace i2d {
class World;
}

namespace tb {

/// What a world frame shows besides the shapes and joints.
struct WorldDrawFlags {
    bool contacts = false;  ///< contact points and normals
    bool aabbs = false;
    bool joints = true;
};

/// Sets the drawer's flags and has the world draw itself into it.
void drawWorld(GlDraw& drawer, const i2d::World& world, const WorldDrawFlags& flags);

class OffscreenRenderer {
public:
    /// Output images are width × height; drawing happens at supersample × that.
    OffscreenRenderer(int width, int height, int supersample = 2, DrawStyle style = {});

    int width() const { return width_; }
    int height() const { return height_; }
    int supersample() const { return supersample_; }

    /// Renders one frame: `view` is in output pixels (its pixel size is
    /// replaced by this renderer's), `draw` issues the drawing, `caption`
    /// (if not empty) is written at the top left.
    Image render(const View2D& view, const std::function<void(GlDraw&)>& draw, const std::string& caption = {});

    /// Renders a world with the given flags.
    Image renderWorld(const i2d::World& world, const View2D& view, const WorldDrawFlags& flags = {},
                      const std::string& caption = {});

private:
    int width_, height_, supersample_;
    OsmesaTarget target_;
    GlDraw drawer_;
};

}  // namespace tb
