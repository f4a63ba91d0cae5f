// Testbed — scene files → tb::SceneDesc. The format is documented in
// docs/scene-format.md and described by assets/scenes/scene.schema.json;
// the limits below are the ones those documents state.
#include "scene_loader.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace tb {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// Limits (documented in docs/scene-format.md). They keep every value well
// inside single precision so that the engine never sees inf or NaN from a
// scene file, and keep a typo in a count from exhausting memory.
constexpr double kMaxCoordinate = 1.0e7;  // m; float spacing there is ~1 m
constexpr double kMaxSize = 1.0e5;        // m; radius, half-extent, length
constexpr double kMaxSpeed = 1.0e5;       // m/s and rad/s
constexpr double kMaxAngle = 1.0e4;       // rad
constexpr double kMaxDensity = 1.0e6;     // kg/m²
constexpr double kMaxFriction = 1.0e3;
constexpr double kMaxRate = 1.0e6;        // Hz, damping ratios, 1/s
constexpr std::int64_t kMaxBodies = 250000;
constexpr std::int64_t kMaxIterations = 1000;

// ---- Locations and errors -----------------------------------------------

struct Loc {
    const std::string* file = nullptr;
    std::string path;

    Loc key(const std::string& k) const { return {file, path.empty() ? k : path + "." + k}; }
    Loc at(std::size_t i) const { return {file, path + "[" + std::to_string(i) + "]"}; }
};

[[noreturn]] void fail(const Loc& loc, const std::string& what) {
    throw SceneError(*loc.file + ": " + (loc.path.empty() ? std::string() : loc.path + ": ") + what);
}

std::string fmt(double v) {
    std::ostringstream os;
    os.precision(9);
    os << v;
    return os.str();
}

std::string typeName(const json& j) {
    if (j.is_number_integer()) return "an integer";
    if (j.is_number()) return "a number";
    if (j.is_string()) return "a string";
    if (j.is_boolean()) return "a boolean";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    return "null";
}

struct Range {
    double lo;
    double hi;
    bool loOpen = false;  // lo itself excluded
    bool hiOpen = false;
};

std::string describe(const Range& r) {
    if (r.lo == -r.hi && !r.loOpen && !r.hiOpen) return "must have magnitude at most " + fmt(r.hi);
    return std::string("must be in ") + (r.loOpen ? "(" : "[") + fmt(r.lo) + ", " + fmt(r.hi) + (r.hiOpen ? ")" : "]");
}

double checkNumber(const json& j, const Loc& loc, const Range& r) {
    if (!j.is_number()) fail(loc, "expected a number, got " + typeName(j));
    double v = j.get<double>();
    if (!std::isfinite(v)) fail(loc, "not a finite number");
    if (std::fabs(v) > static_cast<double>(FLT_MAX)) fail(loc, "value " + fmt(v) + " is too large for a 32-bit float");
    bool below = r.loOpen ? v <= r.lo : v < r.lo;
    bool above = r.hiOpen ? v >= r.hi : v > r.hi;
    if (below || above) fail(loc, "value " + fmt(v) + " out of range: " + describe(r));
    return v;
}

std::int64_t checkInt(const json& j, const Loc& loc, std::int64_t lo, std::int64_t hi) {
    if (!j.is_number_integer()) fail(loc, "expected an integer, got " + typeName(j));
    if (j.is_number_unsigned() && j.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
        fail(loc, "integer out of range: must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    std::int64_t v = j.get<std::int64_t>();
    if (v < lo || v > hi)
        fail(loc, "value " + std::to_string(v) + " out of range: must be in [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "]");
    return v;
}

// An object whose keys are checked against the allowed set on construction.
class Obj {
public:
    Obj(const json& j, Loc loc, std::initializer_list<const char*> allowed) : j_(j), loc_(std::move(loc)) {
        if (!j.is_object()) fail(loc_, "expected an object, got " + typeName(j));
        allow(allowed);
    }
    // Adds allowed keys (used when the allowed set depends on a "type" field).
    void allow(std::initializer_list<const char*> more) {
        for (const char* k : more) allowed_.insert(k);
    }
    // Called once the allowed set is final.
    void checkUnknown() const {
        for (auto it = j_.begin(); it != j_.end(); ++it)
            if (!allowed_.count(it.key()))
                fail(loc_.key(it.key()), "unknown field (allowed here: " + allowedList() + ")");
    }
    std::string allowedList() const {
        std::string list;
        for (const auto& a : allowed_) list += (list.empty() ? "" : ", ") + a;
        return list;
    }

    const Loc& loc() const { return loc_; }
    bool has(const char* k) const { return j_.contains(k); }
    const json& get(const char* k) const {
        if (!j_.contains(k)) fail(loc_, std::string("missing required field '") + k + "'");
        return j_.at(k);
    }
    Loc at(const char* k) const { return loc_.key(k); }

    double num(const char* k, double def, const Range& r) const { return has(k) ? checkNumber(j_.at(k), at(k), r) : def; }
    double reqNum(const char* k, const Range& r) const { return checkNumber(get(k), at(k), r); }
    float f(const char* k, float def, const Range& r) const { return static_cast<float>(num(k, def, r)); }
    float reqF(const char* k, const Range& r) const { return static_cast<float>(reqNum(k, r)); }
    std::int64_t integer(const char* k, std::int64_t def, std::int64_t lo, std::int64_t hi) const {
        return has(k) ? checkInt(j_.at(k), at(k), lo, hi) : def;
    }
    std::int64_t reqInt(const char* k, std::int64_t lo, std::int64_t hi) const { return checkInt(get(k), at(k), lo, hi); }
    bool boolean(const char* k, bool def) const {
        if (!has(k)) return def;
        const json& v = j_.at(k);
        if (!v.is_boolean()) fail(at(k), "expected a boolean, got " + typeName(v));
        return v.get<bool>();
    }
    std::string str(const char* k, const std::string& def) const {
        if (!has(k)) return def;
        const json& v = j_.at(k);
        if (!v.is_string()) fail(at(k), "expected a string, got " + typeName(v));
        return v.get<std::string>();
    }
    std::string reqStr(const char* k) const {
        get(k);
        return str(k, "");
    }
    i2d::Vec2 vec(const char* k, i2d::Vec2 def, double maxAbs) const {
        if (!has(k)) return def;
        return vec2(j_.at(k), at(k), maxAbs);
    }
    i2d::Vec2 reqVec(const char* k, double maxAbs) const { return vec2(get(k), at(k), maxAbs); }

    static i2d::Vec2 vec2(const json& v, const Loc& loc, double maxAbs) {
        if (!v.is_array() || v.size() != 2) fail(loc, "expected an array of 2 numbers [x, y], got " + typeName(v) +
                                                          (v.is_array() ? " of " + std::to_string(v.size()) : ""));
        Range r{-maxAbs, maxAbs};
        return {static_cast<float>(checkNumber(v[0], loc.at(0), r)), static_cast<float>(checkNumber(v[1], loc.at(1), r))};
    }

private:
    const json& j_;
    Loc loc_;
    std::set<std::string> allowed_;
};

template <class E>
E enumField(const Obj& o, const char* k, E def, std::initializer_list<std::pair<const char*, E>> values) {
    if (!o.has(k)) return def;
    std::string s = o.str(k, "");
    std::string list;
    for (const auto& [name, value] : values) {
        if (s == name) return value;
        list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    }
    fail(o.at(k), "unknown value \"" + s + "\" (expected one of " + list + ")");
}

// ---- JSON text → json, with the path of a syntax error ---------------------

// Follows the parser's position so an error thrown while reading a value (a
// number overflow has no position of its own) can name the field, and
// refuses duplicate keys, which JSON allows but which are always a mistake here.
struct PathTracker {
    struct Frame {
        bool isArray = false;
        std::size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };
    std::vector<Frame> stack;
    std::string duplicate;

    std::string path() const {
        std::string p;
        for (const auto& f : stack) {
            if (f.isArray) {
                p += "[" + std::to_string(f.index) + "]";
            } else if (!f.key.empty()) {
                p += (p.empty() ? "" : ".") + f.key;
            }
        }
        return p;
    }
    void valueDone() {
        if (!stack.empty() && stack.back().isArray) ++stack.back().index;
    }
};

struct DuplicateKey {};

json parseJson(const std::string& text, const std::string& file) {
    PathTracker tr;
    auto cb = [&tr](int, json::parse_event_t ev, json& parsed) -> bool {
        switch (ev) {
            case json::parse_event_t::object_start: tr.stack.push_back({false, 0, {}, {}}); break;
            case json::parse_event_t::array_start: tr.stack.push_back({true, 0, {}, {}}); break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                tr.stack.pop_back();
                tr.valueDone();
                break;
            case json::parse_event_t::key: {
                std::string k = parsed.get<std::string>();
                auto& f = tr.stack.back();
                f.key = k;
                if (!f.keys.insert(k).second) {
                    tr.duplicate = k;
                    throw DuplicateKey{};
                }
                break;
            }
            case json::parse_event_t::value: tr.valueDone(); break;
        }
        return true;
    };
    Loc root{&file, {}};
    try {
        return json::parse(text, cb);
    } catch (const DuplicateKey&) {
        fail(Loc{&file, tr.path()}, "duplicate field '" + tr.duplicate + "'");
    } catch (const json::parse_error& e) {
        fail(root, std::string("malformed JSON: ") + e.what());
    } catch (const json::out_of_range& e) {
        // 406: "number overflow parsing '1e999'" — a number not representable as a double.
        fail(Loc{&file, tr.path()}, std::string("not a finite number (") + e.what() + ")");
    } catch (const json::exception& e) {
        fail(root, std::string("invalid JSON: ") + e.what());
    }
}

// ---- Scene parts ----------------------------------------------------------

i2d::WorldSettings parseWorld(const json& j, const Loc& loc) {
    Obj o(j, loc, {"comment", "gravity", "position_correction", "impact_model", "velocity_iterations",
                   "position_iterations", "substeps", "push_factor", "penetration_slop", "max_push_speed",
                   "contact_hertz", "contact_damping_ratio", "joint_hertz", "joint_damping_ratio",
                   "restitution_threshold", "impact_threshold", "speculative_distance", "aabb_margin",
                   "max_linear_speed", "enable_warm_starting", "enable_continuous", "enable_sleep", "time_to_sleep",
                   "linear_sleep_tolerance", "angular_sleep_tolerance"});
    o.checkUnknown();
    o.str("comment", "");
    i2d::WorldSettings s;
    using PC = i2d::PositionCorrection;
    using IM = i2d::ImpactModel;
    s.gravity = o.vec("gravity", s.gravity, 1.0e4);
    s.positionCorrection = enumField(o, "position_correction", s.positionCorrection,
                                     {{"soft_step", PC::soft_step}, {"baumgarte", PC::baumgarte}, {"split", PC::split}});
    s.impactModel = enumField(o, "impact_model", s.impactModel,
                              {{"closed_form", IM::closed_form}, {"velocity_bias", IM::velocity_bias}});
    s.velocityIterations = static_cast<int>(o.integer("velocity_iterations", s.velocityIterations, 1, kMaxIterations));
    s.positionIterations = static_cast<int>(o.integer("position_iterations", s.positionIterations, 0, kMaxIterations));
    s.substeps = static_cast<int>(o.integer("substeps", s.substeps, 1, kMaxIterations));
    s.pushFactor = o.f("push_factor", s.pushFactor, {0, 1});
    s.penetrationSlop = o.f("penetration_slop", s.penetrationSlop, {0, 1});
    s.maxPushSpeed = o.f("max_push_speed", s.maxPushSpeed, {0, kMaxSpeed});
    s.contactHertz = o.f("contact_hertz", s.contactHertz, {0, kMaxRate});
    s.contactDampingRatio = o.f("contact_damping_ratio", s.contactDampingRatio, {0, kMaxRate});
    s.jointHertz = o.f("joint_hertz", s.jointHertz, {0, kMaxRate});
    s.jointDampingRatio = o.f("joint_damping_ratio", s.jointDampingRatio, {0, kMaxRate});
    s.restitutionThreshold = o.f("restitution_threshold", s.restitutionThreshold, {0, kMaxSpeed});
    s.impactThreshold = o.f("impact_threshold", s.impactThreshold, {0, kMaxSpeed});
    s.speculativeDistance = o.f("speculative_distance", s.speculativeDistance, {0, 10});
    s.aabbMargin = o.f("aabb_margin", s.aabbMargin, {0, 100});
    s.maxLinearSpeed = o.f("max_linear_speed", s.maxLinearSpeed, {0, kMaxSpeed, true});
    s.enableWarmStarting = o.boolean("enable_warm_starting", s.enableWarmStarting);
    s.enableContinuous = o.boolean("enable_continuous", s.enableContinuous);
    s.enableSleep = o.boolean("enable_sleep", s.enableSleep);
    s.timeToSleep = o.f("time_to_sleep", s.timeToSleep, {0, kMaxRate});
    s.linearSleepTolerance = o.f("linear_sleep_tolerance", s.linearSleepTolerance, {0, kMaxSpeed});
    s.angularSleepTolerance = o.f("angular_sleep_tolerance", s.angularSleepTolerance, {0, kMaxSpeed});
    return s;
}

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
    Obj o(j, loc, {"comment", "type", "density", "friction", "restitution", "filter", "sensor",
                   "enable_contact_events", "enable_sensor_events"});
    std::string type = o.reqStr("type");
    ShapeDesc s;
    const Range size{0, kMaxSize, true};
    if (type == "circle") {
        o.allow({"center", "radius"});
        o.checkUnknown();
        s.type = i2d::ShapeType::circle;
        s.circle.center = o.vec("center", {}, kMaxCoordinate);
        s.circle.radius = o.reqF("radius", size);
    } else if (type == "capsule") {
        o.allow({"center1", "center2", "radius"});
        o.checkUnknown();
        s.type = i2d::ShapeType::capsule;
        s.capsule.center1 = o.reqVec("center1", kMaxCoordinate);
        s.capsule.center2 = o.reqVec("center2", kMaxCoordinate);
        s.capsule.radius = o.reqF("radius", size);
        if (i2d::distance(s.capsule.center1, s.capsule.center2) < i2d::kLinearSlop)
            fail(o.at("center2"), "capsule centres are closer than 0.005 m (use a circle)");
    } else if (type == "segment") {
        o.allow({"point1", "point2"});
        o.checkUnknown();
        s.type = i2d::ShapeType::segment;
        s.segment.point1 = o.reqVec("point1", kMaxCoordinate);
        s.segment.point2 = o.reqVec("point2", kMaxCoordinate);
        if (i2d::distance(s.segment.point1, s.segment.point2) < i2d::kLinearSlop)
            fail(o.at("point2"), "segment end points are closer than 0.005 m");
    } else if (type == "polygon") {
        o.allow({"points", "radius"});
        o.checkUnknown();
        s.type = i2d::ShapeType::polygon;
        const json& pts = o.get("points");
        Loc pl = o.at("points");
        if (!pts.is_array()) fail(pl, "expected an array of [x, y] points, got " + typeName(pts));
        if (pts.size() < 3 || pts.size() > static_cast<std::size_t>(i2d::kMaxPolygonVertices))
            fail(pl, "a polygon needs 3 to " + std::to_string(i2d::kMaxPolygonVertices) + " points, got " +
                         std::to_string(pts.size()));
        std::vector<i2d::Vec2> v;
        for (std::size_t i = 0; i < pts.size(); ++i) v.push_back(Obj::vec2(pts[i], pl.at(i), kMaxCoordinate));
        float radius = o.f("radius", 0.0f, {0, kMaxSize});
        i2d::Hull hull = i2d::computeHull(v);
        std::optional<i2d::Polygon> poly;
        if (hull.count >= 3) poly = i2d::makePolygon(hull, radius);
        if (!poly)
            fail(pl, "degenerate polygon: fewer than 3 points remain after welding points closer than 0.005 m and "
                     "dropping collinear ones");
        s.polygon = *poly;
    } else if (type == "box") {
        o.allow({"hx", "hy", "center", "angle", "radius"});
        o.checkUnknown();
        s.type = i2d::ShapeType::polygon;
        float hx = o.reqF("hx", size);
        float hy = o.reqF("hy", size);
        i2d::Vec2 c = o.vec("center", {}, kMaxCoordinate);
        float a = o.f("angle", 0.0f, {-kMaxAngle, kMaxAngle});
        float r = o.f("radius", 0.0f, {0, kMaxSize});
        s.polygon = i2d::makeOffsetBox(hx, hy, c, a);
        s.polygon.radius = r;
    } else {
        fail(o.at("type"), "unknown shape type \"" + type + "\" (expected circle, capsule, segment, polygon or box)");
    }
    s.def.density = o.f("density", s.def.density, {0, kMaxDensity});
    s.def.friction = o.f("friction", s.def.friction, {0, kMaxFriction});
    s.def.restitution = o.f("restitution", s.def.restitution, {0, 1});
    if (o.has("filter")) s.def.filter = parseFilter(o.get("filter"), o.at("filter"));
    s.def.isSensor = o.boolean("sensor", false);
    s.def.enableContactEvents = o.boolean("enable_contact_events", s.def.enableContactEvents);
    s.def.enableSensorEvents = o.boolean("enable_sensor_events", s.def.enableSensorEvents);
    o.str("comment", "");
    return s;
}

// A body object; templates (inside generators) may not set name or position.
BodyDesc parseBody(const json& j, const Loc& loc, bool isTemplate) {
    Obj o(j, loc, {"comment", "type", "angle", "linear_velocity", "angular_velocity", "linear_damping",
                   "angular_damping", "gravity_scale", "fixed_rotation", "awake", "enable_sleep", "shapes"});
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
    b.def.type = enumField(o, "type", i2d::BodyType::dynamic_body,
                           {{"dynamic", i2d::BodyType::dynamic_body},
                            {"static", i2d::BodyType::static_body},
                            {"kinematic", i2d::BodyType::kinematic_body}});
    b.def.angle = o.f("angle", 0.0f, {-kMaxAngle, kMaxAngle});
    b.def.linearVelocity = o.vec("linear_velocity", {}, kMaxSpeed);
    b.def.angularVelocity = o.f("angular_velocity", 0.0f, {-kMaxSpeed, kMaxSpeed});
    b.def.linearDamping = o.f("linear_damping", 0.0f, {0, kMaxRate});
    b.def.angularDamping = o.f("angular_damping", 0.0f, {0, kMaxRate});
    b.def.gravityScale = o.f("gravity_scale", 1.0f, {-kMaxSize, kMaxSize});
    b.def.fixedRotation = o.boolean("fixed_rotation", false);
    b.def.isAwake = o.boolean("awake", true);
    b.def.enableSleep = o.boolean("enable_sleep", true);
    if (o.has("shapes")) {
        const json& sh = o.get("shapes");
        Loc sl = o.at("shapes");
        if (!sh.is_array()) fail(sl, "expected an array of shapes, got " + typeName(sh));
        for (std::size_t i = 0; i < sh.size(); ++i) b.shapes.push_back(parseShape(sh[i], sl.at(i)));
    }
    return b;
}

// A joint waiting for its body references to be resolved (bodies may be
// named after the joint that uses them, and generators add bodies).
struct PendingJoint {
    Loc loc;
    // A reference is a body name (string) or index (integer) given at refLoc,
    // or an already known index (chain links).
    const json* refA = nullptr;
    Loc refALoc;
    int indexA = -1;
    const json* refB = nullptr;
    Loc refBLoc;
    int indexB = -1;
    i2d::DistanceJointDef def{};
    bool hasLength = false;
};

void parseJointOptions(const Obj& o, PendingJoint& pj) {
    if (o.has("length")) {
        pj.hasLength = true;
        pj.def.length = o.reqF("length", {0, kMaxSize, true});
        if (pj.def.length < i2d::kLinearSlop) fail(o.at("length"), "a joint length must be at least 0.005 m");
    }
    if (o.has("spring")) {
        Obj sp(o.get("spring"), o.at("spring"), {"comment", "hertz", "damping_ratio"});
        sp.checkUnknown();
        pj.def.enableSpring = true;
        pj.def.hertz = sp.f("hertz", 0.0f, {0, kMaxRate});
        pj.def.dampingRatio = sp.f("damping_ratio", 0.0f, {0, kMaxRate});
    }
    if (o.has("limit")) {
        Obj li(o.get("limit"), o.at("limit"), {"comment", "min", "max"});
        li.checkUnknown();
        pj.def.enableLimit = true;
        pj.def.minLength = li.f("min", 0.0f, {0, kMaxSize});
        pj.def.maxLength = li.f("max", static_cast<float>(kMaxSize), {0, kMaxSize});
        if (pj.def.maxLength < pj.def.minLength) fail(li.at("max"), "limit max must be ≥ min");
    }
    pj.def.collideConnected = o.boolean("collide_connected", false);
}

PendingJoint parseJoint(const json& j, const Loc& loc) {
    Obj o(j, loc, {"comment", "type", "body_a", "body_b", "anchor_a", "anchor_b", "length", "spring", "limit",
                   "collide_connected"});
    o.checkUnknown();
    o.str("comment", "");
    std::string type = o.str("type", "distance");
    if (type != "distance") fail(o.at("type"), "unknown joint type \"" + type + "\" (expected \"distance\")");
    PendingJoint pj;
    pj.loc = loc;
    pj.refA = &o.get("body_a");
    pj.refALoc = o.at("body_a");
    pj.refB = &o.get("body_b");
    pj.refBLoc = o.at("body_b");
    pj.def.localAnchorA = o.vec("anchor_a", {}, kMaxCoordinate);
    pj.def.localAnchorB = o.vec("anchor_b", {}, kMaxCoordinate);
    parseJointOptions(o, pj);
    return pj;
}

struct Builder {
    const std::string* file;
    std::vector<BodyDesc> bodies;
    std::map<std::string, int> names;
    std::vector<PendingJoint> joints;

    void addBody(BodyDesc b, const Loc& loc) {
        if (static_cast<std::int64_t>(bodies.size()) >= kMaxBodies)
            fail(loc, "too many bodies (limit " + std::to_string(kMaxBodies) + ")");
        if (!b.name.empty()) {
            if (!names.emplace(b.name, static_cast<int>(bodies.size())).second)
                fail(loc, "duplicate body name '" + b.name + "'");
        }
        bodies.push_back(std::move(b));
    }

    int resolve(const json& ref, const Loc& loc) const {
        if (ref.is_string()) {
            auto it = names.find(ref.get<std::string>());
            if (it == names.end()) fail(loc, "unknown body name '" + ref.get<std::string>() + "'");
            return it->second;
        }
        if (ref.is_number_integer()) {
            std::int64_t n = static_cast<std::int64_t>(bodies.size());
            if (n == 0) fail(loc, "body index given but the scene has no bodies");
            return static_cast<int>(checkInt(ref, loc, 0, n - 1));
        }
        fail(loc, "expected a body name (string) or index (integer), got " + typeName(ref));
    }
};

// Generators: see docs/scene-format.md, "Generators".
void expandGenerator(const json& j, const Loc& loc, Builder& bld) {
    Obj o(j, loc, {"comment", "generator", "body", "name_prefix", "name_first", "name_last", "name_at"});
    std::string kind = o.reqStr("generator");
    if (kind == "row") {
        o.allow({"count", "origin", "step", "copies", "copy_step"});
    } else if (kind == "grid") {
        o.allow({"columns", "rows", "origin", "spacing", "copies", "copy_step", "link"});
    } else if (kind == "pyramid") {
        o.allow({"base", "origin", "spacing", "copies", "copy_step"});
    } else if (kind == "chain") {
        o.allow({"count", "origin", "step", "anchor_prev", "anchor_next", "length", "spring", "limit",
                 "collide_connected", "attach_start", "attach_end"});
    } else {
        fail(o.at("generator"), "unknown generator \"" + kind + "\" (expected row, grid, pyramid or chain)");
    }
    o.checkUnknown();
    o.str("comment", "");
    BodyDesc tmpl = parseBody(o.get("body"), o.at("body"), true);

    // Positions relative to the generator's origin, in creation order.
    std::vector<i2d::Vec2> local;
    const std::int64_t maxCount = kMaxBodies;
    i2d::Vec2 origin = o.vec("origin", {}, kMaxCoordinate);
    if (kind == "row" || kind == "chain") {
        std::int64_t n = o.reqInt("count", 1, maxCount);
        i2d::Vec2 step = o.reqVec("step", kMaxSize);
        for (std::int64_t i = 0; i < n; ++i) local.push_back(static_cast<float>(i) * step);
    } else if (kind == "grid") {
        std::int64_t cols = o.reqInt("columns", 1, maxCount);
        std::int64_t rows = o.reqInt("rows", 1, maxCount);
        if (cols * rows > maxCount) fail(loc, "too many bodies (limit " + std::to_string(kMaxBodies) + ")");
        i2d::Vec2 sp = o.reqVec("spacing", kMaxSize);
        for (std::int64_t r = 0; r < rows; ++r)
            for (std::int64_t c = 0; c < cols; ++c)
                local.push_back({static_cast<float>(c) * sp.x, static_cast<float>(r) * sp.y});
    } else {  // pyramid
        std::int64_t base = o.reqInt("base", 1, 700);  // 700 → 245,350 bodies, just under the body limit
        i2d::Vec2 sp = o.reqVec("spacing", kMaxSize);
        for (std::int64_t r = 0; r < base; ++r) {
            std::int64_t n = base - r;
            for (std::int64_t c = 0; c < n; ++c)
                local.push_back({(static_cast<float>(c) - 0.5f * static_cast<float>(n - 1)) * sp.x,
                                 static_cast<float>(r) * sp.y});
        }
    }
    std::int64_t cx = 1, cy = 1;
    i2d::Vec2 copyStep{};
    if (o.has("copies")) {
        const json& c = o.get("copies");
        Loc cl = o.at("copies");
        if (!c.is_array() || c.size() != 2) fail(cl, "expected an array of 2 integers [columns, rows]");
        cx = checkInt(c[0], cl.at(0), 1, maxCount);
        cy = checkInt(c[1], cl.at(1), 1, maxCount);
        copyStep = o.reqVec("copy_step", kMaxCoordinate);
    } else if (o.has("copy_step")) {
        fail(o.at("copy_step"), "copy_step needs copies");
    }
    std::int64_t total = cx * cy * static_cast<std::int64_t>(local.size());
    if (total + static_cast<std::int64_t>(bld.bodies.size()) > kMaxBodies)
        fail(loc, "generator makes " + std::to_string(total) + " bodies; the limit is " + std::to_string(kMaxBodies) +
                      " per scene");

    std::string prefix = o.str("name_prefix", "");
    std::string first = o.str("name_first", "");
    std::string last = o.str("name_last", "");
    std::map<std::int64_t, std::string> nameAt;
    if (o.has("name_at")) {
        Obj na(o.get("name_at"), o.at("name_at"), {});
        for (auto it = o.get("name_at").begin(); it != o.get("name_at").end(); ++it) {
            Loc kl = na.loc().key(it.key());
            char* end = nullptr;
            long long idx = std::strtoll(it.key().c_str(), &end, 10);
            if (it.key().empty() || *end != '\0' || idx < 0 || idx >= total)
                fail(kl, "key must be a body index of this generator, from 0 to " + std::to_string(total - 1));
            if (!it.value().is_string() || it.value().get<std::string>().empty())
                fail(kl, "expected a non-empty name (string), got " + typeName(it.value()));
            nameAt[idx] = it.value().get<std::string>();
        }
    }
    int firstIndex = static_cast<int>(bld.bodies.size());
    std::int64_t k = 0;
    for (std::int64_t qy = 0; qy < cy; ++qy) {
        for (std::int64_t qx = 0; qx < cx; ++qx) {
            i2d::Vec2 off = origin + i2d::Vec2{static_cast<float>(qx) * copyStep.x, static_cast<float>(qy) * copyStep.y};
            for (const i2d::Vec2& p : local) {
                BodyDesc b = tmpl;
                b.def.position = off + p;
                if (!i2d::isFinite(b.def.position) || std::fabs(b.def.position.x) > kMaxCoordinate ||
                    std::fabs(b.def.position.y) > kMaxCoordinate)
                    fail(loc, "generated position out of range: coordinates must have magnitude at most 1e7");
                if (auto it = nameAt.find(k); it != nameAt.end()) {
                    b.name = it->second;
                } else if (k == 0 && !first.empty()) {
                    b.name = first;
                } else if (k == total - 1 && !last.empty()) {
                    b.name = last;
                } else if (!prefix.empty()) {
                    b.name = prefix + std::to_string(k);
                }
                bld.addBody(std::move(b), loc);
                ++k;
            }
        }
    }

    if (kind == "grid" && o.has("link")) {
        // Joints between each body and its right and upper neighbours, centre to centre.
        if (o.has("copies")) fail(o.at("link"), "link cannot be combined with copies");
        Obj lo(o.get("link"), o.at("link"), {"comment", "length", "spring", "limit", "collide_connected"});
        lo.checkUnknown();
        PendingJoint base;
        parseJointOptions(lo, base);
        base.loc = o.at("link");
        int cols = static_cast<int>(o.reqInt("columns", 1, maxCount));
        int rows = static_cast<int>(o.reqInt("rows", 1, maxCount));
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < cols; ++c) {
                int i = firstIndex + r * cols + c;
                if (c + 1 < cols) {
                    PendingJoint pj = base;
                    pj.indexA = i;
                    pj.indexB = i + 1;
                    bld.joints.push_back(pj);
                }
                if (r + 1 < rows) {
                    PendingJoint pj = base;
                    pj.indexA = i;
                    pj.indexB = i + cols;
                    bld.joints.push_back(pj);
                }
            }
        }
    }
    if (kind != "chain") return;
    PendingJoint base;
    base.loc = loc;
    i2d::Vec2 prevAnchor = o.vec("anchor_prev", {}, kMaxSize);
    i2d::Vec2 nextAnchor = o.vec("anchor_next", {}, kMaxSize);
    parseJointOptions(o, base);
    int n = static_cast<int>(local.size());
    auto attach = [&](const char* key, bool atStart) {
        if (!o.has(key)) return;
        Obj a(o.get(key), o.at(key), {"comment", "body", "anchor"});
        a.checkUnknown();
        PendingJoint pj = base;
        pj.loc = o.at(key);
        pj.hasLength = false;  // an attachment takes its length from the initial layout
        i2d::Vec2 anchor = a.vec("anchor", {}, kMaxCoordinate);
        int link = atStart ? firstIndex : firstIndex + n - 1;
        if (atStart) {
            pj.refA = &a.get("body");
            pj.refALoc = a.at("body");
            pj.def.localAnchorA = anchor;
            pj.indexB = link;
            pj.def.localAnchorB = prevAnchor;
        } else {
            pj.indexA = link;
            pj.def.localAnchorA = nextAnchor;
            pj.refB = &a.get("body");
            pj.refBLoc = a.at("body");
            pj.def.localAnchorB = anchor;
        }
        bld.joints.push_back(pj);
    };
    attach("attach_start", true);
    for (int i = 0; i + 1 < n; ++i) {
        PendingJoint pj = base;
        pj.indexA = firstIndex + i;
        pj.indexB = firstIndex + i + 1;
        pj.def.localAnchorA = nextAnchor;
        pj.def.localAnchorB = prevAnchor;
        bld.joints.push_back(pj);
    }
    attach("attach_end", false);
}

i2d::Vec2 worldPoint(const BodyDesc& b, i2d::Vec2 local) {
    return i2d::transformPoint({b.def.position, i2d::makeRot(b.def.angle)}, local);
}

}  // namespace

SceneDesc parseSceneDesc(const std::string& text, const std::string& file, const std::string& name) {
    json root = parseJson(text, file);
    Loc loc{&file, {}};
    Obj o(root, loc, {"$schema", "comment", "name", "description", "dt", "world", "camera", "bodies", "joints"});
    o.checkUnknown();
    o.str("$schema", "");
    o.str("comment", "");
    SceneDesc desc;
    desc.file = file;
    desc.name = o.str("name", name);
    desc.description = o.str("description", "");
    desc.dt = o.f("dt", desc.dt, {0, 1, true});
    if (o.has("world")) desc.settings = parseWorld(o.get("world"), o.at("world"));
    if (o.has("camera")) {
        Obj c(o.get("camera"), o.at("camera"), {"comment", "center", "height"});
        c.checkUnknown();
        Camera cam;
        cam.center = c.vec("center", {}, kMaxCoordinate);
        cam.height = c.f("height", cam.height, {0, kMaxCoordinate, true});
        desc.camera = cam;
    }

    Builder bld{&file, {}, {}, {}};
    const json& bodies = o.get("bodies");
    Loc bl = o.at("bodies");
    if (!bodies.is_array()) fail(bl, "expected an array of bodies and generators, got " + typeName(bodies));
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const json& e = bodies[i];
        if (e.is_object() && e.contains("generator")) {
            expandGenerator(e, bl.at(i), bld);
        } else {
            bld.addBody(parseBody(e, bl.at(i), false), bl.at(i));
        }
    }
    if (o.has("joints")) {
        const json& js = o.get("joints");
        Loc jl = o.at("joints");
        if (!js.is_array()) fail(jl, "expected an array of joints, got " + typeName(js));
        for (std::size_t i = 0; i < js.size(); ++i) bld.joints.push_back(parseJoint(js[i], jl.at(i)));
    }

    for (PendingJoint& pj : bld.joints) {
        int a = pj.refA ? bld.resolve(*pj.refA, pj.refALoc) : pj.indexA;
        int b = pj.refB ? bld.resolve(*pj.refB, pj.refBLoc) : pj.indexB;
        if (a == b) fail(pj.loc, "a joint needs two different bodies (both are body " + std::to_string(a) + ")");
        if (bld.bodies[a].def.type != i2d::BodyType::dynamic_body && bld.bodies[b].def.type != i2d::BodyType::dynamic_body)
            fail(pj.loc, "a joint needs at least one dynamic body");
        if (!pj.hasLength) {
            float len = i2d::distance(worldPoint(bld.bodies[a], pj.def.localAnchorA),
                                      worldPoint(bld.bodies[b], pj.def.localAnchorB));
            if (!(len >= i2d::kLinearSlop))
                fail(pj.loc, "the anchors are " + fmt(len) +
                                 " m apart at the start; give a length of at least 0.005 m or move the anchors");
            pj.def.length = len;
        }
        desc.joints.push_back({a, b, pj.def});
    }
    desc.bodies = std::move(bld.bodies);
    return desc;
}

std::string resolveScenePath(const std::string& nameOrPath, const std::string& assetsDir) {
    bool looksLikePath = nameOrPath.find('/') != std::string::npos ||
                         (nameOrPath.size() > 5 && nameOrPath.substr(nameOrPath.size() - 5) == ".json");
    std::error_code ec;
    if (looksLikePath) {
        if (!fs::is_regular_file(nameOrPath, ec)) throw SceneError(nameOrPath + ": no such file");
        return nameOrPath;
    }
    std::string dir = assetsDir.empty() ? defaultAssetsDir() : assetsDir;
    if (dir.empty())
        throw SceneError(nameOrPath + ": no assets directory found (give --assets DIR or a path to a scene file)");
    for (const fs::path& p : {fs::path(dir) / "scenes" / (nameOrPath + ".json"), fs::path(dir) / (nameOrPath + ".json")})
        if (fs::is_regular_file(p, ec)) return p.string();
    throw SceneError(nameOrPath + ": no such scene in " + (fs::path(dir) / "scenes").string() +
                     " (see `testbed list`)");
}

SceneDesc loadSceneDesc(const std::string& nameOrPath, const std::string& assetsDir) {
    std::string path = resolveScenePath(nameOrPath, assetsDir);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open file");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) throw SceneError(path + ": read error");
    return parseSceneDesc(ss.str(), path, fs::path(path).stem().string());
}

std::vector<std::pair<std::string, std::string>> listScenes(const std::string& assetsDir) {
    std::vector<std::pair<std::string, std::string>> out;
    std::string dir = assetsDir.empty() ? defaultAssetsDir() : assetsDir;
    if (dir.empty()) return out;
    std::error_code ec;
    fs::path scenes = fs::path(dir) / "scenes";
    if (!fs::is_directory(scenes, ec)) scenes = dir;
    for (const auto& entry : fs::directory_iterator(scenes, ec)) {
        const fs::path& p = entry.path();
        std::string fname = p.filename().string();
        if (p.extension() != ".json" || fname.ends_with(".schema.json")) continue;
        std::string description;
        try {
            std::ifstream in(p, std::ios::binary);
            std::ostringstream ss;
            ss << in.rdbuf();
            json j = json::parse(ss.str());
            if (j.is_object() && j.contains("description") && j["description"].is_string())
                description = j["description"].get<std::string>();
        } catch (const std::exception& e) {
            description = std::string("(invalid: ") + e.what() + ")";
        }
        out.emplace_back(p.stem().string(), description);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string defaultAssetsDir() {
    std::vector<fs::path> candidates;
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        fs::path d = exe.parent_path();
        candidates.push_back(d / "assets");
        candidates.push_back(d / ".." / "assets");
        candidates.push_back(d / ".." / "share" / "impulse2d" / "assets");
    }
#ifdef TB_SOURCE_ASSETS_DIR
    candidates.push_back(TB_SOURCE_ASSETS_DIR);
#endif
    for (const fs::path& c : candidates)
        if (fs::is_directory(c / "scenes", ec)) return fs::weakly_canonical(c, ec).string();
    return {};
}

}  // namespace tb
