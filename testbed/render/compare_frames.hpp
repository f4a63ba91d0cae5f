// Testbed — one scene in two engines, frame by frame (`testbed render
// --compare box2d`): Impulse2D and the other engine at the same step with the
// same camera and scale, side by side (each frame 2W × H) or overlaid (W × H,
// the second engine drawn as outlines). Each panel is captioned with its
// engine and settings and carries a scale bar in metres; the frames, contact
// sheet and animation are written as by renderSceneFrames.
#pragma once

#include "render/scene_frames.hpp"
#include "scene.hpp"
#include "simulation.hpp"

namespace tb {

struct CompareOptions {
    EngineKind second = EngineKind::box2d;  ///< drawn right of (or over) Impulse2D
    Box2DSettings box2d;                    ///< Box2D's iteration counts
    bool overlay = false;                   ///< one panel, the second engine as outlines
};

/// Steps `desc` in Impulse2D and in compare.second and writes the frames.
/// Throws SceneError when an engine refuses the scene, std::runtime_error
/// when a file cannot be written.
RenderResult renderCompareFrames(const SceneDesc& desc, const RenderOptions& options, const CompareOptions& compare);

/// Width of a comparison frame for panels `panelWidth` pixels wide.
inline int compareFrameWidth(int panelWidth, bool overlay) { return overlay ? panelWidth : 2 * panelWidth; }

}  // namespace tb
