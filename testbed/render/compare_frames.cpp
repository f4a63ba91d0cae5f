// Testbed — two engines, one scene, frame by frame (see compare_frames.hpp).
#include "render/compare_frames.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "engine_label.hpp"
#include "render/frame_writer.hpp"
#include "render/offscreen.hpp"
#include "render/sample_draw.hpp"
#include "render/scale_bar.hpp"
#include "render/text.hpp"
#include "scene_build.hpp"

namespace tb {

namespace {

// The second engine's outlines when overlaid: a colour no body has.
constexpr i2d::Color kOverlayColour{0.35f, 0.85f, 1.0f, 1.0f};
constexpr i2d::Color kTextColour{0.92f, 0.92f, 0.92f, 1.0f};

std::string timeLine(const SceneDesc& desc, int step) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s  t = %.2f s  step %d", desc.name.empty() ? "scene" : desc.name.c_str(),
                  static_cast<double>(step) * static_cast<double>(desc.dt), step);
    return buf;
}

/// Font pixel size in target pixels, as OffscreenRenderer's caption.
int textScale(const GlDraw& d) {
    const float outputHeight = static_cast<float>(d.view().pixelHeight) / d.pixelScale();
    return (outputHeight >= 480.0f ? 2 : 1) * static_cast<int>(d.pixelScale());
}

/// Caption lines from the top left, then the scale bar.
void drawPanelText(GlDraw& d, const std::vector<std::string>& lines, bool caption) {
    const int scale = textScale(d);
    if (caption) {
        int y = 5 * scale;
        for (const std::string& line : lines) {
            drawText(d.gl(), d.view().pixelWidth, d.view().pixelHeight, 6 * scale, y, line, scale, kTextColour);
            y += textHeight(scale) + 3 * scale;
        }
        d.applyWorldProjection();
    }
    drawScaleBar(d, scale);
}

/// `a` and `b` side by side with a 2-pixel divider over their shared edge.
Image sideBySide(const Image& a, const Image& b) {
    Image out(a.width + b.width, std::max(a.height, b.height), 0x000000FFu);
    for (int y = 0; y < out.height; ++y) {
        if (y < a.height) std::copy_n(a.pixel(0, y), 4 * a.width, out.pixel(0, y));
        if (y < b.height) std::copy_n(b.pixel(0, y), 4 * b.width, out.pixel(a.width, y));
        for (int x = a.width - 1; x <= a.width && x < out.width; ++x) {
            std::uint8_t* p = out.pixel(x, y);
            p[0] = p[1] = p[2] = 0x70;
        }
    }
    return out;
}

}  // namespace

RenderResult renderCompareFrames(const SceneDesc& desc, const RenderOptions& options, const CompareOptions& compare) {
    if (options.frames < 1) throw std::runtime_error("--frames must be at least 1");
    if (options.every < 1) throw std::runtime_error("--every must be at least 1");
    if (options.width < 16 || options.height < 16 || options.width > 8192 || options.height > 8192)
        throw std::runtime_error("--size must be between 16x16 and 8192x8192");

    std::unique_ptr<Simulation> first = makeSimulation(desc, EngineKind::impulse2d);
    std::unique_ptr<Simulation> second = makeSimulation(desc, compare.second, compare.box2d);
    const std::string firstLabel = engineSettingsLabel(EngineKind::impulse2d, desc.settings, compare.box2d);
    const std::string secondLabel = engineSettingsLabel(compare.second, desc.settings, compare.box2d);

    // One camera for both panels: the one `testbed render` picks for the scene.
    View2D view;
    {
        const Scene scene = buildScene(desc);
        view = sceneView(scene, options.width, options.height);
    }
    const int frameWidth = compareFrameWidth(options.width, compare.overlay);
    const int panels = frameWidth / options.width;
    FrameWriter writer(options, 320 * panels, 640 * panels);
    OffscreenRenderer renderer(options.width, options.height, options.supersample);

    const auto panel = [&](const Simulation& sim, const std::vector<std::string>& lines) {
        return renderer.render(view, [&](GlDraw& d) {
            d.drawJoints = true;
            drawSimulation(d, desc, sim);
            drawPanelText(d, lines, options.caption);
        });
    };

    ProgressBar progress(options.frames);
    for (int step = 0; step < options.frames; ++step) {
        if (step % options.every == 0) {
            const std::string when = timeLine(desc, step);
            if (compare.overlay) {
                writer.add(renderer.render(view, [&](GlDraw& d) {
                    d.drawJoints = true;
                    drawSimulation(d, desc, *first);
                    const float fill = d.style().fillAlpha;
                    d.setFillAlpha(0.0f);
                    drawSimulation(d, desc, *second, kOverlayColour);
                    d.setFillAlpha(fill);
                    drawPanelText(d, {when, firstLabel + "  (filled)", secondLabel + "  (blue outlines)"},
                                  options.caption);
                }));
            } else {
                writer.add(sideBySide(panel(*first, {firstLabel, when}), panel(*second, {secondLabel, when})));
            }
        }
        first->step(desc.dt);
        second->step(desc.dt);
        if (options.progress) progress.update(step + 1);
    }
    return writer.finish(desc.dt);
}

}  // namespace tb
