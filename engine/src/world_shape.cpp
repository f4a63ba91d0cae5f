// World: the public API facade for shapes — creation with the geometry
// checks, destruction, material, filter and inspection. Validates, then calls
// the shape module.
#include <algorithm>
#include <cmath>

#include "impulse2d/world.hpp"
#include "world_state.hpp"

namespace i2d {

using detail::fail;
using detail::requireBounded;
using detail::requireFinite;
using detail::requireInRange;
using detail::requireUnitInterval;

namespace {

void validateShapeDef(const ShapeDef& d) {
    requireInRange(d.density, 0.0f, detail::kMaxDensity, "shape density");
    requireInRange(d.friction, 0.0f, detail::kMaxFriction, "shape friction");
    requireUnitInterval(d.restitution, "shape restitution");
    requireInRange(d.rollingResistance, 0.0f, detail::kMaxFriction, "shape rolling resistance");
    requireBounded(d.tangentSpeed, "shape tangent speed");
}

template <class Fill>
ShapeId addShape(detail::WorldState& w, BodyId bodyId, const ShapeDef& def, ShapeType type, Fill&& fill) {
    w.checkUnlocked();
    int b = w.bodyIndex(bodyId);
    validateShapeDef(def);
    detail::ShapeGeometry geometry;
    fill(geometry);
    return w.shapeHandle(detail::createShape(w, b, def, type, geometry));
}

}  // namespace

ShapeId World::createCircleShape(BodyId body, const ShapeDef& def, const Circle& c) {
    requireBounded(c.center, "circle centre");
    requireFinite(c.radius, "circle radius");
    if (!(c.radius > 0.0f) || c.radius > detail::kMaxRadius) fail("circle radius must be in (0, 1e5]");
    return addShape(state(), body, def, ShapeType::circle, [&](detail::ShapeGeometry& g) { g.circle = c; });
}

ShapeId World::createCapsuleShape(BodyId body, const ShapeDef& def, const Capsule& c) {
    requireBounded(c.center1, "capsule centre1");
    requireBounded(c.center2, "capsule centre2");
    requireFinite(c.radius, "capsule radius");
    if (!(c.radius > 0.0f) || c.radius > detail::kMaxRadius) fail("capsule radius must be in (0, 1e5]");
    if (distanceSquared(c.center1, c.center2) <= kLinearSlop * kLinearSlop)
        fail("capsule centres must be further apart than the linear slop (use a circle)");
    return addShape(state(), body, def, ShapeType::capsule, [&](detail::ShapeGeometry& g) { g.capsule = c; });
}

ShapeId World::createPolygonShape(BodyId body, const ShapeDef& def, const Polygon& p) {
    if (p.count < 3 || p.count > kMaxPolygonVertices)
        fail("polygon must have 3 to 8 vertices (build it with makePolygon)");
    requireInRange(p.radius, 0.0f, detail::kMaxRadius, "polygon radius");
    for (int i = 0; i < p.count; ++i) {
        requireBounded(p.vertices[i], "polygon vertex");
        requireFinite(p.normals[i], "polygon normal");
        if (std::abs(lengthSquared(p.normals[i]) - 1.0f) > 1.0e-3f)
            fail("polygon normals must be unit length (build it with makePolygon)");
    }
    requireBounded(p.centroid, "polygon centroid");
    // Each edge at least kMinPolygonFeature long, with its outward normal:
    // the clockwise perpendicular of the edge.
    for (int i = 0; i < p.count; ++i) {
        Vec2 e = p.vertices[i + 1 < p.count ? i + 1 : 0] - p.vertices[i];
        float len = length(e);
        if (!(len >= detail::kMinPolygonFeature)) fail("polygon edge shorter than 0.0005 m");
        if (dot(p.normals[i], rightPerp(e)) < (1.0f - 1.0e-3f) * len)
            fail("polygon normal does not belong to its edge (build it with makePolygon)");
    }
    // Convex and counter-clockwise: every vertex lies behind every edge.
    for (int i = 0; i < p.count; ++i) {
        for (int j = 0; j < p.count; ++j) {
            if (dot(p.normals[i], p.vertices[j] - p.vertices[i]) > 10.0f * kLinearSlop)
                fail("polygon is not convex and counter-clockwise (build it with makePolygon)");
        }
    }
    // Not collinear: some vertex lies at least kMinPolygonFeature behind each edge.
    for (int i = 0; i < p.count; ++i) {
        float deepest = 0.0f;
        for (int j = 0; j < p.count; ++j) deepest = std::min(deepest, dot(p.normals[i], p.vertices[j] - p.vertices[i]));
        if (deepest > -detail::kMinPolygonFeature)
            fail("polygon is degenerate: thinner than 0.0005 m (collinear vertices)");
    }
    Polygon core = p;
    core.radius = 0.0f;
    if (!containsPoint(core, p.centroid)) fail("polygon centroid lies outside the polygon");
    return addShape(state(), body, def, ShapeType::polygon, [&](detail::ShapeGeometry& g) { g.polygon = p; });
}

ShapeId World::createSegmentShape(BodyId body, const ShapeDef& def, const Segment& seg) {
    requireBounded(seg.point1, "segment point1");
    requireBounded(seg.point2, "segment point2");
    if (distanceSquared(seg.point1, seg.point2) <= kLinearSlop * kLinearSlop)
        fail("segment points must be further apart than the linear slop");
    return addShape(state(), body, def, ShapeType::segment, [&](detail::ShapeGeometry& g) { g.segment = seg; });
}

void World::destroyShape(ShapeId id, bool updateBodyMass) {
    auto& w = state();
    w.checkUnlocked();
    int s = w.shapeIndex(id);
    int b = w.shapes[s].body;
    const detail::Shape& gone = w.shapes[s];
    if (gone.chainSegment) {
        // Its neighbours in the chain lose their ghost vertex on its side: the
        // vertex becomes a corner, whose vertex normals collide again (kept
        // as a ghost, it dropped them as if the removed segment still
        // continued the surface).
        const Segment seg = gone.geometry.segment;
        for (int k : detail::bodyShapes(w.shapes, w.bodies[b])) {
            detail::Shape& other = w.shapes[k];
            if (!other.chainSegment || k == s) continue;
            const Segment& o = other.geometry.segment;
            if (o.point2 == seg.point1 && other.ghost2 == seg.point2) other.ghost2 = o.point2;
            if (o.point1 == seg.point2 && other.ghost1 == seg.point1) other.ghost1 = o.point1;
        }
    }
    detail::destroyShape(w, s);
    detail::wakeBody(w, b);
    if (updateBodyMass) detail::updateMass(w, b);
}

bool World::isValid(ShapeId id) const { return state().find(id, state().shapes) != detail::kNullIndex; }

ShapeType World::shapeType(ShapeId id) const { return state().shapes[state().shapeIndex(id)].type; }
BodyId World::shapeBody(ShapeId id) const { return state().bodyHandle(state().shapes[state().shapeIndex(id)].body); }

namespace {
const detail::Shape& shapeOfType(const detail::WorldState& w, ShapeId id, ShapeType type) {
    const detail::Shape& s = w.shapes[w.shapeIndex(id)];
    if (s.type != type) fail("shape is of another type");
    return s;
}
}  // namespace

Circle World::shapeCircle(ShapeId id) const { return shapeOfType(state(), id, ShapeType::circle).geometry.circle; }
Capsule World::shapeCapsule(ShapeId id) const { return shapeOfType(state(), id, ShapeType::capsule).geometry.capsule; }
Polygon World::shapePolygon(ShapeId id) const { return shapeOfType(state(), id, ShapeType::polygon).geometry.polygon; }
Segment World::shapeSegment(ShapeId id) const { return shapeOfType(state(), id, ShapeType::segment).geometry.segment; }

float World::density(ShapeId id) const { return state().shapes[state().shapeIndex(id)].density; }
void World::setDensity(ShapeId id, float density, bool updateBodyMass) {
    state().checkUnlocked();
    int s = state().shapeIndex(id);
    requireInRange(density, 0.0f, detail::kMaxDensity, "density");
    state().shapes[s].density = density;
    if (updateBodyMass) detail::updateMass(state(), state().shapes[s].body);
}
float World::friction(ShapeId id) const { return state().shapes[state().shapeIndex(id)].friction; }
void World::setFriction(ShapeId id, float f) {
    int s = state().shapeIndex(id);
    requireInRange(f, 0.0f, detail::kMaxFriction, "friction");
    state().shapes[s].friction = f;
}
float World::restitution(ShapeId id) const { return state().shapes[state().shapeIndex(id)].restitution; }
void World::setRestitution(ShapeId id, float e) {
    int s = state().shapeIndex(id);
    requireUnitInterval(e, "restitution");
    state().shapes[s].restitution = e;
}
Filter World::filter(ShapeId id) const { return state().shapes[state().shapeIndex(id)].filter; }
void World::setFilter(ShapeId id, const Filter& f) {
    auto& w = state();
    w.checkUnlocked();
    int s = w.shapeIndex(id);
    w.shapes[s].filter = f;
    // Re-evaluate pairs: drop this shape's contacts, let the broadphase find them again.
    detail::refilterShape(w, s);
}
bool World::isSensor(ShapeId id) const { return state().shapes[state().shapeIndex(id)].isSensor; }
std::uintptr_t World::userData(ShapeId id) const { return state().shapes[state().shapeIndex(id)].userData; }
void World::setUserData(ShapeId id, std::uintptr_t data) { state().shapes[state().shapeIndex(id)].userData = data; }

float World::rollingResistance(ShapeId id) const { return state().shapes[state().shapeIndex(id)].rollingResistance; }
void World::setRollingResistance(ShapeId id, float resistance) {
    int s = state().shapeIndex(id);
    requireInRange(resistance, 0.0f, detail::kMaxFriction, "rolling resistance");
    state().shapes[s].rollingResistance = resistance;
}
float World::tangentSpeed(ShapeId id) const { return state().shapes[state().shapeIndex(id)].tangentSpeed; }
void World::setTangentSpeed(ShapeId id, float speed) {
    auto& w = state();
    int s = w.shapeIndex(id);
    requireBounded(speed, "tangent speed");
    w.shapes[s].tangentSpeed = speed;
    // Existing contacts hold the sum of their shapes' speeds (and keep
    // their rolling impulse).
    for (int c : w.bodies[w.shapes[s].body].contacts) {
        const detail::Contact& ct = w.contacts[c];
        if (ct.shapeA != s && ct.shapeB != s) continue;
        const detail::ContactSurface* old = detail::contactSurface(w, c);
        const float rollingImpulse = old ? old->rollingImpulse : 0.0f;
        detail::setContactSurface(w, c, ct.shapeA, ct.shapeB);
        if (!w.contactSurfaces.empty()) w.contactSurfaces[static_cast<std::size_t>(c)].rollingImpulse = rollingImpulse;
    }
}
AABB World::shapeAABB(ShapeId id) const {
    const detail::Shape& s = state().shapes[state().shapeIndex(id)];
    return detail::shapeAABB(s, state().bodies[s.body].xf);
}

}  // namespace i2d
