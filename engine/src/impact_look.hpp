// The narrowphase's look at a contact for the impact stage (lookAtImpacts),
// inline: the narrowphase takes it for every contact it updates, right after
// the manifold (contact.cpp), and the impact stage asks it again
// (impact_stage.cpp).
#pragma once

#include <algorithm>

#include "world_state.hpp"

namespace i2d::detail {

/// The shock pass strikes until no contact it looks at approaches faster
/// than this fraction of the impact threshold: what it leaves to the solver
/// is a residual the sweeps' order made, not symmetric (two supports struck
/// in turn leave the body turning towards the last).
constexpr float kShockResidual = 0.01f;
/// A contact between moving bodies whose masses differ by this factor or
/// more has its closing stopped by the shock pass in every step, not only
/// after an impact (lookAtImpacts): one sweep of the solver moves the
/// heavy body by a part of its impulse as small as the ratio's inverse.
constexpr float kShockMassRatio = 10.0f;

/// The body's free acceleration for the impact stage's timing (gravity and
/// applied force), zero if it does not move.
inline Vec2 freeAcceleration(const Body& b, bool moves, Vec2 gravity) {
    return moves ? b.gravityScale * gravity + b.invMass * b.force : Vec2{};
}

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

inline ImpactLook lookAtImpacts(const WorldState& w, const Contact& ct, bool touching) {
    if (!touching || ct.isSensor || ct.manifold.pointCount == 0 || ct.overlapFromStart) return {true, false};
    const Body& a = w.bodies[ct.bodyA];
    const Body& b = w.bodies[ct.bodyB];
    const float threshold = w.settings.impactThreshold;
    // Two moving bodies, one at least kShockMassRatio times the other's mass.
    const bool heavy = a.type == BodyType::dynamic_body && b.type == BodyType::dynamic_body && a.awake && b.awake &&
                       a.invMass > 0.0f && b.invMass > 0.0f &&
                       std::max(a.invMass, b.invMass) >= kShockMassRatio * std::min(a.invMass, b.invMass);
    const float closing = heavy ? kShockResidual * threshold : threshold;
    // The threshold holds for the approach at the moment of impact. A point
    // with a gap meets within the step along the bodies' free flight, up to
    // their relative acceleration along the normal over half a substep
    // (semi-implicit Euler's lag, impact_stage.cpp) and the whole step faster
    // than the step's start; found only for such a point that approaches but
    // not yet faster than the threshold.
    auto moves = [](const Body& x) { return x.type == BodyType::dynamic_body && x.awake; };
    const Vec2 g = w.settings.gravity;
    auto halfSubstep = [&] { return 0.5f * w.stepDt / static_cast<float>(solverSubsteps(w.settings)); };
    float flight = NAN;
    auto flightGain = [&] {
        const float an = dot(freeAcceleration(b, moves(b), g) - freeAcceleration(a, moves(a), g), ct.manifold.normal);
        return an * halfSubstep() + std::min(an, 0.0f) * w.stepDt;
    };
    // The lagging velocities the impact stage reads (laggingVelocity).
    Vec2 va = a.v, vb = b.v;
    float wa = a.w, wb = b.w;
    if (a.splitKick || b.splitKick) {
        const float hs = halfSubstep();
        va = laggingVelocity(a, freeAcceleration(a, moves(a), g), hs);
        vb = laggingVelocity(b, freeAcceleration(b, moves(b), g), hs);
        if (a.splitKick && moves(a)) wa -= hs * a.invInertia * a.torque;
        if (b.splitKick && moves(b)) wb -= hs * b.invInertia * b.torque;
    }
    ImpactLook look{true, false};
    for (int j = 0; j < ct.manifold.pointCount; ++j) {
        const ManifoldPoint& mp = ct.manifold.points[j];
        const Vec2 dv = (vb + cross(wb, mp.point - b.center)) - (va + cross(wa, mp.point - a.center));
        const float vn = dot(dv, ct.manifold.normal);
        if (vn < -closing) look.heavyOnLight = heavy;
        if (vn < -threshold) {
            look.passOver = false;
        } else if (mp.separation > 0.0f && vn < 0.0f) {
            if (std::isnan(flight)) flight = flightGain();
            if (vn + flight < -threshold) look.passOver = false;
        }
    }
    return look;  // (NaN compares false: passed over, as the full test would)
}

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
inline bool passesOverImpacts(const WorldState& w, const Contact& ct, bool touching) {
    return lookAtImpacts(w, ct, touching).passOver;
}

}  // namespace i2d::detail
