// Tests of the testbed renderer. The offscreen tests run everywhere (OSMesa
// needs no display); the viewer test needs xvfb-run and is skipped without it.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "commands/render_command.hpp"
#include "commands/view_command.hpp"
#include "render/camera.hpp"
#include "render/gif_writer.hpp"
#include "render/offscreen.hpp"
#include "render/png_io.hpp"
#include "render/scene_frames.hpp"
#include "render/text.hpp"
#include "render/viewer.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"
#include "test_scene.hpp"

namespace fs = std::filesystem;

namespace {

fs::path workDir(const std::string& name) {
    fs::path dir = fs::path(TB_TEST_WORK_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Largest channel difference between a pixel and a colour.
int colourDistance(const std::uint8_t* p, const i2d::Color& c) {
    int d = 0;
    const float ch[3] = {c.r, c.g, c.b};
    for (int i = 0; i < 3; ++i) d = std::max(d, std::abs(p[i] - static_cast<int>(std::lround(ch[i] * 255.0f))));
    return d;
}

/// Fraction of the pixels of row y (columns x0..x1) that are not the background.
double rowCoverage(const tb::Image& img, int y, int x0, int x1, const i2d::Color& background) {
    int hit = 0;
    for (int x = x0; x < x1; ++x) hit += colourDistance(img.pixel(x, y), background) > 12 ? 1 : 0;
    return static_cast<double>(hit) / static_cast<double>(x1 - x0);
}

/// Known drawing, no engine involved: a ground box (top y = 0), a rotated
/// box, a rounded box, a circle, a capsule, a segment, a point and a line.
void drawPrimitives(tb::GlDraw& d) {
    const i2d::Color ground{0.4f, 0.8f, 0.4f, 1.0f};
    const i2d::Vec2 groundBox[4] = {{-30, -1}, {30, -1}, {30, 1}, {-30, 1}};
    d.drawSolidPolygon({{0, -1}, {}}, groundBox, 4, 0.0f, ground);
    const i2d::Vec2 unit[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    d.drawSolidPolygon({{-6, 1.2f}, i2d::makeRot(0.4f)}, unit, 4, 0.0f, {0.9f, 0.7f, 0.4f, 1});
    d.drawSolidPolygon({{-1.5f, 5}, i2d::makeRot(-0.2f)}, unit, 4, 0.4f, {0.8f, 0.5f, 0.9f, 1});
    d.drawSolidCircle({3, 1}, 1.0f, {std::cos(0.8f), std::sin(0.8f)}, {0.9f, 0.6f, 0.6f, 1});
    d.drawSolidCapsule({5, 4}, {8, 6}, 0.6f, {0.5f, 0.6f, 0.95f, 1});
    d.drawSegment({-10, 10}, {10, 11}, {0.8f, 0.8f, 0.3f, 1});
    d.drawPoint({0, 8}, 6.0f, {1, 0.2f, 0.2f, 1});
    d.drawLine({0, 8}, {2, 9}, 2.0f, {1, 0.2f, 0.2f, 1});
}

tb::View2D testView(int w, int h) {
    tb::View2D v;
    v.center = {0.0f, tbtest::kCameraY};
    v.height = tbtest::kCameraHeight;
    v.pixelWidth = w;
    v.pixelHeight = h;
    return v;
}

}  // namespace

TEST(Camera, MapsWorldToPixelsAndBack) {
    tb::View2D v = testView(320, 180);
    // 20 m over 180 rows: 9 px per metre; the view centre (0, 5) is the image centre.
    i2d::Vec2 c = v.worldToPixel({0.0f, 5.0f});
    EXPECT_FLOAT_EQ(c.x, 160.0f);
    EXPECT_FLOAT_EQ(c.y, 90.0f);
    i2d::Vec2 ground = v.worldToPixel({1.0f, 0.0f});
    EXPECT_FLOAT_EQ(ground.y, 135.0f);
    EXPECT_FLOAT_EQ(ground.x, 169.0f);
    i2d::Vec2 back = v.pixelToWorld(v.worldToPixel({-3.25f, 7.5f}));
    EXPECT_NEAR(back.x, -3.25f, 1e-5f);
    EXPECT_NEAR(back.y, 7.5f, 1e-5f);
}

TEST(Camera, FitViewContainsTheBoxWithMargin) {
    i2d::AABB box{{-10.0f, 0.0f}, {30.0f, 2.0f}};  // wide and flat: width decides
    tb::View2D v = tb::fitView(box, 1280, 720, 0.1f);
    i2d::AABB b = v.bounds();
    EXPECT_LT(b.lower.x, box.lower.x);
    EXPECT_GT(b.upper.x, box.upper.x);
    EXPECT_LT(b.lower.y, box.lower.y);
    EXPECT_GT(b.upper.y, box.upper.y);
    EXPECT_NEAR(b.upper.x - b.lower.x, 40.0f * 1.2f, 1e-3f);
}

TEST(Camera, SceneViewUsesTheSceneCameraOrFitsTheShapes) {
    tb::Scene scene = tbtest::makeTestScene();
    tb::View2D v = tb::sceneView(scene, 640, 360);
    EXPECT_FLOAT_EQ(v.center.y, tbtest::kCameraY);
    EXPECT_FLOAT_EQ(v.height, tbtest::kCameraHeight);

    scene.desc.camera.reset();
    tb::View2D fitted = tb::sceneView(scene, 640, 360);
    i2d::AABB b = fitted.bounds();
    // Both dynamic bodies are inside; the 60 m ground is clipped near them.
    EXPECT_LT(b.lower.x, -4.5f);
    EXPECT_GT(b.upper.x, 4.0f);
    EXPECT_GT(b.upper.y, 7.0f);
    EXPECT_LT(b.lower.y, 0.0f);
    EXPECT_LT(b.upper.x - b.lower.x, 40.0f);
}

TEST(Png, RoundTripKeepsPixelsAndSize) {
    tb::Image img(7, 5, 0x102030FFu);
    img.pixel(3, 2)[0] = 250;
    img.pixel(6, 4)[2] = 1;
    fs::path file = workDir("png") / "roundtrip.png";
    std::string error;
    ASSERT_TRUE(tb::writePng(file.string(), img, &error)) << error;
    tb::Image back;
    ASSERT_TRUE(tb::readPng(file.string(), back, &error)) << error;
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 5);
    EXPECT_EQ(back.rgba, img.rgba);
    EXPECT_FALSE(tb::readPng((file.parent_path() / "missing.png").string(), back, &error));
    EXPECT_FALSE(error.empty());
}

TEST(Image, DownsampleAveragesBlocks) {
    tb::Image img(4, 2, 0x000000FFu);
    img.pixel(0, 0)[0] = 255;  // one of four pixels of the first block
    tb::Image half = tb::downsample(img, 2);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 1);
    EXPECT_EQ(half.pixel(0, 0)[0], 64);
    EXPECT_EQ(half.pixel(1, 0)[0], 0);
}

TEST(Image, ContactSheetPlacesThumbnailsInAGrid) {
    std::vector<tb::Image> frames;
    for (int i = 0; i < 5; ++i) frames.emplace_back(64, 36, i % 2 ? 0xFF0000FFu : 0x00FF00FFu);
    tb::Image sheet = tb::contactSheet(frames, 3, 32, 4, 0x000000FFu);
    EXPECT_EQ(sheet.width, 4 + 3 * (32 + 4));
    EXPECT_EQ(sheet.height, 4 + 2 * (18 + 4));
    EXPECT_EQ(sheet.pixel(4 + 10, 4 + 5)[1], 255);          // frame 0: green
    EXPECT_EQ(sheet.pixel(4 + 36 + 10, 4 + 5)[0], 255);     // frame 1: red
    EXPECT_EQ(sheet.pixel(4 + 36 + 10, 4 + 22 + 5)[0], 0);  // frame 4 (row 2, col 2): green
    EXPECT_EQ(sheet.pixel(4 + 36 + 10, 4 + 22 + 5)[1], 255);
    EXPECT_EQ(sheet.pixel(sheet.width - 2, sheet.height - 2)[1], 0);  // empty cell: background
}

TEST(Text, GlyphsAreDistinctAndSpacesBlank) {
    const unsigned char* space = tb::glyphColumns(' ');
    for (int i = 0; i < 5; ++i) EXPECT_EQ(space[i], 0);
    EXPECT_NE(std::vector<unsigned char>(tb::glyphColumns('0'), tb::glyphColumns('0') + 5),
              std::vector<unsigned char>(tb::glyphColumns('O'), tb::glyphColumns('O') + 5));
    EXPECT_EQ(tb::glyphColumns('\x01'), tb::glyphColumns('?'));
    EXPECT_EQ(tb::textWidth("abc", 2), 36);
}

TEST(Offscreen, PrimitivesLandWhereTheCameraPutsThem) {
    tb::OffscreenRenderer renderer(320, 180, 2);
    tb::Image img = renderer.render(testView(320, 180), drawPrimitives);
    ASSERT_EQ(img.width, 320);
    ASSERT_EQ(img.height, 180);
    const i2d::Color bg = tb::DrawStyle{}.background;
    // Ground: y ∈ [−2, 0] ↔ rows 135..153. Well inside it, every pixel is ground;
    // the top rows of the sky have no shape except the thin segment near y = 10.
    for (int y = 138; y < 151; ++y) EXPECT_GT(rowCoverage(img, y, 0, 320, bg), 0.99) << "row " << y;
    for (int y = 158; y < 180; ++y) EXPECT_LT(rowCoverage(img, y, 0, 320, bg), 0.01) << "row " << y;
    EXPECT_LT(rowCoverage(img, 5, 0, 320, bg), 0.01);
    // The ground's fill is its colour blended at 45 % over the background.
    const std::uint8_t* g = img.pixel(20, 145);
    EXPECT_NEAR(g[1], std::lround(255 * (0.45f * 0.8f + 0.55f * bg.g)), 3);
    // Circle at (3, 1), radius 1: centre pixel (187, 126) is filled, far outside is not.
    EXPECT_GT(colourDistance(img.pixel(187, 126), bg), 20);
    EXPECT_LE(colourDistance(img.pixel(187, 110), bg), 2);
    // The point of 6 px at (0, 8) ↔ pixel (160, 63) is bright red.
    EXPECT_GT(img.pixel(160, 63)[0], 200);
    EXPECT_LT(img.pixel(160, 63)[1], 100);
}

// The golden image is primitives drawn with known colours at 320×180 with a
// caption. A software rasteriser of another Mesa version may round edge
// coverage and blending differently, so the comparison allows:
//   * any per-channel difference up to 24 levels (rounding of blended and
//     supersampled edge pixels), and
//   * larger differences on at most 1 % of the pixels (pixels whose
//     coverage flips along an edge),
// with a mean absolute difference under 2 levels. A moved, missing or
// recoloured shape breaks all three by far. Set TB_UPDATE_GOLDEN=1 to rewrite it.
TEST(Offscreen, MatchesTheGoldenImage) {
    tb::OffscreenRenderer renderer(320, 180, 2);
    tb::Image img = renderer.render(testView(320, 180), drawPrimitives, "golden 0123 Ag");
    fs::path golden = fs::path(TB_GOLDEN_DIR) / "primitives_320x180.png";
    if (std::getenv("TB_UPDATE_GOLDEN")) {
        std::string error;
        ASSERT_TRUE(tb::writePng(golden.string(), img, &error)) << error;
        GTEST_SKIP() << "golden image rewritten: " << golden;
    }
    tb::Image ref;
    std::string error;
    ASSERT_TRUE(tb::readPng(golden.string(), ref, &error)) << error;
    ASSERT_EQ(ref.width, img.width);
    ASSERT_EQ(ref.height, img.height);
    long long sum = 0;
    int over = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) {
            int diff = std::abs(img.rgba[i + c] - ref.rgba[i + c]);
            d = std::max(d, diff);
            sum += diff;
        }
        over += d > 24 ? 1 : 0;
    }
    const double pixels = static_cast<double>(img.width) * img.height;
    const double mean = static_cast<double>(sum) / (3.0 * pixels);
    EXPECT_LE(over, static_cast<int>(0.01 * pixels)) << "pixels differing by more than 24 levels";
    EXPECT_LT(mean, 2.0) << "mean absolute difference";
    if (over > 0 || mean > 0.0) {
        tb::writePng((workDir("golden") / "actual.png").string(), img);
    }
}

TEST(RenderScene, FramesAreValidPngsOfTheAskedSizeWithTheGroundInPlace) {
    tb::Scene scene = tbtest::makeTestScene();
    tb::RenderOptions o;
    o.frames = 10;
    o.every = 3;  // frames after 0, 3, 6, 9 steps
    o.width = 320;
    o.height = 180;
    o.outDir = workDir("frames").string();
    o.progress = false;
    tb::RenderResult r = tb::renderSceneFrames(scene, o);
    ASSERT_EQ(r.framePaths.size(), 4u);
    EXPECT_EQ(fs::path(r.framePaths[0]).filename(), "frame_0000.png");
    EXPECT_EQ(fs::path(r.framePaths[3]).filename(), "frame_0003.png");
    const i2d::Color bg = tb::DrawStyle{}.background;
    for (const std::string& path : r.framePaths) {
        tb::Image img;
        std::string error;
        ASSERT_TRUE(tb::readPng(path, img, &error)) << error;
        ASSERT_EQ(img.width, 320);
        ASSERT_EQ(img.height, 180);
        // The static ground box spans y ∈ [−2, 0] ↔ rows 135..153 for the
        // scene's camera (centre y = 5, 20 m high).
        for (int y = 138; y < 151; ++y) EXPECT_GT(rowCoverage(img, y, 0, 320, bg), 0.99) << path << " row " << y;
        for (int y = 158; y < 180; ++y) EXPECT_LT(rowCoverage(img, y, 0, 320, bg), 0.01) << path << " row " << y;
        // Not blank above the ground: the two dynamic bodies are somewhere.
        int shapeRows = 0;
        for (int y = 20; y < 132; ++y) shapeRows += rowCoverage(img, y, 0, 320, bg) > 0.02 ? 1 : 0;
        EXPECT_GT(shapeRows, 10) << path;
    }
    tb::Image sheet;
    ASSERT_FALSE(r.sheetPath.empty());
    ASSERT_TRUE(tb::readPng(r.sheetPath, sheet));
    EXPECT_GT(sheet.width, 320);  // four thumbnails side by side or in rows
    if (tb::findInPath("convert").empty()) {
        EXPECT_TRUE(r.gifPath.empty());
        EXPECT_NE(r.gifMessage.find("convert"), std::string::npos) << r.gifMessage;
    } else {
        ASSERT_FALSE(r.gifPath.empty()) << r.gifMessage;
        EXPECT_EQ(fileBytes(r.gifPath).substr(0, 6), "GIF89a");
    }
}

TEST(RenderScene, SameSceneGivesTheSameBytes) {
    auto run = [](const std::string& name) {
        tb::Scene scene = tbtest::makeTestScene();
        tb::RenderOptions o;
        o.frames = 30;
        o.every = 10;
        o.width = 320;
        o.height = 180;
        o.outDir = workDir(name).string();
        o.progress = false;
        return tb::renderSceneFrames(scene, o);
    };
    tb::RenderResult a = run("det_a"), b = run("det_b");
    ASSERT_EQ(a.framePaths.size(), 3u);
    ASSERT_EQ(b.framePaths.size(), a.framePaths.size());
    for (std::size_t i = 0; i < a.framePaths.size(); ++i) {
        std::string x = fileBytes(a.framePaths[i]);
        EXPECT_FALSE(x.empty());
        EXPECT_EQ(x, fileBytes(b.framePaths[i])) << "frame " << i;
    }
    EXPECT_EQ(fileBytes(a.sheetPath), fileBytes(b.sheetPath));
    if (!a.gifPath.empty()) {
        EXPECT_EQ(fileBytes(a.gifPath), fileBytes(b.gifPath));
    }
    // Frames of a falling scene differ from each other.
    EXPECT_NE(fileBytes(a.framePaths[0]), fileBytes(a.framePaths[2]));
}

TEST(RenderScene, MissingConvertIsReportedAndThePngsStillWritten) {
    const char* oldPath = std::getenv("PATH");
    std::string saved = oldPath ? oldPath : "";
    fs::path empty = workDir("nopath");
    setenv("PATH", empty.c_str(), 1);
    tb::Scene scene = tbtest::makeTestScene();
    tb::RenderOptions o;
    o.frames = 2;
    o.width = 64;
    o.height = 36;
    o.outDir = workDir("noconvert").string();
    o.progress = false;
    tb::RenderResult r = tb::renderSceneFrames(scene, o);
    setenv("PATH", saved.c_str(), 1);
    EXPECT_TRUE(r.gifPath.empty());
    EXPECT_FALSE(fs::exists(fs::path(o.outDir) / "anim.gif"));
    EXPECT_NE(r.gifMessage.find("'convert' not found"), std::string::npos) << r.gifMessage;
    EXPECT_EQ(r.framePaths.size(), 2u);
    EXPECT_TRUE(fs::exists(r.sheetPath));
}

TEST(RenderScene, RejectsBadOptions) {
    tb::Scene scene = tbtest::makeTestScene();
    tb::RenderOptions o;
    o.outDir = workDir("bad").string();
    o.progress = false;
    o.frames = 0;
    EXPECT_THROW(tb::renderSceneFrames(scene, o), std::runtime_error);
    o.frames = 1;
    o.every = 0;
    EXPECT_THROW(tb::renderSceneFrames(scene, o), std::runtime_error);
}

struct CommandRun {
    int code;
    std::string out, err;
};

CommandRun renderCommand(const std::vector<std::string>& args) {
    std::ostringstream out, err;
    const int code = tb::runRenderCommand(args, out, err);
    return {code, out.str(), err.str()};
}

CommandRun viewCommand(const std::vector<std::string>& args) {
    std::ostringstream out, err;
    const int code = tb::runViewCommand(args, out, err);
    return {code, out.str(), err.str()};
}

// The message's first line: "testbed render: " once, then what is wrong.
std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST(RenderCommand, BadArgumentsAreUsageErrors) {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--frames"},
             {"x", "--size", "12"},
             {"x", "--size", "12x12"},
             {"x", "--size", "9000x100"},
             {"x", "--frames", "0"},
             {"x", "--frames", "many"},
             {"x", "--every", "-3"},
             {"x", "--ssaa", "5"},
             {"x", "--frobnicate"},
             {"x", "y"},
             {},
         }) {
        const CommandRun r = renderCommand(args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(r.err.rfind("testbed render: ", 0), 0u) << r.err;
        EXPECT_EQ(firstLine(r.err).find("render: ", 16), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
}

// `--every 0` used to reach the renderer, fail there with the prefix twice
// ("testbed render: render: ...") and exit 1.
TEST(RenderCommand, EveryZeroIsAUsageErrorWithOnePrefix) {
    const CommandRun r = renderCommand({"stack5", "--every", "0", "--quiet"});
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(firstLine(r.err), "testbed render: --every: expected an integer of at least 1, got '0'");
    EXPECT_NE(r.err.find("usage: testbed render"), std::string::npos) << r.err;
}

TEST(RenderCommand, HelpGoesToStandardOutput) {
    const CommandRun r = renderCommand({"--help"});
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out.rfind("usage: testbed render", 0), 0u);
    EXPECT_TRUE(r.err.empty());
}

TEST(ViewCommand, BadArgumentsAreUsageErrors) {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--size"},
             {"--size", "15x100"},
             {"--frames", "3"},
             {"--screenshot", "x.png", "--frames", "0"},
             {"a", "b"},
             {"--frobnicate"},
         }) {
        const CommandRun r = viewCommand(args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(r.err.rfind("testbed view: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("usage: testbed view"), std::string::npos) << r.err;
    }
}

TEST(Viewer, TakesAScreenshotUnderXvfbAndQuits) {
    if (tb::findInPath("xvfb-run").empty())
        GTEST_SKIP() << "xvfb-run is not installed (Debian package xvfb): no X server to open the viewer on";
    fs::path shot = workDir("view") / "shot.png";
    std::string cmd = std::string("xvfb-run -a -s '-screen 0 1280x1024x24' '") + TB_VIEW_PROBE +
                      "' --size 640x360 --frames 5 --screenshot '" + shot.string() + "'";
    int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << cmd;
    ASSERT_EQ(WEXITSTATUS(status), 0) << cmd;
    tb::Image img;
    std::string error;
    ASSERT_TRUE(tb::readPng(shot.string(), img, &error)) << error;
    ASSERT_EQ(img.width, 640);
    ASSERT_EQ(img.height, 360);
    const i2d::Color bg = tb::DrawStyle{}.background;
    // Same camera as above at twice the size: the ground spans rows 270..306.
    for (int y = 276; y < 300; ++y) EXPECT_GT(rowCoverage(img, y, 0, 640, bg), 0.97) << "row " << y;
    // The status line at the top is drawn: light text pixels in the first rows.
    int bright = 0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 640; ++x) bright += img.pixel(x, y)[0] > 200 ? 1 : 0;
    EXPECT_GT(bright, 100);
}

namespace {

std::vector<tb::ViewerScene> viewerScenes() {
    return {{"first", [] { return tbtest::makeTestScene(); }},
            {"second",
             [] {
                 tb::Scene s = tbtest::makeTestScene();
                 s.desc.name = "second";
                 return s;
             }},
            {"broken", []() -> tb::Scene { throw std::runtime_error("no such file"); }}};
}

i2d::Vec2 ballPosition(tb::ViewerController& v) { return v.scene().world->position(v.scene().bodies[2]); }

}  // namespace

TEST(ViewerControl, KeysMapToActions) {
    // SDL key codes of printable keys are their characters.
    EXPECT_EQ(tb::actionForKey(' '), tb::ViewerAction::togglePause);
    EXPECT_EQ(tb::actionForKey('s'), tb::ViewerAction::singleStep);
    EXPECT_EQ(tb::actionForKey('r'), tb::ViewerAction::restart);
    EXPECT_EQ(tb::actionForKey('n'), tb::ViewerAction::nextScene);
    EXPECT_EQ(tb::actionForKey('p'), tb::ViewerAction::previousScene);
    EXPECT_EQ(tb::actionForKey('m'), tb::ViewerAction::cyclePositionCorrection);
    EXPECT_EQ(tb::actionForKey('='), tb::ViewerAction::moreIterations);
    EXPECT_EQ(tb::actionForKey('-'), tb::ViewerAction::fewerIterations);
    EXPECT_EQ(tb::actionForKey('c'), tb::ViewerAction::toggleContacts);
    EXPECT_FALSE(tb::actionForKey('q').has_value());  // quit is handled by the window loop
}

TEST(ViewerControl, SettingKeysChangeTheWorldAndTheStatusLines) {
    tb::ViewerController v(viewerScenes(), 0, 640, 360);
    const i2d::WorldSettings before = v.scene().world->settings();
    v.apply(tb::ViewerAction::cyclePositionCorrection);
    v.apply(tb::ViewerAction::toggleImpactModel);
    v.apply(tb::ViewerAction::toggleSleep);
    v.apply(tb::ViewerAction::moreIterations);
    v.apply(tb::ViewerAction::fewerIterations);
    v.apply(tb::ViewerAction::fewerIterations);
    v.apply(tb::ViewerAction::toggleContacts);
    const i2d::WorldSettings& s = v.scene().world->settings();
    EXPECT_NE(s.positionCorrection, before.positionCorrection);
    EXPECT_NE(s.impactModel, before.impactModel);
    EXPECT_NE(s.enableSleep, before.enableSleep);
    EXPECT_EQ(s.velocityIterations, before.velocityIterations - 1);
    EXPECT_TRUE(v.flags().contacts);
    const std::string line = v.settingsLine();
    EXPECT_NE(line.find("iters " + std::to_string(before.velocityIterations - 1)), std::string::npos) << line;
    EXPECT_NE(line.find(before.enableSleep ? "sleep off" : "sleep on"), std::string::npos) << line;
    EXPECT_NE(line.find("contacts on"), std::string::npos) << line;
    EXPECT_NE(v.statusLine().find("bodies 3"), std::string::npos) << v.statusLine();
    // Three presses of m come back to the first mode.
    v.apply(tb::ViewerAction::cyclePositionCorrection);
    v.apply(tb::ViewerAction::cyclePositionCorrection);
    EXPECT_EQ(v.scene().world->settings().positionCorrection, before.positionCorrection);
}

TEST(ViewerControl, RestartKeepsSettingsAndNextSceneDropsThem) {
    tb::ViewerController v(viewerScenes(), 0, 640, 360);
    const i2d::Vec2 start = ballPosition(v);
    const int iterations = v.scene().world->settings().velocityIterations;
    v.apply(tb::ViewerAction::moreIterations);
    for (int i = 0; i < 20; ++i) v.stepOnce();
    EXPECT_EQ(v.steps(), 20);
    EXPECT_LT(ballPosition(v).y, start.y);
    v.apply(tb::ViewerAction::restart);
    EXPECT_EQ(v.steps(), 0);
    EXPECT_EQ(ballPosition(v), start);
    EXPECT_EQ(v.scene().world->settings().velocityIterations, iterations + 1);
    v.apply(tb::ViewerAction::nextScene);
    EXPECT_EQ(v.sceneIndex(), 1);
    EXPECT_EQ(v.scene().desc.name, "second");
    EXPECT_EQ(v.scene().world->settings().velocityIterations, iterations);
    v.apply(tb::ViewerAction::previousScene);
    v.apply(tb::ViewerAction::previousScene);  // wraps to the last scene, which fails to load
    EXPECT_EQ(v.sceneIndex(), 0) << "a scene that fails to load leaves the current one";
    EXPECT_NE(v.message().find("no such file"), std::string::npos) << v.message();
}

TEST(ViewerControl, PauseSingleStepAndRealTimeStepping) {
    tb::ViewerController v(viewerScenes(), 0, 640, 360, /*paused=*/true);
    const double dt = v.scene().desc.dt;
    v.advance(1.0);
    EXPECT_EQ(v.steps(), 0);
    v.apply(tb::ViewerAction::singleStep);
    v.advance(0.0);
    EXPECT_EQ(v.steps(), 1);
    EXPECT_TRUE(v.paused());
    v.apply(tb::ViewerAction::togglePause);
    v.advance(2.5 * dt);
    EXPECT_EQ(v.steps(), 3);
    v.advance(10.0);  // a long stall: at most 4 steps catch up
    EXPECT_LE(v.steps(), 3 + 4);
    EXPECT_GE(v.steps(), 3 + 3);
}

TEST(ViewerControl, MouseDragPullsTheGrabbedBody) {
    tb::ViewerController v(viewerScenes(), 0, 640, 360);
    EXPECT_FALSE(v.beginDrag({0.0f, 12.0f})) << "empty space";
    EXPECT_FALSE(v.beginDrag({0.0f, -1.0f})) << "static ground";
    const i2d::Vec2 start = ballPosition(v);
    const int joints = v.scene().world->jointCount();
    ASSERT_TRUE(v.beginDrag(start));
    EXPECT_TRUE(v.dragging());
    // The drag is a mouse joint, removed when the drag ends.
    EXPECT_EQ(v.scene().world->jointCount(), joints + 1);
    v.moveMouse(start + i2d::Vec2{2.0f, 3.0f});
    for (int i = 0; i < 60; ++i) v.stepOnce();
    const i2d::Vec2 pulled = ballPosition(v);
    EXPECT_NEAR(pulled.x, start.x + 2.0f, 0.5f);
    EXPECT_NEAR(pulled.y, start.y + 3.0f, 0.5f);
    v.endDrag();
    EXPECT_FALSE(v.dragging());
    EXPECT_EQ(v.scene().world->jointCount(), joints);
    for (int i = 0; i < 30; ++i) v.stepOnce();
    EXPECT_LT(ballPosition(v).y, pulled.y) << "falls again once released";
}

// The viewer plays a platformer scene's player from the keys (setPlayerInput
// is what the window loop calls with the arrow keys held), and from the
// scene's script when no key was ever given.
TEST(ViewerControl, PlatformerPlayerFollowsTheKeys) {
    const std::vector<tb::ViewerScene> scenes = {
        {"platformer", [] { return tb::buildScene(tb::loadSceneDesc("platformer", TB_TEST_ASSETS_DIR)); }}};
    tb::ViewerController scripted(scenes, 0, 640, 360);
    tb::ViewerController keyed(scenes, 0, 640, 360);
    ASSERT_TRUE(keyed.scene().game);
    const i2d::BodyId player = keyed.scene().named.at("player");
    const float x0 = keyed.scene().world->position(player).x;
    keyed.setPlayerInput({-1.0f, false});  // left arrow held
    for (int i = 0; i < 30; ++i) {
        keyed.stepOnce();
        scripted.stepOnce();
    }
    // 0.5 s at 5 m/s: 2.5 m to the left (10 cm for the first step's start);
    // the script runs right.
    EXPECT_NEAR(keyed.scene().world->position(player).x, x0 - 2.5f, 0.1f);
    EXPECT_NEAR(scripted.scene().world->position(scripted.scene().named.at("player")).x, x0 + 2.5f, 0.1f);
    EXPECT_NE(keyed.statusLine().find("coins 0/2"), std::string::npos) << keyed.statusLine();
}
