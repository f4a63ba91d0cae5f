// Testbed — the small platformer game a scene file can describe (its
// "platformer" section, docs/scene-format.md): a player run and jumped by the
// keyboard in `testbed view` or by the scene's script in `run` and `render`,
// one-way platforms (a pre-solve callback), platforms moved back and forth
// (kinematic bodies) and coins (sensors) that vanish when collected (the
// body is disabled). Only the Impulse2D world plays it.
#pragma once

#include "scene.hpp"

namespace tb {

class PlatformerGame {
public:
    /// Takes the parts from the scene's bodies and installs the one-way
    /// platforms' pre-solve callback in its world.
    PlatformerGame(Scene& scene, const PlatformerDesc& desc);

    /// Before a step: the platforms' velocities and the player's, from the
    /// input (or, when none is given, from the script at the current time).
    void beforeStep(Scene& scene, float dt, const PlayerInput* input);
    /// After a step: collects the coins the player touched.
    void afterStep(Scene& scene, float dt);

    int coinsCollected() const { return collected_; }
    int coinCount() const { return static_cast<int>(desc_.coins.size()); }
    /// True when the player stood on something at the last step.
    bool playerGrounded() const { return grounded_; }
    /// The scripted input at time t (s).
    PlayerInput scripted(float t) const;

private:
    PlatformerDesc desc_;
    i2d::BodyId player_{};
    std::vector<i2d::ShapeId> oneWay_;
    std::vector<i2d::BodyId> coins_;
    float time_ = 0.0f;
    int collected_ = 0;
    bool grounded_ = false;
    bool jumpUsed_ = false;  ///< this press of the jump key has jumped
};

/// One step of dt seconds: the game's input and platforms before, coins
/// after (nothing more for a scene without a game). `input` null: the script.
void stepScene(Scene& scene, float dt, const PlayerInput* input = nullptr);

}  // namespace tb
