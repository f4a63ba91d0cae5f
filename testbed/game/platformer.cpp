// Testbed — the platformer game (platformer.hpp).
#include "game/platformer.hpp"

#include <algorithm>
#include <cmath>

namespace tb {

namespace {

// The normal of a contact as seen from the body `self`: pointing from the
// other shape towards it.
i2d::Vec2 normalTowards(const i2d::World& w, const i2d::ContactData& c, i2d::BodyId self) {
    return w.shapeBody(c.shapeB) == self ? c.manifold.normal : -c.manifold.normal;
}

}  // namespace

PlatformerGame::PlatformerGame(Scene& scene, const PlatformerDesc& desc) : desc_(desc) {
    i2d::World& w = *scene.world;
    player_ = scene.bodies[static_cast<std::size_t>(desc.player)];
    for (int b : desc.oneWay)
        for (i2d::ShapeId s : w.bodyShapes(scene.bodies[static_cast<std::size_t>(b)])) oneWay_.push_back(s);
    for (int b : desc.coins) coins_.push_back(scene.bodies[static_cast<std::size_t>(b)]);
    // One-way platforms: a contact with one is kept only while it pushes the
    // other body up and that body is not moving up through it. The callback
    // reads the world and changes nothing (the world is locked in it).
    const std::vector<i2d::ShapeId> platforms = oneWay_;
    i2d::World* world = &w;
    w.setPreSolve([platforms, world](i2d::ShapeId a, i2d::ShapeId b, const i2d::Manifold& m) {
        const bool aIsPlatform = std::find(platforms.begin(), platforms.end(), a) != platforms.end();
        const bool bIsPlatform = std::find(platforms.begin(), platforms.end(), b) != platforms.end();
        if (aIsPlatform == bIsPlatform) return true;
        // The normal from the platform to the other shape must point up …
        const i2d::Vec2 up = aIsPlatform ? m.normal : -m.normal;
        if (up.y < 0.7f) return false;
        // … and the other body must not be rising relative to the platform.
        const i2d::BodyId other = world->shapeBody(aIsPlatform ? b : a);
        const i2d::BodyId platform = world->shapeBody(aIsPlatform ? a : b);
        return world->linearVelocity(other).y - world->linearVelocity(platform).y <= 0.5f;
    });
}

PlayerInput PlatformerGame::scripted(float t) const {
    for (const PlatformerDesc::Key& k : desc_.script)
        if (t < k.until) return k.input;
    return {};
}

void PlatformerGame::beforeStep(Scene& scene, float dt, const PlayerInput* input) {
    i2d::World& w = *scene.world;
    // Platforms: velocity that brings each to its place on a there-and-back
    // path at the end of this step (a smooth cosine ease, so it slows at the ends).
    for (const PlatformerDesc::Path& p : desc_.moving) {
        const i2d::BodyId id = scene.bodies[static_cast<std::size_t>(p.body)];
        const float phase = 0.5f - 0.5f * std::cos(6.2831853f * (time_ + dt) / p.period);
        const i2d::Vec2 target = p.from + phase * (p.to - p.from);
        w.setLinearVelocity(id, (1.0f / dt) * (target - w.position(id)));
    }
    const PlayerInput in = input ? *input : scripted(time_);
    // Grounded: a touching contact whose normal pushes the player up; the
    // ground's velocity is carried (riding a moving platform).
    grounded_ = false;
    i2d::Vec2 groundVelocity{};
    for (const i2d::ContactData& c : w.bodyContacts(player_)) {
        if (normalTowards(w, c, player_).y < 0.7f) continue;
        grounded_ = true;
        const i2d::BodyId other = w.shapeBody(w.shapeBody(c.shapeA) == player_ ? c.shapeB : c.shapeA);
        groundVelocity = w.linearVelocity(other);
    }
    i2d::Vec2 v = w.linearVelocity(player_);
    v.x = std::clamp(in.move, -1.0f, 1.0f) * desc_.runSpeed + groundVelocity.x;
    // A jump starts on the ground, once per press: a press made in the air
    // (or on a bump of the ground) jumps as soon as the player lands.
    if (!in.jump) jumpUsed_ = false;
    if (in.jump && !jumpUsed_ && grounded_) {
        v.y = desc_.jumpSpeed + std::max(groundVelocity.y, 0.0f);
        jumpUsed_ = true;
    }
    w.setLinearVelocity(player_, v);
}

void PlatformerGame::afterStep(Scene& scene, float dt) {
    i2d::World& w = *scene.world;
    time_ += dt;
    for (const i2d::SensorBeginEvent& e : w.sensorBeginEvents()) {
        if (!w.isValid(e.visitor) || w.shapeBody(e.visitor) != player_) continue;
        const i2d::BodyId coin = w.shapeBody(e.sensor);
        if (std::find(coins_.begin(), coins_.end(), coin) == coins_.end() || !w.isEnabled(coin)) continue;
        // Disabled, not destroyed: restarting the level could enable it again.
        w.disableBody(coin);
        ++collected_;
    }
}

void stepScene(Scene& scene, float dt, const PlayerInput* input) {
    if (scene.game) scene.game->beforeStep(scene, dt, input);
    scene.world->step(dt);
    if (scene.game) scene.game->afterStep(scene, dt);
}

}  // namespace tb
