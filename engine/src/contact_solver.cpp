// The contact rows: preparation, warm start, the Gauss-Seidel sweeps of each
// solver pass, split mode's push, the restitution pass, and storing the
// impulses for the next step (contact_solver.hpp describes the layout).
//
// Each row is solved on its own against the current velocities and its
// accumulated impulse is clamped (normal ≥ 0, |friction| ≤ μ·normal): the
// projected Gauss-Seidel of Tamis and Maggiore (2015), Constraint based
// physics solver, §7.2, without ever forming the matrix A = J M⁻¹ Jᵀ, since a
// row's update λ += −(J v − v_target)/(J M⁻¹ Jᵀ) is the same computation.
#include <algorithm>
#include <cmath>

#include "contact_solver.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

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
void sharePushAmongDeepContacts(WorldState& w) {
    std::vector<int>& count = w.solver.deepContactCount;
    count.back() = 1;  // the immovable stand-in never shares
    for (ContactConstraint& cc : w.solver.constraints) {
        if (!cc.deepOverlap) continue;
        const int n = std::max(count[static_cast<std::size_t>(cc.a)], count[static_cast<std::size_t>(cc.b)]);
        if (n > 1) cc.maxPush /= static_cast<float>(n);
    }
}

}  // namespace

bool contactRowBodies(const WorldState& w, const Contact& ct, int zeroState, RowBodies& out) {
    if (!ct.touching || ct.isSensor || ct.manifold.pointCount == 0) return false;
    const Body& bA = w.bodies[ct.bodyA];
    const Body& bB = w.bodies[ct.bodyB];
    // solverIndex is set for this step's awake bodies only (static and sleeping: none).
    out.a = bA.solverIndex >= 0 ? bA.solverIndex : zeroState;
    out.b = bB.solverIndex >= 0 ? bB.solverIndex : zeroState;
    out.invMassA = out.a != zeroState ? bA.invMass : 0.0f;
    out.invIA = out.a != zeroState ? bA.invInertia : 0.0f;
    out.invMassB = out.b != zeroState ? bB.invMass : 0.0f;
    out.invIB = out.b != zeroState ? bB.invInertia : 0.0f;
    // Neither side moves (two sleeping or infinitely heavy bodies): no row.
    return out.invMassA != 0.0f || out.invIA != 0.0f || out.invMassB != 0.0f || out.invIB != 0.0f;
}

void prepareContacts(WorldState& w, float h, bool soft) {
    const WorldSettings& set = w.settings;
    const int zeroState = static_cast<int>(w.solver.states.size()) - 1;
    const float rate = 1.0f / h;
    const float hertz = std::min(set.contactHertz, 0.25f * rate);
    const Softness dynamicSoft = makeSoft(hertz, set.contactDampingRatio, h);
    // Against an immovable body only one side gives: stiffen (Solver2D doubles the hertz).
    const Softness staticSoft = makeSoft(2.0f * hertz, set.contactDampingRatio, h);
    const bool biasRestitution = set.impactModel == ImpactModel::velocity_bias && !soft;
    const float fullDt = soft ? h * static_cast<float>(set.substeps) : h;
    const float warm = set.enableWarmStarting ? 1.0f : 0.0f;
    SolverArrays& s = w.solver;
    s.deepContactCount.assign(s.states.size(), 0);
    s.rolling.clear();
    bool anyDeep = false;
    // Each row goes straight to its place in colour order (solver.cpp coloured
    // the contacts and left each colour's first slot in colourOffsets).
    s.constraints.resizeForOverwrite(static_cast<std::size_t>(s.rowCount));
    const std::size_t activeCount = w.activeContacts.size();

    for (std::size_t k = 0; k < activeCount; ++k) {
        const std::uint8_t colour = s.contactColours[k];
        if (colour == kNoRow) continue;
        const int c = w.activeContacts[k];
        const Contact& ct = w.contacts[c];
        const Body& bA = w.bodies[ct.bodyA];
        const Body& bB = w.bodies[ct.bodyB];
        RowBodies rb;
        contactRowBodies(w, ct, zeroState, rb);
        const int a = rb.a, b = rb.b;
        // Every field the passes read is written below (a row reads only its
        // first pointCount points), so the slot needs no clearing.
        const int row = s.colourOffsets[colour]++;
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(row)];
        cc.contact = c;
        cc.a = a;
        cc.b = b;
        cc.invMassA = rb.invMassA;
        cc.invIA = rb.invIA;
        cc.invMassB = rb.invMassB;
        cc.invIB = rb.invIB;
        cc.normal = ct.manifold.normal;
        cc.friction = ct.friction;
        cc.restitution = ct.restitution;
        const Softness& sf = (cc.invMassA == 0.0f || cc.invMassB == 0.0f) ? staticSoft : dynamicSoft;
        cc.biasRate = sf.biasRate;
        cc.massScale = sf.massScale;
        cc.impulseScale = sf.impulseScale;
        cc.pointCount = static_cast<std::uint8_t>(ct.manifold.pointCount);
        cc.maxPush = set.maxPushSpeed;
        const ContactSurface* surface = contactSurface(w, c);
        cc.tangentSpeed = surface ? surface->tangentSpeed : 0.0f;
        if (surface && surface->rollingResistance > 0.0f) prepareRollingResistance(w, row, *surface);
        cc.deepOverlap = false;
        for (int j = 0; j < cc.pointCount; ++j)
            cc.deepOverlap = cc.deepOverlap || ct.manifold.points[j].separation < -kDeepOverlap;
        if (cc.deepOverlap) {
            ++w.solver.deepContactCount[static_cast<std::size_t>(a)];
            ++w.solver.deepContactCount[static_cast<std::size_t>(b)];
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
            // Effective mass of the normal row: 1 / (J M⁻¹ Jᵀ) with J of Tamis and Maggiore (2015) §5.3.
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
            // Tamis and Maggiore (2015) eq. 8.2.1: bounce target −e·v_n for an approach faster than
            // the threshold that closes the gap within this step.
            cp.restitutionBias = 0.0f;
            if (biasRestitution && cc.restitution > 0.0f && cp.relativeVelocity < -set.restitutionThreshold &&
                mp.separation + cp.relativeVelocity * fullDt < 0.0f) {
                cp.restitutionBias = -cc.restitution * cp.relativeVelocity;
            }
        }
    }
    if (anyDeep) sharePushAmongDeepContacts(w);
}

void warmStartContacts(WorldState& w) {
    if (!w.solver.rolling.empty()) warmStartRollingResistance(w);
    BodyState* states = w.solver.states.data();
    for (ContactConstraint& cc : w.solver.constraints) {
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

namespace {

/// One Gauss-Seidel sweep over the contacts, compiled once per pass so the
/// per-point branches on it fold away.
template <SolvePass target>
void solveContactsFor(WorldState& w, float h) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    const float slop = set.penetrationSlop;
    const float beta = set.pushFactor;
    // The last relax of a step limits the approach speed for the next step's
    // first substep. With the closed-form impact model a fast approach belongs
    // to the impact law at the start of that step: leave it alone here, or the
    // solver would absorb it inelastically before the law ever sees it.
    const bool leaveImpacts = target == SolvePass::soft_relax_last && set.impactModel == ImpactModel::closed_form;
    const float impactSpeed = set.impactThreshold;
    BodyState* states = w.solver.states.data();
    for (ContactConstraint& cc : w.solver.constraints) {
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
            } else if constexpr (target == SolvePass::soft_bias) {
                bias = std::max(cc.biasRate * s, -cc.maxPush);
                massScale = cc.massScale;
                impulseScale = cc.impulseScale;
            } else if constexpr (target == SolvePass::baumgarte) {
                // Tamis and Maggiore (2015) eq. 5.3.1 with slop: push β·d/Δt, capped.
                bias = std::max(beta * invH * std::min(s + slop, 0.0f), -cc.maxPush);
            }
            if constexpr (target == SolvePass::baumgarte || target == SolvePass::no_push) {
                // Tamis and Maggiore (2015) §8.2: restitution target added to the push (classic modes).
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
        // (not the μmg bound of Tamis and Maggiore (2015) §5.4, which is wrong for stacks, as it says).
        const Vec2 t = rightPerp(n);
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
            float vt = dot(dv, t) - cc.tangentSpeed;
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

}  // namespace

void solveContacts(WorldState& w, float h, SolvePass target) {
    switch (target) {
        case SolvePass::soft_bias: solveContactsFor<SolvePass::soft_bias>(w, h); break;
        case SolvePass::soft_relax: solveContactsFor<SolvePass::soft_relax>(w, h); break;
        case SolvePass::soft_relax_last: solveContactsFor<SolvePass::soft_relax_last>(w, h); break;
        case SolvePass::baumgarte: solveContactsFor<SolvePass::baumgarte>(w, h); break;
        case SolvePass::no_push: solveContactsFor<SolvePass::no_push>(w, h); break;
    }
    if (!w.solver.rolling.empty()) solveRollingResistance(w);
}

/// Split mode (Tamis and Maggiore (2015) §8.1): solve the push alone on pseudo-velocities
/// (`biasV`/`biasW`, with the zero entry last like the states).
void solveContactPush(WorldState& w, float h) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    for (ContactConstraint& cc : w.solver.constraints) {
        Vec2& vA = w.solver.biasV[static_cast<std::size_t>(cc.a)];
        float& wA = w.solver.biasW[static_cast<std::size_t>(cc.a)];
        Vec2& vB = w.solver.biasV[static_cast<std::size_t>(cc.b)];
        float& wB = w.solver.biasW[static_cast<std::size_t>(cc.b)];
        const Vec2 n = cc.normal;
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            float s = cp.adjustedSeparation + dot(cp.rB - cp.rA, n);
            float target = std::min(set.pushFactor * invH * std::max(-(s + set.penetrationSlop), 0.0f),
                                    set.maxPushSpeed);
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
void applyRestitution(WorldState& w) {
    const float threshold = w.settings.restitutionThreshold;
    BodyState* states = w.solver.states.data();
    for (ContactConstraint& cc : w.solver.constraints) {
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

void storeContactImpulses(WorldState& w) {
    if (!w.solver.rolling.empty()) storeRollingResistance(w);
    for (const ContactConstraint& cc : w.solver.constraints) {
        Contact& ct = w.contacts[cc.contact];
        for (int j = 0; j < cc.pointCount; ++j) {
            ct.normalImpulse[j] = cc.points[j].normalImpulse;
            ct.tangentImpulse[j] = cc.points[j].tangentImpulse;
        }
    }
}

// ---- Rolling resistance ------------------------------------------------------
// A contact whose shapes resist rolling gets one more row: the relative
// angular velocity ω_B − ω_A is driven to zero with an impulse bounded by the
// resistance times the contact's total normal impulse, so a ball rolling on
// flat ground loses a torque of c·r·N and comes to rest (the rolling
// resistance of Catto's Box2D v3, with the coefficient scaled by the radius as
// there). The rows live in SolverArrays::rolling, apart from the contact rows.

void prepareRollingResistance(WorldState& w, int row, const ContactSurface& surface) {
    const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(row)];
    const float k = cc.invIA + cc.invIB;
    if (k <= 0.0f) return;  // neither body turns
    const float warm = w.settings.enableWarmStarting ? 1.0f : 0.0f;
    w.solver.rolling.push_back({row, surface.rollingResistance, 1.0f / k, warm * surface.rollingImpulse});
}

void warmStartRollingResistance(WorldState& w) {
    BodyState* states = w.solver.states.data();
    for (const RollingConstraint& rc : w.solver.rolling) {
        const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(rc.row)];
        states[cc.a].w -= cc.invIA * rc.impulse;
        states[cc.b].w += cc.invIB * rc.impulse;
    }
}

void solveRollingResistance(WorldState& w) {
    BodyState* states = w.solver.states.data();
    for (RollingConstraint& rc : w.solver.rolling) {
        const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(rc.row)];
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        float totalNormal = 0.0f;
        for (int j = 0; j < cc.pointCount; ++j) totalNormal += cc.points[j].normalImpulse;
        const float maxImpulse = rc.resistance * totalNormal;
        const float old = rc.impulse;
        rc.impulse = clamp(old - rc.mass * (sB.w - sA.w), -maxImpulse, maxImpulse);
        const float impulse = rc.impulse - old;
        sA.w -= cc.invIA * impulse;
        sB.w += cc.invIB * impulse;
    }
}

void storeRollingResistance(WorldState& w) {
    for (const RollingConstraint& rc : w.solver.rolling) {
        const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(rc.row)];
        w.contactSurfaces[static_cast<std::size_t>(cc.contact)].rollingImpulse = rc.impulse;
    }
}

}  // namespace i2d::detail
