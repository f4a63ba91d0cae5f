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
//  * A speculative contact (gap s > 0 at the step's start) hits at time
//    t* = s/|v_n| into the step. The bodies are moved by t*(v_before − v_after)
//    so that integrating the new velocities over the step places them where
//    flight until t* and rebound after it would.
#include <algorithm>
#include <cmath>

#include "impact_stage.hpp"
#include "impulse2d/impact.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {
constexpr int kMaxSweeps = 8;
}

void resolveImpacts(WorldState& w, float dt) {
    const WorldSettings& settings = w.settings;
    if (settings.impactModel != ImpactModel::closed_form) return;
    const float threshold = settings.impactThreshold;

    std::uint32_t sweepStamp = 0;
    // changed[b] == the sweep in which body b's velocity last changed.
    std::vector<std::uint32_t>& changed = w.impactChanged;
    changed.assign(static_cast<std::size_t>(w.bodies.capacity()), 0u);

    for (int sweep = 1; sweep <= kMaxSweeps; ++sweep) {
        bool any = false;
        sweepStamp = static_cast<std::uint32_t>(sweep);
        for (int c : w.activeContacts) {
            Contact& ct = w.contacts[c];
            if (!ct.touching || ct.isSensor || ct.manifold.pointCount == 0) continue;
            Body& A = w.bodies[ct.bodyA];
            Body& B = w.bodies[ct.bodyB];
            if (A.type != BodyType::dynamic_body && B.type != BodyType::dynamic_body) continue;
            if (!A.awake && !B.awake) continue;
            if (sweep > 1 && changed[static_cast<std::size_t>(ct.bodyA)] != sweepStamp - 1 &&
                changed[static_cast<std::size_t>(ct.bodyB)] != sweepStamp - 1)
                continue;
            const Vec2 n = ct.manifold.normal;  // from A to B
            Vec2 point{};
            float gap = 0.0f, approach = 0.0f;
            int count = 0;
            for (int j = 0; j < ct.manifold.pointCount; ++j) {
                const ManifoldPoint& mp = ct.manifold.points[j];
                Vec2 dv = (B.v + cross(B.w, mp.point - B.center)) - (A.v + cross(A.w, mp.point - A.center));
                float vn = dot(dv, n);
                if (vn < -threshold && mp.separation + vn * dt < 0.0f) {
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

            // The law's convention: f points from B to A and A receives +p.
            // Our manifold normal points from A to B, so A of the law is our B.
            const bool aMoves = A.type == BodyType::dynamic_body && A.awake;
            const bool bMoves = B.type == BodyType::dynamic_body && B.awake;
            ImpactInput in;
            in.restitution = ct.restitution;
            in.friction = ct.friction;
            in.normal = {n.x, n.y};
            Vec2 rB = point - B.center, rA = point - A.center;
            in.a = {bMoves ? B.invMass : 0.0, bMoves ? B.invInertia : 0.0, {rB.x, rB.y}, {B.v.x, B.v.y}, B.w};
            in.b = {aMoves ? A.invMass : 0.0, aMoves ? A.invInertia : 0.0, {rA.x, rA.y}, {A.v.x, A.v.y}, A.w};
            ImpactResult r;
            try {
                r = resolveImpact(in);
            } catch (const Error&) {
                continue;  // e.g. two immovable bodies: nothing to resolve
            }
            if (r.kind == ImpactCase::not_colliding) continue;

            const Vec2 vB0 = B.v, vA0 = A.v;
            const float wB0 = B.w, wA0 = A.w;
            if (bMoves) {
                B.v = {static_cast<float>(r.vA.x), static_cast<float>(r.vA.y)};
                B.w = static_cast<float>(r.wA);
            }
            if (aMoves) {
                A.v = {static_cast<float>(r.vB.x), static_cast<float>(r.vB.y)};
                A.w = static_cast<float>(r.wB);
            }
            // Time of impact within the step for a speculative contact.
            float tHit = approach < 0.0f ? std::min(gap / -approach, dt) : 0.0f;
            if (tHit > 0.0f) {
                if (bMoves) {
                    keepStepStart(B, w.stepStamp);
                    B.center += tHit * (vB0 - B.v);
                    B.xf.q = integrateRotation(B.xf.q, tHit * (wB0 - B.w));
                    B.xf.p = B.center - rotate(B.xf.q, B.localCenter);
                }
                if (aMoves) {
                    keepStepStart(A, w.stepStamp);
                    A.center += tHit * (vA0 - A.v);
                    A.xf.q = integrateRotation(A.xf.q, tHit * (wA0 - A.w));
                    A.xf.p = A.center - rotate(A.xf.q, A.localCenter);
                }
            }
            // The solver must not undo the bounce with stale warm-start impulses.
            ct.normalImpulse[0] = ct.normalImpulse[1] = 0.0f;
            ct.tangentImpulse[0] = ct.tangentImpulse[1] = 0.0f;
            // The manifold keeps its start-of-step gap on purpose: the shift
            // above puts the bodies where the exact flight-and-rebound would be
            // at the step's end, and an updated (now negative) separation would
            // make the solver push them apart and add energy.
            changed[static_cast<std::size_t>(ct.bodyA)] = sweepStamp;
            changed[static_cast<std::size_t>(ct.bodyB)] = sweepStamp;
            any = true;
        }
        if (!any) break;
    }
}

}  // namespace i2d::detail
