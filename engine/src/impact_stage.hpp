// The impact stage of a step (impact_stage.cpp): applies the closed-form
// impact law to the contacts that close fast.
#pragma once

#include "impulse2d/math.hpp"

namespace i2d::detail {

/// A contact in the impact stage's shock pass (impact_stage.cpp): its slot,
/// its bodies (their index in the pass, then their levels) and its level.
struct ShockEdge {
    int contact, a, b, level;
    bool heavyOnLight;  ///< its look's kLookHeavyOnLight
};

/// A body's motion before the shock pass struck it, to undo the pass.
struct ShockSaved {
    int body;
    Vec2 v;
    float w;
    Vec2 center;
    Transform xf;
};

struct WorldState;

/// Resolves the impacts among this step's active contacts (closed_form
/// impact model only; nothing otherwise).
void resolveImpacts(WorldState& w, float dt);

}  // namespace i2d::detail
