// The impact stage of a step (impact_stage.cpp): applies the closed-form
// impact law to the contacts that close fast.
#pragma once

#include "impulse2d/math.hpp"

namespace i2d::detail {

struct WorldState;

/// A body's velocity and centre as the impact stage reads them for its
/// first look at each contact; `known` 0 where it must read the body.
struct BodyMotion {
    Vec2 v{};
    Vec2 center{};
    float w = 0.0f;
    float known = 0.0f;
};

/// The impact stage's first look at an active contact, taken on the workers.
struct ImpactLook {
    int bodyA, bodyB;
    bool passOver;  ///< approaches at none of its points (or has none)
};

/// Resolves the impacts among this step's active contacts (closed_form
/// impact model only; nothing otherwise).
void resolveImpacts(WorldState& w, float dt);

}  // namespace i2d::detail
