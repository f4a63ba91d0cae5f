// Four contact manifolds at a time (see wide_contact.hpp). The order of
// operations follows solveContactsFor, warmStartContacts and their helpers in
// contact_solver.cpp line by line: normal rows with their regimes
// (speculative, soft push capped at maxPush, relax), a manifold's two points
// together (pairScale) or one after the other, then Coulomb friction per
// point. What the scalar row skips with a branch, a lane keeps with a select.
#include "wide_contact.hpp"

#include "solver.hpp"
#include "wide_body.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// Lane `lane` of block k from row cc (null: an empty lane), every field written.
inline void packLane(WideContactBlock& k, int lane, const ContactConstraint* cc, int row, int zero) {
    const bool used = cc != nullptr;
    k.a[lane] = used ? cc->a : zero;
    k.b[lane] = used ? cc->b : zero;
    k.row[lane] = used ? row : -1;
    k.contact[lane] = used ? cc->contact : -1;
    k.nx[lane] = used ? cc->normal.x : 0.0f, k.ny[lane] = used ? cc->normal.y : 0.0f;
    k.friction[lane] = used ? cc->friction : 0.0f;
    k.tangentSpeed[lane] = used ? cc->tangentSpeed : 0.0f;
    k.mA[lane] = used ? cc->invMassA : 0.0f, k.iA[lane] = used ? cc->invIA : 0.0f;
    k.mB[lane] = used ? cc->invMassB : 0.0f, k.iB[lane] = used ? cc->invIB : 0.0f;
    k.biasRate[lane] = used ? cc->biasRate : 0.0f;
    k.massScale[lane] = used ? cc->massScale : 1.0f;
    k.impulseScale[lane] = used ? cc->impulseScale : 0.0f;
    k.maxPush[lane] = used ? cc->maxPush : 0.0f;
    k.pairScale[lane] = used ? cc->pairScale : 1.0f;
    k.together[lane] = used && cc->pointsTogether ? 1.0f : 0.0f;
    k.roundA[lane] = used && cc->roundA ? 1.0f : 0.0f;
    k.roundB[lane] = used && cc->roundB ? 1.0f : 0.0f;
    for (int j = 0; j < 2; ++j) {
        WideContactPoint& p = k.points[j];
        const bool present = used && j < cc->pointCount;
        const ContactPointConstraint* cp = present ? &cc->points[j] : nullptr;
        p.rAx[lane] = present ? cp->rA.x : 0.0f, p.rAy[lane] = present ? cp->rA.y : 0.0f;
        p.rBx[lane] = present ? cp->rB.x : 0.0f, p.rBy[lane] = present ? cp->rB.y : 0.0f;
        p.adjustedSeparation[lane] = present ? cp->adjustedSeparation : 0.0f;
        p.normalMass[lane] = present ? cp->normalMass : 0.0f;
        p.tangentMass[lane] = present ? cp->tangentMass : 0.0f;
        p.normalImpulse[lane] = present ? cp->normalImpulse : 0.0f;
        p.tangentImpulse[lane] = present ? cp->tangentImpulse : 0.0f;
        p.maxNormalImpulse[lane] = present ? cp->maxNormalImpulse : 0.0f;
        p.present[lane] = present ? 1.0f : 0.0f;
    }
}

}  // namespace

void packWideContactBlock(SolverArrays& s, int block, int start, int last) {
    const int zero = static_cast<int>(s.states.size()) - 1;
    WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(block)];
    for (int lane = 0; lane < 4; ++lane) {
        const int r = start + lane;
        packLane(k, lane, r < last ? &s.constraints[static_cast<std::size_t>(r)] : nullptr, r, zero);
    }
}

void prepareWideContactLane(const WorldState& w, const RowContext& x, int contact, WideContactBlock& k, int lane) {
    // The scalar row's own preparation, on the stack: the lane holds exactly
    // what packing that row would have given.
    ContactConstraint cc;
    prepareContactRow(w, x, contact, cc);
    finishContactRow(x, w.settings.penetrationSlop, cc);
    packLane(k, lane, &cc, -1, x.zeroState);
}

void packEmptyWideContactLane(WideContactBlock& k, int lane, int zeroState) {
    packLane(k, lane, nullptr, -1, zeroState);
}

void storeWideContacts(SolverArrays& s, SlotArray<Contact>& contacts, int firstBlock, int lastBlock) {
    for (int i = firstBlock; i < lastBlock; ++i) {
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(i)];
        for (int lane = 0; lane < 4; ++lane) {
            if (k.contact[lane] < 0) continue;
            Contact& ct = contacts[k.contact[lane]];
            for (int j = 0; j < ct.manifold.pointCount; ++j) {
                ct.normalImpulse[j] = k.points[j].normalImpulse[lane];
                ct.tangentImpulse[j] = k.points[j].tangentImpulse[lane];
            }
        }
    }
}

namespace {

struct WideVelocities {
    Float4 vAx, vAy, wA, vBx, vBy, wB;
};

/// A point's arms and masses, loaded once per sweep of its block.
struct WideArms {
    Float4 rAx, rAy, rBx, rBy;
};
WideArms armsOf(const WideContactPoint& p) { return {load4(p.rAx), load4(p.rAy), load4(p.rBx), load4(p.rBy)}; }

/// dot((v_B + ω_B × r_B) − (v_A + ω_A × r_A), d) for a direction (dx, dy),
/// with ω × r = (−ω·r_y, ω·r_x) as i2d::cross(float, Vec2).
Float4 relativeSpeed(const WideVelocities& v, const WideArms& r, Float4 dx, Float4 dy) {
    const Float4 ux = (v.vBx + (-v.wB) * r.rBy) - (v.vAx + (-v.wA) * r.rAy);
    const Float4 uy = (v.vBy + v.wB * r.rBx) - (v.vAy + v.wA * r.rAx);
    return ux * dx + uy * dy;
}

/// Applies the impulse P = (px, py) at the point where `m` holds: A (−), B (+).
inline __attribute__((always_inline)) void applyMasked(Mask4 m, const WideArms& r, Float4 px, Float4 py, Float4 mA,
                                                       Float4 iA, Float4 mB, Float4 iB, WideVelocities& v) {
    v.vAx = select(m, v.vAx - mA * px, v.vAx);
    v.vAy = select(m, v.vAy - mA * py, v.vAy);
    v.wA = select(m, v.wA - iA * (r.rAx * py - r.rAy * px), v.wA);
    v.vBx = select(m, v.vBx + mB * px, v.vBx);
    v.vBy = select(m, v.vBy + mB * py, v.vBy);
    v.wB = select(m, v.wB + iB * (r.rBx * py - r.rBy * px), v.wB);
}

}  // namespace

void warmStartWideContacts(SolverArrays& s, int firstBlock, int lastBlock) {
    BodyState* states = s.states.data();
    for (int i = firstBlock; i < lastBlock; ++i) {
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(i)];
        WideBody A = gatherBodies(states, k.a), B = gatherBodies(states, k.b);
        WideVelocities v{A.vx, A.vy, A.w, B.vx, B.vy, B.w};
        const Float4 nx = load4(k.nx), ny = load4(k.ny);
        const Float4 tx = ny, ty = -nx;  // rightPerp(n)
        const Float4 mA = load4(k.mA), iA = load4(k.iA), mB = load4(k.mB), iB = load4(k.iB);
        for (const WideContactPoint& p : k.points) {
            const Float4 ln = load4(p.normalImpulse), lt = load4(p.tangentImpulse);
            applyMasked(nonZero(load4(p.present)), armsOf(p), ln * nx + lt * tx, ln * ny + lt * ty, mA, iA, mB, iB, v);
        }
        A.vx = v.vAx, A.vy = v.vAy, A.w = v.wA;
        B.vx = v.vBx, B.vy = v.vBy, B.w = v.wB;
        scatterVelocities(states, k.a, A, k.mA, k.iA);
        scatterVelocities(states, k.b, B, k.mB, k.iB);
    }
}

namespace {

template <bool kTrackMax>
void solveWideContactsFor(SolverArrays& s, SolvePass pass, float h, bool leaveImpacts, float impactSpeed,
                          int firstBlock, int lastBlock) {
    const Float4 invH = splat(1.0f / h), zero = splat(0.0f), one = splat(1.0f);
    const Float4 minusImpactSpeed = splat(-impactSpeed);
    const bool softBias = pass == SolvePass::soft_bias;
    BodyState* states = s.states.data();
    for (int i = firstBlock; i < lastBlock; ++i) {
        WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(i)];
        WideBody A = gatherBodies(states, k.a), B = gatherBodies(states, k.b);
        WideVelocities v{A.vx, A.vy, A.w, B.vx, B.vy, B.w};
        const Float4 nx = load4(k.nx), ny = load4(k.ny);
        const Float4 mA = load4(k.mA), iA = load4(k.iA), mB = load4(k.mB), iB = load4(k.iB);
        // A round side's contact point does not turn with it (contact_solver.cpp).
        const Mask4 roundA = nonZero(load4(k.roundA)), roundB = nonZero(load4(k.roundB));
        const Float4 qAc = select(roundA, one, A.qc), qAs = select(roundA, zero, A.qs);
        const Float4 qBc = select(roundB, one, B.qc), qBs = select(roundB, zero, B.qs);
        const Float4 dpx = B.dpx - A.dpx, dpy = B.dpy - A.dpy;

        // Each point's target: Δλ = −m·ms·(vn + bias) − is·λ, and whether the
        // last relax leaves it to the impact law.
        WideArms arms[2];
        Float4 bias[2], ms[2], is[2];
        Mask4 skip[2], present[2];
        for (int j = 0; j < 2; ++j) {
            const WideContactPoint& p = k.points[j];
            const WideArms& r = arms[j] = armsOf(p);
            present[j] = nonZero(load4(p.present));
            const Float4 rotBx = qBc * r.rBx - qBs * r.rBy, rotBy = qBs * r.rBx + qBc * r.rBy;
            const Float4 rotAx = qAc * r.rAx - qAs * r.rAy, rotAy = qAs * r.rAx + qAc * r.rAy;
            const Float4 dx = dpx + (rotBx - rotAx), dy = dpy + (rotBy - rotAy);
            const Float4 sep = (dx * nx + dy * ny) + load4(p.adjustedSeparation);
            const Mask4 speculative = sep > zero;
            skip[j] = leaveImpacts ? speculative & (relativeSpeed(v, r, nx, ny) < minusImpactSpeed) : Mask4{};
            if (softBias) {
                bias[j] = select(speculative, sep * invH, max4(load4(k.biasRate) * sep, -load4(k.maxPush)));
                ms[j] = select(speculative, one, load4(k.massScale));
                is[j] = select(speculative, zero, load4(k.impulseScale));
            } else {
                bias[j] = select(speculative, sep * invH, zero);
                ms[j] = one;
                is[j] = zero;
            }
        }

        // Normal rows: both points against the same velocities where the
        // manifold's points go together, one after the other elsewhere.
        const Mask4 pair = andNot(andNot(nonZero(load4(k.together)), skip[0]), skip[1]);
        const Float4 scale = select(pair, load4(k.pairScale), one);
        WideContactPoint& p0 = k.points[0];
        WideContactPoint& p1 = k.points[1];
        Float4 increment[2];
        Mask4 acts[2];
        for (int j = 0; j < 2; ++j) {
            WideContactPoint& p = k.points[j];
            const Float4 lambda = load4(p.normalImpulse);
            const Float4 vn = relativeSpeed(v, arms[j], nx, ny);
            const Float4 alone = (-load4(p.normalMass)) * ms[j] * (vn + bias[j]) - is[j] * lambda;
            const Float4 next = max4(lambda + scale * alone, zero);
            increment[j] = next - lambda;
            acts[j] = andNot(present[j], skip[j]);
            store4(p.normalImpulse, select(acts[j], next, lambda));
            if (j == 0) {
                // One after the other: the first point acts before the second is solved.
                const Mask4 now = andNot(acts[0], pair);
                if constexpr (kTrackMax)
                    store4(p0.maxNormalImpulse,
                           select(now, max4(load4(p0.maxNormalImpulse), increment[0]), load4(p0.maxNormalImpulse)));
                applyMasked(now, arms[0], increment[0] * nx, increment[0] * ny, mA, iA, mB, iB, v);
            }
        }
        {
            const Mask4 later = acts[0] & pair;
            if constexpr (kTrackMax)
                store4(p0.maxNormalImpulse,
                       select(later, max4(load4(p0.maxNormalImpulse), increment[0]), load4(p0.maxNormalImpulse)));
            applyMasked(later, arms[0], increment[0] * nx, increment[0] * ny, mA, iA, mB, iB, v);
            if constexpr (kTrackMax)
                store4(p1.maxNormalImpulse,
                       select(acts[1], max4(load4(p1.maxNormalImpulse), increment[1]), load4(p1.maxNormalImpulse)));
            applyMasked(acts[1], arms[1], increment[1] * nx, increment[1] * ny, mA, iA, mB, iB, v);
        }

        // Coulomb friction, bounded by μ times the point's own normal impulse.
        const Float4 tx = ny, ty = -nx;  // rightPerp(n)
        const Float4 friction = load4(k.friction), tangentSpeed = load4(k.tangentSpeed);
        for (int j = 0; j < 2; ++j) {
            WideContactPoint& p = k.points[j];
            const Float4 vt = relativeSpeed(v, arms[j], tx, ty) - tangentSpeed;
            const Float4 lambda = load4(p.tangentImpulse);
            const Float4 maxFriction = friction * load4(p.normalImpulse);
            const Float4 next = clamp4(lambda + (-load4(p.tangentMass)) * vt, -maxFriction, maxFriction);
            const Float4 impulse = next - lambda;
            store4(p.tangentImpulse, select(present[j], next, lambda));
            applyMasked(present[j], arms[j], impulse * tx, impulse * ty, mA, iA, mB, iB, v);
        }
        A.vx = v.vAx, A.vy = v.vAy, A.w = v.wA;
        B.vx = v.vBx, B.vy = v.vBy, B.w = v.wB;
        scatterVelocities(states, k.a, A, k.mA, k.iA);
        scatterVelocities(states, k.b, B, k.mB, k.iB);
    }
}

}  // namespace

void solveWideContacts(SolverArrays& s, SolvePass pass, float h, bool leaveImpacts, float impactSpeed, int firstBlock,
                       int lastBlock, bool trackMax) {
    if (trackMax)
        solveWideContactsFor<true>(s, pass, h, leaveImpacts, impactSpeed, firstBlock, lastBlock);
    else
        solveWideContactsFor<false>(s, pass, h, leaveImpacts, impactSpeed, firstBlock, lastBlock);
}

void writeBackWideContacts(SolverArrays& s, int firstBlock, int lastBlock) {
    for (int i = firstBlock; i < lastBlock; ++i) {
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(i)];
        for (int lane = 0; lane < 4; ++lane) {
            if (k.row[lane] < 0) continue;
            ContactConstraint& cc = s.constraints[static_cast<std::size_t>(k.row[lane])];
            for (int j = 0; j < cc.pointCount; ++j) {
                ContactPointConstraint& cp = cc.points[j];
                cp.normalImpulse = k.points[j].normalImpulse[lane];
                cp.tangentImpulse = k.points[j].tangentImpulse[lane];
                cp.maxNormalImpulse = k.points[j].maxNormalImpulse[lane];
            }
        }
    }
}

void dropWideContactImpulses(SolverArrays& s, const std::vector<char>& bad) {
    for (WideContactBlock& k : s.wideContacts)
        for (int lane = 0; lane < 4; ++lane) {
            if (!bad[static_cast<std::size_t>(k.a[lane])] && !bad[static_cast<std::size_t>(k.b[lane])]) continue;
            for (WideContactPoint& p : k.points)
                p.normalImpulse[lane] = p.tangentImpulse[lane] = p.maxNormalImpulse[lane] = 0.0f;
        }
}

}  // namespace i2d::detail
