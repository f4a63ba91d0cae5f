// Argument checks shared by the public entry points (see error.hpp).
#pragma once

#include <string>

#include "impulse2d/error.hpp"
#include "impulse2d/math.hpp"

namespace i2d::detail {

/// Largest coordinate or speed accepted (m, m/s): far beyond any sensible
/// world (single precision has ~1 mm resolution at 1e4 m), small enough that
/// squares and sums of such values stay finite.
inline constexpr float kMaxCoordinate = 1.0e7f;

[[noreturn]] inline void fail(const std::string& what) { throw Error("impulse2d: " + what); }

inline void requireFinite(float v, const char* name) {
    if (!isFinite(v)) fail(std::string(name) + " must be finite");
}
inline void requireFinite(Vec2 v, const char* name) {
    if (!isFinite(v)) fail(std::string(name) + " must be finite");
}
inline void requireBounded(float v, const char* name) {
    requireFinite(v, name);
    if (v > kMaxCoordinate || v < -kMaxCoordinate) fail(std::string(name) + " is out of range (|value| > 1e7)");
}
inline void requireBounded(Vec2 v, const char* name) {
    requireBounded(v.x, name);
    requireBounded(v.y, name);
}
inline void requireNonNegative(float v, const char* name) {
    requireFinite(v, name);
    if (v < 0.0f) fail(std::string(name) + " must be >= 0");
}
inline void requireUnitInterval(float v, const char* name) {
    requireFinite(v, name);
    if (v < 0.0f || v > 1.0f) fail(std::string(name) + " must be in [0, 1]");
}

}  // namespace i2d::detail
