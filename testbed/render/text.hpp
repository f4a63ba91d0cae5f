// Testbed renderer — one line of text on screen with a small built-in bitmap
// font (5×8 pixel glyphs in a 6×9 cell, printable ASCII), drawn as GL quads.
#pragma once

#include <string_view>

#include <impulse2d/debug_draw.hpp>

#include "render/gl_api.hpp"

namespace tb {

inline constexpr int kGlyphCellWidth = 6;
inline constexpr int kGlyphCellHeight = 9;

/// Bits of a glyph column: bit r set means row r (from the top) is lit.
/// Characters outside 32..126 map to '?'.
const unsigned char* glyphColumns(char c);

/// Width and height in pixels of `text` drawn at integer `scale`.
int textWidth(std::string_view text, int scale);
inline int textHeight(int scale) { return kGlyphCellHeight * scale; }

/// Draws `text` with its top-left corner at pixel (x, y) of a viewport of
/// viewportWidth × viewportHeight pixels, over a translucent dark band when
/// `background` is set. Replaces the projection with a pixel projection.
void drawText(const GlApi& gl, int viewportWidth, int viewportHeight, int x, int y, std::string_view text, int scale,
              i2d::Color color, bool background = true);

}  // namespace tb
