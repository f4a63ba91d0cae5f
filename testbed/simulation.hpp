// Testbed — one scene, any engine.
//
// A Simulation is a scene (tb::SceneDesc) instantiated in one physics engine:
// Impulse2D, or Box2D 2.4.1 for side-by-side comparison. Everything the
// testbed measures (energy, penetration, named bodies, joint stretch) is read
// through this interface, with the same formulas for both engines, so that a
// figure means the same thing whichever engine produced it.
//
// The interface is for measurement, not for speed: step() is one virtual call
// per step; per-body reads are only made between steps, outside the timing.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene.hpp"

namespace tb {

enum class EngineKind { impulse2d, box2d };

/// "impulse2d" or "box2d".
const char* engineName(EngineKind kind);
/// True when this build of the testbed includes the Box2D 2.4.1 backend.
bool box2dAvailable();

/// Iteration counts of Box2D 2.4.1's solver (b2World::Step).
struct Box2DSettings {
    int velocityIterations = 8;
    int positionIterations = 3;
};

/// The state of one body, in the same units and conventions for every engine.
struct BodySample {
    float x = 0, y = 0;    ///< body origin, world (m)
    float angle = 0;       ///< radians, counter-clockwise
    float vx = 0, vy = 0;  ///< velocity of the centre of mass (m/s)
    float w = 0;           ///< angular velocity (rad/s)
    float cx = 0, cy = 0;  ///< centre of mass, world (m)
    float mass = 0;        ///< kg (0 for static and kinematic bodies)
    float inertia = 0;     ///< about the centre of mass (kg m²)
    float gravityScale = 1;
    bool dynamic = false;
    bool awake = false;
};

class Simulation {
public:
    virtual ~Simulation() = default;

    virtual EngineKind engine() const = 0;
    /// Advance by dt seconds with the scene's (or the overridden) settings;
    /// the scene's driven bodies (BodyDesc::driveSpeed) are driven first.
    virtual void step(float dt) = 0;
    /// Bodies in scene order: sample(i) is desc.bodies[i].
    virtual int bodyCount() const = 0;
    virtual BodySample sample(int index) const = 0;
    /// Set the horizontal velocity of the centre of mass (m/s), keeping the
    /// vertical one (a scripted player, BodyDesc::driveSpeed).
    virtual void driveX(int index, float vx) = 0;
    virtual int jointCount() const = 0;
    /// Contacts whose shapes touch (at least one manifold point).
    virtual int touchingContactCount() const = 0;
    /// Largest penetration depth (m) over the touching contacts' points, 0 when
    /// nothing overlaps. Box2D 2.4.1 measures it between its polygons' skins
    /// (b2_polygonRadius = 1 cm beyond the vertices).
    virtual float maxPenetration() const = 0;
    /// The engine's own timing of the last step's stages (ms), in stage
    /// order; empty for an engine that does not time them.
    virtual std::vector<std::pair<const char*, double>> stageTimes() const { return {}; }
    /// What the engine could not express of the scene, one sentence each
    /// (empty when it took the scene as it is).
    const std::vector<std::string>& notes() const { return notes_; }

protected:
    std::vector<std::string> notes_;
    /// The driven bodies: (index, horizontal speed), from the scene.
    std::vector<std::pair<int, float>> drives_;

    void keepDrives(const SceneDesc& desc) {
        for (std::size_t i = 0; i < desc.bodies.size(); ++i)
            if (desc.bodies[i].driveSpeed) drives_.emplace_back(static_cast<int>(i), *desc.bodies[i].driveSpeed);
    }
    void applyDrives() {
        for (const auto& [index, speed] : drives_) driveX(index, speed);
    }
};

/// Build `desc` in the given engine. Impulse2D takes desc.settings as they
/// are; Box2D takes gravity, sleeping and the iteration counts in `box2d`, and
/// reports in notes() every setting or feature it has no equivalent for.
/// Throws SceneError when the engine refuses the scene, or when the Box2D
/// backend is not part of this build.
std::unique_ptr<Simulation> makeSimulation(const SceneDesc& desc, EngineKind kind, const Box2DSettings& box2d = {});

/// Built by makeSimulation; exposed for the two implementation files.
std::unique_ptr<Simulation> makeImpulseSimulation(const SceneDesc& desc);
std::unique_ptr<Simulation> makeBox2DSimulation(const SceneDesc& desc, const Box2DSettings& settings);

}  // namespace tb
