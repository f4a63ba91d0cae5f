// Testbed — the limits of the scene-file format (documented in
// docs/scene-format.md and assets/scenes/scene.schema.json).
#pragma once

#include <cstdint>

namespace tb::scene_file {

// Limits (documented in docs/scene-format.md). They keep every value well
// inside single precision so that the engine never sees inf or NaN from a
// scene file, and keep a typo in a count from exhausting memory.
constexpr double kMaxCoordinate = 1.0e7;  // m; float spacing there is ~1 m
constexpr double kMaxSize = 1.0e5;        // m; radius, half-extent, length
constexpr double kMaxSpeed = 1.0e5;       // m/s and rad/s
constexpr double kMaxAngle = 1.0e4;       // rad
constexpr double kMaxDensity = 1.0e6;     // kg/m²
constexpr double kMaxFriction = 1.0e3;
constexpr double kMaxRate = 1.0e6;    // Hz, damping ratios, 1/s
constexpr double kMaxForce = 1.0e10;  // N and N·m: joint motors and force caps
constexpr std::int64_t kMaxBodies = 250000;
constexpr std::int64_t kMaxIterations = 1000;

}  // namespace tb::scene_file
