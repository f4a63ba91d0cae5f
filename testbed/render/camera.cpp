// Testbed renderer — implementation of camera.hpp (see there).
#include "render/camera.hpp"

#include <algorithm>

#include "scene.hpp"

namespace tb {

i2d::AABB View2D::bounds() const {
    i2d::Vec2 half{0.5f * width(), 0.5f * height};
    return {center - half, center + half};
}

i2d::Vec2 View2D::worldToPixel(i2d::Vec2 p) const {
    float s = static_cast<float>(pixelHeight) / height;
    return {0.5f * static_cast<float>(pixelWidth) + (p.x - center.x) * s,
            0.5f * static_cast<float>(pixelHeight) - (p.y - center.y) * s};
}

i2d::Vec2 View2D::pixelToWorld(i2d::Vec2 px) const {
    float m = metresPerPixel();
    return {center.x + (px.x - 0.5f * static_cast<float>(pixelWidth)) * m,
            center.y - (px.y - 0.5f * static_cast<float>(pixelHeight)) * m};
}

View2D fitView(const i2d::AABB& box, int pixelWidth, int pixelHeight, float margin) {
    View2D v;
    v.pixelWidth = std::max(1, pixelWidth);
    v.pixelHeight = std::max(1, pixelHeight);
    float w = std::max(box.upper.x - box.lower.x, 0.5f);
    float h = std::max(box.upper.y - box.lower.y, 0.5f);
    float aspect = static_cast<float>(v.pixelWidth) / static_cast<float>(v.pixelHeight);
    v.center = 0.5f * (box.lower + box.upper);
    v.height = (1.0f + 2.0f * margin) * std::max(h, w / aspect);
    return v;
}

bool worldFrameBounds(const i2d::World& world, i2d::AABB& out) {
    bool haveAll = false, haveMoving = false;
    i2d::AABB all{}, moving{};
    for (i2d::BodyId body : world.bodies()) {
        bool isStatic = world.bodyType(body) == i2d::BodyType::static_body;
        for (i2d::ShapeId shape : world.bodyShapes(body)) {
            i2d::AABB b = world.shapeAABB(shape);
            all = haveAll ? i2d::unionOf(all, b) : b;
            haveAll = true;
            if (!isStatic) {
                moving = haveMoving ? i2d::unionOf(moving, b) : b;
                haveMoving = true;
            }
        }
    }
    if (!haveAll) return false;
    if (!haveMoving) {
        out = all;
        return true;
    }
    // Static geometry counts only within a generous neighbourhood of the
    // moving bodies (half their extent, at least 2 m, on each side).
    i2d::Vec2 size = moving.upper - moving.lower;
    i2d::Vec2 pad{std::max(0.5f * size.x, 2.0f), std::max(0.5f * size.y, 2.0f)};
    i2d::AABB near{moving.lower - pad, moving.upper + pad};
    i2d::AABB clipped{i2d::max(all.lower, near.lower), i2d::min(all.upper, near.upper)};
    out = i2d::unionOf(moving, clipped);
    return true;
}

View2D sceneView(const Scene& scene, int pixelWidth, int pixelHeight) {
    if (scene.desc.camera) {
        View2D v;
        v.center = scene.desc.camera->center;
        v.height = scene.desc.camera->height > 0.0f ? scene.desc.camera->height : 20.0f;
        v.pixelWidth = std::max(1, pixelWidth);
        v.pixelHeight = std::max(1, pixelHeight);
        return v;
    }
    i2d::AABB box{};
    if (scene.world && worldFrameBounds(*scene.world, box)) {
        View2D v = fitView(box, pixelWidth, pixelHeight);
        // Room at the top for the text lines: the scene sits a little lower.
        v.height *= 1.08f;
        v.center.y += 0.04f * v.height;
        return v;
    }
    View2D v;
    v.pixelWidth = std::max(1, pixelWidth);
    v.pixelHeight = std::max(1, pixelHeight);
    return v;
}

}  // namespace tb
