// Testbed — typed access to the JSON of a scene file. Every check that fails
// throws SceneError naming the file and the field path
// ("scene.json: bodies[3].shapes[0].radius: value -1 out of range: ...").
#pragma once

#include <nlohmann/json.hpp>

#include <impulse2d/impulse2d.hpp>

#include <cstdint>
#include <initializer_list>
#include <set>
#include <string>

#include "enum_names.hpp"
#include "scene.hpp"

namespace tb::scene_file {

using json = nlohmann::json;

/// Where a value is: the file and the field path inside it.
struct Loc {
    const std::string* file = nullptr;
    std::string path;

    Loc key(const std::string& k) const { return {file, path.empty() ? k : path + "." + k}; }
    Loc at(std::size_t i) const { return {file, path + "[" + std::to_string(i) + "]"}; }
};

/// Throws SceneError "FILE: PATH: what".
[[noreturn]] void fail(const Loc& loc, const std::string& what);

/// A number as written in messages (up to 9 significant digits).
std::string fmt(double v);
/// "an integer", "a string", ... for messages.
std::string typeName(const json& j);

/// Allowed values of a number; open ends exclude the bound itself.
struct Range {
    double lo;
    double hi;
    bool loOpen = false;  // lo itself excluded
    bool hiOpen = false;
};

/// The number at `loc`, finite, within float range and within `r`.
double checkNumber(const json& j, const Loc& loc, const Range& r);
/// The integer at `loc`, within [lo, hi].
std::int64_t checkInt(const json& j, const Loc& loc, std::int64_t lo, std::int64_t hi);

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

    double num(const char* k, double def, const Range& r) const {
        return has(k) ? checkNumber(j_.at(k), at(k), r) : def;
    }
    double reqNum(const char* k, const Range& r) const { return checkNumber(get(k), at(k), r); }
    float f(const char* k, float def, const Range& r) const { return static_cast<float>(num(k, def, r)); }
    float reqF(const char* k, const Range& r) const { return static_cast<float>(reqNum(k, r)); }
    std::int64_t integer(const char* k, std::int64_t def, std::int64_t lo, std::int64_t hi) const {
        return has(k) ? checkInt(j_.at(k), at(k), lo, hi) : def;
    }
    std::int64_t reqInt(const char* k, std::int64_t lo, std::int64_t hi) const {
        return checkInt(get(k), at(k), lo, hi);
    }
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
        if (!v.is_array() || v.size() != 2)
            fail(loc, "expected an array of 2 numbers [x, y], got " + typeName(v) +
                          (v.is_array() ? " of " + std::to_string(v.size()) : ""));
        Range r{-maxAbs, maxAbs};
        return {static_cast<float>(checkNumber(v[0], loc.at(0), r)),
                static_cast<float>(checkNumber(v[1], loc.at(1), r))};
    }

private:
    const json& j_;
    Loc loc_;
    std::set<std::string> allowed_;
};

/// The enum field `k` (named as in enum_names.hpp), `def` when absent.
template <class E>
E enumField(const Obj& o, const char* k, E def) {
    if (!o.has(k)) return def;
    const std::string s = o.str(k, "");
    if (auto v = enumFromName<E>(s)) return *v;
    fail(o.at(k), "unknown value \"" + s + "\" (expected one of " + enumNameList<E>("\"", ", ", ", ") + ")");
}

}  // namespace tb::scene_file
