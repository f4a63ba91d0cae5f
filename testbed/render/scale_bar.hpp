// Testbed renderer — a scale bar in metres at the bottom left of a frame, so
// that panels and frames can be measured by eye.
#pragma once

#include "render/gl_draw.hpp"

namespace tb {

/// A round length (1, 2 or 5 × 10^k m) close to a fifth of `viewWidth` metres.
float scaleBarLength(float viewWidth);

/// Draws the bar with its label ("2 m") in the drawer's current view;
/// `textScale` is the font's pixel size in target pixels. Leaves the world
/// projection in place.
void drawScaleBar(GlDraw& drawer, int textScale);

}  // namespace tb
