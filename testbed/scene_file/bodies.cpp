// Testbed — bodies and their shapes in a scene file (see parts.hpp).
#include <optional>
#include <vector>

#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

namespace {

constexpr Range kSizeRange{0, kMaxSize, true};  // radius, half-extent

void parseCircle(Obj& o, ShapeDesc& s) {
    o.allow({"center", "radius"});
    o.checkUnknown();
    s.circle.center = o.vec("center", {}, kMaxCoordinate);
    s.circle.radius = o.reqF("radius", kSizeRange);
}

void parseCapsule(Obj& o, ShapeDesc& s) {
    o.allow({"center1", "center2", "radius"});
    o.checkUnknown();
    s.capsule.center1 = o.reqVec("center1", kMaxCoordinate);
    s.capsule.center2 = o.reqVec("center2", kMaxCoordinate);
    s.capsule.radius = o.reqF("radius", kSizeRange);
    if (i2d::distance(s.capsule.center1, s.capsule.center2) < i2d::kLinearSlop)
        fail(o.at("center2"), "capsule centres are closer than 0.005 m (use a circle)");
}

void parseSegment(Obj& o, ShapeDesc& s) {
    o.allow({"point1", "point2"});
    o.checkUnknown();
    s.segment.point1 = o.reqVec("point1", kMaxCoordinate);
    s.segment.point2 = o.reqVec("point2", kMaxCoordinate);
    if (i2d::distance(s.segment.point1, s.segment.point2) < i2d::kLinearSlop)
        fail(o.at("point2"), "segment end points are closer than 0.005 m");
}

/// The "points" array of [x, y] points.
std::vector<i2d::Vec2> readPoints(Obj& o) {
    const json& pts = o.get("points");
    Loc pl = o.at("points");
    if (!pts.is_array()) fail(pl, "expected an array of [x, y] points, got " + typeName(pts));
    std::vector<i2d::Vec2> v;
    for (std::size_t i = 0; i < pts.size(); ++i) v.push_back(Obj::vec2(pts[i], pl.at(i), kMaxCoordinate));
    return v;
}

void parsePolygon(Obj& o, ShapeDesc& s) {
    o.allow({"points", "radius"});
    o.checkUnknown();
    Loc pl = o.at("points");
    const std::vector<i2d::Vec2> v = readPoints(o);
    if (v.size() < 3 || v.size() > static_cast<std::size_t>(i2d::kMaxPolygonVertices))
        fail(pl, "a polygon needs 3 to " + std::to_string(i2d::kMaxPolygonVertices) + " points, got " +
                     std::to_string(v.size()));
    float radius = o.f("radius", 0.0f, {0, kMaxSize});
    i2d::Hull hull = i2d::computeHull(v);
    std::optional<i2d::Polygon> poly;
    if (hull.count >= 3) poly = i2d::makePolygon(hull, radius);
    if (!poly)
        fail(pl, "degenerate polygon: fewer than 3 points remain after welding points closer than 0.005 m and "
                 "dropping collinear ones");
    s.polygon = *poly;
}

// A chain: its points and whether it loops, checked by the engine's own
// rules (at least 2 points, 3 for a loop; no coincident points; no fold,
// crossing or touch) so that both engines get a chain they can build.
void parseChain(Obj& o, ShapeDesc& s) {
    o.allow({"points", "loop"});
    o.checkUnknown();
    Loc pl = o.at("points");
    s.chainPoints = readPoints(o);
    s.chainLoop = o.boolean("loop", false);
    s.chain = true;
    s.type = i2d::ShapeType::segment;
    try {
        i2d::World check;
        check.createChain(check.createBody({}), {.points = s.chainPoints, .isLoop = s.chainLoop});
    } catch (const i2d::Error& e) {
        fail(pl, e.what());
    }
}

// "box" is the format's shorthand for a rectangle, built as a polygon.
void parseBox(Obj& o, ShapeDesc& s) {
    o.allow({"hx", "hy", "center", "angle", "radius"});
    o.checkUnknown();
    float hx = o.reqF("hx", kSizeRange);
    float hy = o.reqF("hy", kSizeRange);
    i2d::Vec2 c = o.vec("center", {}, kMaxCoordinate);
    float a = o.f("angle", 0.0f, {-kMaxAngle, kMaxAngle});
    float r = o.f("radius", 0.0f, {0, kMaxSize});
    s.polygon = i2d::makeOffsetBox(hx, hy, c, a);
    s.polygon.radius = r;
}

}  // namespace

i2d::Filter parseFilter(const json& j, const Loc& loc) {
    Obj o(j, loc, {"comment", "category_bits", "mask_bits", "group_index"});
    o.checkUnknown();
    i2d::Filter f;
    f.categoryBits = static_cast<std::uint32_t>(o.integer("category_bits", f.categoryBits, 0, UINT32_MAX));
    f.maskBits = static_cast<std::uint32_t>(o.integer("mask_bits", f.maskBits, 0, UINT32_MAX));
    f.groupIndex = static_cast<std::int32_t>(o.integer("group_index", f.groupIndex, INT32_MIN, INT32_MAX));
    return f;
}

ShapeDesc parseShape(const json& j, const Loc& loc) {
    Obj o(j, loc,
          {"comment", "type", "density", "friction", "restitution", "filter", "sensor", "enable_contact_events",
           "enable_sensor_events", "enable_hit_events", "rolling_resistance", "tangent_speed"});
    const std::string type = o.reqStr("type");
    ShapeDesc s;
    if (type == "box") {
        s.type = i2d::ShapeType::polygon;
        parseBox(o, s);
    } else if (type == "chain") {
        parseChain(o, s);
    } else if (std::optional<i2d::ShapeType> t = enumFromName<i2d::ShapeType>(type)) {
        s.type = *t;
        switch (*t) {
            case i2d::ShapeType::circle: parseCircle(o, s); break;
            case i2d::ShapeType::capsule: parseCapsule(o, s); break;
            case i2d::ShapeType::segment: parseSegment(o, s); break;
            case i2d::ShapeType::polygon: parsePolygon(o, s); break;
        }
    } else {
        fail(o.at("type"), "unknown shape type \"" + type + "\" (expected " +
                               enumNameList<i2d::ShapeType>("", ", ", ", ") + ", box or chain)");
    }
    s.def.density = o.f("density", s.def.density, {0, kMaxDensity});
    s.def.friction = o.f("friction", s.def.friction, {0, kMaxFriction});
    s.def.restitution = o.f("restitution", s.def.restitution, {0, 1});
    if (o.has("filter")) s.def.filter = parseFilter(o.get("filter"), o.at("filter"));
    s.def.isSensor = o.boolean("sensor", false);
    if (s.chain && s.def.isSensor) fail(o.at("sensor"), "a chain cannot be a sensor");
    s.def.enableContactEvents = o.boolean("enable_contact_events", s.def.enableContactEvents);
    s.def.enableSensorEvents = o.boolean("enable_sensor_events", s.def.enableSensorEvents);
    s.def.enableHitEvents = o.boolean("enable_hit_events", s.def.enableHitEvents);
    s.def.rollingResistance = o.f("rolling_resistance", s.def.rollingResistance, {0, kMaxFriction});
    s.def.tangentSpeed = o.f("tangent_speed", s.def.tangentSpeed, {-kMaxSpeed, kMaxSpeed});
    o.str("comment", "");
    return s;
}

// A body object; templates (inside generators) may not set name or position.
BodyDesc parseBody(const json& j, const Loc& loc, bool isTemplate) {
    Obj o(j, loc,
          {"comment", "type", "angle", "linear_velocity", "angular_velocity", "linear_damping", "angular_damping",
           "gravity_scale", "fixed_rotation", "awake", "enable_sleep", "bullet", "drive_speed", "shapes"});
    if (!isTemplate) o.allow({"name", "position"});
    if (isTemplate) {
        for (const char* k : {"name", "position"})
            if (o.has(k)) fail(o.at(k), "set by the generator; not allowed in a generator's body template");
    }
    o.checkUnknown();
    o.str("comment", "");
    BodyDesc b;
    if (!isTemplate) {
        b.name = o.str("name", "");
        if (o.has("name") && b.name.empty()) fail(o.at("name"), "a name must not be empty");
        b.def.position = o.vec("position", {}, kMaxCoordinate);
    }
    b.def.type = enumField(o, "type", i2d::BodyType::dynamic_body);
    b.def.angle = o.f("angle", 0.0f, {-kMaxAngle, kMaxAngle});
    b.def.linearVelocity = o.vec("linear_velocity", {}, kMaxSpeed);
    b.def.angularVelocity = o.f("angular_velocity", 0.0f, {-kMaxSpeed, kMaxSpeed});
    b.def.linearDamping = o.f("linear_damping", 0.0f, {0, kMaxRate});
    b.def.angularDamping = o.f("angular_damping", 0.0f, {0, kMaxRate});
    b.def.gravityScale = o.f("gravity_scale", 1.0f, {-kMaxSize, kMaxSize});
    b.def.fixedRotation = o.boolean("fixed_rotation", false);
    b.def.isAwake = o.boolean("awake", true);
    b.def.enableSleep = o.boolean("enable_sleep", true);
    b.def.isBullet = o.boolean("bullet", false);
    if (o.has("drive_speed")) {
        b.driveSpeed = o.f("drive_speed", 0.0f, {-kMaxSpeed, kMaxSpeed});
        if (b.def.type != i2d::BodyType::dynamic_body) fail(o.at("drive_speed"), "only a dynamic body can be driven");
    }
    if (o.has("shapes")) {
        const json& sh = o.get("shapes");
        Loc sl = o.at("shapes");
        if (!sh.is_array()) fail(sl, "expected an array of shapes, got " + typeName(sh));
        for (std::size_t i = 0; i < sh.size(); ++i) b.shapes.push_back(parseShape(sh[i], sl.at(i)));
    }
    return b;
}

}  // namespace tb::scene_file
