// Loads a destroyed contact or joint takes away (lost_load.hpp says why).
#include "lost_load.hpp"

#include <algorithm>
#include <cstddef>

#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// The share of a body's support (r below) under which a lost load is left.
constexpr float kNegligibleShare = 0.05f;

bool movable(const WorldState& w, int b) { return w.bodies[b].type == BodyType::dynamic_body; }

/// Whether the joint's point impulse (JointImpulses::linear, on B, world) is
/// the load it carries between its bodies.
bool carriesPointLoad(const Joint& jt) {
    return jt.type == JointType::revolute || jt.type == JointType::weld || jt.type == JointType::motor;
}

/// Adds `impulse` to body b's lost load; a load that reaches a body already
/// visited (placed before `visited`) is left. WorldState::lostLoadPlace finds
/// a body's place (a search of the list made a load spreading down a pile
/// of n bodies cost n²).
void addLoss(WorldState& w, std::vector<LostLoad>& lost, int b, Vec2 impulse, std::size_t visited) {
    std::vector<int>& place = w.lostLoadPlace;
    if (place.size() < static_cast<std::size_t>(w.bodies.capacity()))
        place.resize(static_cast<std::size_t>(w.bodies.capacity()), -1);
    int& at = place[static_cast<std::size_t>(b)];
    // (A place left by a walk that never ended names another list.)
    if (at >= 0 && !(static_cast<std::size_t>(at) < lost.size() && lost[static_cast<std::size_t>(at)].body == b))
        at = -1;
    if (at < 0) {
        at = static_cast<int>(lost.size());
        lost.push_back({b, impulse});
    } else if (static_cast<std::size_t>(at) >= visited) {
        lost[static_cast<std::size_t>(at)].impulse += impulse;
    }
}

/// What of a load `last` (an impulse a substep) is gone when the body has
/// `now` instead: the part of `last` along its own direction that `now` no
/// longer gives (all of it when `now` is zero or turned away, none when `now`
/// is as large along it). What `now` adds, along `last` or across it, is a new
/// load the solver finds, not one to take out of the warm starts: taken as
/// a lost load the other way, it took the load off the contacts above a
/// body as if they had held it against the new force.
Vec2 removedPart(Vec2 last, Vec2 now) {
    const float size2 = dot(last, last);
    if (!(size2 > 0.0f)) return {};
    const float kept = std::clamp(dot(now, last) / size2, 0.0f, 1.0f);
    return (1.0f - kept) * last;
}

}  // namespace

void addContactLoss(WorldState& w, const Contact& ct, std::vector<LostLoad>& lost) {
    const float impulse = ct.normalImpulse[0] + ct.normalImpulse[1];
    if (!ct.touching || ct.isSensor || !(impulse > 0.0f)) return;
    // The normal points from A to B: the contact pushed B along it.
    if (movable(w, ct.bodyB)) addLoss(w, lost, ct.bodyB, impulse * ct.manifold.normal, 0);
    if (movable(w, ct.bodyA)) addLoss(w, lost, ct.bodyA, -impulse * ct.manifold.normal, 0);
}

void addJointLoss(WorldState& w, const Joint& jt, std::vector<LostLoad>& lost) {
    if (!carriesPointLoad(jt)) return;
    const Vec2 p = jt.impulses.linear;
    if (p.x == 0.0f && p.y == 0.0f) return;
    if (movable(w, jt.bodyB)) addLoss(w, lost, jt.bodyB, p, 0);
    if (movable(w, jt.bodyA)) addLoss(w, lost, jt.bodyA, -p, 0);
}

void releaseLostLoads(WorldState& w, std::vector<LostLoad>& lost) {
    // The places go back to −1 however the walk ends.
    struct ClearPlaces {
        WorldState& w;
        const std::vector<LostLoad>& lost;
        ~ClearPlaces() {
            for (const LostLoad& l : lost) w.lostLoadPlace[static_cast<std::size_t>(l.body)] = -1;
        }
    } clear{w, lost};
    for (std::size_t k = 0; k < lost.size(); ++k) {
        const int b = lost[k].body;
        const Vec2 load = lost[k].impulse;
        const float size = length(load);
        if (!(size > 0.0f)) continue;
        const Vec2 against = (-1.0f / size) * load;
        // The push of a contact or joint on b.
        auto pushOn = [&](const Contact& ct) { return ct.bodyB == b ? ct.manifold.normal : -ct.manifold.normal; };
        auto jointOn = [&](const Joint& jt) { return jt.bodyB == b ? jt.impulses.linear : -jt.impulses.linear; };
        float held = 0.0f;  // Σ s_i
        for (int c : w.bodies[b].contacts) {
            const Contact& ct = w.contacts[c];
            if (!ct.touching || ct.isSensor) continue;
            const float along = dot(pushOn(ct), against);
            if (along > 0.0f) held += (ct.normalImpulse[0] + ct.normalImpulse[1]) * along;
        }
        for (int j : bodyJoints(w.joints, w.bodies[b], b)) {
            const Joint& jt = w.joints[j];
            if (carriesPointLoad(jt)) held += std::max(dot(jointOn(jt), against), 0.0f);
        }
        if (!(held > 0.0f)) continue;
        const float r = std::min(1.0f, size / held);
        // A load small beside what the body's supports carry leaves their
        // warm start nearly right: the walk stops there. Spread down a pile,
        // a box's weight soon is (the walk from a destroyed box of a
        // 5,050-box pyramid reached most of it, 37 µs a box).
        if (r < kNegligibleShare) continue;
        // What a contact or joint gives up on b (ΔJ on b) is what the body at
        // its other end no longer gets: that body's lost load.
        for (int c : w.bodies[b].contacts) {
            Contact& ct = w.contacts[c];
            if (!ct.touching || ct.isSensor) continue;
            const Vec2 push = pushOn(ct);
            if (!(dot(push, against) > 0.0f)) continue;
            const float taken = r * (ct.normalImpulse[0] + ct.normalImpulse[1]);
            if (taken > 0.0f) {
                if (w.unloadedAt.size() < static_cast<std::size_t>(w.contacts.capacity()))
                    w.unloadedAt.resize(static_cast<std::size_t>(w.contacts.capacity()), 0);
                w.unloadedAt[static_cast<std::size_t>(c)] = w.lastUnloadedAt = w.stepStamp + 1;
            }
            for (int i = 0; i < 2; ++i) {
                ct.normalImpulse[i] *= 1.0f - r;
                ct.tangentImpulse[i] *= 1.0f - r;
                ct.restLoad[i] = scaledRestLoad(ct.restLoad[i], 1.0f - r);  // a built-in load goes too (rest_load.hpp)
            }
            const int other = ct.bodyA == b ? ct.bodyB : ct.bodyA;
            if (movable(w, other)) addLoss(w, lost, other, -taken * push, k + 1);
        }
        for (int j : bodyJoints(w.joints, w.bodies[b], b)) {
            Joint& jt = w.joints[j];
            if (!carriesPointLoad(jt)) continue;
            const float support = dot(jointOn(jt), against);
            if (!(support > 0.0f)) continue;
            const Vec2 change = (-r * support) * against;  // its support along −L, less
            jt.impulses.linear += jt.bodyB == b ? change : -change;
            const int other = jt.bodyA == b ? jt.bodyB : jt.bodyA;
            if (movable(w, other)) addLoss(w, lost, other, change, k + 1);
        }
    }
}

void releaseRemovedForces(WorldState& w, float h) {
    const Vec2 g = w.settings.gravity;
    // The gravity the last step's warm starts carried (none before the first step).
    const bool stepped = w.gravityStepped;
    const Vec2 gLast = stepped ? w.lastGravity : g;
    w.lastGravity = g;
    w.gravityStepped = true;
    const bool gravityChanged = gLast.x != g.x || gLast.y != g.y;
    if (w.appliedLoads.empty() && w.forcedBodies.empty() && w.rescaledBodies.empty() && !gravityChanged) return;
    auto current = [&](int b, std::uint32_t generation) -> const Body* {
        if (b < 0 || b >= w.bodies.capacity()) return nullptr;
        const Body& body = w.bodies[b];
        return body.alive && body.generation == generation && body.type == BodyType::dynamic_body ? &body : nullptr;
    };
    std::vector<LostLoad>& lost = w.removedForceScratch;
    lost.clear();
    // Gravity: of the weight m·s_last·g_last a substep, what m·s·g no longer
    // gives (removedPart), s_last the body's gravity
    // scale in the last step (WorldState::rescaledBodies keeps the first
    // scale a body had before the game changed it). Every dynamic body when
    // the world's gravity changed, asleep or not (a sleeping pile's warm
    // starts act when it wakes); the rescaled bodies otherwise.
    std::stable_sort(w.rescaledBodies.begin(), w.rescaledBodies.end(),
                     [](const RescaledBody& x, const RescaledBody& y) { return x.body < y.body; });
    w.rescaledBodies.erase(std::unique(w.rescaledBodies.begin(), w.rescaledBodies.end(),
                                       [](const RescaledBody& x, const RescaledBody& y) { return x.body == y.body; }),
                           w.rescaledBodies.end());
    auto gravityGone = [&](const Body& body, float scaleLast) {
        return removedPart((body.mass * h * scaleLast) * gLast, (body.mass * h * body.gravityScale) * g);
    };
    if (gravityChanged) {
        std::size_t next = 0;  // the rescaled bodies, in slot order as the loop
        for (int b = 0; b < w.bodies.capacity(); ++b) {
            const Body& body = w.bodies[b];
            if (!body.alive || body.type != BodyType::dynamic_body) continue;
            while (next < w.rescaledBodies.size() && w.rescaledBodies[next].body < b) ++next;
            const bool rescaled = next < w.rescaledBodies.size() && w.rescaledBodies[next].body == b &&
                                  w.rescaledBodies[next].generation == body.generation;
            const Vec2 gone = gravityGone(body, rescaled ? w.rescaledBodies[next].scale : body.gravityScale);
            if (gone.x != 0.0f || gone.y != 0.0f) addLoss(w, lost, b, gone, 0);
        }
    } else {
        for (const RescaledBody& r : w.rescaledBodies)
            if (const Body* body = current(r.body, r.generation)) {
                const Vec2 gone = gravityGone(*body, r.scale);
                if (gone.x != 0.0f || gone.y != 0.0f) addLoss(w, lost, r.body, gone, 0);
            }
    }
    w.rescaledBodies.clear();
    for (const AppliedLoad& a : w.appliedLoads) {
        const Body* body = current(a.body, a.generation);
        if (body == nullptr) continue;
        // (A body that fell asleep at the end of the last step had its force
        // cleared: the whole of it is gone.)
        const Vec2 gone = removedPart(h * a.force, h * body->force);
        if (gone.x != 0.0f || gone.y != 0.0f) addLoss(w, lost, a.body, gone, 0);
    }
    // Released from the top down (along the last step's gravity): a load
    // reaching a body whose own was released before it is left (releaseLostLoads).
    if (lost.size() > 1) {
        const float size = length(gLast);
        const Vec2 up = size > 0.0f ? (-1.0f / size) * gLast : Vec2{0.0f, 1.0f};
        std::stable_sort(lost.begin(), lost.end(), [&](const LostLoad& x, const LostLoad& y) {
            return dot(w.bodies[x.body].center, up) > dot(w.bodies[y.body].center, up);
        });
        for (std::size_t k = 0; k < lost.size(); ++k)
            w.lostLoadPlace[static_cast<std::size_t>(lost[k].body)] = static_cast<int>(k);
    }
    if (!lost.empty()) releaseLostLoads(w, lost);
    // This step's forces, for the next. A body is listed again when its force
    // went back to zero and was given another: kept once.
    w.appliedLoads.clear();
    std::sort(w.forcedBodies.begin(), w.forcedBodies.end());
    w.forcedBodies.erase(std::unique(w.forcedBodies.begin(), w.forcedBodies.end()), w.forcedBodies.end());
    for (const int b : w.forcedBodies) {
        const Body& body = w.bodies[b];
        if (current(b, body.generation) == nullptr || (body.force.x == 0.0f && body.force.y == 0.0f)) continue;
        w.appliedLoads.push_back({b, body.generation, body.force});
    }
    w.forcedBodies.clear();
}

}  // namespace i2d::detail
