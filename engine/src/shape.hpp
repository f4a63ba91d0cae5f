// Shapes: a body's collision geometry with its material and filter, and the
// operations that depend only on the geometry (bounding box, mass, core
// points, ray cast, point test), dispatched on the shape's type.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

#include "body.hpp"
#include "dynamic_tree.hpp"
#include "impulse2d/geometry.hpp"
#include "impulse2d/types.hpp"
#include "slot_array.hpp"

namespace i2d::detail {

struct WorldState;

/// The geometry of one shape, stored once: which member is live is Shape::type.
union ShapeGeometry {
    Circle circle;
    Capsule capsule;
    Segment segment;
    Polygon polygon;
    ShapeGeometry() : polygon{} {}
};

struct Shape {
    /// Beside the geometry: the narrowphase reads both for every contact
    /// each step. A circle's type and geometry span 16 bytes and a capsule's
    /// 24, so they share a cache line unless the shape (232 bytes, not
    /// line-aligned) starts in a line's last few bytes; 196 bytes apart, they
    /// never did.
    ShapeType type = ShapeType::circle;
    ShapeGeometry geometry;
    float density = 1.0f, friction = 0.6f, restitution = 0.0f;
    float rollingResistance = 0.0f, tangentSpeed = 0.0f;
    Filter filter{};
    int body = kNullIndex;
    int prevShape = kNullIndex, nextShape = kNullIndex;  ///< neighbours in the body's list
    int proxy = DynamicTree::kNull;
    std::uint32_t generation = 1;
    /// A chain's segment (ShapeType::segment): one-sided, with the ghost
    /// vertices of its neighbours in the body frame (equal to its own end
    /// point where it has none). seams.cpp applies both.
    Vec2 ghost1{}, ghost2{};
    bool chainSegment = false;
    bool isSensor = false;
    bool enableContactEvents = true;
    bool enableSensorEvents = true;
    bool enableHitEvents = false;
    bool alive = false;
    /// The broadphase tree its proxy is in: its body's type when the proxy
    /// was made (BroadPhase::tree).
    BodyType treeType = BodyType::static_body;
    bool moved = false;  ///< in the broadphase move buffer
    std::uintptr_t userData = 0;

    bool inStaticTree() const { return treeType == BodyType::static_body; }
};

/// The shapes of a body in creation order, for range-for:
///   for (int s : bodyShapes(w.shapes, body)) ...
/// (do not destroy shapes while iterating).
class BodyShapes {
public:
    BodyShapes(const SlotArray<Shape>& shapes, int first) : shapes_(&shapes), first_(first) {}
    struct Iterator {
        const SlotArray<Shape>* shapes;
        int s;
        int operator*() const { return s; }
        Iterator& operator++() {
            s = (*shapes)[s].nextShape;
            return *this;
        }
        bool operator!=(const Iterator& o) const { return s != o.s; }
    };
    Iterator begin() const { return {shapes_, first_}; }
    Iterator end() const { return {shapes_, kNullIndex}; }

private:
    const SlotArray<Shape>* shapes_;
    int first_;
};

inline AABB shapeAABB(const Shape& s, const Transform& xf) {
    switch (s.type) {
        case ShapeType::circle: return computeAABB(s.geometry.circle, xf);
        case ShapeType::capsule: return computeAABB(s.geometry.capsule, xf);
        case ShapeType::segment: return computeAABB(s.geometry.segment, xf);
        case ShapeType::polygon: return computeAABB(s.geometry.polygon, xf);
    }
    return {};
}

/// How thick a shape is (m): a round shape's diameter; for a polygon, twice
/// the sum of the centroid's distance to its nearest face and the rounding
/// (exact for boxes and regular polygons, an underestimate otherwise); a
/// segment, which has no inside, is infinitely thick. What a contact's deep-overlap depth scales with
/// (contact.hpp, kDeepFraction).
inline float shapeThickness(const Shape& s) {
    switch (s.type) {
        case ShapeType::circle: return 2.0f * s.geometry.circle.radius;
        case ShapeType::capsule: return 2.0f * s.geometry.capsule.radius;
        case ShapeType::segment: break;
        case ShapeType::polygon: {
            const Polygon& p = s.geometry.polygon;
            float nearest = INFINITY;
            for (int i = 0; i < p.count; ++i)
                nearest = std::min(nearest, dot(p.normals[i], p.vertices[i] - p.centroid));
            return 2.0f * (nearest + p.radius);
        }
    }
    return INFINITY;
}

/// Mass data of a shape with area; none for segments (they add no mass).
inline std::optional<MassData> shapeMass(const Shape& s) {
    switch (s.type) {
        case ShapeType::circle: return computeMass(s.geometry.circle, s.density);
        case ShapeType::capsule: return computeMass(s.geometry.capsule, s.density);
        case ShapeType::polygon: return computeMass(s.geometry.polygon, s.density);
        case ShapeType::segment: break;
    }
    return std::nullopt;
}

/// The largest d·x over a shape's points in world coordinates (its support
/// along d, rounding included).
inline float shapeSupport(const Shape& s, const Transform& xf, Vec2 d) {
    switch (s.type) {
        case ShapeType::circle: return dot(transformPoint(xf, s.geometry.circle.center), d) + s.geometry.circle.radius;
        case ShapeType::capsule: {
            const Capsule& c = s.geometry.capsule;
            return std::max(dot(transformPoint(xf, c.center1), d), dot(transformPoint(xf, c.center2), d)) + c.radius;
        }
        case ShapeType::segment: {
            const Segment& c = s.geometry.segment;
            return std::max(dot(transformPoint(xf, c.point1), d), dot(transformPoint(xf, c.point2), d));
        }
        case ShapeType::polygon: {
            const Polygon& p = s.geometry.polygon;
            float m = dot(transformPoint(xf, p.vertices[0]), d);
            for (int i = 1; i < p.count; ++i) m = std::max(m, dot(transformPoint(xf, p.vertices[i]), d));
            return m + p.radius;
        }
    }
    return 0.0f;
}

/// The outward normals of a shape's flat sides in world coordinates: a
/// polygon's faces, both sides of a capsule or a segment, none for a circle.
/// Returns how many were written to `out` (at most kMaxPolygonVertices).
inline int shapeFaceNormals(const Shape& s, const Transform& xf, Vec2* out) {
    switch (s.type) {
        case ShapeType::circle: return 0;
        case ShapeType::capsule:
        case ShapeType::segment: {
            const Vec2 p1 = s.type == ShapeType::capsule ? s.geometry.capsule.center1 : s.geometry.segment.point1;
            const Vec2 p2 = s.type == ShapeType::capsule ? s.geometry.capsule.center2 : s.geometry.segment.point2;
            const Vec2 d = rotate(xf.q, p2 - p1);
            const float len = length(d);
            if (!(len > 0.0f)) return 0;
            out[0] = {-d.y / len, d.x / len};
            out[1] = -out[0];
            return 2;
        }
        case ShapeType::polygon: {
            const Polygon& p = s.geometry.polygon;
            for (int i = 0; i < p.count; ++i) out[i] = rotate(xf.q, p.normals[i]);
            return p.count;
        }
    }
    return 0;
}

/// A shape as a convex core (points) and a radius, for the distance function.
struct ShapeCore {
    Vec2 points[kMaxPolygonVertices];
    int count = 0;
    float radius = 0.0f;
};

inline ShapeCore shapeCore(const Shape& s) {
    ShapeCore c;
    switch (s.type) {
        case ShapeType::circle:
            c.points[0] = s.geometry.circle.center;
            c.count = 1;
            c.radius = s.geometry.circle.radius;
            break;
        case ShapeType::capsule:
            c.points[0] = s.geometry.capsule.center1;
            c.points[1] = s.geometry.capsule.center2;
            c.count = 2;
            c.radius = s.geometry.capsule.radius;
            break;
        case ShapeType::segment:
            c.points[0] = s.geometry.segment.point1;
            c.points[1] = s.geometry.segment.point2;
            c.count = 2;
            break;
        case ShapeType::polygon:
            std::copy(s.geometry.polygon.vertices, s.geometry.polygon.vertices + s.geometry.polygon.count, c.points);
            c.count = s.geometry.polygon.count;
            c.radius = s.geometry.polygon.radius;
            break;
    }
    return c;
}

/// Ray cast in the shape's body frame.
inline std::optional<RayHit> shapeRayCast(const Shape& s, const RayCastInput& in) {
    switch (s.type) {
        case ShapeType::circle: return rayCast(in, s.geometry.circle);
        case ShapeType::capsule: return rayCast(in, s.geometry.capsule);
        case ShapeType::polygon: return rayCast(in, s.geometry.polygon);
        case ShapeType::segment: return rayCast(in, s.geometry.segment);
    }
    return std::nullopt;
}

/// Point test in the shape's body frame; segments contain no point.
inline bool shapeContains(const Shape& s, Vec2 localPoint) {
    switch (s.type) {
        case ShapeType::circle: return containsPoint(s.geometry.circle, localPoint);
        case ShapeType::capsule: return containsPoint(s.geometry.capsule, localPoint);
        case ShapeType::polygon: return containsPoint(s.geometry.polygon, localPoint);
        case ShapeType::segment: break;
    }
    return false;
}

inline BodyShapes bodyShapes(const SlotArray<Shape>& shapes, const Body& body) { return {shapes, body.firstShape}; }

/// Creates a shape on a body: its slot, its proxy in the broadphase and,
/// unless `updateBodyMass` is false (a caller adding many shapes, which then
/// calls updateMass once: it visits every shape of the body), the body's new
/// mass. The geometry must have been validated.
int createShape(WorldState& w, int body, const ShapeDef& def, ShapeType type, const ShapeGeometry& geometry,
                bool updateBodyMass = true);

/// Destroys a shape with its contacts (end events for touching ones) and its proxy.
/// The body's mass is not updated.
void destroyShape(WorldState& w, int shape);

/// Drops the shape's contacts and re-inserts its proxy so the broadphase
/// finds its pairs again under a new filter.
void refilterShape(WorldState& w, int shape);

}  // namespace i2d::detail
