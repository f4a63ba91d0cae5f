// Loads a destroyed contact or joint takes away from the warm starts of the
// contacts and joints that carried it.
//
// A contact or joint keeps the impulse of its last step as the warm start of
// the next, re-applied in every substep. When the game destroys one that
// carried a load (a body or shape destroyed, a body disabled, a filter or a
// body type changed, a joint destroyed), the contacts and joints below it
// keep impulses found for that load; warm-started with them, their bodies
// jump: two circles left under a destroyed one 100 times as heavy rose at up
// to 0.94 m/s (Box2D v3's Warm Start Energy sample), a chain of ten links
// whose end 1,000 times as heavy was destroyed at 36 m/s. The load is taken
// out along its path instead (releaseLostLoads). Clearing every warm start
// the path reaches was measured first: the rest of a pile sagged without its
// loads and pushed back, a 40-row pyramid whose top box was destroyed
// jumping at 0.88 m/s.
//
// A force the game stops applying is a lost load the same way, and so is
// weight a change of gravity takes away: the contacts and joints that held a
// body against it keep impulses found for it. A column of five 1 kg boxes
// whose top the game pressed down with 1 kN for half a second was thrown up
// at 1.2 m/s when let go; a column of 20 whose gravity was turned off, at
// 0.6 m/s (releaseRemovedForces).
#pragma once

#include <cstdint>
#include <vector>

#include "impulse2d/math.hpp"

namespace i2d::detail {

struct WorldState;
struct Contact;
struct Joint;

/// A load a destroyed contact or joint no longer puts on a body: the
/// impulse it gave the body in each substep of its last step (N·s).
struct LostLoad {
    int body;
    Vec2 impulse;
};

/// Adds the loads contact `ct`, about to be destroyed, took off its movable
/// bodies (none unless it touched and pushed). The list is released (and
/// WorldState::lostLoadPlace reset) by releaseLostLoads, called next.
void addContactLoss(WorldState& w, const Contact& ct, std::vector<LostLoad>& lost);

/// The same for joint `jt` (its point impulse: revolute, weld and motor
/// joints; the others carry their loads along axes not followed here).
void addJointLoss(WorldState& w, const Joint& jt, std::vector<LostLoad>& lost);

/// Takes the lost loads out of the warm starts of the contacts and joints
/// that carried them, body by body down the load path. A body's contacts
/// and joints that held it against a lost load L (the part of their impulse
/// on it along −L, s_i) together carry |L| less, each its share: a contact's
/// impulse (normal and friction) is scaled by 1 − r, a joint's loses r·s_i
/// along −L, with r = min(1, |L| / Σ s_i). What each no longer gives the body
/// at its other end is that body's lost load in turn; a static or kinematic
/// body ends the path, and so does a body whose supports the load is less
/// than 5 % of (r < 0.05: their warm start is nearly right). Each body is
/// visited once, in the order its first lost load reached it (a load
/// reaching it later, round a loop of contacts, is left).
void releaseLostLoads(WorldState& w, std::vector<LostLoad>& lost);

/// A force the game applied to a body in the last step, for the next step
/// to compare with its own.
struct AppliedLoad {
    int body;
    std::uint32_t generation;  ///< the body's, so that a slot reused since is not taken for it
    Vec2 force;
};

/// A body whose gravity scale the game changed since the last step, with the
/// scale it had then (World::setGravityScale lists it).
struct RescaledBody {
    int body;
    std::uint32_t generation;
    float scale;
};

/// At the start of a step whose substep is h, once the warm starts are
/// scaled to it (warm_start.hpp): what each body's applied force gave it in
/// a substep and no longer gives it in this one (of h·F_last, the part along
/// it that h·F does not give) is released down its load path as a lost load
/// (releaseLostLoads); then this step's forces are kept for the next. The
/// same for gravity: when the world's gravity or a body's gravity scale
/// changed, the part of its last weight m·s_last·g_last·h that each body no
/// longer has. Torques are not followed (a lost load is a force on a body).
/// A world whose game changes none of these pays nothing:
/// the bodies given a force or a new gravity scale are listed as the game
/// gives them (WorldState::forcedBodies, rescaledBodies).
void releaseRemovedForces(WorldState& w, float h);

}  // namespace i2d::detail
