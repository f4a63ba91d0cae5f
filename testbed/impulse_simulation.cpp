// Testbed — a scene as an Impulse2D world, behind the Simulation interface.
#include <algorithm>

#include "enum_names.hpp"
#include "game/platformer.hpp"
#include "scene_build.hpp"
#include "simulation.hpp"
#include "thread_pool.hpp"

namespace tb {
namespace {

class ImpulseSimulation final : public Simulation {
public:
    explicit ImpulseSimulation(const SceneDesc& desc) : scene_(buildScene(desc)) {
        keepDrives(desc);
        if (desc.threads > 1) {
            pool_ = std::make_unique<ThreadPool>(desc.threads);
            scene_.world->setTaskSystem(pool_.get());
        }
        // The world holds everything the simulation needs; the description's
        // bodies and joints are not kept (the Box2D backend keeps none either,
        // so memory figures compare the two engines, not the testbed).
        std::vector<BodyDesc>().swap(scene_.desc.bodies);
        std::vector<JointDesc>().swap(scene_.desc.joints);
    }

    EngineKind engine() const override { return EngineKind::impulse2d; }
    void step(float dt) override {
        applyDrives();
        stepScene(scene_, dt);
    }
    int bodyCount() const override { return static_cast<int>(scene_.bodies.size()); }
    int jointCount() const override { return scene_.world->jointCount(); }
    int touchingContactCount() const override { return scene_.world->contactCount(); }

    void driveX(int index, float vx) override {
        i2d::World& w = *scene_.world;
        const i2d::BodyId id = scene_.bodies[static_cast<std::size_t>(index)];
        w.setLinearVelocity(id, {vx, w.linearVelocity(id).y});
    }

    BodySample sample(int index) const override {
        const i2d::World& w = *scene_.world;
        i2d::BodyId id = scene_.bodies[static_cast<std::size_t>(index)];
        BodySample s;
        i2d::Vec2 p = w.position(id), v = w.linearVelocity(id), c = w.worldCenterOfMass(id);
        s.x = p.x;
        s.y = p.y;
        s.angle = w.angle(id);
        s.vx = v.x;
        s.vy = v.y;
        s.w = w.angularVelocity(id);
        s.cx = c.x;
        s.cy = c.y;
        s.dynamic = w.bodyType(id) == i2d::BodyType::dynamic_body;
        s.mass = s.dynamic ? w.mass(id) : 0.0f;
        s.inertia = s.dynamic ? w.rotationalInertia(id) : 0.0f;
        s.gravityScale = w.gravityScale(id);
        s.awake = w.isAwake(id);
        return s;
    }

    float maxPenetration() const override {
        float worst = 0.0f;
        for (const i2d::ContactData& c : scene_.world->contacts())
            for (int i = 0; i < c.manifold.pointCount; ++i) worst = std::max(worst, -c.manifold.points[i].separation);
        return worst;
    }

    std::vector<std::pair<const char*, double>> stageTimes() const override {
        const i2d::Profile& p = scene_.world->profile();
        return {{"pairs", p.pairs}, {"collide", p.collide},       {"impacts", p.impacts}, {"prepare", p.prepare},
                {"solve", p.solve}, {"continuous", p.continuous}, {"sleep", p.sleep},     {"step", p.step}};
    }

    ~ImpulseSimulation() override {
        if (pool_) scene_.world->setTaskSystem(nullptr);
    }

private:
    Scene scene_;
    std::unique_ptr<ThreadPool> pool_;  ///< the world's workers beyond the caller (--threads)
};

}  // namespace

std::unique_ptr<Simulation> makeImpulseSimulation(const SceneDesc& desc) {
    return std::make_unique<ImpulseSimulation>(desc);
}

const char* engineName(EngineKind kind) { return enumName(kind); }

std::unique_ptr<Simulation> makeSimulation(const SceneDesc& desc, EngineKind kind, const Box2DSettings& box2d) {
    if (kind == EngineKind::impulse2d) return makeImpulseSimulation(desc);
    if (!box2dAvailable())
        throw SceneError(
            "this testbed was built without the Box2D 2.4.1 backend (libbox2d-dev not found at configure time)");
    return makeBox2DSimulation(desc, box2d);
}

}  // namespace tb
