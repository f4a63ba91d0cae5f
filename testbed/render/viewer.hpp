// Testbed — `testbed view`: an SDL2 window with an OpenGL context showing a
// scene live.
//
//   testbed view [SCENE] [--assets DIR] [--size WxH] [--paused]
//                [--screenshot FILE --frames N]
//
// Keys: space pause, s / right arrow single step, r restart, n / p (page
// down / page up) next / previous scene, m position correction mode,
// i impact model, z sleeping on/off, + / - velocity iterations, . / ,
// substeps, c contacts, a AABBs, j joints, h help line, q / escape quit.
// Mouse: drag a dynamic body (a damped spring to the pointer); wheel zooms.
// With --screenshot the viewer steps N frames, saves the window as PNG and quits.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace tb {

struct Scene;

/// A scene the viewer can switch to; build() is called again on restart.
struct ViewerScene {
    std::string name;
    std::function<Scene()> build;
};

struct ViewerOptions {
    int width = 1280;
    int height = 720;
    bool paused = false;
    std::string screenshot;  ///< non-empty: step `frames` frames, save, quit
    int frames = 60;
    std::string title = "Impulse2D testbed";
};

/// Runs the window until it is closed (or the screenshot is written).
/// Returns the process exit code.
int runViewer(const std::vector<ViewerScene>& scenes, int startIndex, const ViewerOptions& options);

/// `testbed view ...`; args are the words after "view". Returns the exit code.
int runViewCommand(const std::vector<std::string>& args);

}  // namespace tb
