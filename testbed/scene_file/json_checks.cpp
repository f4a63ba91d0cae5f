// Testbed — checks on the JSON of a scene file (see json_checks.hpp).
#include "scene_file/json_checks.hpp"

#include <cfloat>
#include <cmath>
#include <sstream>

namespace tb::scene_file {

namespace {

std::string describe(const Range& r) {
    if (r.lo == -r.hi && !r.loOpen && !r.hiOpen) return "must have magnitude at most " + fmt(r.hi);
    return std::string("must be in ") + (r.loOpen ? "(" : "[") + fmt(r.lo) + ", " + fmt(r.hi) + (r.hiOpen ? ")" : "]");
}

}  // namespace

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

}  // namespace tb::scene_file
