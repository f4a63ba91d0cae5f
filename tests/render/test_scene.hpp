// A scene built in code for the renderer tests: a wide static ground box
// whose top is at y = 0, a dynamic box and a dynamic circle above it, and a
// fixed camera, so that the tests know where the ground must appear.
#pragma once

#include "scene.hpp"

namespace tbtest {

/// Ground: centre (0, −1), half-extents 30 × 1 (top at y = 0, bottom at y = −2).
inline constexpr float kGroundTop = 0.0f;
inline constexpr float kGroundBottom = -2.0f;
/// Camera: centre (0, 5), 20 m visible vertically.
inline constexpr float kCameraY = 5.0f;
inline constexpr float kCameraHeight = 20.0f;

tb::Scene makeTestScene();

}  // namespace tbtest
