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
    if (w.appliedLoads.empty() && w.forcedBodies.empty()) return;
    auto current = [&](int b, std::uint32_t generation) -> const Body* {
        if (b < 0 || b >= w.bodies.capacity()) return nullptr;
        const Body& body = w.bodies[b];
        return body.alive && body.generation == generation && body.type == BodyType::dynamic_body ? &body : nullptr;
    };
    std::vector<LostLoad>& lost = w.removedForceScratch;
    lost.clear();
    for (const AppliedLoad& a : w.appliedLoads) {
        const Body* body = current(a.body, a.generation);
        if (body == nullptr) continue;
        // (A body that fell asleep at the end of the last step had its force
        // cleared: the whole of it is gone.)
        const Vec2 gone = h * (a.force - body->force);
        if (gone.x != 0.0f || gone.y != 0.0f) addLoss(w, lost, a.body, gone, 0);
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
