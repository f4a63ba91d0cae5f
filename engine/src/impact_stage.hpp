// The impact stage of a step (impact_stage.cpp): applies the closed-form
// impact law to the contacts that close fast.
#pragma once

namespace i2d::detail {

struct WorldState;

/// The impact stage's first look at an active contact, taken on the workers.
struct ImpactLook {
    int bodyA, bodyB;
    bool passOver;  ///< approaches at none of its points (or has none)
};

/// Resolves the impacts among this step's active contacts (closed_form
/// impact model only; nothing otherwise).
void resolveImpacts(WorldState& w, float dt);

}  // namespace i2d::detail
