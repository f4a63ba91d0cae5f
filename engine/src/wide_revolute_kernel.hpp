// The warm start and the sweep of wide revolute blocks (wide_revolute.hpp),
// written once over a lane policy (wide_lanes.hpp): four lanes in
// wide_revolute.cpp, eight on CPUs with AVX2 in wide_avx2.cpp. Per lane, as
// revolute_joint.cpp: anchors turned by each body's rotation since the step
// began, Ċ = v_B + ω_B × r_B − v_A − ω_A × r_A, the separation C, the 2×2
// effective mass K solved by Cramer's rule, the impulse
// −massScale·K⁻¹(Ċ + bias·C) − impulseScale·λ, applied to both bodies. The
// same operations in the same order on every path: bit-identical results.
#pragma once

#include "wide_lanes.hpp"
#include "wide_revolute.hpp"

namespace i2d::detail {

/// A block's anchors turned by the bodies' rotations since the step began.
template <class V>
struct WideAnchorsT {
    V rAx, rAy, rBx, rBy;
};

/// The point matrix of turned anchors r: K (k11, k12, k22) and 1/det K (0
/// when singular), as solvePointRows computes it.
template <class V>
struct WidePointMatrixT {
    V k11, k12, k22, inv;
};

/// A block's two sides gathered, with its anchors and K.
template <class V>
struct WideHingesT {
    WideBodyT<V> A, B;
    WideAnchorsT<V> r;
    WidePointMatrixT<V> K;
};

/// The block's anchors turned to the current positions and its K: kept from
/// the last pass when the positions have not moved since (`kept`), else made
/// and kept for the passes until they move.
template <class L>
I2D_KERNEL WideHingesT<typename L::V> gatherHinges(const L& k, const BodyState* states, bool kept) {
    using V = typename L::V;
    using B = WideRevoluteBlock;
    WideHingesT<V> h{k.gather(states, true), k.gather(states, false), {}, {}};
    if (kept) {
        h.r = {k.load(&B::turnedAx), k.load(&B::turnedAy), k.load(&B::turnedBx), k.load(&B::turnedBy)};
        h.K = {k.load(&B::k11), k.load(&B::k12), k.load(&B::k22), k.load(&B::invDet)};
        return h;
    }
    const V ax = k.load(&B::rAx), ay = k.load(&B::rAy), bx = k.load(&B::rBx), by = k.load(&B::rBy);
    const WideBodyT<V>&A = h.A, &Bd = h.B;
    h.r = {A.qc * ax - A.qs * ay, A.qs * ax + A.qc * ay, Bd.qc * bx - Bd.qs * by, Bd.qs * bx + Bd.qc * by};
    const V mA = k.load(&B::mA), iA = k.load(&B::iA), mB = k.load(&B::mB), iB = k.load(&B::iB);
    const V m = mA + mB;
    const WideAnchorsT<V>& r = h.r;
    h.K.k11 = m + r.rAy * r.rAy * iA + r.rBy * r.rBy * iB;
    h.K.k12 = -(r.rAy * r.rAx * iA) - r.rBy * r.rBx * iB;
    h.K.k22 = m + r.rAx * r.rAx * iA + r.rBx * r.rBx * iB;
    const V det = h.K.k11 * h.K.k22 - h.K.k12 * h.K.k12;
    h.K.inv = whereNonZero(det, L::splat(1.0f) / det);
    k.store(&B::turnedAx, r.rAx), k.store(&B::turnedAy, r.rAy), k.store(&B::turnedBx, r.rBx);
    k.store(&B::turnedBy, r.rBy);
    k.store(&B::k11, h.K.k11), k.store(&B::k12, h.K.k12), k.store(&B::k22, h.K.k22), k.store(&B::invDet, h.K.inv);
    return h;
}

/// Applies the impulse P at the anchors: A (−), B (+).
template <class L>
I2D_KERNEL void applyHinge(const L& k, const WideAnchorsT<typename L::V>& r, typename L::V px, typename L::V py,
                           WideBodyT<typename L::V>& A, WideBodyT<typename L::V>& B) {
    using V = typename L::V;
    using W = WideRevoluteBlock;
    const V mA = k.load(&W::mA), iA = k.load(&W::iA), mB = k.load(&W::mB), iB = k.load(&W::iB);
    A.vx = A.vx - mA * px;
    A.vy = A.vy - mA * py;
    A.w = A.w - iA * (r.rAx * py - r.rAy * px);
    B.vx = B.vx + mB * px;
    B.vy = B.vy + mB * py;
    B.w = B.w + iB * (r.rBx * py - r.rBy * px);
}

template <class L>
I2D_KERNEL void warmStartHingeBlock(const L& k, BodyState* states, bool kept) {
    auto [A, B, r, K] = gatherHinges(k, states, kept);
    applyHinge(k, r, k.load(&WideRevoluteBlock::px), k.load(&WideRevoluteBlock::py), A, B);
    k.scatter(states, true, A);
    k.scatter(states, false, B);
}

/// The pass's rates (rigidBias), applied to each component of the separation.
struct HingeRates {
    float bias, massScale, impulseScale;
};

template <class L>
I2D_KERNEL void solveHingeBlock(const L& k, BodyState* states, const HingeRates& rates, bool kept) {
    using V = typename L::V;
    using W = WideRevoluteBlock;
    const V bias = L::splat(rates.bias), massScale = L::splat(rates.massScale);
    const V impulseScale = L::splat(rates.impulseScale);
    auto [A, B, r, K] = gatherHinges(k, states, kept);
    const V cdx = (B.vx - B.w * r.rBy) - (A.vx - A.w * r.rAy);
    const V cdy = (B.vy + B.w * r.rBx) - (A.vy + A.w * r.rAx);
    const V sepx = (B.dpx - A.dpx) + (r.rBx - r.rAx) + k.load(&W::dcx);
    const V sepy = (B.dpy - A.dpy) + (r.rBy - r.rAy) + k.load(&W::dcy);
    const V bx = cdx + bias * sepx, by = cdy + bias * sepy;
    const V x = K.inv * (K.k22 * bx - K.k12 * by), y = K.inv * (K.k11 * by - K.k12 * bx);
    const V px = k.load(&W::px), py = k.load(&W::py);
    const V ix = -(massScale * x) - impulseScale * px;
    const V iy = -(massScale * y) - impulseScale * py;
    k.store(&W::px, px + ix);
    k.store(&W::py, py + iy);
    applyHinge(k, r, ix, iy, A, B);
    k.scatter(states, true, A);
    k.scatter(states, false, B);
}

}  // namespace i2d::detail
