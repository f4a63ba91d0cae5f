// The preparation of one contact row from its contact and bodies, inline:
// every active contact passes through it each step, into a scalar row
// (contact_solver.cpp, solver.cpp) or straight into a wide lane
// (wide_contact.cpp), which then keeps the row's values in registers instead
// of a row on the stack.
#pragma once

#include <cmath>

#include "contact_persistence.hpp"
#include "contact_solver.hpp"
#include "rest_load.hpp"
#include "world_state.hpp"

namespace i2d::detail {

/// The 2×2 effective-mass matrix K of a two-point row: K11 and K22 (the
/// points' own, 1/normalMass) and K12, the coupling: how fast point 2's gap
/// closes per unit impulse at point 1.
struct PairMatrix {
    float k11, k22, k12;
};
inline PairMatrix pairMatrix(const ContactConstraint& cc) {
    const ContactPointConstraint& c1 = cc.points[0];
    const ContactPointConstraint& c2 = cc.points[1];
    const Vec2 n = cc.normal;
    const float rn1A = cross(c1.rA, n), rn1B = cross(c1.rB, n);
    const float rn2A = cross(c2.rA, n), rn2B = cross(c2.rB, n);
    const float mAB = cc.invMassA + cc.invMassB;
    return {mAB + cc.invIA * rn1A * rn1A + cc.invIB * rn1B * rn1B,
            mAB + cc.invIA * rn2A * rn2A + cc.invIB * rn2B * rn2B,
            mAB + cc.invIA * rn1A * rn2A + cc.invIB * rn1B * rn2B};
}

/// The scale of a turning row's two increments solved side by side
/// (solveTurningRow): 1/(1 + ρ) for a positive coupling ρ = K12/√(K11·K22),
/// else 1.
inline float pairScale(const ContactConstraint& cc) {
    const PairMatrix k = pairMatrix(cc);
    const float coupling = k.k11 > 0.0f && k.k22 > 0.0f ? k.k12 / std::sqrt(k.k11 * k.k22) : 0.0f;
    return coupling > 0.0f ? 1.0f / (1.0f + coupling) : 1.0f;
}

/// The block solve's denominator 1 − ρ², ρ² = K12²/(K11·K22), from the
/// points' normal masses (1/K11, 1/K22) and K12, in the operations the
/// solve repeats (solvePointPair, wide_contact_kernel.hpp).
inline float blockDeterminant(float normalMass1, float normalMass2, float k12) {
    return 1.0f - (normalMass1 * k12) * (normalMass2 * k12);
}
/// The block solve is used while 1 − ρ² stays above this (the points'
/// rows are far from parallel: Box2D 2.4.1 asks the same of its block
/// solver, with a condition number below 1000); nearer, the points are
/// solved one after the other.
inline constexpr float kLeastBlockDeterminant = 0.01f;

/// Whether a row pushes against a side that cannot move (a zero inverse mass):
/// such a row takes the stiffer softness (RowContext::staticSoft), in the
/// scalar rows and in the wide lanes' flags alike.
inline bool againstImmovable(float invMassA, float invMassB) { return invMassA == 0.0f || invMassB == 0.0f; }
inline bool againstImmovable(const ContactConstraint& cc) { return againstImmovable(cc.invMassA, cc.invMassB); }

/// How far the impact stage moved the material point of `b` that was at `p`
/// when the step began (zero when it did not move the body).
inline Vec2 startShift(const WorldState& w, const Body& b, Vec2 p) {
    const StepStart* start = w.shiftedStart(b);
    if (start == nullptr) return {};
    const Vec2 arm = p - start->center;
    return (b.center - start->center) + rotate(invMulRot(start->q, b.xf.q), arm) - arm;
}

/// How much the impact stage's time-of-impact shifts (impact_stage.cpp) opened
/// (+) or closed (−) contact c's gap at p along n. The manifold was computed
/// before them; a row that kept its gap let two bodies shifted towards each
/// other through (a column of boxes landing at 12 m/s: a pair 4 cm apart was
/// shifted 13 cm together by the repeated strikes of a cascade and ended the
/// step 17 cm deep). A struck contact's own shift also carries its rebound
/// since its moment of impact t* (t* times its separating speed): that part is
/// the flight after the hit, not an overlap, and is left to the rebound
/// (pushed apart it would add energy).
inline float impactShift(const WorldState& w, int c, const Body& a, const Body& b, Vec2 p, Vec2 n) {
    if (w.startsShiftedAt != w.stepStamp) return 0.0f;  // no body's start moved in this step
    float d = dot(startShift(w, b, p) - startShift(w, a, p), n);
    if (d == 0.0f) return 0.0f;
    const auto i = static_cast<std::size_t>(c);
    if (i < w.impactTime.size() && w.impactTime[i] >= 0.0f) {
        const Vec2 dv = (b.v + cross(b.w, p - b.center)) - (a.v + cross(a.w, p - a.center));
        d += w.impactTime[i] * std::max(dot(dv, n), 0.0f);
    }
    return d;
}

/// Writes every field of the row of contact slot `c` (which gets one:
/// contactRowBodies) but pointsTogether and pairScale, which
/// finishContactRow sets once the push caps are final. Reads the world
/// only, so rows may be prepared on any worker. Returns whether a point
/// overlaps deeper than kDeepOverlap.
inline bool prepareContactRow(const WorldState& w, const RowContext& x, int c, ContactConstraint& cc) {
    const WorldSettings& set = w.settings;
    const Contact& ct = w.contacts[c];
    const Body& bA = w.bodies[ct.bodyA];
    const Body& bB = w.bodies[ct.bodyB];
    RowBodies rb;
    contactRowBodies(ct, bA, bB, x.zeroState, rb);
    // Every field the passes read is written below (a row reads only its
    // first pointCount points), so the slot needs no clearing.
    cc.contact = c;
    cc.a = rb.a;
    cc.b = rb.b;
    cc.invMassA = rb.invMassA;
    cc.invIA = rb.invIA;
    cc.invMassB = rb.invMassB;
    cc.invIB = rb.invIB;
    cc.normal = ct.manifold.normal;
    cc.friction = ct.friction;
    cc.restitution = ct.restitution;
    const bool immovable = againstImmovable(cc);
    const Softness& sf = immovable ? x.staticSoft : x.dynamicSoft;
    const float restCompliance = immovable ? x.staticRestCompliance : x.dynamicRestCompliance;
    cc.biasRate = sf.biasRate;
    cc.massScale = sf.massScale;
    cc.impulseScale = sf.impulseScale;
    cc.pointCount = static_cast<std::uint8_t>(ct.manifold.pointCount);
    cc.maxPush = set.maxPushSpeed;
    const ContactSurface* surface = contactSurface(w, c);
    cc.tangentSpeed = surface ? surface->tangentSpeed : 0.0f;
    cc.deepOverlap = false;
    cc.overlapFromStart = ct.overlapFromStart;
    cc.roundA = ct.roundA;
    cc.roundB = ct.roundB;
    cc.turnA = cc.turnB = false;  // (setTurning, from the contact's look)
    for (int j = 0; j < cc.pointCount; ++j)
        cc.deepOverlap = cc.deepOverlap || ct.manifold.points[j].separation < -deepOverlapOf(ct);
    const Vec2 n = cc.normal;
    const Vec2 t = rightPerp(n);
    const Vec2 vA = bA.v, vB = bB.v;
    const float wA = bA.w, wB = bB.w;
    for (int j = 0; j < cc.pointCount; ++j) {
        const ManifoldPoint& mp = ct.manifold.points[j];
        ContactPointConstraint& cp = cc.points[j];
        contactArms(ct, bA, bB, j, cp.rA, cp.rB);
        // Effective mass of the normal row: 1 / (J M⁻¹ Jᵀ) with J of Tamis and Maggiore (2015) §5.3.
        float rnA = cross(cp.rA, n), rnB = cross(cp.rB, n);
        float kn = cc.invMassA + cc.invMassB + cc.invIA * rnA * rnA + cc.invIB * rnB * rnB;
        cp.normalMass = kn > 0.0f ? 1.0f / kn : 0.0f;
        // The overlap is measured from the sag of the load the point was built
        // carrying (rest_load.hpp): zero without one.
        cp.adjustedSeparation = (mp.separation + impactShift(w, c, bA, bB, mp.point, n) - dot(cp.rB - cp.rA, n)) -
                                restSag(ct.restLoad[j], kn, restCompliance, deepOverlapOf(ct));
        float rtA = cross(cp.rA, t), rtB = cross(cp.rB, t);
        float kt = cc.invMassA + cc.invMassB + cc.invIA * rtA * rtA + cc.invIB * rtB * rtB;
        cp.tangentMass = kt > 0.0f ? 1.0f / kt : 0.0f;
        cp.normalImpulse = x.warm * ct.normalImpulse[j];
        cp.tangentImpulse = x.warm * ct.tangentImpulse[j];
        cp.maxNormalImpulse = 0.0f;
        cp.biasImpulse = 0.0f;
        Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
        cp.relativeVelocity = dot(n, dv);
        // Tamis and Maggiore (2015) eq. 8.2.1: bounce target −e·v_n for an approach faster than
        // the threshold that closes the gap within this step.
        cp.restitutionBias = 0.0f;
        if (x.biasRestitution && cc.restitution > 0.0f && cp.relativeVelocity < -set.restitutionThreshold &&
            mp.separation + cp.relativeVelocity * x.fullDt < 0.0f) {
            cp.restitutionBias = -cc.restitution * cp.relativeVelocity;
        }
    }
    return cc.deepOverlap;
}

/// A turning row's side from the contact's look (kLookTurnA, kLookTurnB).
inline void setTurning(ContactConstraint& cc, std::uint8_t lookFlags) {
    cc.turnA = (lookFlags & kLookTurnA) != 0;
    cc.turnB = (lookFlags & kLookTurnB) != 0;
}

/// Whether the row's two points are solved together, from its deepest
/// point's push against its cap and their coupling, and that coupling.
inline void finishContactRow(const RowContext& x, float penetrationSlop, ContactConstraint& cc) {
    float deepest = 0.0f;
    for (int j = 0; j < cc.pointCount; ++j) {
        const ContactPointConstraint& cp = cc.points[j];
        deepest = std::min(deepest, cp.adjustedSeparation + dot(cp.rB - cp.rA, cc.normal));
    }
    const float push = x.soft ? -cc.biasRate * deepest : -x.pushRate * std::min(deepest + penetrationSlop, 0.0f);
    cc.pointsTogether = cc.pointCount == 2 && push < cc.maxPush;
    // A negative coupling is taken as none (solvePointPair).
    const float k12 = cc.pointsTogether ? pairMatrix(cc).k12 : 0.0f;
    cc.pairCoupling = k12 > 0.0f ? k12 : 0.0f;
    if (cc.pointsTogether &&
        !(blockDeterminant(cc.points[0].normalMass, cc.points[1].normalMass, cc.pairCoupling) > kLeastBlockDeterminant))
        cc.pointsTogether = false;
}

}  // namespace i2d::detail
