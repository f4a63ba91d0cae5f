// The sequential-impulse solver (projected Gauss-Seidel, seed 001 §6-7).
//
// Each constraint row is solved on its own against the current velocities
// and its accumulated impulse is clamped (normal ≥ 0, |friction| ≤ μ·normal):
// seed 001 §7.2's algorithm without ever forming the matrix A = J M⁻¹ Jᵀ, since
// a row's update λ += −(J v − v_target)/(J M⁻¹ Jᵀ) is the same computation.
//
// Position error is corrected by one of three schemes (WorldSettings):
//  baumgarte  one step; the push velocity β·d/Δt (eq. 5.2.3, 5.3.1) is part of the
//             velocity target, so it stays in the bodies afterwards;
//  split      one step; seed 001 §8.1's single-frame push factor: the velocity
//             system is solved without the push (f_c0), the push is solved on a
//             separate pseudo-velocity (f_cv − f_c0) that moves positions for this
//             step only and is then dropped: correction adds no kinetic energy;
//  soft_step  `substeps` substeps, each: integrate velocities, warm start, solve
//             with soft (spring-damped) push, integrate positions, relax (solve
//             again without push). Then restitution, then store impulses.
//
// Loops (per step): bodies 2 + 2·substeps; constraints (1 + 2·substeps) for
// soft_step, (1 + velocityIterations + positionIterations) otherwise.
#include <algorithm>
#include <cmath>

#include "world_impl.hpp"

namespace i2d::detail {

namespace {

constexpr float kPi = 3.14159265358979f;

/// Soft constraint coefficients for a spring of frequency `hertz` and damping
/// ratio ζ over a step h (implicit Euler of a spring-damper, in the
/// mass-independent form of Catto's "Solver2D"/Box2D v3 soft step):
///   ω = 2π·hertz, a1 = 2ζ + hω, a2 = hω·a1, a3 = 1/(1 + a2)
///   biasRate = ω/a1, massScale = a2·a3, impulseScale = a3
/// and a row's impulse is −massScale·m_eff·(Jv + biasRate·C) − impulseScale·λ_acc.
struct Softness {
    float biasRate = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
};

Softness makeSoft(float hertz, float zeta, float h) {
    if (hertz == 0.0f) return {0.0f, 1.0f, 0.0f};
    float omega = 2.0f * kPi * hertz;
    float a1 = 2.0f * zeta + h * omega;
    float a2 = h * omega * a1;
    float a3 = 1.0f / (1.0f + a2);
    return {omega / a1, a2 * a3, a3};
}

}  // namespace

// ---------------------------------------------------------------------------
// Contacts
//
// Layout: one ContactConstraint per touching manifold in `w.constraints`,
// streamed in order by every pass. A side that cannot move (static, sleeping,
// or zero inverse mass) points at the zero state kept after the awake bodies
// (`w.states.back()`), so the passes have no branch per side: with zero
// inverse mass, impulses leave that state's zero velocity unchanged.
//
// Order: the constraints are graph-coloured each step (greedy, in slot order)
// and solved colour by colour, as Box2D v3 does (constraint_graph.c). No two
// constraints of a colour share a movable body, so a colour's updates do not
// depend on each other and a Gauss-Seidel sweep over colours has no spatial
// direction. Sweeping in creation order instead (left to right, bottom to top
// in a pyramid) carries every sweep's friction error the same way: pyramid100's
// top box then swayed 0.64 m during the initial settling against 0.09 m
// coloured (docs/performance.md).

namespace {

constexpr int kColourCount = 24;  ///< colours tried before the overflow group

bool movable(const BodyState& s) { return s.invMass != 0.0f || s.invInertia != 0.0f; }

void colourContacts(WorldImpl& w) {
    const std::size_t count = w.constraints.size();
    const std::size_t bodyCount = w.stateBodies.size();
    const std::size_t words = (bodyCount + 63) / 64;
    w.colourBits.assign(words * kColourCount, 0u);
    w.colourCounts.assign(kColourCount + 1, 0);
    w.constraintColours.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const ContactConstraint& cc = w.constraints[i];
        const bool moveA = static_cast<std::size_t>(cc.a) < bodyCount && (cc.invMassA != 0.0f || cc.invIA != 0.0f);
        const bool moveB = static_cast<std::size_t>(cc.b) < bodyCount && (cc.invMassB != 0.0f || cc.invIB != 0.0f);
        const std::size_t wa = static_cast<std::size_t>(cc.a) / 64, wb = static_cast<std::size_t>(cc.b) / 64;
        const std::uint64_t ma = moveA ? std::uint64_t{1} << (cc.a % 64) : 0u;
        const std::uint64_t mb = moveB ? std::uint64_t{1} << (cc.b % 64) : 0u;
        int colour = kColourCount;
        for (int c = 0; c < kColourCount; ++c) {
            std::uint64_t* bits = w.colourBits.data() + static_cast<std::size_t>(c) * words;
            if ((moveA && (bits[wa] & ma)) || (moveB && (bits[wb] & mb))) continue;
            if (moveA) bits[wa] |= ma;
            if (moveB) bits[wb] |= mb;
            colour = c;
            break;
        }
        w.constraintColours[i] = static_cast<std::uint8_t>(colour);
        ++w.colourCounts[static_cast<std::size_t>(colour)];
    }
    // Stable counting sort by colour (the overflow group last, in slot order).
    int offset = 0;
    for (int& n : w.colourCounts) {
        int c = n;
        n = offset;
        offset += c;
    }
    w.constraintScratch.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        int& slot = w.colourCounts[w.constraintColours[i]];
        w.constraintScratch[static_cast<std::size_t>(slot++)] = w.constraints[i];
    }
    w.constraints.swap(w.constraintScratch);
}

// The push that separates overlapping bodies is capped per contact at
// maxPushSpeed. A body overlapping many others deeply (boxes created on top of
// each other) would otherwise collect one capped push per contact and fly
// off at many times the cap: 100 boxes created at one point left at 50 m/s.
// A body's deep contacts therefore share the cap, each getting
// maxPushSpeed / n (n the larger count of its two bodies), which bounds the
// push a body receives by about maxPushSpeed. Contacts of resting stacks
// overlap by millimetres, far less than kDeepOverlap, and keep the full cap.
constexpr float kDeepOverlap = 0.05f;  ///< m; ten times the linear slop

// Divides the push cap of each deep contact by the larger deep-contact count
// of its two bodies (counted in prepareContacts).
void sharePushAmongDeepContacts(WorldImpl& w) {
    std::vector<int>& count = w.deepContactCount;
    count.back() = 1;  // the immovable stand-in never shares
    for (ContactConstraint& cc : w.constraints) {
        if (!cc.deepOverlap) continue;
        const int n = std::max(count[static_cast<std::size_t>(cc.a)], count[static_cast<std::size_t>(cc.b)]);
        if (n > 1) cc.maxPush /= static_cast<float>(n);
    }
}

void prepareContacts(WorldImpl& w, float h, bool soft) {
    const WorldSettings& set = w.settings;
    w.constraints.clear();
    const int zeroState = static_cast<int>(w.states.size()) - 1;
    const float rate = 1.0f / h;
    const float hertz = std::min(set.contactHertz, 0.25f * rate);
    const Softness dynamicSoft = makeSoft(hertz, set.contactDampingRatio, h);
    // Against an immovable body only one side gives: stiffen (Solver2D doubles the hertz).
    const Softness staticSoft = makeSoft(2.0f * hertz, set.contactDampingRatio, h);
    const bool biasRestitution = set.impactModel == ImpactModel::velocity_bias && !soft;
    const float fullDt = soft ? h * static_cast<float>(set.substeps) : h;
    const float warm = set.enableWarmStarting ? 1.0f : 0.0f;
    w.deepContactCount.assign(w.states.size(), 0);
    bool anyDeep = false;

    for (int c : w.activeContacts) {
        const Contact& ct = w.contacts[c];
        if (!ct.touching || ct.isSensor || ct.manifold.pointCount == 0) continue;
        const Body& bA = w.bodies[ct.bodyA];
        const Body& bB = w.bodies[ct.bodyB];
        // solverIndex is set for this step's awake bodies only (static and sleeping: none).
        const int a = bA.solverIndex >= 0 ? bA.solverIndex : zeroState;
        const int b = bB.solverIndex >= 0 ? bB.solverIndex : zeroState;
        const BodyState& sA = w.states[static_cast<std::size_t>(a)];
        const BodyState& sB = w.states[static_cast<std::size_t>(b)];
        if (!movable(sA) && !movable(sB)) continue;
        ContactConstraint& cc = w.constraints.emplace_back();
        cc.contact = c;
        cc.a = a;
        cc.b = b;
        cc.invMassA = sA.invMass;
        cc.invIA = sA.invInertia;
        cc.invMassB = sB.invMass;
        cc.invIB = sB.invInertia;
        cc.normal = ct.manifold.normal;
        cc.friction = ct.friction;
        cc.restitution = ct.restitution;
        const Softness& sf = (cc.invMassA == 0.0f || cc.invMassB == 0.0f) ? staticSoft : dynamicSoft;
        cc.biasRate = sf.biasRate;
        cc.massScale = sf.massScale;
        cc.impulseScale = sf.impulseScale;
        cc.pointCount = ct.manifold.pointCount;
        cc.maxPush = set.maxPushSpeed;
        cc.deepOverlap = false;
        for (int j = 0; j < cc.pointCount; ++j) cc.deepOverlap = cc.deepOverlap || ct.manifold.points[j].separation < -kDeepOverlap;
        if (cc.deepOverlap) {
            ++w.deepContactCount[static_cast<std::size_t>(a)];
            ++w.deepContactCount[static_cast<std::size_t>(b)];
            anyDeep = true;
        }
        const Vec2 n = cc.normal;
        const Vec2 t = rightPerp(n);
        const Vec2 vA = bA.v, vB = bB.v;
        const float wA = bA.w, wB = bB.w;
        for (int j = 0; j < cc.pointCount; ++j) {
            const ManifoldPoint& mp = ct.manifold.points[j];
            ContactPointConstraint& cp = cc.points[j];
            cp.rA = mp.point - bA.center;
            cp.rB = mp.point - bB.center;
            cp.adjustedSeparation = mp.separation - dot(cp.rB - cp.rA, n);
            // Effective mass of the normal row: 1 / (J M⁻¹ Jᵀ) with J of seed 001 §5.3.
            float rnA = cross(cp.rA, n), rnB = cross(cp.rB, n);
            float kn = cc.invMassA + cc.invMassB + cc.invIA * rnA * rnA + cc.invIB * rnB * rnB;
            cp.normalMass = kn > 0.0f ? 1.0f / kn : 0.0f;
            float rtA = cross(cp.rA, t), rtB = cross(cp.rB, t);
            float kt = cc.invMassA + cc.invMassB + cc.invIA * rtA * rtA + cc.invIB * rtB * rtB;
            cp.tangentMass = kt > 0.0f ? 1.0f / kt : 0.0f;
            cp.normalImpulse = warm * ct.normalImpulse[j];
            cp.tangentImpulse = warm * ct.tangentImpulse[j];
            cp.maxNormalImpulse = 0.0f;
            cp.biasImpulse = 0.0f;
            Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
            cp.relativeVelocity = dot(n, dv);
            // Seed 001 eq. 8.2.1: bounce target −e·v_n for an approach faster than
            // the threshold that closes the gap within this step.
            cp.restitutionBias = 0.0f;
            if (biasRestitution && cc.restitution > 0.0f && cp.relativeVelocity < -set.restitutionThreshold &&
                mp.separation + cp.relativeVelocity * fullDt < 0.0f) {
                cp.restitutionBias = -cc.restitution * cp.relativeVelocity;
            }
        }
    }
    if (anyDeep) sharePushAmongDeepContacts(w);
    colourContacts(w);
}

void warmStartContacts(WorldImpl& w) {
    BodyState* states = w.states.data();
    for (ContactConstraint& cc : w.constraints) {
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        Vec2 vA = sA.v, vB = sB.v;
        float wA = sA.w, wB = sB.w;
        const Vec2 n = cc.normal, t = rightPerp(n);
        for (int j = 0; j < cc.pointCount; ++j) {
            const ContactPointConstraint& cp = cc.points[j];
            Vec2 P = cp.normalImpulse * n + cp.tangentImpulse * t;
            vA = mulSub(vA, cc.invMassA, P);
            wA -= cc.invIA * cross(cp.rA, P);
            vB = mulAdd(vB, cc.invMassB, P);
            wB += cc.invIB * cross(cp.rB, P);
        }
        sA.v = vA;
        sA.w = wA;
        sB.v = vB;
        sB.w = wB;
    }
}

/// One Gauss-Seidel sweep over the contacts. `mode` selects the normal target:
///  soft (useBias or relax), or classic with/without the Baumgarte push.
enum class Target { soft_bias, soft_relax, baumgarte, no_push, soft_relax_last };

/// The sweep, compiled once per target so the per-point branches on it fold away.
template <Target target>
void solveContactsFor(WorldImpl& w, float h) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    const float slop = set.penetrationSlop;
    const float beta = set.pushFactor;
    // The last relax of a step limits the approach speed for the next step's
    // first substep. With the closed-form impact model a fast approach belongs
    // to the impact law at the start of that step: leave it alone here, or the
    // solver would absorb it inelastically before the law ever sees it.
    const bool leaveImpacts = target == Target::soft_relax_last && set.impactModel == ImpactModel::closed_form;
    const float impactSpeed = set.impactThreshold;
    BodyState* states = w.states.data();
    for (ContactConstraint& cc : w.constraints) {
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        Vec2 vA = sA.v, vB = sB.v;
        float wA = sA.w, wB = sB.w;
        const Rot qA = sA.dq, qB = sB.dq;
        const float mA = cc.invMassA, iA = cc.invIA, mB = cc.invMassB, iB = cc.invIB;
        const Vec2 n = cc.normal;
        const Vec2 dp = sB.dp - sA.dp;

        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            // Current separation from the bodies' motion since the step began
            // (anchors fixed in the bodies, rotated by their delta rotation).
            Vec2 d = dp + (rotate(qB, cp.rB) - rotate(qA, cp.rA));
            float s = dot(d, n) + cp.adjustedSeparation;

            Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
            float vn = dot(dv, n);
            if (leaveImpacts && s > 0.0f && vn < -impactSpeed) continue;

            float bias = 0.0f, massScale = 1.0f, impulseScale = 0.0f;
            if (s > 0.0f) {
                // Speculative: allow exactly the approach that closes the gap this (sub)step.
                bias = s * invH;
            } else if constexpr (target == Target::soft_bias) {
                bias = std::max(cc.biasRate * s, -cc.maxPush);
                massScale = cc.massScale;
                impulseScale = cc.impulseScale;
            } else if constexpr (target == Target::baumgarte) {
                // Seed 001 eq. 5.3.1 with slop: push β·d/Δt, capped.
                bias = std::max(beta * invH * std::min(s + slop, 0.0f), -cc.maxPush);
            }
            if constexpr (target == Target::baumgarte || target == Target::no_push) {
                // Seed 001 §8.2: restitution target added to the push (classic modes).
                if (cp.restitutionBias > 0.0f) bias = std::min(bias, -cp.restitutionBias);
            }

            float impulse = -cp.normalMass * massScale * (vn + bias) - impulseScale * cp.normalImpulse;
            float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, impulse);
            Vec2 P = impulse * n;
            vA = mulSub(vA, mA, P);
            wA -= iA * cross(cp.rA, P);
            vB = mulAdd(vB, mB, P);
            wB += iB * cross(cp.rB, P);
        }

        // Coulomb friction bounded by μ times this point's own normal impulse
        // (not seed 001 §5.4's μmg, which is wrong for stacks, as it says).
        const Vec2 t = rightPerp(n);
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
            float vt = dot(dv, t);
            float impulse = -cp.tangentMass * vt;
            float maxFriction = cc.friction * cp.normalImpulse;
            float newImpulse = clamp(cp.tangentImpulse + impulse, -maxFriction, maxFriction);
            impulse = newImpulse - cp.tangentImpulse;
            cp.tangentImpulse = newImpulse;
            Vec2 P = impulse * t;
            vA = mulSub(vA, mA, P);
            wA -= iA * cross(cp.rA, P);
            vB = mulAdd(vB, mB, P);
            wB += iB * cross(cp.rB, P);
        }
        sA.v = vA;
        sA.w = wA;
        sB.v = vB;
        sB.w = wB;
    }
}

void solveContacts(WorldImpl& w, float h, Target target) {
    switch (target) {
        case Target::soft_bias: solveContactsFor<Target::soft_bias>(w, h); break;
        case Target::soft_relax: solveContactsFor<Target::soft_relax>(w, h); break;
        case Target::soft_relax_last: solveContactsFor<Target::soft_relax_last>(w, h); break;
        case Target::baumgarte: solveContactsFor<Target::baumgarte>(w, h); break;
        case Target::no_push: solveContactsFor<Target::no_push>(w, h); break;
    }
}

/// Split mode (seed 001 §8.1): solve the push alone on pseudo-velocities
/// (`biasV`/`biasW`, with the zero entry last like the states).
void solveContactPush(WorldImpl& w, float h) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    for (ContactConstraint& cc : w.constraints) {
        Vec2& vA = w.biasV[static_cast<std::size_t>(cc.a)];
        float& wA = w.biasW[static_cast<std::size_t>(cc.a)];
        Vec2& vB = w.biasV[static_cast<std::size_t>(cc.b)];
        float& wB = w.biasW[static_cast<std::size_t>(cc.b)];
        const Vec2 n = cc.normal;
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            float s = cp.adjustedSeparation + dot(cp.rB - cp.rA, n);
            float target = std::min(set.pushFactor * invH * std::max(-(s + set.penetrationSlop), 0.0f), set.maxPushSpeed);
            if (target <= 0.0f && cp.biasImpulse == 0.0f) continue;
            Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
            float impulse = -cp.normalMass * (dot(dv, n) - target);
            float newImpulse = std::max(cp.biasImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.biasImpulse;
            cp.biasImpulse = newImpulse;
            Vec2 P = impulse * n;
            vA = mulSub(vA, cc.invMassA, P);
            wA -= cc.invIA * cross(cp.rA, P);
            vB = mulAdd(vB, cc.invMassB, P);
            wB += cc.invIB * cross(cp.rB, P);
        }
    }
}

/// Soft step's restitution pass (velocity-bias impact model): after the
/// substeps, drive each point that was hit faster than the threshold to
/// separate at e times its approach speed.
void applyRestitution(WorldImpl& w) {
    const float threshold = w.settings.restitutionThreshold;
    BodyState* states = w.states.data();
    for (ContactConstraint& cc : w.constraints) {
        if (cc.restitution == 0.0f) continue;
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        const Vec2 n = cc.normal;
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            if (cp.relativeVelocity > -threshold || cp.maxNormalImpulse == 0.0f) continue;
            Vec2 dv = (sB.v + cross(sB.w, cp.rB)) - (sA.v + cross(sA.w, cp.rA));
            float vn = dot(dv, n);
            float impulse = -cp.normalMass * (vn + cc.restitution * cp.relativeVelocity);
            float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            Vec2 P = impulse * n;
            sA.v = mulSub(sA.v, cc.invMassA, P);
            sA.w -= cc.invIA * cross(cp.rA, P);
            sB.v = mulAdd(sB.v, cc.invMassB, P);
            sB.w += cc.invIB * cross(cp.rB, P);
        }
    }
}

void storeContactImpulses(WorldImpl& w) {
    for (const ContactConstraint& cc : w.constraints) {
        Contact& ct = w.contacts[cc.contact];
        for (int j = 0; j < cc.pointCount; ++j) {
            ct.normalImpulse[j] = cc.points[j].normalImpulse;
            ct.tangentImpulse[j] = cc.points[j].tangentImpulse;
        }
    }
}

}  // namespace

// ---------------------------------------------------------------------------
// Distance joints (seed 001 §5.2). The constraint C = |p_b − p_a| − L has the
// same Jacobian direction as the seed's ½(|p_ab|² − l²) (scaled by |p_ab|),
// so the effective mass is taken along the unit axis.

namespace {

void prepareJoints(WorldImpl& w) {
    w.activeJoints.clear();
    for (int j = 0; j < w.joints.capacity(); ++j) {
        DistanceJoint& jt = w.joints[j];
        if (!jt.alive) continue;
        const Body& bA = w.bodies[jt.bodyA];
        const Body& bB = w.bodies[jt.bodyB];
        if (!bA.awake && !bB.awake) continue;
        jt.a = bA.awake ? bA.solverIndex : kNullIndex;
        jt.b = bB.awake ? bB.solverIndex : kNullIndex;
        jt.invMassA = jt.a >= 0 ? w.states[static_cast<std::size_t>(jt.a)].invMass : 0.0f;
        jt.invIA = jt.a >= 0 ? w.states[static_cast<std::size_t>(jt.a)].invInertia : 0.0f;
        jt.invMassB = jt.b >= 0 ? w.states[static_cast<std::size_t>(jt.b)].invMass : 0.0f;
        jt.invIB = jt.b >= 0 ? w.states[static_cast<std::size_t>(jt.b)].invInertia : 0.0f;
        jt.rA = rotate(bA.xf.q, jt.def.localAnchorA - bA.localCenter);
        jt.rB = rotate(bB.xf.q, jt.def.localAnchorB - bB.localCenter);
        jt.deltaCenter = bB.center - bA.center;
        Vec2 axis = normalize(jt.deltaCenter + jt.rB - jt.rA);
        float crA = cross(jt.rA, axis), crB = cross(jt.rB, axis);
        float k = jt.invMassA + jt.invMassB + jt.invIA * crA * crA + jt.invIB * crB * crB;
        jt.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
        jt.biasImpulse = 0.0f;
        if (!w.settings.enableWarmStarting) jt.impulse = jt.lowerImpulse = jt.upperImpulse = 0.0f;
        w.activeJoints.push_back(j);
    }
}

struct JointFrame {
    Vec2 rA, rB, axis;
    float length;
};

JointFrame currentFrame(const DistanceJoint& jt, const BodyState& sA, const BodyState& sB) {
    JointFrame f;
    f.rA = rotate(sA.dq, jt.rA);
    f.rB = rotate(sB.dq, jt.rB);
    Vec2 d = (sB.dp - sA.dp) + jt.deltaCenter + f.rB - f.rA;
    f.axis = normalize(d, f.length);
    return f;
}

void applyAxial(const DistanceJoint& jt, const JointFrame& f, float impulse, BodyState& sA, BodyState& sB) {
    Vec2 P = impulse * f.axis;
    sA.v = mulSub(sA.v, jt.invMassA, P);
    sA.w -= jt.invIA * cross(f.rA, P);
    sB.v = mulAdd(sB.v, jt.invMassB, P);
    sB.w += jt.invIB * cross(f.rB, P);
}

void warmStartJoints(WorldImpl& w) {
    BodyState dA, dB;
    for (int j : w.activeJoints) {
        DistanceJoint& jt = w.joints[j];
        BodyState& sA = jt.a >= 0 ? w.states[static_cast<std::size_t>(jt.a)] : (dA = BodyState{});
        BodyState& sB = jt.b >= 0 ? w.states[static_cast<std::size_t>(jt.b)] : (dB = BodyState{});
        JointFrame f = currentFrame(jt, sA, sB);
        applyAxial(jt, f, jt.impulse + jt.lowerImpulse - jt.upperImpulse, sA, sB);
    }
}

/// Joint sweeps in each substep's solve stage (soft_step). A chain carrying a
/// heavy body (heavy_chain: 100 kg on 1 kg links) is a stiff, badly
/// conditioned system: one Gauss-Seidel sweep per substep left most of each
/// link's share of the load unresolved, so the soft rows stretched far beyond
/// their spring compliance and, at jointHertz 60, grew unstable. A second sweep
/// costs little (joints are few next to contacts) and holds the chain: total
/// stretch after 5 s 3.09 m → 1.01 m (docs/performance.md).
constexpr int kJointSolvePasses = 2;

bool isRigid(const DistanceJoint& jt) {
    return !(jt.def.enableSpring && (!jt.def.enableLimit || jt.def.minLength < jt.def.maxLength));
}

// Adds `impulse` to `accumulated` within [lo, hi]; returns the part applied.
float boundedIncrement(float& accumulated, float impulse, float lo, float hi) {
    const float total = clamp(accumulated + impulse, lo, hi);
    impulse = total - accumulated;
    accumulated = total;
    return impulse;
}

void solveJoints(WorldImpl& w, float h, Target target) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    // Joint stiffness capped at 1/4 of the substep rate, so jointHertz 60 holds
    // at 4 substeps as in Box2D v3 (twice its contact hertz). This needs the two
    // joint passes of the solve stage (see kJointSolvePasses): with one pass,
    // a 100:1 chain (heavy_chain) diverged at this stiffness, and at the former
    // cap of 1/8 it stretched by 3.1 m.
    const Softness jointSoft = makeSoft(std::min(set.jointHertz, 0.25f * invH), set.jointDampingRatio, h);
    BodyState dA, dB;
    for (int j : w.activeJoints) {
        DistanceJoint& jt = w.joints[j];
        BodyState& sA = jt.a >= 0 ? w.states[static_cast<std::size_t>(jt.a)] : (dA = BodyState{});
        BodyState& sB = jt.b >= 0 ? w.states[static_cast<std::size_t>(jt.b)] : (dB = BodyState{});
        JointFrame f = currentFrame(jt, sA, sB);
        // A joint's impulse per (sub)step never needs to exceed what changes
        // the relative speed along it by twice the speed limit; bounding it
        // keeps a diverging row (a fuzzed, stretched 600:1 joint reached
        // 1e36 N·s, then NaN) finite.
        const float maxImpulse = 2.0f * set.maxLinearSpeed * jt.axialMass;
        auto cdot = [&]() {
            Vec2 dv = (sB.v + cross(sB.w, f.rB)) - (sA.v + cross(sA.w, f.rA));
            return dot(dv, f.axis);
        };
        if (isRigid(jt)) {
            float C = f.length - jt.def.length;
            float bias = 0.0f, ms = 1.0f, is = 0.0f;
            if (target == Target::soft_bias) {
                bias = jointSoft.biasRate * C;
                ms = jointSoft.massScale;
                is = jointSoft.impulseScale;
            } else if (target == Target::baumgarte) {
                bias = set.pushFactor * invH * C;  // seed 001 eq. 5.2.3
            }
            float impulse = -ms * jt.axialMass * (cdot() + bias) - is * jt.impulse;
            impulse = boundedIncrement(jt.impulse, impulse, -maxImpulse, maxImpulse);
            applyAxial(jt, f, impulse, sA, sB);
        } else if (jt.def.hertz > 0.0f) {
            // A spring: its softness is physical, so it applies in every pass.
            Softness spring = makeSoft(jt.def.hertz, jt.def.dampingRatio, h);
            float C = f.length - jt.def.length;
            float impulse = -spring.massScale * jt.axialMass * (cdot() + spring.biasRate * C) - spring.impulseScale * jt.impulse;
            impulse = boundedIncrement(jt.impulse, impulse, -maxImpulse, maxImpulse);
            applyAxial(jt, f, impulse, sA, sB);
        }
        if (jt.def.enableLimit && jt.def.minLength < jt.def.maxLength) {
            // One-sided limit row along `sign`·axis: C ≥ 0 is allowed (speculative
            // when positive), the accumulated impulse stays ≥ 0.
            auto limitRow = [&](float C, float sign, float& accumulated) {
                float bias = 0.0f, ms = 1.0f, is = 0.0f;
                if (C > 0.0f) {
                    bias = C * invH;
                } else if (target == Target::soft_bias) {
                    bias = jointSoft.biasRate * C;
                    ms = jointSoft.massScale;
                    is = jointSoft.impulseScale;
                } else if (target == Target::baumgarte) {
                    bias = set.pushFactor * invH * C;
                }
                float impulse = -ms * jt.axialMass * (sign * cdot() + bias) - is * accumulated;
                impulse = boundedIncrement(accumulated, impulse, 0.0f, maxImpulse);
                applyAxial(jt, f, sign * impulse, sA, sB);
            };
            // Lower limit: length ≥ minLength (pushes apart).
            limitRow(f.length - jt.def.minLength, 1.0f, jt.lowerImpulse);
            // Upper limit: length ≤ maxLength, a rope (pulls together).
            limitRow(jt.def.maxLength - f.length, -1.0f, jt.upperImpulse);
        }
    }
}

/// Split mode: the joints' position error solved on the pseudo-velocities.
void solveJointPush(WorldImpl& w, float h) {
    const float invH = 1.0f / h;
    for (int j : w.activeJoints) {
        DistanceJoint& jt = w.joints[j];
        BodyState sA = jt.a >= 0 ? w.states[static_cast<std::size_t>(jt.a)] : BodyState{};
        BodyState sB = jt.b >= 0 ? w.states[static_cast<std::size_t>(jt.b)] : BodyState{};
        JointFrame f = currentFrame(jt, sA, sB);
        float C;
        if (isRigid(jt)) {
            C = f.length - jt.def.length;
        } else if (jt.def.enableLimit && f.length < jt.def.minLength) {
            C = f.length - jt.def.minLength;
        } else if (jt.def.enableLimit && f.length > jt.def.maxLength) {
            C = f.length - jt.def.maxLength;
        } else {
            continue;
        }
        // Pseudo-velocities of the two bodies, in and out of the bias arrays.
        BodyState pA{}, pB{};
        if (jt.a >= 0) {
            pA.v = w.biasV[static_cast<std::size_t>(jt.a)];
            pA.w = w.biasW[static_cast<std::size_t>(jt.a)];
        }
        if (jt.b >= 0) {
            pB.v = w.biasV[static_cast<std::size_t>(jt.b)];
            pB.w = w.biasW[static_cast<std::size_t>(jt.b)];
        }
        Vec2 dv = (pB.v + cross(pB.w, f.rB)) - (pA.v + cross(pA.w, f.rA));
        float target = -w.settings.pushFactor * invH * C;
        float impulse = -jt.axialMass * (dot(dv, f.axis) - target);
        applyAxial(jt, f, impulse, pA, pB);
        if (jt.a >= 0) {
            w.biasV[static_cast<std::size_t>(jt.a)] = pA.v;
            w.biasW[static_cast<std::size_t>(jt.a)] = pA.w;
        }
        if (jt.b >= 0) {
            w.biasV[static_cast<std::size_t>(jt.b)] = pB.v;
            w.biasW[static_cast<std::size_t>(jt.b)] = pB.w;
        }
    }
}

void storeJointImpulses(WorldImpl& w, float dt) {
    for (int j : w.activeJoints) {
        DistanceJoint& jt = w.joints[j];
        jt.lastForce = std::abs(jt.impulse + jt.lowerImpulse - jt.upperImpulse) / dt;
    }
}

}  // namespace

// ---------------------------------------------------------------------------
// Integration (seed 001 §3.2, semi-implicit Euler)

namespace {

void integrateVelocities(WorldImpl& w, float h) {
    const Vec2 g = w.settings.gravity;
    const float maxSpeed = w.settings.maxLinearSpeed;
    for (std::size_t i = 0; i < w.stateBodies.size(); ++i) {
        BodyState& s = w.states[i];
        const Body& body = w.bodies[w.stateBodies[i]];
        if (body.type != BodyType::dynamic_body) continue;
        // Eq. 3.2.1-3.2.2 in velocities: v += Δt·(g·scale + F/m), ω += Δt·τ/I.
        Vec2 v = s.v + h * (body.gravityScale * g + s.invMass * body.force);
        float av = s.w + h * s.invInertia * body.torque;
        // Damping as the exact-for-linear-drag factor's Padé form: v /= 1 + h·c.
        v *= 1.0f / (1.0f + h * body.linearDamping);
        av *= 1.0f / (1.0f + h * body.angularDamping);
        float speed2 = lengthSquared(v);
        if (speed2 > maxSpeed * maxSpeed) v *= maxSpeed / std::sqrt(speed2);
        s.v = v;
        s.w = av;
    }
}

// The speed limits hold for the velocities the positions are integrated with,
// after the constraints have acted: a joint or contact impulse can exceed what
// integrateVelocities clamped (a fuzzed distance joint launched a body at
// 1750 m/s and 55,000 rad/s). Angular: at most a quarter turn per (sub)step,
// beyond which the rotation integration and the narrowphase lose the body's
// orientation (Box2D v3 uses the same bound).
constexpr float kMaxRotationPerStep = 0.25f * 3.14159265f;

void clampVelocity(BodyState& s, float maxSpeed, float maxAngularSpeed) {
    const float speed2 = lengthSquared(s.v);
    if (speed2 > maxSpeed * maxSpeed) s.v *= maxSpeed / std::sqrt(speed2);
    if (std::abs(s.w) > maxAngularSpeed) s.w = s.w > 0.0f ? maxAngularSpeed : -maxAngularSpeed;
}

void integratePositions(WorldImpl& w, float h) {
    const float maxSpeed = w.settings.maxLinearSpeed, maxAngular = kMaxRotationPerStep / h;
    for (std::size_t i = 0; i < w.stateBodies.size(); ++i) {
        BodyState& s = w.states[i];
        clampVelocity(s, maxSpeed, maxAngular);
        // Eq. 3.2.3-3.2.4 with the new velocities.
        s.dp = mulAdd(s.dp, h, s.v);
        s.dq = integrateRotation(s.dq, h * s.w);
    }
}

}  // namespace

// ---------------------------------------------------------------------------

void WorldImpl::solve(float dt) {
    const std::size_t n = awakeBodies.size();
    states.resize(n + 1);
    states[n] = BodyState{};  // the zero state for immovable sides of contacts
    stateBodies.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        int b = awakeBodies[i];
        Body& body = bodies[b];
        body.solverIndex = static_cast<int>(i);
        stateBodies[i] = b;
        BodyState& s = states[i];
        s.v = body.v;
        s.w = body.w;
        s.invMass = body.invMass;
        s.invInertia = body.invInertia;
        s.dp = {};
        s.dq = {};
    }

    const bool soft = settings.positionCorrection == PositionCorrection::soft_step;
    const int substeps = soft ? settings.substeps : 1;
    const float h = dt / static_cast<float>(substeps);

    prepareContacts(*this, h, soft);
    prepareJoints(*this);

    if (soft) {
        for (int i = 0; i < substeps; ++i) {
            integrateVelocities(*this, h);
            warmStartContacts(*this);
            warmStartJoints(*this);
            for (int pass = 0; pass < kJointSolvePasses; ++pass) solveJoints(*this, h, Target::soft_bias);
            solveContacts(*this, h, Target::soft_bias);
            integratePositions(*this, h);
            solveJoints(*this, h, Target::soft_relax);
            solveContacts(*this, h, i + 1 == substeps ? Target::soft_relax_last : Target::soft_relax);
        }
        if (settings.impactModel == ImpactModel::velocity_bias) applyRestitution(*this);
    } else {
        const bool baumgarte = settings.positionCorrection == PositionCorrection::baumgarte;
        const Target target = baumgarte ? Target::baumgarte : Target::no_push;
        integrateVelocities(*this, dt);
        warmStartContacts(*this);
        warmStartJoints(*this);
        for (int it = 0; it < settings.velocityIterations; ++it) {
            solveJoints(*this, dt, target);
            solveContacts(*this, dt, target);
        }
        if (!baumgarte) {
            biasV.assign(n + 1, Vec2{});
            biasW.assign(n + 1, 0.0f);
            for (int it = 0; it < settings.positionIterations; ++it) {
                solveJointPush(*this, dt);
                solveContactPush(*this, dt);
            }
            // Move by v + v_push for this step only; v_push is then dropped.
            for (std::size_t i = 0; i < n; ++i) {
                BodyState& s = states[i];
                clampVelocity(s, settings.maxLinearSpeed, kMaxRotationPerStep / dt);
                // The limits hold for the motion including the push: a light,
                // small body's pseudo-velocity could otherwise turn it by an
                // angle whose square overflows (fuzz_world: NaN rotation).
                BodyState moved = s;
                moved.v = s.v + biasV[i];
                moved.w = s.w + biasW[i];
                clampVelocity(moved, settings.maxLinearSpeed, kMaxRotationPerStep / dt);
                s.dp = mulAdd(s.dp, dt, moved.v);
                s.dq = integrateRotation(s.dq, dt * moved.w);
            }
        } else {
            integratePositions(*this, dt);
        }
    }

    storeContactImpulses(*this);
    storeJointImpulses(*this, dt);

    // Write back: centre of mass, rotation, origin, velocities; clear forces.
    // The relax and restitution passes act after the last position update, so
    // the limits are applied once more to the velocities the body keeps.
    const float maxAngular = kMaxRotationPerStep / (dt / static_cast<float>(substeps));
    for (std::size_t i = 0; i < n; ++i) {
        Body& body = bodies[stateBodies[i]];
        BodyState& s = states[i];
        clampVelocity(s, settings.maxLinearSpeed, maxAngular);
        body.v = s.v;
        body.w = s.w;
        body.center += s.dp;
        Rot q = mulRot(s.dq, body.xf.q);
        float mag = std::sqrt(q.c * q.c + q.s * q.s);
        q = {q.c / mag, q.s / mag};
        body.xf.q = q;
        body.xf.p = body.center - rotate(q, body.localCenter);
        body.force = {};
        body.torque = 0.0f;
        body.solverIndex = kNullIndex;
    }
}

}  // namespace i2d::detail
