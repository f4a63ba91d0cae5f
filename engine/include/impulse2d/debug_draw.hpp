// Impulse2D — the debug-draw interface. A renderer implements it; the world
// calls it from World::draw with every shape, joint and contact in world space.
#pragma once

#include <cstdint>

#include "impulse2d/math.hpp"

namespace i2d {

struct Color {
    float r = 1.0f, g = 1.0f, b = 1.0f, a = 1.0f;
};

class DebugDraw {
public:
    virtual ~DebugDraw() = default;

    /// A solid convex polygon (counter-clockwise), rounded by `radius` ≥ 0.
    virtual void drawSolidPolygon(const Transform& xf, const Vec2* vertices, int count, float radius, Color color) = 0;
    /// A solid circle; `axis` is a unit vector marking the body's rotation.
    virtual void drawSolidCircle(Vec2 center, float radius, Vec2 axis, Color color) = 0;
    /// A solid capsule between two world points.
    virtual void drawSolidCapsule(Vec2 p1, Vec2 p2, float radius, Color color) = 0;
    /// A line segment.
    virtual void drawSegment(Vec2 p1, Vec2 p2, Color color) = 0;
    /// A point of the given size in pixels.
    virtual void drawPoint(Vec2 p, float size, Color color) = 0;

    bool drawShapes = true;
    bool drawJoints = true;
    bool drawAABBs = false;
    bool drawContacts = false;
    bool drawContactNormals = false;
};

}  // namespace i2d
