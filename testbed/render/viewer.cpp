// Testbed — the interactive viewer: its controller and the SDL2 window (see viewer.hpp).
#include "render/viewer.hpp"

#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "enum_names.hpp"
#include "game/platformer.hpp"
#include "render/camera.hpp"
#include "render/gl_draw.hpp"
#include "render/offscreen.hpp"
#include "render/png_io.hpp"
#include "render/text.hpp"
#include "scene.hpp"
#include "scene_build.hpp"

namespace tb {

namespace {

/// A damped spring (5 Hz, damping ratio 0.7) pulling the grabbed point
/// toward the pointer, on the effective mass at that point so that the
/// spring stays stable for bodies grabbed far from their centre; it also
/// carries the body's weight so the body hangs at the pointer.
/// A static body of the world to hang the mouse joint on (any static body:
/// the joint never moves it); one without shapes is added when there is none.
i2d::BodyId staticReference(i2d::World& world) {
    for (i2d::BodyId b : world.bodies())
        if (world.bodyType(b) == i2d::BodyType::static_body) return b;
    return world.createBody({});
}

struct SdlSession {
    SDL_Window* window = nullptr;
    SDL_GLContext context = nullptr;
    ~SdlSession() {
        if (context) SDL_GL_DeleteContext(context);
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
    }
};

void* sdlProc(const char* name) { return SDL_GL_GetProcAddress(name); }

const char* const kNoDisplayHint =
    "\n  set DISPLAY (X11) or WAYLAND_DISPLAY, or run under xvfb-run; `testbed render` needs no display\n";

/// True when the environment's SDL_VIDEODRIVER names this driver.
bool requestedDriver(const std::string& name) {
    const char* wanted = SDL_getenv("SDL_VIDEODRIVER");
    return wanted != nullptr && !name.empty() && name == wanted;
}

}  // namespace

std::optional<ViewerAction> actionForKey(int key) {
    switch (key) {
        case SDLK_SPACE: return ViewerAction::togglePause;
        case SDLK_s:
        case SDLK_RIGHT: return ViewerAction::singleStep;
        case SDLK_r: return ViewerAction::restart;
        case SDLK_n:
        case SDLK_PAGEDOWN: return ViewerAction::nextScene;
        case SDLK_p:
        case SDLK_PAGEUP: return ViewerAction::previousScene;
        case SDLK_m: return ViewerAction::cyclePositionCorrection;
        case SDLK_i: return ViewerAction::toggleImpactModel;
        case SDLK_z: return ViewerAction::toggleSleep;
        case SDLK_PLUS:
        case SDLK_EQUALS:
        case SDLK_KP_PLUS: return ViewerAction::moreIterations;
        case SDLK_MINUS:
        case SDLK_KP_MINUS: return ViewerAction::fewerIterations;
        case SDLK_PERIOD: return ViewerAction::moreSubsteps;
        case SDLK_COMMA: return ViewerAction::fewerSubsteps;
        case SDLK_c: return ViewerAction::toggleContacts;
        case SDLK_a: return ViewerAction::toggleAabbs;
        case SDLK_j: return ViewerAction::toggleJoints;
        case SDLK_h: return ViewerAction::toggleHelp;
        default: return std::nullopt;
    }
}

ViewerController::ViewerController(std::vector<ViewerScene> scenes, int start, int pixelWidth, int pixelHeight,
                                   bool paused)
    : scenes_(std::move(scenes)), paused_(paused) {
    view_.pixelWidth = std::max(1, pixelWidth);
    view_.pixelHeight = std::max(1, pixelHeight);
    if (scenes_.empty()) throw std::runtime_error("no scenes to view");
    if (!load(start, false)) throw std::runtime_error(message_);
}

bool ViewerController::load(int index, bool keepSettings) {
    int n = static_cast<int>(scenes_.size());
    index = ((index % n) + n) % n;
    try {
        Scene s = scenes_[static_cast<std::size_t>(index)].build();
        if (!s.world) throw std::runtime_error("scene has no world");
        if (keepSettings && userSettings_) s.world->setSettings(*userSettings_);
        if (!keepSettings) userSettings_.reset();
        scene_ = std::move(s);
        index_ = index;
        drag_.reset();
        steps_ = 0;
        stepMs_ = 0.0;
        accumulator_ = 0.0;
        view_ = sceneView(scene_, view_.pixelWidth, view_.pixelHeight);
        message_.clear();
        return true;
    } catch (const std::exception& e) {
        message_ = "cannot load " + scenes_[static_cast<std::size_t>(index)].name + ": " + e.what();
        std::cerr << "testbed view: " << message_ << "\n";
        return false;
    }
}

void ViewerController::changeSettings(const std::function<void(i2d::WorldSettings&)>& change) {
    i2d::WorldSettings s = scene_.world->settings();
    change(s);
    try {
        scene_.world->setSettings(s);
        userSettings_ = s;
    } catch (const std::exception& e) {
        message_ = std::string("setting refused: ") + e.what();
    }
}

void ViewerController::apply(ViewerAction action) {
    using A = ViewerAction;
    using PC = i2d::PositionCorrection;
    switch (action) {
        case A::togglePause: paused_ = !paused_; break;
        case A::singleStep:
            paused_ = true;
            pendingStep_ = true;
            break;
        case A::restart: load(index_, true); break;
        case A::nextScene: load(index_ + 1, false); break;
        case A::previousScene: load(index_ - 1, false); break;
        case A::cyclePositionCorrection:
            changeSettings([](i2d::WorldSettings& s) {
                s.positionCorrection = s.positionCorrection == PC::baumgarte ? PC::split
                                       : s.positionCorrection == PC::split   ? PC::soft_step
                                                                             : PC::baumgarte;
            });
            break;
        case A::toggleImpactModel:
            changeSettings([](i2d::WorldSettings& s) {
                s.impactModel = s.impactModel == i2d::ImpactModel::closed_form ? i2d::ImpactModel::velocity_bias
                                                                               : i2d::ImpactModel::closed_form;
            });
            break;
        case A::toggleSleep: changeSettings([](i2d::WorldSettings& s) { s.enableSleep = !s.enableSleep; }); break;
        case A::moreIterations:
            changeSettings(
                [](i2d::WorldSettings& s) { s.velocityIterations = std::min(s.velocityIterations + 1, 100); });
            break;
        case A::fewerIterations:
            changeSettings([](i2d::WorldSettings& s) { s.velocityIterations = std::max(s.velocityIterations - 1, 1); });
            break;
        case A::moreSubsteps:
            changeSettings([](i2d::WorldSettings& s) { s.substeps = std::min(s.substeps + 1, 64); });
            break;
        case A::fewerSubsteps:
            changeSettings([](i2d::WorldSettings& s) { s.substeps = std::max(s.substeps - 1, 1); });
            break;
        case A::toggleContacts: flags_.contacts = !flags_.contacts; break;
        case A::toggleAabbs: flags_.aabbs = !flags_.aabbs; break;
        case A::toggleJoints: flags_.joints = !flags_.joints; break;
        case A::toggleHelp: showHelp_ = !showHelp_; break;
    }
}

void ViewerController::stepOnce() {
    if (drag_ && scene_.world->isValid(drag_->joint)) scene_.world->setMouseJointTarget(drag_->joint, mouse_);
    auto t0 = std::chrono::steady_clock::now();
    stepScene(scene_, scene_.desc.dt, playerKeys_ ? &playerInput_ : nullptr);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    stepMs_ = steps_ == 0 ? ms : 0.9 * stepMs_ + 0.1 * ms;  // smoothed for reading
    ++steps_;
}

void ViewerController::advance(double elapsedSeconds) {
    if (pendingStep_) {
        pendingStep_ = false;
        accumulator_ = 0.0;
        stepOnce();
        return;
    }
    if (paused_) return;
    const double dt = scene_.desc.dt;
    accumulator_ = std::min(accumulator_ + std::max(elapsedSeconds, 0.0), 4.0 * dt);
    while (accumulator_ >= dt) {
        stepOnce();
        accumulator_ -= dt;
    }
}

bool ViewerController::beginDrag(i2d::Vec2 p) {
    mouse_ = p;
    i2d::World& world = *scene_.world;
    for (i2d::ShapeId shape : world.queryPoint(p)) {
        i2d::BodyId body = world.shapeBody(shape);
        if (world.bodyType(body) != i2d::BodyType::dynamic_body) continue;
        // A 5 Hz spring, damped at 0.7, pulling with up to a thousand times
        // the body's weight: quick, firm, yet unable to launch it.
        const float weight = world.mass(body) * std::max(i2d::length(world.gravity()), 1.0f);
        const i2d::JointId joint = world.createMouseJoint({.bodyA = staticReference(world),
                                                           .bodyB = body,
                                                           .target = p,
                                                           .hertz = 5.0f,
                                                           .dampingRatio = 0.7f,
                                                           .maxForce = 1000.0f * weight});
        drag_ = Drag{body, joint, i2d::invTransformPoint(world.transform(body), p)};
        return true;
    }
    return false;
}

void ViewerController::endDrag() {
    if (drag_ && scene_.world->isValid(drag_->joint)) scene_.world->destroyJoint(drag_->joint);
    drag_.reset();
}

std::string ViewerController::statusLine() const {
    char line[256];
    std::snprintf(line, sizeof line, "step %.2f ms | bodies %d (awake %d) | %s (%d/%d) step %lld%s", stepMs_,
                  scene_.world->bodyCount(), scene_.world->awakeBodyCount(), scene_.desc.name.c_str(), index_ + 1,
                  static_cast<int>(scenes_.size()), steps_, paused_ ? " | PAUSED" : "");
    std::string out = line;
    if (scene_.game)
        out += " | coins " + std::to_string(scene_.game->coinsCollected()) + "/" +
               std::to_string(scene_.game->coinCount()) + (playerKeys_ ? " | arrows: run, jump" : " | script");
    return out;
}

std::string ViewerController::settingsLine() const {
    const i2d::WorldSettings& s = scene_.world->settings();
    char line[256];
    std::snprintf(line, sizeof line, "%s | %s | sleep %s | iters %d | substeps %d | contacts %s | aabbs %s",
                  enumName(s.positionCorrection), enumName(s.impactModel), s.enableSleep ? "on" : "off",
                  s.velocityIterations, s.substeps, flags_.contacts ? "on" : "off", flags_.aabbs ? "on" : "off");
    return line;
}

void ViewerController::draw(GlDraw& drawer) {
    const GlApi& gl = drawer.gl();
    drawWorld(drawer, *scene_.world, flags_);
    if (drag_ && scene_.world->isValid(drag_->body)) {
        i2d::Vec2 anchor = i2d::transformPoint(scene_.world->transform(drag_->body), drag_->localAnchor);
        drawer.drawLine(anchor, mouse_, 1.5f, {0.95f, 0.95f, 0.95f, 1.0f});
        drawer.drawPoint(anchor, 6.0f, {0.95f, 0.95f, 0.95f, 1.0f});
        drawer.drawPoint(mouse_, 6.0f, {0.3f, 0.9f, 0.3f, 1.0f});
    }
    const int w = view_.pixelWidth, h = view_.pixelHeight;
    const int scale = w >= 1100 ? 2 : 1;
    const int lineStep = textHeight(scale) + 6 * scale;
    int y = 6 * scale;
    drawText(gl, w, h, 6 * scale, y, statusLine(), scale, {0.92f, 0.92f, 0.92f, 1.0f});
    y += lineStep;
    drawText(gl, w, h, 6 * scale, y, settingsLine(), scale, {0.6f, 0.85f, 1.0f, 1.0f});
    if (!message_.empty()) {
        y += lineStep;
        drawText(gl, w, h, 6 * scale, y, message_, scale, {1.0f, 0.5f, 0.4f, 1.0f});
    }
    if (showHelp_) {
        const char* help =
            "space pause | s step | r restart | n/p scene | m correction | i impact | z sleep | +/- iters | "
            "./, substeps | c contacts | a aabbs | j joints | h help | drag bodies with the mouse";
        drawText(gl, w, h, 6, h - textHeight(1) - 6, help, 1, {0.75f, 0.75f, 0.75f, 1.0f});
    }
    drawer.applyWorldProjection();
}

namespace {

int runWindow(ViewerController& viewer, const ViewerOptions& options) {
    SdlSession sdl;
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::cerr << "testbed view: cannot open a display: " << SDL_GetError() << kNoDisplayHint;
        return 1;
    }
    // With no display SDL falls back to a driver that draws nowhere
    // ("offscreen", "dummy"): the viewer would run unseen until killed. Only a
    // driver the user asked for by name (SDL_VIDEODRIVER) is accepted.
    const char* driver = SDL_GetCurrentVideoDriver();
    const std::string name = driver ? driver : "";
    if ((name == "offscreen" || name == "dummy" || name.empty()) && !requestedDriver(name)) {
        std::cerr << "testbed view: cannot open a display (no X11 or Wayland display is reachable; SDL offers only "
                     "its '"
                  << name << "' video driver)" << kNoDisplayHint;
        return 1;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 2);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 1);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
    const bool shooting = !options.screenshot.empty();
    Uint32 flags = SDL_WINDOW_OPENGL;
    if (!shooting) flags |= SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
    sdl.window = SDL_CreateWindow(options.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, options.width,
                                  options.height, flags);
    if (!sdl.window) {
        std::cerr << "testbed view: cannot open a window: " << SDL_GetError() << "\n";
        return 1;
    }
    sdl.context = SDL_GL_CreateContext(sdl.window);
    if (!sdl.context) {
        std::cerr << "testbed view: cannot create an OpenGL context: " << SDL_GetError() << "\n";
        return 1;
    }
    SDL_GL_SetSwapInterval(shooting ? 0 : 1);
    GlApi gl;
    const char* missing = nullptr;
    if (!gl.load(&sdlProc, &missing)) {
        std::cerr << "testbed view: OpenGL lacks " << (missing ? missing : "a function") << "\n";
        return 1;
    }
    GlDraw drawer(gl);

    int windowW = 0, windowH = 0;
    auto syncSize = [&] {
        int dw = 0, dh = 0;
        SDL_GL_GetDrawableSize(sdl.window, &dw, &dh);
        SDL_GetWindowSize(sdl.window, &windowW, &windowH);
        viewer.view().pixelWidth = std::max(1, dw);
        viewer.view().pixelHeight = std::max(1, dh);
    };
    // Window coordinates may differ from drawable pixels (high-DPI).
    auto toWorld = [&](int x, int y) {
        const View2D& v = viewer.view();
        float sx = windowW > 0 ? static_cast<float>(v.pixelWidth) / static_cast<float>(windowW) : 1.0f;
        float sy = windowH > 0 ? static_cast<float>(v.pixelHeight) / static_cast<float>(windowH) : 1.0f;
        return v.pixelToWorld({(static_cast<float>(x) + 0.5f) * sx, (static_cast<float>(y) + 0.5f) * sy});
    };
    syncSize();

    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    int framesDone = 0;
    bool running = true;
    while (running) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            switch (e.type) {
                case SDL_QUIT: running = false; break;
                case SDL_KEYDOWN:
                    if (e.key.keysym.sym == SDLK_ESCAPE || e.key.keysym.sym == SDLK_q) {
                        running = false;
                    } else if (viewer.scene().game && (e.key.keysym.sym == SDLK_LEFT ||
                                                       e.key.keysym.sym == SDLK_RIGHT || e.key.keysym.sym == SDLK_UP)) {
                        // A platformer's player keys (read below), not the viewer's.
                    } else if (auto action = actionForKey(e.key.keysym.sym)) {
                        int before = viewer.sceneIndex();
                        viewer.apply(*action);
                        if (viewer.sceneIndex() != before || *action == ViewerAction::restart) syncSize();
                    }
                    break;
                case SDL_WINDOWEVENT:
                    if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) syncSize();
                    break;
                case SDL_MOUSEBUTTONDOWN:
                    if (e.button.button == SDL_BUTTON_LEFT) viewer.beginDrag(toWorld(e.button.x, e.button.y));
                    break;
                case SDL_MOUSEBUTTONUP:
                    if (e.button.button == SDL_BUTTON_LEFT) viewer.endDrag();
                    break;
                case SDL_MOUSEMOTION: viewer.moveMouse(toWorld(e.motion.x, e.motion.y)); break;
                case SDL_MOUSEWHEEL: {
                    // Zoom about the pointer.
                    float f = e.wheel.y > 0 ? 1.0f / 1.15f : (e.wheel.y < 0 ? 1.15f : 1.0f);
                    int mx = 0, my = 0;
                    SDL_GetMouseState(&mx, &my);
                    i2d::Vec2 before = toWorld(mx, my);
                    viewer.view().height = std::clamp(viewer.view().height * f, 0.05f, 1.0e5f);
                    viewer.view().center += before - toWorld(mx, my);
                    break;
                }
                default: break;
            }
        }

        auto now = Clock::now();
        double elapsed = std::chrono::duration<double>(now - last).count();
        last = now;
        if (viewer.scene().game && !shooting) {
            // Held keys drive a platformer's player; screenshots keep the script.
            const Uint8* keys = SDL_GetKeyboardState(nullptr);
            PlayerInput in;
            in.move = (keys[SDL_SCANCODE_RIGHT] ? 1.0f : 0.0f) - (keys[SDL_SCANCODE_LEFT] ? 1.0f : 0.0f);
            in.jump = keys[SDL_SCANCODE_UP] != 0;
            viewer.setPlayerInput(in);
        }
        if (shooting)
            viewer.stepOnce();  // exactly one step per frame: reproducible screenshots
        else
            viewer.advance(elapsed);

        drawer.beginFrame(viewer.view(), 1.0f);
        viewer.draw(drawer);
        if (shooting && ++framesDone >= options.frames) {
            Image shot(viewer.view().pixelWidth, viewer.view().pixelHeight);
            gl.Finish();
            gl.ReadBuffer(GL_BACK);
            gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
            gl.ReadPixels(0, 0, shot.width, shot.height, GL_RGBA, GL_UNSIGNED_BYTE, shot.rgba.data());
            flipVertical(shot);
            std::string error;
            if (!writePng(options.screenshot, shot, &error)) {
                std::cerr << "testbed view: " << error << "\n";
                return 1;
            }
            std::cerr << "screenshot " << options.screenshot << " after " << viewer.steps() << " steps\n";
            running = false;
        }
        SDL_GL_SwapWindow(sdl.window);
    }
    return 0;
}

}  // namespace

int runViewer(const std::vector<ViewerScene>& scenes, int startIndex, const ViewerOptions& options) {
    try {
        ViewerController viewer(scenes, startIndex, options.width, options.height, options.paused);
        return runWindow(viewer, options);
    } catch (const std::exception& e) {
        std::cerr << "testbed view: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace tb
