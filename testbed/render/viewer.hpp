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
// Mouse: drag a dynamic body (a mouse joint pulls the grabbed point to the
// pointer); wheel zooms.
// With --screenshot the viewer steps N frames, saves the window as PNG and quits.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/offscreen.hpp"
#include "scene.hpp"

namespace tb {

class GlDraw;

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

/// What a key does in the viewer.
enum class ViewerAction {
    togglePause,
    singleStep,
    restart,
    nextScene,
    previousScene,
    cyclePositionCorrection,
    toggleImpactModel,
    toggleSleep,
    moreIterations,
    fewerIterations,
    moreSubsteps,
    fewerSubsteps,
    toggleContacts,
    toggleAabbs,
    toggleJoints,
    toggleHelp,
};

/// The action bound to an SDL key code (SDLK_*), if any.
std::optional<ViewerAction> actionForKey(int sdlKeycode);

/// The viewer's state and behaviour without a window: the current scene,
/// settings changed by keys, stepping, mouse dragging, and what is drawn.
class ViewerController {
public:
    /// Loads scenes[start]; throws std::runtime_error when it cannot be built.
    ViewerController(std::vector<ViewerScene> scenes, int start, int pixelWidth, int pixelHeight, bool paused = false);

    /// Switches to scenes[index] (wrapping around). With keepSettings the
    /// settings changed by keys carry over (restart); otherwise the scene's
    /// own settings apply. On failure the current scene stays and message() says why.
    bool load(int index, bool keepSettings);
    void apply(ViewerAction action);
    /// Advances by real time: fixed steps of the scene's dt, at most 4 per
    /// call; nothing while paused except a pending single step.
    void advance(double elapsedSeconds);
    /// One step of the scene's dt (with the drag force, if dragging).
    void stepOnce();
    /// Keyboard input for a platformer scene's player; without it (never
    /// called) the scene's script plays it, as in `run` and `render`.
    void setPlayerInput(const PlayerInput& input) {
        playerInput_ = input;
        playerKeys_ = true;
    }

    /// Grabs the dynamic body under the world point; false when there is none.
    bool beginDrag(i2d::Vec2 worldPoint);
    void moveMouse(i2d::Vec2 worldPoint) { mouse_ = worldPoint; }
    void endDrag();
    bool dragging() const { return drag_.has_value(); }

    /// Draws the world, the drag line and the text lines into a frame begun on `view()`.
    void draw(GlDraw& drawer);
    /// "step 0.42 ms | bodies 45 (awake 12) | ..." — timing, counts, scene.
    std::string statusLine() const;
    /// "soft_step | closed_form | sleep on | iters 8 | ..." — the settings.
    std::string settingsLine() const;

    Scene& scene() { return scene_; }
    View2D& view() { return view_; }
    int sceneIndex() const { return index_; }
    bool paused() const { return paused_; }
    long long steps() const { return steps_; }
    const WorldDrawFlags& flags() const { return flags_; }
    const std::string& message() const { return message_; }

private:
    /// A body being dragged by a mouse joint to the pointer.
    struct Drag {
        i2d::BodyId body{};
        i2d::JointId joint{};
        i2d::Vec2 localAnchor{};
    };
    void changeSettings(const std::function<void(i2d::WorldSettings&)>& change);

    std::vector<ViewerScene> scenes_;
    int index_ = 0;
    Scene scene_;
    View2D view_;
    std::optional<i2d::WorldSettings> userSettings_;
    std::optional<Drag> drag_;
    i2d::Vec2 mouse_{};
    PlayerInput playerInput_{};
    bool playerKeys_ = false;
    bool paused_ = false;
    bool pendingStep_ = false;
    bool showHelp_ = true;
    WorldDrawFlags flags_{};
    double accumulator_ = 0.0;
    double stepMs_ = 0.0;
    long long steps_ = 0;
    std::string message_;
};

/// Runs the window until it is closed (or the screenshot is written).
/// Returns the process exit code.
int runViewer(const std::vector<ViewerScene>& scenes, int startIndex, const ViewerOptions& options);

}  // namespace tb
