#include "render/viewer.hpp"

#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "render/camera.hpp"
#include "render/gl_draw.hpp"
#include "render/offscreen.hpp"
#include "render/png_io.hpp"
#include "render/text.hpp"
#include "scene.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace tb {

namespace {

const char* correctionName(i2d::PositionCorrection c) {
    switch (c) {
        case i2d::PositionCorrection::baumgarte: return "baumgarte";
        case i2d::PositionCorrection::split: return "split";
        case i2d::PositionCorrection::soft_step: return "soft_step";
    }
    return "?";
}

const char* impactName(i2d::ImpactModel m) {
    return m == i2d::ImpactModel::closed_form ? "closed_form" : "velocity_bias";
}

/// The body being dragged and the grabbed point in its frame.
struct Drag {
    i2d::BodyId body{};
    i2d::Vec2 localAnchor{};
};

/// A damped spring (5 Hz, damping ratio 0.7) pulling the grabbed point
/// toward the pointer, on the effective mass at that point so that the
/// spring stays stable for bodies grabbed far from their centre.
void applyDragForce(i2d::World& world, const Drag& drag, i2d::Vec2 target) {
    if (!world.isValid(drag.body)) return;
    i2d::Vec2 anchor = i2d::transformPoint(world.transform(drag.body), drag.localAnchor);
    float mass = world.mass(drag.body);
    if (mass <= 0.0f) return;
    float inertia = world.rotationalInertia(drag.body);
    i2d::Vec2 r = anchor - world.worldCenterOfMass(drag.body);
    float invMass = 1.0f / mass + (inertia > 0.0f ? i2d::lengthSquared(r) / inertia : 0.0f);
    float effMass = 1.0f / invMass;
    constexpr float omega = 2.0f * 3.14159265f * 5.0f;
    constexpr float zeta = 0.7f;
    i2d::Vec2 v = world.velocityAtPoint(drag.body, anchor);
    i2d::Vec2 force = effMass * (omega * omega * (target - anchor) - 2.0f * zeta * omega * v);
    // Hold the body's weight too, so it hangs at the pointer instead of below it.
    force -= mass * world.gravityScale(drag.body) * world.gravity();
    float maxForce = 2000.0f * mass;
    float len = i2d::length(force);
    if (len > maxForce) force *= maxForce / len;
    world.applyForce(drag.body, force, anchor, true);
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

class Viewer {
public:
    Viewer(const std::vector<ViewerScene>& scenes, int start, const ViewerOptions& options)
        : scenes_(scenes), index_(start), options_(options), paused_(options.paused) {}

    int run();

private:
    bool load(int index, bool keepSettings);
    void handleKey(SDL_Keycode key);
    void changeSettings(const std::function<void(i2d::WorldSettings&)>& change);
    void stepOnce();
    void drawFrame(GlDraw& drawer, const GlApi& gl);
    i2d::Vec2 mouseWorld(int x, int y) const;
    void resize(int w, int h);

    const std::vector<ViewerScene>& scenes_;
    int index_;
    ViewerOptions options_;
    Scene scene_;
    View2D view_;
    std::optional<i2d::WorldSettings> userSettings_;
    std::optional<Drag> drag_;
    i2d::Vec2 mouse_{};
    int windowW_ = 0, windowH_ = 0;  // window coordinates (mouse)
    bool paused_;
    bool singleStep_ = false;
    bool showHelp_ = true;
    WorldDrawFlags flags_{};
    double stepMs_ = 0.0;
    long long steps_ = 0;
    std::string message_;
};

bool Viewer::load(int index, bool keepSettings) {
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
        int pw = view_.pixelWidth > 0 ? view_.pixelWidth : options_.width;
        int ph = view_.pixelHeight > 0 ? view_.pixelHeight : options_.height;
        view_ = sceneView(scene_, pw, ph);
        message_.clear();
        return true;
    } catch (const std::exception& e) {
        message_ = "cannot load " + scenes_[static_cast<std::size_t>(index)].name + ": " + e.what();
        std::cerr << "testbed view: " << message_ << "\n";
        return false;
    }
}

void Viewer::changeSettings(const std::function<void(i2d::WorldSettings&)>& change) {
    i2d::WorldSettings s = scene_.world->settings();
    change(s);
    try {
        scene_.world->setSettings(s);
        userSettings_ = s;
    } catch (const std::exception& e) {
        message_ = std::string("setting refused: ") + e.what();
    }
}

void Viewer::handleKey(SDL_Keycode key) {
    switch (key) {
        case SDLK_SPACE: paused_ = !paused_; break;
        case SDLK_s:
        case SDLK_RIGHT:
            paused_ = true;
            singleStep_ = true;
            break;
        case SDLK_r: load(index_, true); break;
        case SDLK_n:
        case SDLK_PAGEDOWN: load(index_ + 1, false); break;
        case SDLK_p:
        case SDLK_PAGEUP: load(index_ - 1, false); break;
        case SDLK_m:
            changeSettings([](i2d::WorldSettings& s) {
                s.positionCorrection = s.positionCorrection == i2d::PositionCorrection::baumgarte ? i2d::PositionCorrection::split
                                       : s.positionCorrection == i2d::PositionCorrection::split
                                           ? i2d::PositionCorrection::soft_step
                                           : i2d::PositionCorrection::baumgarte;
            });
            break;
        case SDLK_i:
            changeSettings([](i2d::WorldSettings& s) {
                s.impactModel = s.impactModel == i2d::ImpactModel::closed_form ? i2d::ImpactModel::velocity_bias
                                                                               : i2d::ImpactModel::closed_form;
            });
            break;
        case SDLK_z: changeSettings([](i2d::WorldSettings& s) { s.enableSleep = !s.enableSleep; }); break;
        case SDLK_PLUS:
        case SDLK_EQUALS:
        case SDLK_KP_PLUS:
            changeSettings([](i2d::WorldSettings& s) { s.velocityIterations = std::min(s.velocityIterations + 1, 100); });
            break;
        case SDLK_MINUS:
        case SDLK_KP_MINUS:
            changeSettings([](i2d::WorldSettings& s) { s.velocityIterations = std::max(s.velocityIterations - 1, 1); });
            break;
        case SDLK_PERIOD: changeSettings([](i2d::WorldSettings& s) { s.substeps = std::min(s.substeps + 1, 64); }); break;
        case SDLK_COMMA: changeSettings([](i2d::WorldSettings& s) { s.substeps = std::max(s.substeps - 1, 1); }); break;
        case SDLK_c: flags_.contacts = !flags_.contacts; break;
        case SDLK_a: flags_.aabbs = !flags_.aabbs; break;
        case SDLK_j: flags_.joints = !flags_.joints; break;
        case SDLK_h: showHelp_ = !showHelp_; break;
        default: break;
    }
}

i2d::Vec2 Viewer::mouseWorld(int x, int y) const {
    // Window coordinates may differ from drawable pixels (high-DPI).
    float sx = windowW_ > 0 ? static_cast<float>(view_.pixelWidth) / static_cast<float>(windowW_) : 1.0f;
    float sy = windowH_ > 0 ? static_cast<float>(view_.pixelHeight) / static_cast<float>(windowH_) : 1.0f;
    return view_.pixelToWorld({(static_cast<float>(x) + 0.5f) * sx, (static_cast<float>(y) + 0.5f) * sy});
}

void Viewer::resize(int w, int h) {
    view_.pixelWidth = std::max(1, w);
    view_.pixelHeight = std::max(1, h);
}

void Viewer::stepOnce() {
    if (drag_) applyDragForce(*scene_.world, *drag_, mouse_);
    auto t0 = std::chrono::steady_clock::now();
    scene_.world->step(scene_.desc.dt);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    stepMs_ = steps_ == 0 ? ms : 0.9 * stepMs_ + 0.1 * ms;  // smoothed for reading
    ++steps_;
}

void Viewer::drawFrame(GlDraw& drawer, const GlApi& gl) {
    drawer.beginFrame(view_, 1.0f);
    drawWorld(drawer, *scene_.world, flags_);
    if (drag_ && scene_.world->isValid(drag_->body)) {
        i2d::Vec2 anchor = i2d::transformPoint(scene_.world->transform(drag_->body), drag_->localAnchor);
        drawer.drawLine(anchor, mouse_, 1.5f, {0.95f, 0.95f, 0.95f, 1.0f});
        drawer.drawPoint(anchor, 6.0f, {0.95f, 0.95f, 0.95f, 1.0f});
        drawer.drawPoint(mouse_, 6.0f, {0.3f, 0.9f, 0.3f, 1.0f});
    }
    const i2d::WorldSettings& s = scene_.world->settings();
    char line[320];
    std::snprintf(line, sizeof line,
                  "step %.2f ms | bodies %d (awake %d) | %s | %s | sleep %s | iters %d | substeps %d | contacts %s | "
                  "aabbs %s%s",
                  stepMs_, scene_.world->bodyCount(), scene_.world->awakeBodyCount(),
                  correctionName(s.positionCorrection), impactName(s.impactModel), s.enableSleep ? "on" : "off",
                  s.velocityIterations, s.substeps, flags_.contacts ? "on" : "off", flags_.aabbs ? "on" : "off",
                  paused_ ? " | PAUSED" : "");
    int scale = view_.pixelWidth >= 1000 ? 2 : 1;
    i2d::Color white{0.92f, 0.92f, 0.92f, 1.0f};
    int y = 6 * scale;
    drawText(gl, view_.pixelWidth, view_.pixelHeight, 6 * scale, y, line, scale, white);
    y += textHeight(scale) + 6 * scale;
    char second[256];
    std::snprintf(second, sizeof second, "%s (%d/%d)  step %lld", scene_.desc.name.c_str(), index_ + 1,
                  static_cast<int>(scenes_.size()), steps_);
    drawText(gl, view_.pixelWidth, view_.pixelHeight, 6 * scale, y, second, scale, {0.6f, 0.85f, 1.0f, 1.0f});
    if (showHelp_) {
        const char* help =
            "space pause  s step  r restart  n/p scene  m correction  i impact  z sleep  +/- iters  ./, substeps  "
            "c contacts  a aabbs  h help  drag: mouse";
        int hy = view_.pixelHeight - textHeight(scale) - 6 * scale;
        drawText(gl, view_.pixelWidth, view_.pixelHeight, 6 * scale, hy, help, scale, {0.75f, 0.75f, 0.75f, 1.0f});
    }
    if (!message_.empty()) {
        y += textHeight(scale) + 6 * scale;
        drawText(gl, view_.pixelWidth, view_.pixelHeight, 6 * scale, y, message_, scale, {1.0f, 0.5f, 0.4f, 1.0f});
    }
    drawer.applyWorldProjection();
}

void* sdlProc(const char* name) { return SDL_GL_GetProcAddress(name); }

int Viewer::run() {
    if (scenes_.empty()) {
        std::cerr << "testbed view: no scenes\n";
        return 1;
    }
    if (!load(index_, false)) return 1;

    SdlSession sdl;
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::cerr << "testbed view: SDL_Init failed: " << SDL_GetError() << "\n";
        return 1;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 2);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 1);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);
    bool shooting = !options_.screenshot.empty();
    Uint32 flags = SDL_WINDOW_OPENGL | (shooting ? 0u : static_cast<Uint32>(SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI));
    sdl.window = SDL_CreateWindow(options_.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, options_.width,
                                  options_.height, flags);
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
    int dw = 0, dh = 0;
    SDL_GL_GetDrawableSize(sdl.window, &dw, &dh);
    SDL_GetWindowSize(sdl.window, &windowW_, &windowH_);
    i2d::Vec2 keepCenter = view_.center;
    float keepHeight = view_.height;
    resize(dw, dh);
    view_.center = keepCenter;
    view_.height = keepHeight;

    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    double accumulator = 0.0;
    int framesDone = 0;
    bool running = true;
    while (running) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            switch (e.type) {
                case SDL_QUIT: running = false; break;
                case SDL_KEYDOWN:
                    if (e.key.keysym.sym == SDLK_ESCAPE || e.key.keysym.sym == SDLK_q)
                        running = false;
                    else
                        handleKey(e.key.keysym.sym);
                    break;
                case SDL_WINDOWEVENT:
                    if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
                        SDL_GL_GetDrawableSize(sdl.window, &dw, &dh);
                        SDL_GetWindowSize(sdl.window, &windowW_, &windowH_);
                        resize(dw, dh);
                    }
                    break;
                case SDL_MOUSEBUTTONDOWN:
                    if (e.button.button == SDL_BUTTON_LEFT) {
                        mouse_ = mouseWorld(e.button.x, e.button.y);
                        for (i2d::ShapeId shape : scene_.world->queryPoint(mouse_)) {
                            i2d::BodyId body = scene_.world->shapeBody(shape);
                            if (scene_.world->bodyType(body) != i2d::BodyType::dynamic_body) continue;
                            drag_ = Drag{body, i2d::invTransformPoint(scene_.world->transform(body), mouse_)};
                            scene_.world->setAwake(body, true);
                            break;
                        }
                    }
                    break;
                case SDL_MOUSEBUTTONUP:
                    if (e.button.button == SDL_BUTTON_LEFT) drag_.reset();
                    break;
                case SDL_MOUSEMOTION: mouse_ = mouseWorld(e.motion.x, e.motion.y); break;
                case SDL_MOUSEWHEEL: {
                    // Zoom about the pointer.
                    float f = e.wheel.y > 0 ? 1.0f / 1.15f : (e.wheel.y < 0 ? 1.15f : 1.0f);
                    int mx = 0, my = 0;
                    SDL_GetMouseState(&mx, &my);
                    i2d::Vec2 before = mouseWorld(mx, my);
                    view_.height = std::clamp(view_.height * f, 0.05f, 1.0e5f);
                    view_.center += before - mouseWorld(mx, my);
                    break;
                }
                default: break;
            }
        }

        auto now = Clock::now();
        double elapsed = std::chrono::duration<double>(now - last).count();
        last = now;
        if (shooting) {
            stepOnce();  // exactly one step per frame: reproducible screenshots
        } else if (singleStep_) {
            stepOnce();
            singleStep_ = false;
            accumulator = 0.0;
        } else if (!paused_) {
            // Real time, at most 4 steps per frame when the machine falls behind.
            accumulator = std::min(accumulator + elapsed, 4.0 * scene_.desc.dt);
            while (accumulator >= scene_.desc.dt) {
                stepOnce();
                accumulator -= scene_.desc.dt;
            }
        }

        drawFrame(drawer, gl);
        if (shooting && ++framesDone >= options_.frames) {
            Image shot(view_.pixelWidth, view_.pixelHeight);
            gl.Finish();
            gl.ReadBuffer(GL_BACK);
            gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
            gl.ReadPixels(0, 0, shot.width, shot.height, GL_RGBA, GL_UNSIGNED_BYTE, shot.rgba.data());
            flipVertical(shot);
            std::string error;
            if (!writePng(options_.screenshot, shot, &error)) {
                std::cerr << "testbed view: " << error << "\n";
                return 1;
            }
            std::cerr << "screenshot " << options_.screenshot << " after " << steps_ << " steps\n";
            running = false;
        }
        SDL_GL_SwapWindow(sdl.window);
    }
    return 0;
}

void printViewUsage(std::ostream& out) {
    out << "usage: testbed view [SCENE] [--assets DIR] [--size WxH] [--paused] [--screenshot FILE --frames N]\n"
           "keys: space pause, s/right step, r restart, n/p (page down/up) next/previous scene,\n"
           "      m position correction, i impact model, z sleep, +/- velocity iterations, ./, substeps,\n"
           "      c contacts, a AABBs, j joints, h help, q/escape quit; mouse: drag bodies, wheel zoom\n";
}

int parseIntArg(const std::string& flag, const std::string& value) {
    try {
        std::size_t used = 0;
        int v = std::stoi(value, &used);
        if (used == value.size()) return v;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(flag + ": expected an integer, got '" + value + "'");
}

}  // namespace

int runViewer(const std::vector<ViewerScene>& scenes, int startIndex, const ViewerOptions& options) {
    Viewer viewer(scenes, startIndex, options);
    return viewer.run();
}

int runViewCommand(const std::vector<std::string>& args) {
    ViewerOptions options;
    std::string sceneName, assetsDir;
    bool framesGiven = false;
    try {
        for (std::size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            auto value = [&]() -> const std::string& {
                if (i + 1 >= args.size()) throw std::invalid_argument(a + ": missing value");
                return args[++i];
            };
            if (a == "-h" || a == "--help") {
                printViewUsage(std::cout);
                return 0;
            } else if (a == "--assets") {
                assetsDir = value();
            } else if (a == "--size") {
                const std::string& v = value();
                auto x = v.find('x');
                if (x == std::string::npos) throw std::invalid_argument("--size: expected WxH, got '" + v + "'");
                options.width = parseIntArg(a, v.substr(0, x));
                options.height = parseIntArg(a, v.substr(x + 1));
                if (options.width < 16 || options.height < 16) throw std::invalid_argument("--size: too small");
            } else if (a == "--screenshot") {
                options.screenshot = value();
            } else if (a == "--frames") {
                options.frames = parseIntArg(a, value());
                if (options.frames < 1) throw std::invalid_argument("--frames: expected at least 1");
                framesGiven = true;
            } else if (a == "--paused") {
                options.paused = true;
            } else if (!a.empty() && a[0] == '-') {
                throw std::invalid_argument("unknown option " + a);
            } else if (sceneName.empty()) {
                sceneName = a;
            } else {
                throw std::invalid_argument("more than one scene given");
            }
        }
        if (framesGiven && options.screenshot.empty())
            throw std::invalid_argument("--frames needs --screenshot FILE");
    } catch (const std::invalid_argument& e) {
        std::cerr << "testbed view: " << e.what() << "\n";
        printViewUsage(std::cerr);
        return 2;
    }

    try {
        if (assetsDir.empty()) assetsDir = defaultAssetsDir();
        std::vector<ViewerScene> scenes;
        for (const auto& entry : listScenes(assetsDir)) {
            std::string name = entry.first;
            scenes.push_back({name, [name, assetsDir] { return buildScene(loadSceneDesc(name, assetsDir)); }});
        }
        int start = 0;
        if (!sceneName.empty()) {
            auto it = std::find_if(scenes.begin(), scenes.end(), [&](const ViewerScene& s) { return s.name == sceneName; });
            if (it != scenes.end()) {
                start = static_cast<int>(it - scenes.begin());
            } else {
                // A file path or a scene outside the list: first in the cycle.
                loadSceneDesc(sceneName, assetsDir);  // report a bad name before opening a window
                scenes.insert(scenes.begin(),
                              {sceneName, [sceneName, assetsDir] { return buildScene(loadSceneDesc(sceneName, assetsDir)); }});
            }
        }
        if (scenes.empty()) {
            std::cerr << "testbed view: no scenes found in " << assetsDir << "\n";
            return 1;
        }
        return runViewer(scenes, start, options);
    } catch (const std::exception& e) {
        std::cerr << "testbed view: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace tb
