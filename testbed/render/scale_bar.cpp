// Testbed renderer — the scale bar (see scale_bar.hpp).
#include "render/scale_bar.hpp"

#include <cmath>
#include <cstdio>

#include "render/text.hpp"

namespace tb {

float scaleBarLength(float viewWidth) {
    if (!(viewWidth > 0.0f) || !std::isfinite(viewWidth)) return 1.0f;
    const double target = viewWidth / 5.0;
    const double decade = std::pow(10.0, std::floor(std::log10(target)));
    double best = decade;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (std::abs(std::log(m * decade / target)) < std::abs(std::log(best / target))) best = m * decade;
    return static_cast<float>(best);
}

void drawScaleBar(GlDraw& d, int textScale) {
    const View2D& v = d.view();
    const float length = scaleBarLength(v.width());
    const float margin = 16.0f * d.pixelScale();
    const float y = static_cast<float>(v.pixelHeight) - margin;
    const i2d::Vec2 left = v.pixelToWorld({margin, y});
    const i2d::Vec2 right{left.x + length, left.y};
    const i2d::Vec2 tick{0.0f, 5.0f * d.pixelScale() * v.metresPerPixel()};
    const i2d::Color white{0.92f, 0.92f, 0.92f, 1.0f};
    d.drawLine(left, right, 2.0f, white);
    d.drawLine(left - tick, left + tick, 2.0f, white);
    d.drawLine(right - tick, right + tick, 2.0f, white);
    char label[32];
    std::snprintf(label, sizeof label, "%g m", static_cast<double>(length));
    const int textY = static_cast<int>(y) - static_cast<int>(8.0f * d.pixelScale()) - textHeight(textScale);
    drawText(d.gl(), v.pixelWidth, v.pixelHeight, static_cast<int>(margin), textY, label, textScale, white, true);
    d.applyWorldProjection();
}

}  // namespace tb
