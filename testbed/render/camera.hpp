// Testbed renderer — the 2D camera: which part of the world a frame shows and
// how world points map to pixels.
#pragma once

#include <impulse2d/math.hpp>

namespace i2d {
class World;
}

namespace tb {

struct Scene;

/// A view of the world: `center` at the middle of a width × height pixel
/// viewport, `height` world metres visible vertically (the visible width
/// follows from the aspect ratio). Pixel rows count downwards from the top.
struct View2D {
    i2d::Vec2 center{};
    float height = 20.0f;
    int pixelWidth = 1280;
    int pixelHeight = 720;

    float width() const { return height * static_cast<float>(pixelWidth) / static_cast<float>(pixelHeight); }
    /// World metres per pixel.
    float metresPerPixel() const { return height / static_cast<float>(pixelHeight); }
    i2d::AABB bounds() const;
    /// World point → pixel coordinates (x right, y down; pixel centres at +0.5).
    i2d::Vec2 worldToPixel(i2d::Vec2 p) const;
    /// Pixel coordinates (x right, y down) → world point.
    i2d::Vec2 pixelToWorld(i2d::Vec2 px) const;
};

/// The smallest view of the given aspect showing `box` with a margin
/// (`margin` is a fraction of the box size added on each side).
View2D fitView(const i2d::AABB& box, int pixelWidth, int pixelHeight, float margin = 0.08f);

/// Bounds to frame for a world: the moving (non-static) bodies with the
/// static geometry around them, or all shapes when nothing moves. A wide
/// ground is thereby clipped to the region near the bodies instead of
/// shrinking them to a few pixels. Returns false when the world has no shapes.
bool worldFrameBounds(const i2d::World& world, i2d::AABB& out);

/// The view for a scene: its description's camera when it has one, else
/// fitted to worldFrameBounds (a 20 m view of the origin for an empty world).
View2D sceneView(const Scene& scene, int pixelWidth, int pixelHeight);

}  // namespace tb
