// The warm start and the sweep of wide contact blocks (wide_contact.hpp),
// written once over a lane policy L that says how lanes are loaded, stored,
// gathered and scattered: Lanes4 (wide_contact.cpp) runs one block in the
// four lanes of Float4; on x86-64 CPUs with AVX2, Lanes8
// (wide_avx2.cpp) runs two blocks of the same colour in the eight
// lanes of an AVX register. Two blocks of one colour touch no movable body in
// common, so solving them together is solving them one after the other. Each
// lane does the same IEEE operations (+, −, ×, comparisons, selects; no fused
// multiply-add, which AVX2 does not bring) in the same order as the scalar
// row of contact_solver.cpp, so every path gives bit-identical results
// (tests/unit/test_wide_contact.cpp runs them all). The order of operations
// follows solveContactsFor, warmStartContacts and their helpers line by line:
// normal rows with their regimes (speculative, soft push capped at maxPush,
// relax), a manifold's two points together (the block solve) or one after
// the other, then Coulomb friction per point. What the scalar row skips with a
// branch, a lane keeps with a select.
//
// Points (1 or 2) is the most points a lane of the block has: a block of
// one-point manifolds (circles, capsules across each other) skips the second
// point's loads and arithmetic, which in a lane without that point change
// nothing (its masks are all false), so both give the same bits.
//
// This header defines templates only: the eight-lane instantiations use a
// vector type private to the AVX2 file and so stay private to it, and no
// function compiled for AVX2 can be picked by the linker for code that runs
// on a CPU without it.
#pragma once

#include <type_traits>

#include "wide_contact.hpp"
#include "wide_lanes.hpp"

namespace i2d::detail {

template <class V>
struct WideVelocitiesT {
    V vAx, vAy, wA, vBx, vBy, wB;
};

/// A point's arms, loaded once per sweep of its block.
template <class V>
struct WideArmsT {
    V rAx, rAy, rBx, rBy;
};

/// dot((v_B + ω_B × r_B) − (v_A + ω_A × r_A), d) for a direction (dx, dy),
/// with ω × r = (−ω·r_y, ω·r_x) as i2d::cross(float, Vec2).
template <class V>
I2D_KERNEL V relativeSpeed(const WideVelocitiesT<V>& v, const WideArmsT<V>& r, V dx, V dy) {
    const V ux = (v.vBx + (-v.wB) * r.rBy) - (v.vAx + (-v.wA) * r.rAy);
    const V uy = (v.vBy + v.wB * r.rBx) - (v.vAy + v.wA * r.rAx);
    return ux * dx + uy * dy;
}

/// Applies the impulse P = (px, py) at the point where `m` holds: A (−), B (+).
template <class V, class M>
I2D_KERNEL void applyMasked(M m, const WideArmsT<V>& r, V px, V py, V mA, V iA, V mB, V iB, WideVelocitiesT<V>& v) {
    v.vAx = select(m, v.vAx - mA * px, v.vAx);
    v.vAy = select(m, v.vAy - mA * py, v.vAy);
    v.wA = select(m, v.wA - iA * (r.rAx * py - r.rAy * px), v.wA);
    v.vBx = select(m, v.vBx + mB * px, v.vBx);
    v.vBy = select(m, v.vBy + mB * py, v.vBy);
    v.wB = select(m, v.wB + iB * (r.rBx * py - r.rBy * px), v.wB);
}

/// Calls f with std::integral_constant<int, 1> or <int, 2> as `points` says,
/// so that a sweep's loop over blocks is compiled once per point count and
/// the choice is made once, outside it.
template <class F>
I2D_KERNEL void withPointCount(int points, F&& f) {
    if (points == 1)
        f(std::integral_constant<int, 1>{});
    else
        f(std::integral_constant<int, 2>{});
}

using BlockField = float (WideContactBlock::*)[4];
using PointField = float (WideContactPoint::*)[4];

/// The flag of point j (0 or 1) of a contact block.
I2D_KERNEL std::uint32_t pointFlag(int j) { return j == 0 ? kWidePoint0 : kWidePoint1; }

template <int Points, class L>
I2D_KERNEL void warmStartBlock(const L& k, BodyState* states) {
    static_assert(Points == 1 || Points == 2);
    using V = typename L::V;
    using M = typename L::M;
    WideBodyT<V> A = k.gather(states, true), B = k.gather(states, false);
    WideVelocitiesT<V> v{A.vx, A.vy, A.w, B.vx, B.vy, B.w};
    const V nx = k.load(&WideContactBlock::nx), ny = k.load(&WideContactBlock::ny);
    const V tx = ny, ty = -nx;  // rightPerp(n)
    const V mA = k.load(&WideContactBlock::mA), iA = k.load(&WideContactBlock::iA);
    const V mB = k.load(&WideContactBlock::mB), iB = k.load(&WideContactBlock::iB);
    for (int j = 0; j < Points; ++j) {
        const V ln = k.load(j, &WideContactPoint::normalImpulse), lt = k.load(j, &WideContactPoint::tangentImpulse);
        const WideArmsT<V> r{k.load(j, &WideContactPoint::rAx), k.load(j, &WideContactPoint::rAy),
                             k.load(j, &WideContactPoint::rBx), k.load(j, &WideContactPoint::rBy)};
        applyMasked<V, M>(k.flags(pointFlag(j)), r, ln * nx + lt * tx, ln * ny + lt * ty, mA, iA, mB, iB, v);
    }
    A.vx = v.vAx, A.vy = v.vAy, A.w = v.wA;
    B.vx = v.vBx, B.vy = v.vBy, B.w = v.wB;
    k.scatter(states, true, A);
    k.scatter(states, false, B);
}

struct SweepParams {
    float invH;
    float minusImpactSpeed;
    bool softBias;
    bool leaveImpacts;
    bool trackMax;  ///< keep maxNormalImpulse (only the velocity-bias restitution reads it, through the rows)
    Softness dynamicSoft, staticSoft;  ///< the rows' softness: static where a side cannot move (kWideImmovableSide)
    float maxPush;                     ///< the rows' push cap (WorldSettings::maxPushSpeed)
};

template <int Points, class L>
I2D_KERNEL void solveBlock(const L& k, BodyState* states, const SweepParams& sp) {
    static_assert(Points == 1 || Points == 2);
    using V = typename L::V;
    using M = typename L::M;
    const V invH = L::splat(sp.invH), zero = L::splat(0.0f), one = L::splat(1.0f);
    const V minusImpactSpeed = L::splat(sp.minusImpactSpeed);
    WideBodyT<V> A = k.gather(states, true), B = k.gather(states, false);
    WideVelocitiesT<V> v{A.vx, A.vy, A.w, B.vx, B.vy, B.w};
    const V nx = k.load(&WideContactBlock::nx), ny = k.load(&WideContactBlock::ny);
    const V mA = k.load(&WideContactBlock::mA), iA = k.load(&WideContactBlock::iA);
    const V mB = k.load(&WideContactBlock::mB), iB = k.load(&WideContactBlock::iB);
    // A round side's contact point does not turn with it (contact_solver.cpp).
    const M roundA = k.flags(kWideRoundA), roundB = k.flags(kWideRoundB);
    const V qAc = select(roundA, one, A.qc), qAs = select(roundA, zero, A.qs);
    const V qBc = select(roundB, one, B.qc), qBs = select(roundB, zero, B.qs);
    const V dpx = B.dpx - A.dpx, dpy = B.dpy - A.dpy;
    // The rows' softness, the stiffer one where a side cannot move (prepareContactRow).
    const M immovable = k.flags(kWideImmovableSide);
    const V biasRate = select(immovable, L::splat(sp.staticSoft.biasRate), L::splat(sp.dynamicSoft.biasRate));
    const V massScale = select(immovable, L::splat(sp.staticSoft.massScale), L::splat(sp.dynamicSoft.massScale));
    const V impulseScale = select(immovable, L::splat(sp.staticSoft.impulseScale),
                                  L::splat(sp.dynamicSoft.impulseScale));

    // Each point's target: Δλ = −m·ms·(vn + bias) − is·λ, and whether the
    // last relax leaves it to the impact law.
    WideArmsT<V> arms[Points];
    V bias[Points], ms[Points], is[Points];
    M skip[Points], present[Points];
    for (int j = 0; j < Points; ++j) {
        const WideArmsT<V>& r = arms[j] = {k.load(j, &WideContactPoint::rAx), k.load(j, &WideContactPoint::rAy),
                                           k.load(j, &WideContactPoint::rBx), k.load(j, &WideContactPoint::rBy)};
        present[j] = k.flags(pointFlag(j));
        const V rotBx = qBc * r.rBx - qBs * r.rBy, rotBy = qBs * r.rBx + qBc * r.rBy;
        const V rotAx = qAc * r.rAx - qAs * r.rAy, rotAy = qAs * r.rAx + qAc * r.rAy;
        const V dx = dpx + (rotBx - rotAx), dy = dpy + (rotBy - rotAy);
        const V sep = (dx * nx + dy * ny) + k.load(j, &WideContactPoint::adjustedSeparation);
        const M speculative = sep > zero;
        skip[j] = sp.leaveImpacts ? speculative & (relativeSpeed(v, r, nx, ny) < minusImpactSpeed) : M{};
        if (sp.softBias) {
            // A deep overlap's row is rigid here (pushed apart on
            // pseudo-velocities instead, deep_overlap.cpp): no bias, full mass.
            const M rigid = speculative | k.flags(kWideDeep);
            const V soft = maxv<V, M>(biasRate * sep, -L::splat(sp.maxPush));
            bias[j] = select(speculative, sep * invH, select(rigid, zero, soft));
            ms[j] = select(rigid, one, massScale);
            is[j] = select(rigid, zero, impulseScale);
        } else {
            bias[j] = select(speculative, sep * invH, zero);
            ms[j] = one;
            is[j] = zero;
        }
    }

    // Normal rows: a manifold's two points together where they go together
    // (solvePointPair: the block solve, taken where both points press), one
    // after the other elsewhere.
    M block{};  // lanes whose points take the block solve
    V blockNext[Points];
    if constexpr (Points == 2) {
        const M pair = andNot(andNot(k.flags(kWideTogether), skip[0]), skip[1]);
        const V nm0 = k.load(0, &WideContactPoint::normalMass), nm1 = k.load(1, &WideContactPoint::normalMass);
        const V lambda0 = k.load(0, &WideContactPoint::normalImpulse);
        const V lambda1 = k.load(1, &WideContactPoint::normalImpulse);
        const V u0 = (-nm0) * ms[0] * (relativeSpeed(v, arms[0], nx, ny) + bias[0]) - is[0] * lambda0;
        const V u1 = (-nm1) * ms[1] * (relativeSpeed(v, arms[1], nx, ny) + bias[1]) - is[1] * lambda1;
        const V k12 = k.load(&WideContactBlock::pairCoupling);
        const V k0 = nm0 * k12, k1 = nm1 * k12;
        // 1 where the lane does not go together: no division by a vanishing determinant.
        const V det = select(pair, one - k0 * k1, one);
        blockNext[0] = lambda0 + (u0 - k0 * u1) / det;
        blockNext[1] = lambda1 + (u1 - k1 * u0) / det;
        block = andNot(andNot(pair, blockNext[0] < zero), blockNext[1] < zero);
        // Uncoupled lanes where the block solve would pull: each point clamped on its own.
        const M uncoupled = andNot(andNot(pair, k12 > zero), block);
        blockNext[0] = select(uncoupled, maxv<V, M>(lambda0 + u0, zero), blockNext[0]);
        blockNext[1] = select(uncoupled, maxv<V, M>(lambda1 + u1, zero), blockNext[1]);
        block = block | uncoupled;
    }
    V increment[Points];
    M acts[Points];
    for (int j = 0; j < Points; ++j) {
        const V lambda = k.load(j, &WideContactPoint::normalImpulse);
        const V vn = relativeSpeed(v, arms[j], nx, ny);
        const V alone = (-k.load(j, &WideContactPoint::normalMass)) * ms[j] * (vn + bias[j]) - is[j] * lambda;
        V next = maxv<V, M>(lambda + alone, zero);
        if constexpr (Points == 2) next = select(block, blockNext[j], next);
        increment[j] = next - lambda;
        acts[j] = andNot(present[j], skip[j]);
        k.store(j, &WideContactPoint::normalImpulse, select(acts[j], next, lambda));
        if (sp.trackMax) {
            const V old = k.loadMax(j);
            k.storeMax(j, select(acts[j], maxv<V, M>(old, increment[j]), old));
        }
        applyMasked<V, M>(acts[j], arms[j], increment[j] * nx, increment[j] * ny, mA, iA, mB, iB, v);
    }

    // Coulomb friction, bounded by μ times the point's own normal impulse.
    const V tx = ny, ty = -nx;  // rightPerp(n)
    const V friction = k.load(&WideContactBlock::friction), tangentSpeed = k.load(&WideContactBlock::tangentSpeed);
    for (int j = 0; j < Points; ++j) {
        const V vt = relativeSpeed(v, arms[j], tx, ty) - tangentSpeed;
        const V lambda = k.load(j, &WideContactPoint::tangentImpulse);
        const V maxFriction = friction * k.load(j, &WideContactPoint::normalImpulse);
        const V next = clampv<V, M>(lambda + (-k.load(j, &WideContactPoint::tangentMass)) * vt, -maxFriction,
                                    maxFriction);
        const V impulse = next - lambda;
        k.store(j, &WideContactPoint::tangentImpulse, select(present[j], next, lambda));
        applyMasked<V, M>(present[j], arms[j], impulse * tx, impulse * ty, mA, iA, mB, iB, v);
    }
    A.vx = v.vAx, A.vy = v.vAy, A.w = v.wA;
    B.vx = v.vBx, B.vy = v.vBy, B.w = v.wB;
    k.scatter(states, true, A);
    k.scatter(states, false, B);
}

}  // namespace i2d::detail
