// Testbed renderer — implementation of gl_draw.hpp (see there).
#include "render/gl_draw.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tb {

namespace {
constexpr float kPi = 3.14159265358979f;
constexpr int kMaxOutline = 512;
}  // namespace

GlDraw::GlDraw(const GlApi& gl, DrawStyle style) : gl_(gl), style_(style) {}

void GlDraw::beginFrame(const View2D& view, float pixelScale) {
    view_ = view;
    pixelScale_ = pixelScale > 0.0f ? pixelScale : 1.0f;
    gl_.Viewport(0, 0, view.pixelWidth, view.pixelHeight);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Disable(GL_CULL_FACE);
    gl_.Disable(GL_DITHER);  // plain colours: identical pixels everywhere
    gl_.ClearColor(style_.background.r, style_.background.g, style_.background.b, 1.0f);
    gl_.Clear(GL_COLOR_BUFFER_BIT);
    gl_.Enable(GL_BLEND);
    gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    applyWorldProjection();
}

void GlDraw::applyWorldProjection() {
    i2d::AABB b = view_.bounds();
    gl_.MatrixMode(GL_PROJECTION);
    gl_.LoadIdentity();
    gl_.Ortho(b.lower.x, b.upper.x, b.lower.y, b.upper.y, -1.0, 1.0);
    gl_.MatrixMode(GL_MODELVIEW);
    gl_.LoadIdentity();
}

int GlDraw::arcSegments(float radius, float angle) const {
    // About one segment per 3 target pixels of arc, within sane bounds.
    float px = std::fabs(radius * angle) / view_.metresPerPixel();
    int n = static_cast<int>(std::ceil(px / 3.0f));
    int maxN = std::max(2, static_cast<int>(std::ceil(angle / (2.0f * kPi) * 96.0f)));
    return std::clamp(n, 2, maxN);
}

void GlDraw::fillAndStroke(const i2d::Vec2* pts, int count, i2d::Color color) {
    if (count < 2) return;
    if (count >= 3) {
        gl_.Color4f(color.r, color.g, color.b, color.a * style_.fillAlpha);
        gl_.Begin(GL_TRIANGLE_FAN);
        for (int i = 0; i < count; ++i) gl_.Vertex2f(pts[i].x, pts[i].y);
        gl_.End();
    }
    gl_.LineWidth(style_.lineWidth * pixelScale_);
    gl_.Color4f(color.r, color.g, color.b, color.a);
    gl_.Begin(GL_LINE_LOOP);
    for (int i = 0; i < count; ++i) gl_.Vertex2f(pts[i].x, pts[i].y);
    gl_.End();
}

void GlDraw::drawSolidPolygon(const i2d::Transform& xf, const i2d::Vec2* vertices, int count, float radius,
                              i2d::Color color) {
    if (count <= 0) return;
    std::vector<i2d::Vec2> world(static_cast<std::size_t>(count));
    i2d::Vec2 centroid{};
    for (int i = 0; i < count; ++i) {
        world[i] = i2d::transformPoint(xf, vertices[i]);
        centroid += world[i];
    }
    centroid *= 1.0f / static_cast<float>(count);
    if (count < 3) {
        // Degenerate input: show it as a capsule-like stroke.
        drawSolidCapsule(world[0], world[count - 1], radius, color);
        return;
    }

    std::vector<i2d::Vec2> outline;
    if (radius <= 0.0f) {
        outline = world;
    } else {
        // Rounded polygon: at each corner an arc of the radius between the
        // outward normals of the two edges meeting there.
        outline.reserve(kMaxOutline);
        for (int i = 0; i < count; ++i) {
            const i2d::Vec2 prev = world[(i + count - 1) % count], cur = world[i], next = world[(i + 1) % count];
            i2d::Vec2 n0 = i2d::normalize(i2d::rightPerp(cur - prev));
            i2d::Vec2 n1 = i2d::normalize(i2d::rightPerp(next - cur));
            float a0 = std::atan2(n0.y, n0.x);
            float a1 = std::atan2(n1.y, n1.x);
            while (a1 < a0) a1 += 2.0f * kPi;
            int n = arcSegments(radius, a1 - a0);
            for (int k = 0; k <= n && static_cast<int>(outline.size()) < kMaxOutline; ++k) {
                float a = a0 + (a1 - a0) * static_cast<float>(k) / static_cast<float>(n);
                outline.push_back(cur + radius * i2d::Vec2{std::cos(a), std::sin(a)});
            }
        }
    }
    fillAndStroke(outline.data(), static_cast<int>(outline.size()), color);

    // Rotation mark: from the centre along the body's x axis, to the nearest edge.
    float inner = 1.0e30f;
    for (int i = 0; i < count; ++i) {
        i2d::Vec2 e = world[(i + 1) % count] - world[i];
        i2d::Vec2 n = i2d::normalize(i2d::rightPerp(e));
        inner = std::min(inner, i2d::dot(n, world[i] - centroid));
    }
    i2d::Vec2 axis = i2d::rotate(xf.q, {1.0f, 0.0f});
    drawLine(centroid, centroid + (std::max(inner, 0.0f) + radius) * axis, style_.lineWidth, color);
}

void GlDraw::drawSolidCircle(i2d::Vec2 center, float radius, i2d::Vec2 axis, i2d::Color color) {
    int n = std::max(12, arcSegments(radius, 2.0f * kPi));
    std::vector<i2d::Vec2> pts(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(n);
        pts[i] = center + radius * i2d::Vec2{std::cos(a), std::sin(a)};
    }
    fillAndStroke(pts.data(), n, color);
    drawLine(center, center + radius * axis, style_.lineWidth, color);
}

void GlDraw::drawSolidCapsule(i2d::Vec2 p1, i2d::Vec2 p2, float radius, i2d::Color color) {
    float len = i2d::length(p2 - p1);
    i2d::Vec2 d = len > 1.0e-6f ? (1.0f / len) * (p2 - p1) : i2d::Vec2{1.0f, 0.0f};
    float base = std::atan2(d.y, d.x);
    int n = std::max(6, arcSegments(radius, kPi));
    std::vector<i2d::Vec2> pts;
    pts.reserve(2 * static_cast<std::size_t>(n) + 2);
    // Half circle around p2 from −90° to +90° of the axis, then around p1.
    for (int k = 0; k <= n; ++k) {
        float a = base - 0.5f * kPi + kPi * static_cast<float>(k) / static_cast<float>(n);
        pts.push_back(p2 + radius * i2d::Vec2{std::cos(a), std::sin(a)});
    }
    for (int k = 0; k <= n; ++k) {
        float a = base + 0.5f * kPi + kPi * static_cast<float>(k) / static_cast<float>(n);
        pts.push_back(p1 + radius * i2d::Vec2{std::cos(a), std::sin(a)});
    }
    fillAndStroke(pts.data(), static_cast<int>(pts.size()), color);
    // The core segment doubles as the rotation mark.
    drawLine(p1, p2, style_.lineWidth, color);
}

void GlDraw::drawSegment(i2d::Vec2 p1, i2d::Vec2 p2, i2d::Color color) {
    drawLine(p1, p2, style_.lineWidth + 0.5f, color);
}

void GlDraw::drawLine(i2d::Vec2 p1, i2d::Vec2 p2, float widthPixels, i2d::Color color) {
    gl_.LineWidth(std::max(1.0f, widthPixels * pixelScale_));
    gl_.Color4f(color.r, color.g, color.b, color.a);
    gl_.Begin(GL_LINES);
    gl_.Vertex2f(p1.x, p1.y);
    gl_.Vertex2f(p2.x, p2.y);
    gl_.End();
}

void GlDraw::drawPoint(i2d::Vec2 p, float size, i2d::Color color) {
    float h = 0.5f * std::max(size, 1.0f) * pixelScale_ * view_.metresPerPixel();
    gl_.Color4f(color.r, color.g, color.b, color.a);
    gl_.Begin(GL_QUADS);
    gl_.Vertex2f(p.x - h, p.y - h);
    gl_.Vertex2f(p.x + h, p.y - h);
    gl_.Vertex2f(p.x + h, p.y + h);
    gl_.Vertex2f(p.x - h, p.y + h);
    gl_.End();
}

void GlDraw::drawBox(const i2d::AABB& box, i2d::Color color) {
    gl_.LineWidth(std::max(1.0f, pixelScale_));
    gl_.Color4f(color.r, color.g, color.b, color.a);
    gl_.Begin(GL_LINE_LOOP);
    gl_.Vertex2f(box.lower.x, box.lower.y);
    gl_.Vertex2f(box.upper.x, box.lower.y);
    gl_.Vertex2f(box.upper.x, box.upper.y);
    gl_.Vertex2f(box.lower.x, box.upper.y);
    gl_.End();
}

}  // namespace tb
