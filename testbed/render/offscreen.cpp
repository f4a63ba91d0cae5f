// Testbed renderer — implementation of offscreen.hpp (see there).
#include "render/offscreen.hpp"

#include <algorithm>

#include <impulse2d/world.hpp>

#include "render/text.hpp"

namespace tb {

void drawWorld(GlDraw& drawer, const i2d::World& world, const WorldDrawFlags& flags) {
    drawer.drawShapes = true;
    drawer.drawJoints = flags.joints;
    drawer.drawAABBs = flags.aabbs;
    drawer.drawContacts = flags.contacts;
    drawer.drawContactNormals = flags.contacts;
    world.draw(drawer);
}

namespace {
int checkedScale(int s) { return std::clamp(s, 1, 4); }
}  // namespace

OffscreenRenderer::OffscreenRenderer(int width, int height, int supersample, DrawStyle style)
    : width_(width),
      height_(height),
      supersample_(checkedScale(supersample)),
      target_(width * checkedScale(supersample), height * checkedScale(supersample)),
      drawer_(target_.gl(), style) {}

Image OffscreenRenderer::render(const View2D& view, const std::function<void(GlDraw&)>& draw,
                                const std::string& caption) {
    target_.makeCurrent();
    View2D v = view;
    v.pixelWidth = width_ * supersample_;
    v.pixelHeight = height_ * supersample_;
    drawer_.beginFrame(v, static_cast<float>(supersample_));
    if (draw) draw(drawer_);
    if (!caption.empty()) {
        // 2 font pixels per glyph pixel at 720 rows and more, 1 below.
        int scale = (height_ >= 480 ? 2 : 1) * supersample_;
        drawText(target_.gl(), v.pixelWidth, v.pixelHeight, 6 * scale, 5 * scale, caption, scale,
                 {0.92f, 0.92f, 0.92f, 1.0f});
        drawer_.applyWorldProjection();
    }
    return downsample(target_.readImage(), supersample_);
}

Image OffscreenRenderer::renderWorld(const i2d::World& world, const View2D& view, const WorldDrawFlags& flags,
                                     const std::string& caption) {
    return render(
        view, [&](GlDraw& d) { drawWorld(d, world, flags); }, caption);
}

}  // namespace tb
