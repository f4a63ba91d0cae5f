// Argument checks shared by the public entry points (see error.hpp).
#pragma once

#include <cstdio>
#include <string>

#include "impulse2d/error.hpp"
#include "impulse2d/math.hpp"

namespace i2d::detail {

/// Largest coordinate or speed accepted (m, m/s): far beyond any sensible
/// world (single precision has ~1 mm resolution at 1e4 m), small enough that
/// squares and sums of such values stay finite.
inline constexpr float kMaxCoordinate = 1.0e7f;
/// Largest radius of a circle, capsule or rounded polygon (m).
inline constexpr float kMaxRadius = 1.0e5f;
/// Shortest polygon edge and thinnest polygon accepted by the world (m): a
/// tenth of the linear slop — thin enough for 2 mm playing cards, thick enough
/// that every edge has a well-defined direction and the polygon an area.
inline constexpr float kMinPolygonFeature = 0.0005f;
/// Largest shape density (kg/m²): with kMaxCoordinate it keeps masses and
/// inertias finite in single precision.
inline constexpr float kMaxDensity = 1.0e9f;
/// Largest friction coefficient: the friction impulse bound μ·λ must not overflow.
inline constexpr float kMaxFriction = 1.0e3f;
/// Largest stiffness (Hz) and damping ratio: ω² = (2π·1e6)² stays finite and
/// the soft-constraint coefficients derived from it stay well defined.
inline constexpr float kMaxRate = 1.0e6f;

/// A number as printf's %g writes it (1e+06, 0.005), for messages.
inline std::string shortNumber(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(v));
    return buf;
}

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
inline void requireInRange(float v, float lo, float hi, const char* name) {
    requireFinite(v, name);
    if (v < lo || v > hi) fail(std::string(name) + " must be in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]");
}
inline void requireUnitInterval(float v, const char* name) {
    requireFinite(v, name);
    if (v < 0.0f || v > 1.0f) fail(std::string(name) + " must be in [0, 1]");
}

}  // namespace i2d::detail
