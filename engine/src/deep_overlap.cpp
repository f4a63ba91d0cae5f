// Deep overlaps in the soft step, pushed apart without adding kinetic energy.
//
// The soft step pushes an overlap apart through the velocity: the soft row's
// bias adds up to maxPushSpeed to the bodies' velocities and the relax pass
// takes it out again, but only as far as the row's accumulated impulse
// allows and only while the contact is still active. A pile of bodies
// created at one point defeats that: each body is pushed by many contacts
// whose pushes add (along different normals, through chains of bodies), the
// contacts that part are relaxed no more, and what the relax cannot take
// back stays as velocity. 50 boxes created at one point in the air threw
// one 3.8 m up (9.4 m/s) with the pushes shared (a body's n deep contacts
// getting the cap over n each, which made separation take 8-12 s), and 50
// capsules 23 m up (21 m/s).
//
// A deep contact's push is therefore solved on pseudo-velocities, as in the
// single-frame push factor (split impulses) of Tamis and Maggiore (2015),
// Constraint based physics solver, §8.1: within each substep the push moves
// the positions and is then dropped, so no push velocity is ever left in a
// body. The velocity rows of a deep contact are rigid: they keep the bodies
// from approaching and carry the load (contact_solver.cpp). Each point asks
// for a separating pseudo-speed of biasRate·d (d its depth: the soft row's
// own push, so the push is continuous where a contact becomes shallow) less
// the push its load needs (loadPush: the push at which a soft row would hold
// the point's accumulated impulse), up to maxPushSpeed. A contact sunk deep
// under a heavy load is thus held where a soft row would hold it, not pushed
// out: pushed by its full depth, the contact under a box 100 times heavier
// than the 5-box stack below it (7 cm deep) went out of and back into the
// deep regime every few steps, and the stack rocked 13 cm; at 150:1 it fell.
// Every body's pseudo-velocity is limited afterwards (below): pushes that add
// along a chain of bodies move none faster than the limit, whatever the
// number of its contacts. Box2D 2.4.1 moves positions directly in its
// position iterations (nonlinear Gauss-Seidel,
// b2ContactSolver::SolvePositionConstraints), to the same end, without a
// limit per body.
#include <algorithm>
#include <cmath>

#include "deep_overlap.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

// Gauss-Seidel sweeps of the push per substep. The push must travel through
// a pile: with one sweep 50 boxes created at one point and dropped from 10 m
// were still 0.22 m deep 2 s later, with four 3.5 cm, with eight no better
// (1.6 and 4.7 cm for two seeds). The sweeps run only in steps with a deep
// overlap.
constexpr int kPushSweeps = 4;

}  // namespace

void pushDeepOverlaps(WorldState& w) {
    SolverArrays& s = w.solver;
    const float cap = w.settings.maxPushSpeed;
    s.biasV.assign(s.states.size(), Vec2{});
    s.biasW.assign(s.states.size(), 0.0f);
    for (ContactConstraint& cc : s.constraints)
        for (int j = 0; j < cc.pointCount; ++j) cc.points[j].biasImpulse = 0.0f;
    const BodyState* states = s.states.data();
    for (int sweep = 0; sweep < kPushSweeps; ++sweep) {
        for (ContactConstraint& cc : s.constraints) {
            if (!cc.deepOverlap) continue;
            const BodyState& sA = states[cc.a];
            const BodyState& sB = states[cc.b];
            Vec2& vA = s.biasV[static_cast<std::size_t>(cc.a)];
            float& wA = s.biasW[static_cast<std::size_t>(cc.a)];
            Vec2& vB = s.biasV[static_cast<std::size_t>(cc.b)];
            float& wB = s.biasW[static_cast<std::size_t>(cc.b)];
            const Rot qA = cc.roundA ? Rot{} : sA.dq, qB = cc.roundB ? Rot{} : sB.dq;
            const Vec2 n = cc.normal;
            const Vec2 dp = sB.dp - sA.dp;
            for (int j = 0; j < cc.pointCount; ++j) {
                ContactPointConstraint& cp = cc.points[j];
                // The current separation, as the velocity rows read it, and the
                // separating pseudo-speed asked for beyond what the load
                // explains (none once it is closed).
                const float sep = dot(dp + (rotate(qB, cp.rB) - rotate(qA, cp.rA)), n) + cp.adjustedSeparation;
                const float target = std::max(std::min(-cc.biasRate * sep - loadPush(cc, cp), cap), 0.0f);
                const Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
                // Projected Gauss-Seidel on the accumulated push impulse (≥ 0).
                const float accumulated = std::max(cp.biasImpulse - cp.normalMass * (dot(dv, n) - target), 0.0f);
                const float impulse = accumulated - cp.biasImpulse;
                cp.biasImpulse = accumulated;
                const Vec2 P = impulse * n;
                vA = mulSub(vA, cc.invMassA, P);
                wA -= cc.invIA * cross(cp.rA, P);
                vB = mulAdd(vB, cc.invMassB, P);
                wB += cc.invIB * cross(cp.rB, P);
            }
        }
    }
    // Each body's pseudo-velocity: at most maxPushSpeed c, and against its
    // free acceleration (up, under gravity) at most c less its speed along
    // that acceleration, and never less than c/2. A body at rest may be
    // pushed up at c (out of the ground under a stack of four boxes:
    // stack5_overlap, apart in 1.8 s; at c/2 it took 2.2 s). A body of a
    // falling pile pushed up at u while it falls at g·t gains g·u·t of
    // energy per unit mass; its speed stays within what a free fall from its
    // height allows plus c at every moment iff u ≤ c/2 (at g·t = 2u its
    // height is back where it started and it falls at 2u): at c, piles of 50
    // bodies created at one point were up to 2.9 m/s faster than that.
    const std::size_t n = s.stateBodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        Vec2& v = s.biasV[i];
        const Vec2 a = s.integration[i].linearAcceleration;
        const float g = length(a);
        if (g > 0.0f) {
            const Vec2 up = (-1.0f / g) * a;
            const float falling = std::max(-dot(s.states[i].v, up), 0.0f);
            const float limit = cap - std::min(falling, 0.5f * cap);
            const float u = dot(v, up);
            if (u > limit) v -= (u - limit) * up;
        }
        const float speed = length(v);
        if (speed > cap) v *= cap / speed;
        // Moved by the push, the body is not resting (its velocity says
        // nothing of it: a box created inside the ground slept there).
        if (speed > w.settings.linearSleepTolerance) w.bodies[s.stateBodies[i]].sleepTime = 0.0f;
    }
}

}  // namespace i2d::detail
