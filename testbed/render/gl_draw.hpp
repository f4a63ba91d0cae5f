// Testbed renderer — the one OpenGL implementation of i2d::DebugDraw, used by
// both the offscreen renderer (OSMesa) and the window (SDL2). Immediate-mode
// OpenGL 1.x: filled shapes with opaque outlines, a line marking each body's
// rotation, points of a given pixel size, lines scaled with the resolution.
#pragma once

#include <impulse2d/debug_draw.hpp>
#include <impulse2d/math.hpp>

#include "render/camera.hpp"
#include "render/gl_api.hpp"

namespace tb {

struct DrawStyle {
    i2d::Color background{0.11f, 0.12f, 0.14f, 1.0f};
    float fillAlpha = 0.45f;  ///< fills are the shape colour blended over what is below
    float lineWidth = 1.5f;   ///< outline width in logical pixels
};

class GlDraw : public i2d::DebugDraw {
public:
    explicit GlDraw(const GlApi& gl, DrawStyle style = {});

    /// Starts a frame: viewport, clear, world projection of `view`.
    /// `pixelScale` is the number of target pixels per logical pixel (the
    /// supersampling factor), applied to line widths and point sizes.
    void beginFrame(const View2D& view, float pixelScale = 1.0f);
    /// Restores the world projection (after drawing text, for example).
    void applyWorldProjection();

    void drawSolidPolygon(const i2d::Transform& xf, const i2d::Vec2* vertices, int count, float radius,
                          i2d::Color color) override;
    void drawSolidCircle(i2d::Vec2 center, float radius, i2d::Vec2 axis, i2d::Color color) override;
    void drawSolidCapsule(i2d::Vec2 p1, i2d::Vec2 p2, float radius, i2d::Color color) override;
    void drawSegment(i2d::Vec2 p1, i2d::Vec2 p2, i2d::Color color) override;
    void drawPoint(i2d::Vec2 p, float size, i2d::Color color) override;

    /// Outline of a box (for AABBs drawn by the caller).
    void drawBox(const i2d::AABB& box, i2d::Color color);
    /// A line of `widthPixels` logical pixels.
    void drawLine(i2d::Vec2 p1, i2d::Vec2 p2, float widthPixels, i2d::Color color);

    const View2D& view() const { return view_; }
    const GlApi& gl() const { return gl_; }
    const DrawStyle& style() const { return style_; }
    /// Fill opacity of the shapes drawn next (0: outlines only).
    void setFillAlpha(float alpha) { style_.fillAlpha = alpha; }
    float pixelScale() const { return pixelScale_; }

private:
    /// Fills the convex outline `pts` (world) and strokes it.
    void fillAndStroke(const i2d::Vec2* pts, int count, i2d::Color color);
    int arcSegments(float radius, float angle) const;

    const GlApi& gl_;
    DrawStyle style_;
    View2D view_{};
    float pixelScale_ = 1.0f;
};

}  // namespace tb
