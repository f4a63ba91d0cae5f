// `testbed render --compare box2d`: both engines at the same step, side by
// side (frames twice as wide) or overlaid, both panels showing the scene;
// the scale bar's length; the command's refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "commands/render_command.hpp"
#include "render/compare_frames.hpp"
#include "render/gl_draw.hpp"
#include "render/png_io.hpp"
#include "render/scale_bar.hpp"
#include "scene_loader.hpp"

namespace fs = std::filesystem;

namespace {

fs::path compareDir(const std::string& name) {
    fs::path dir = fs::path(TB_TEST_WORK_DIR) / name;
    fs::remove_all(dir);
    return dir;
}

/// Pixels of columns [x0, x1) in rows [y0, y1) that differ from the background.
int shapePixels(const tb::Image& img, int x0, int x1, int y0, int y1) {
    const i2d::Color bg = tb::DrawStyle{}.background;
    const int ref[3] = {static_cast<int>(bg.r * 255.0f + 0.5f), static_cast<int>(bg.g * 255.0f + 0.5f),
                        static_cast<int>(bg.b * 255.0f + 0.5f)};
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = img.pixel(x, y);
            int d = 0;
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(p[c] - ref[c]));
            n += d > 12 ? 1 : 0;
        }
    return n;
}

tb::RenderOptions smallOptions(const fs::path& dir) {
    tb::RenderOptions o;
    o.frames = 30;
    o.every = 10;
    o.width = 240;
    o.height = 160;
    o.supersample = 1;
    o.outDir = dir.string();
    o.writeGif = false;
    o.progress = false;
    return o;
}

}  // namespace

TEST(CompareRender, SideBySideFramesAreTwiceAsWideWithBothPanelsDrawn) {
    if (!tb::box2dAvailable()) GTEST_SKIP() << "built without the Box2D 2.4.1 backend";
    const tb::SceneDesc desc = tb::loadSceneDesc("stack5", TB_TEST_ASSETS_DIR);
    const fs::path dir = compareDir("compare_side");
    const tb::RenderResult result = tb::renderCompareFrames(desc, smallOptions(dir), {});
    ASSERT_EQ(result.framePaths.size(), 3u);
    EXPECT_TRUE(fs::exists(result.sheetPath));
    for (const std::string& path : result.framePaths) {
        tb::Image img;
        ASSERT_TRUE(tb::readPng(path, img));
        ASSERT_EQ(img.width, 480);
        ASSERT_EQ(img.height, 160);
        // Below the captions (2 lines) and above the scale bar, each panel shows
        // the stack and the ground; the two panels start identical.
        const int left = shapePixels(img, 0, 238, 40, 130), right = shapePixels(img, 242, 480, 40, 130);
        EXPECT_GT(left, 500) << path;
        EXPECT_GT(right, 500) << path;
        EXPECT_NEAR(left, right, 0.25 * left) << path;
    }
    // The first frame is the initial state: the panels match pixel for pixel
    // below the captions (same camera, same scale, same drawing).
    tb::Image first;
    ASSERT_TRUE(tb::readPng(result.framePaths[0], first));
    int differing = 0;
    for (int y = 40; y < 160; ++y)
        for (int x = 1; x < 238; ++x)  // x + 240 = 240 is the divider
            for (int c = 0; c < 3; ++c) differing += first.pixel(x, y)[c] != first.pixel(x + 240, y)[c] ? 1 : 0;
    EXPECT_EQ(differing, 0);
}

TEST(CompareRender, OverlayKeepsThePanelSizeAndDrawsTheSecondEngineInOutline) {
    if (!tb::box2dAvailable()) GTEST_SKIP() << "built without the Box2D 2.4.1 backend";
    const tb::SceneDesc desc = tb::loadSceneDesc("stack5", TB_TEST_ASSETS_DIR);
    const fs::path dir = compareDir("compare_overlay");
    tb::CompareOptions compare;
    compare.overlay = true;
    const tb::RenderResult result = tb::renderCompareFrames(desc, smallOptions(dir), compare);
    ASSERT_EQ(result.framePaths.size(), 3u);
    tb::Image img;
    ASSERT_TRUE(tb::readPng(result.framePaths.back(), img));
    EXPECT_EQ(img.width, 240);
    EXPECT_EQ(img.height, 160);
    // The outline colour (light blue: blue channel well above red) is present.
    int blue = 0;
    for (int y = 40; y < 140; ++y)
        for (int x = 0; x < 240; ++x) blue += img.pixel(x, y)[2] > 200 && img.pixel(x, y)[0] < 150 ? 1 : 0;
    EXPECT_GT(blue, 20);
}

TEST(ScaleBar, RoundLengthNearAFifthOfTheView) {
    EXPECT_FLOAT_EQ(tb::scaleBarLength(50.0f), 10.0f);
    EXPECT_FLOAT_EQ(tb::scaleBarLength(23.0f), 5.0f);
    EXPECT_FLOAT_EQ(tb::scaleBarLength(8.0f), 2.0f);
    EXPECT_FLOAT_EQ(tb::scaleBarLength(0.6f), 0.1f);
    EXPECT_FLOAT_EQ(tb::scaleBarLength(0.0f), 1.0f);
}

TEST(CompareRender, BadOptionsAreUsageErrors) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"stack5", "--compare", "bullet"}, "--compare: expected impulse2d or box2d, got 'bullet'"},
        {{"stack5", "--compare", "impulse2d"}, "--compare: the left panel is impulse2d already"},
        {{"stack5", "--overlay"}, "--overlay needs --compare"},
        {{"stack5", "--compare", "box2d", "--contacts"}, "not with --compare"},
        {{"stack5", "--trace", "t.csv"}, "--trace is an option of `testbed run`"},
    };
    for (const auto& [args, message] : cases) {
        std::ostringstream out, err;
        EXPECT_EQ(tb::runRenderCommand(args, out, err), 2) << message;
        EXPECT_EQ(err.str().rfind("testbed render: ", 0), 0u) << err.str();
        EXPECT_NE(err.str().find(message), std::string::npos) << err.str();
    }
}
