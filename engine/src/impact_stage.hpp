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
struct Contact;

/// The look at contact `ct` after its manifold update (`touching`: what the
/// update found), from the bodies' motion at the step's start: true (passed
/// over) when it is not touching, is a sensor, has no point, has overlapped
/// since its first touch (Contact::overlapFromStart), or approaches at none
/// of its points faster than the impact threshold (nothing changes the
/// bodies' velocities between the narrowphase and the impact stage). Two
/// bodies created inside each other meet at no surface point: their
/// manifold's point and normal are the overlap's, and the solver pushes it
/// apart (deep_overlap.cpp). Struck, a landing lump of capsules created at
/// one point, still overlapping 2 to 18 cm, passed the landing up through
/// the overlaps' alternating normals and threw its top capsules up at 5 to
/// 7 m/s and sideways at 9 (docs/impacts.md, "Overlaps are no impacts").
bool passesOverImpacts(const WorldState& w, const Contact& ct, bool touching);

/// The narrowphase's look at contact `ct` for the impact stage: `passOver`
/// as passesOverImpacts, and `heavyOnLight` when it joins two moving bodies
/// of which one is at least kShockMassRatio times as heavy as the other,
/// closing at a point faster than the shock pass's residual: the impact
/// stage then runs its shock pass (impact_stage.cpp), which the solver's
/// sweeps need between such bodies (each moves the heavy one by a small
/// part of its impulse). One pass over the points for both.
struct ImpactLook {
    bool passOver, heavyOnLight;
};
ImpactLook lookAtImpacts(const WorldState& w, const Contact& ct, bool touching);

/// Resolves the impacts among this step's active contacts (closed_form
/// impact model only; nothing otherwise).
void resolveImpacts(WorldState& w, float dt);

}  // namespace i2d::detail
