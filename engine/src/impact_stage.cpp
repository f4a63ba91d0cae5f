// The impact stage of a step: contacts that close with a real approach speed
// are resolved by the closed-form impact law (impact_law.cpp; Baber (2011),
// A Correction To Brian Mirtich's Thesis "Impulse-based Dynamic Simulation
// of Rigid Body Systems", §5) before the iterative solver runs, which then
// only sees what remains (resting contact, joints) and adds no restitution of
// its own.
//
// Strategy (see docs/impacts.md):
//  * A manifold's impact point is the mean of its points that approach faster
//    than impactThreshold and would close their gap within this step; a box
//    landing flat is thus struck at its centre line, not corner by corner.
//  * Contacts are swept in slot order, Gauss-Seidel fashion, each resolved with
//    the current velocities; sweeps repeat while some contact still
//    approaches, up to kMaxSweeps. A later sweep only revisits contacts whose
//    bodies changed in the previous sweep. Each application is the exact
//    law for that pair and never adds kinetic energy, so neither does any
//    sequence of them; a chain of touching bodies (Newton's cradle) passes
//    momentum along within one sweep.
//  * A speculative contact (gap s > 0 at the step's start) hits at time t*
//    into the step. The law acts on the velocities the bodies really have at
//    t*, and the bodies are given the velocities and start positions with
//    which the solver's integration of the step ends where flight until t*
//    and rebound after it would (below, "Timing within the step").
#include <algorithm>
#include <cmath>

#include "impact_stage.hpp"
#include "impulse2d/impact.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {
constexpr int kMaxSweeps = 8;

// Timing within the step. The solver integrates by semi-implicit Euler over
// N substeps of h = Δt/N: v_k = v_(k−1) + a·h, x_k = x_(k−1) + h·v_k, with a
// a body's free acceleration (gravity, force). From a stored velocity v the
// positions then follow exactly the parabola x(t) = x0 + (v + a·h/2)·t +
// a·t²/2: the stored velocity is half a substep of acceleration away from the
// velocity the body really has, v_true = v + a·h/2 (the staggering of the
// symplectic Euler method; Hairer, Lubich and Wanner (2003), Geometric
// numerical integration illustrated by the Störmer–Verlet method, §1.2). The
// law is applied to the true velocities at the moment of impact t*,
//   v(t*) = v + a·(h/2 + t*),
// and gives true velocities v⁺ at t*. Storing
//   v_new = v⁺ − a·(t* + h/2)
// and moving the start of the step by
//   δ = t*·(v(t*) − v⁺)
// makes the solver's N substeps end at the exact position and (staggered)
// velocity of flight until t* and rebound after it (expand both and the terms
// in a·Δt², a·h·Δt cancel). Without the staggering, every rebound was launched
// a·h/2 too slow and the flight after it lost u·h/2 of apex height (u the
// rebound speed): −6.5 % at the third bounce of a ball with e = 0.5 dropped
// from 5 m, −61 % at the fourth. Rotation has no free acceleration here: its
// start is moved by t*·(ω before − ω after) as before.

/// The body's free acceleration for the timing, zero if it does not move.
Vec2 freeAcceleration(const Body& b, bool moves, Vec2 gravity) {
    return moves ? b.gravityScale * gravity + b.invMass * b.force : Vec2{};
}

/// The first time t in [0, dt] at which a gap s closing at speed vn < 0 with
/// acceleration an (along the normal) reaches zero: s + vn·t + an·t²/2 = 0;
/// dt if it does not close within the step.
float closingTime(float s, float vn, float an, float dt) {
    if (s <= 0.0f) return 0.0f;
    if (std::abs(an) < 1e-6f) return vn < 0.0f ? std::min(s / -vn, dt) : dt;
    const float disc = vn * vn - 2.0f * an * s;
    if (disc < 0.0f) return dt;
    // The smaller positive root, in the form that keeps precision for small an.
    const float t = 2.0f * s / (-vn + std::sqrt(disc));
    return t > 0.0f ? std::min(t, dt) : dt;
}

}  // namespace

bool passesOverImpacts(const WorldState& w, const Contact& ct, bool touching) {
    if (!touching || ct.isSensor || ct.manifold.pointCount == 0) return true;
    const Body& a = w.bodies[ct.bodyA];
    const Body& b = w.bodies[ct.bodyB];
    const float threshold = w.settings.impactThreshold;
    for (int j = 0; j < ct.manifold.pointCount; ++j) {
        const Vec2 p = ct.manifold.points[j].point;
        const Vec2 dv = (b.v + cross(b.w, p - b.center)) - (a.v + cross(a.w, p - a.center));
        if (dot(dv, ct.manifold.normal) < -threshold) return false;
    }
    return true;  // (NaN compares false: passed over, as the full test would)
}

void resolveImpacts(WorldState& w, float dt) {
    // changed[b] == the sweep in which body b's velocity last changed (0:
    // none this step). hitTime[c] == when contact c was struck in this step,
    // −1 while it was not; bodyTime[b] the same for body b's first impact.
    // Kept between steps and only grown: the entries the last stage wrote
    // (its struck bodies and contacts) go back to their defaults here, so a
    // step pays for what was struck, not for every slot (filled anew every
    // step, they charged 10,000 idle bodies to the 100 awake beside them).
    std::vector<std::uint32_t>& changed = w.impactChanged;
    std::vector<float>& hitTime = w.impactTime;
    std::vector<float>& bodyTime = w.impactBodyTime;
    for (int b : w.impactStruckBodies) {
        changed[static_cast<std::size_t>(b)] = 0u;
        bodyTime[static_cast<std::size_t>(b)] = -1.0f;
    }
    for (int c : w.impactStruckContacts) hitTime[static_cast<std::size_t>(c)] = -1.0f;
    w.impactStruckBodies.clear();
    w.impactStruckContacts.clear();
    const auto bodySlots = static_cast<std::size_t>(w.bodies.capacity());
    const auto contactSlots = static_cast<std::size_t>(w.contacts.capacity());
    if (changed.size() < bodySlots) changed.resize(bodySlots, 0u);
    if (bodyTime.size() < bodySlots) bodyTime.resize(bodySlots, -1.0f);
    if (hitTime.size() < contactSlots) hitTime.resize(contactSlots, -1.0f);

    const WorldSettings& settings = w.settings;
    if (settings.impactModel != ImpactModel::closed_form) return;
    const float threshold = settings.impactThreshold;
    const int substeps = settings.positionCorrection == PositionCorrection::soft_step ? settings.substeps : 1;
    const float halfSubstep = 0.5f * dt / static_cast<float>(substeps);

    std::uint32_t sweepStamp = 0;
    // Moves body b's start so that the step ends as flight until its first
    // impact and the changed velocity after it (timing above).
    auto shiftStart = [&](Body& body, int b, float tHit, Vec2 dv, float dw) {
        float& first = bodyTime[static_cast<std::size_t>(b)];
        if (first < 0.0f) first = tHit;
        if (first <= 0.0f) return;
        keepStepStart(body, w.stepStamp);
        w.startsShiftedAt = w.stepStamp;
        body.center += first * dv;
        body.xf.q = integrateRotation(body.xf.q, first * dw);
        body.xf.p = body.center - rotate(body.xf.q, body.localCenter);
    };

    // The first sweep's look at each contact was taken by the narrowphase
    // (passesOverImpacts), from the bodies' motion at the stage's start. That is
    // the look the sweep itself would take while neither body has been struck
    // (a strike marks both in `changed`); for a contact with a struck body the
    // sweep looks again. (Taken here, on the workers in a pass of its own, it
    // read every contact and both its bodies once more: 4 to 6 % of the step
    // of a large pile. The bodies' motion was once copied into an array by
    // body slot for it: filled every step, it made 10,000 idle bodies cost the
    // 100 awake beside them a fifth more.)
    const std::size_t activeCount = w.activeContacts.size();
    const std::vector<ContactLook>& looks = w.activeLooks;
    auto passedOver = [&](const Contact& ct) { return passesOverImpacts(w, ct, ct.touching); };
    auto stillPassedOver = [&](std::size_t i) {  // in the first sweep
        const ContactLook& l = looks[i];
        return l.passOver && changed[static_cast<std::size_t>(l.bodyA)] != 1u &&
               changed[static_cast<std::size_t>(l.bodyB)] != 1u;
    };

    for (int sweep = 1; sweep <= kMaxSweeps; ++sweep) {
        bool any = false;
        sweepStamp = static_cast<std::uint32_t>(sweep);
        for (std::size_t i = 0; i < activeCount; ++i) {
            if (sweep == 1 && stillPassedOver(i)) continue;
            // A later sweep looks only at the contacts of bodies the last one
            // struck, found from the narrowphase's look (its bodies) before the
            // contact is read: in a large pile the later sweeps read every
            // contact and both its bodies to pass over nearly all of them.
            if (sweep > 1 && changed[static_cast<std::size_t>(looks[i].bodyA)] != sweepStamp - 1 &&
                changed[static_cast<std::size_t>(looks[i].bodyB)] != sweepStamp - 1)
                continue;
            const int c = w.activeContacts[i];
            Contact& ct = w.contacts[c];
            if (passedOver(ct)) continue;
            Body& A = w.bodies[ct.bodyA];
            Body& B = w.bodies[ct.bodyB];
            if (A.type != BodyType::dynamic_body && B.type != BodyType::dynamic_body) continue;
            if (!A.awake && !B.awake) continue;
            const Vec2 n = ct.manifold.normal;  // from A to B
            const bool aMoves = A.type == BodyType::dynamic_body && A.awake;
            const bool bMoves = B.type == BodyType::dynamic_body && B.awake;
            const Vec2 accA = freeAcceleration(A, aMoves, settings.gravity);
            const Vec2 accB = freeAcceleration(B, bMoves, settings.gravity);
            const float an = dot(accB - accA, n);  // relative normal acceleration
            Vec2 point{};
            float gap = 0.0f, approach = 0.0f;
            int count = 0;
            for (int j = 0; j < ct.manifold.pointCount; ++j) {
                const ManifoldPoint& mp = ct.manifold.points[j];
                Vec2 dv = (B.v + cross(B.w, mp.point - B.center)) - (A.v + cross(A.w, mp.point - A.center));
                float vn = dot(dv, n);
                // Closes within the step along its true flight (timing above).
                const float vTrue = vn + an * halfSubstep;
                if (vn < -threshold && mp.separation + (vTrue + 0.5f * an * dt) * dt < 0.0f) {
                    point += mp.point;
                    gap += std::max(mp.separation, 0.0f);
                    approach += vn;
                    ++count;
                }
            }
            if (count == 0) continue;
            const float inv = 1.0f / static_cast<float>(count);
            point = inv * point;
            gap *= inv;
            approach *= inv;

            // Time of impact within the step and the velocities then (timing above).
            // A pair struck again in a later sweep (a body of it was struck by
            // a third meanwhile) is struck at the moment it first met: its gap
            // closed then. Timed again from the start's gap at the new, slower
            // approach, each repeat moved the pair's start positions by about
            // the gap again, into each other, where its rows (keeping the
            // start's gap) could not see it.
            float& firstHit = hitTime[static_cast<std::size_t>(c)];
            if (firstHit < 0.0f) w.impactStruckContacts.push_back(c);
            const float tHit = firstHit >= 0.0f ? firstHit : closingTime(gap, approach + an * halfSubstep, an, dt);
            firstHit = tHit;
            const Vec2 vA0 = A.v + (halfSubstep + tHit) * accA;
            const Vec2 vB0 = B.v + (halfSubstep + tHit) * accB;
            const float wB0 = B.w, wA0 = A.w;

            // The law's convention: f points from B to A and A receives +p.
            // Our manifold normal points from A to B, so A of the law is our B.
            ImpactInput in;
            in.restitution = ct.restitution;
            in.friction = ct.friction;
            in.normal = {n.x, n.y};
            Vec2 rB = point - B.center, rA = point - A.center;
            in.a = {bMoves ? B.invMass : 0.0, bMoves ? B.invInertia : 0.0, {rB.x, rB.y}, {vB0.x, vB0.y}, B.w};
            in.b = {aMoves ? A.invMass : 0.0, aMoves ? A.invInertia : 0.0, {rA.x, rA.y}, {vA0.x, vA0.y}, A.w};
            ImpactResult r;
            try {
                r = resolveImpact(in);
            } catch (const Error&) {
                continue;  // e.g. two immovable bodies: nothing to resolve
            }
            if (r.kind == ImpactCase::not_colliding) continue;

            const Vec2 vBAfter{static_cast<float>(r.vA.x), static_cast<float>(r.vA.y)};
            const Vec2 vAAfter{static_cast<float>(r.vB.x), static_cast<float>(r.vB.y)};
            if (bMoves) {
                B.v = vBAfter - (tHit + halfSubstep) * accB;
                B.w = static_cast<float>(r.wA);
            }
            if (aMoves) {
                A.v = vAAfter - (tHit + halfSubstep) * accA;
                A.w = static_cast<float>(r.wB);
            }
            // Each body's velocity changes at its first impact of the step
            // (below, "Cascades").
            if (bMoves) shiftStart(B, ct.bodyB, tHit, vB0 - vBAfter, wB0 - B.w);
            if (aMoves) shiftStart(A, ct.bodyA, tHit, vA0 - vAAfter, wA0 - A.w);
            // The solver must not undo the bounce with stale warm-start impulses.
            ct.normalImpulse[0] = ct.normalImpulse[1] = 0.0f;
            ct.tangentImpulse[0] = ct.tangentImpulse[1] = 0.0f;
            // The manifold keeps its start-of-step gap on purpose: the shift
            // above puts the bodies where the exact flight-and-rebound would be
            // at the step's end, and an updated (now negative) separation would
            // make the solver push them apart and add energy.
            for (int b : {ct.bodyA, ct.bodyB}) {
                std::uint32_t& when = changed[static_cast<std::size_t>(b)];
                if (when == 0u) w.impactStruckBodies.push_back(b);
                when = sweepStamp;
            }
            any = true;
        }
        if (!any) break;
    }
}

}  // namespace i2d::detail
