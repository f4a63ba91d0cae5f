// Four revolute point blocks at a time (see wide_revolute.hpp). Per lane, as
// revolute_joint.cpp: anchors turned by each body's rotation since the step
// began, Ċ = v_B + ω_B × r_B − v_A − ω_A × r_A, the separation C, the 2×2
// effective mass K solved by Cramer's rule, the impulse −massScale·K⁻¹(Ċ + bias·C)
// − impulseScale·λ, applied to both bodies.
#include "wide_revolute.hpp"

#include "joint_rows.hpp"
#include "wide_body.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void packWideRevolutes(const WorldState& w, SolverArrays& s, int first, int last) {
    const int zero = static_cast<int>(s.states.size()) - 1;
    const bool warm = w.settings.enableWarmStarting;
    for (int start = first; start < last; start += 4) {
        WideRevoluteBlock& block = s.wideRevolutes.emplace_back();
        for (int lane = 0; lane < 4; ++lane) {
            const int place = start + lane;
            if (place >= last) {
                block.a[lane] = block.b[lane] = zero;
                block.joint[lane] = -1;
                block.rAx[lane] = block.rAy[lane] = block.rBx[lane] = block.rBy[lane] = 0.0f;
                block.dcx[lane] = block.dcy[lane] = 0.0f;
                block.mA[lane] = block.iA[lane] = block.mB[lane] = block.iB[lane] = 0.0f;
                block.px[lane] = block.py[lane] = 0.0f;
                continue;
            }
            const JointSlot& slot =
                s.jointSlots[static_cast<std::size_t>(s.jointOrder[static_cast<std::size_t>(place)])];
            const Vec2 rA = slot.rA, rB = slot.rB, dc = slot.deltaCenter;
            const Vec2 p = warm ? w.joints[slot.joint].impulses.linear : Vec2{};
            block.a[lane] = slot.a >= 0 ? slot.a : zero;
            block.b[lane] = slot.b >= 0 ? slot.b : zero;
            block.joint[lane] = slot.joint;
            block.rAx[lane] = rA.x, block.rAy[lane] = rA.y, block.rBx[lane] = rB.x, block.rBy[lane] = rB.y;
            block.dcx[lane] = dc.x, block.dcy[lane] = dc.y;
            block.mA[lane] = slot.invMassA, block.iA[lane] = slot.invIA;
            block.mB[lane] = slot.invMassB, block.iB[lane] = slot.invIB;
            block.px[lane] = p.x, block.py[lane] = p.y;
        }
    }
}

namespace {

/// A block's anchors turned by the bodies' rotations since the step began.
struct WideAnchors {
    Float4 rAx, rAy, rBx, rBy;
};
WideAnchors turnedAnchors(const WideRevoluteBlock& k, const WideBody& A, const WideBody& B) {
    const Float4 ax = load4(k.rAx), ay = load4(k.rAy), bx = load4(k.rBx), by = load4(k.rBy);
    return {A.qc * ax - A.qs * ay, A.qs * ax + A.qc * ay, B.qc * bx - B.qs * by, B.qs * bx + B.qc * by};
}

/// The point matrix of turned anchors r: K (k11, k12, k22) and 1/det K (0
/// when singular), as solvePointRows computes it.
struct WidePointMatrix {
    Float4 k11, k12, k22, inv;
};
WidePointMatrix pointMatrixOf(const WideRevoluteBlock& k, const WideAnchors& r) {
    const Float4 mA = load4(k.mA), iA = load4(k.iA), mB = load4(k.mB), iB = load4(k.iB);
    const Float4 m = mA + mB;
    WidePointMatrix K;
    K.k11 = m + r.rAy * r.rAy * iA + r.rBy * r.rBy * iB;
    K.k12 = -(r.rAy * r.rAx * iA) - r.rBy * r.rBx * iB;
    K.k22 = m + r.rAx * r.rAx * iA + r.rBx * r.rBx * iB;
    const Float4 det = K.k11 * K.k22 - K.k12 * K.k12;
    K.inv = whereNonZero(det, splat(1.0f) / det);
    return K;
}

/// Applies the impulse P at the anchors: A (−), B (+).
void applyWide(const WideRevoluteBlock& k, const WideAnchors& r, Float4 px, Float4 py, WideBody& A, WideBody& B) {
    const Float4 mA = load4(k.mA), iA = load4(k.iA), mB = load4(k.mB), iB = load4(k.iB);
    A.vx = A.vx - mA * px;
    A.vy = A.vy - mA * py;
    A.w = A.w - iA * (r.rAx * py - r.rAy * px);
    B.vx = B.vx + mB * px;
    B.vy = B.vy + mB * py;
    B.w = B.w + iB * (r.rBx * py - r.rBy * px);
}

/// The block's anchors turned to the current positions and its K: kept from
/// the last pass when the positions have not moved since (`kept`), else made
/// and kept for the passes until they move.
inline __attribute__((always_inline)) void frameOf(WideRevoluteBlock& k, const WideBody& A, const WideBody& B,
                                                   bool kept, WideAnchors& r, WidePointMatrix& K) {
    if (kept) {
        r = {load4(k.turnedAx), load4(k.turnedAy), load4(k.turnedBx), load4(k.turnedBy)};
        K = {load4(k.k11), load4(k.k12), load4(k.k22), load4(k.invDet)};
        return;
    }
    r = turnedAnchors(k, A, B);
    K = pointMatrixOf(k, r);
    store4(k.turnedAx, r.rAx), store4(k.turnedAy, r.rAy), store4(k.turnedBx, r.rBx), store4(k.turnedBy, r.rBy);
    store4(k.k11, K.k11), store4(k.k12, K.k12), store4(k.k22, K.k22), store4(k.invDet, K.inv);
}

/// A block's two sides gathered, with its anchors and K (frameOf).
struct WideHinges {
    WideBody A, B;
    WideAnchors r;
    WidePointMatrix K;
};
inline __attribute__((always_inline)) WideHinges gatherHinges(const BodyState* states, WideRevoluteBlock& k,
                                                              bool kept) {
    WideHinges h{gatherBodies(states, k.a), gatherBodies(states, k.b), {}, {}};
    frameOf(k, h.A, h.B, kept, h.r, h.K);
    return h;
}

}  // namespace

void warmStartWideRevolutes(SolverArrays& s, int firstBlock, int lastBlock, bool kept) {
    BodyState* states = s.states.data();
    for (int i = firstBlock; i < lastBlock; ++i) {
        WideRevoluteBlock& k = s.wideRevolutes[static_cast<std::size_t>(i)];
        auto [A, B, r, K] = gatherHinges(states, k, kept);
        applyWide(k, r, load4(k.px), load4(k.py), A, B);
        scatterVelocities(states, k.a, A, k.mA, k.iA);
        scatterVelocities(states, k.b, B, k.mB, k.iB);
    }
}

void solveWideRevolutes(SolverArrays& s, const JointContext& ctx, int firstBlock, int lastBlock, bool kept) {
    const RowBias rb = rigidBias(ctx, 1.0f);  // the rates, applied to each component of the separation
    const Float4 bias = splat(rb.bias), massScale = splat(rb.massScale), impulseScale = splat(rb.impulseScale);
    BodyState* states = s.states.data();
    for (int i = firstBlock; i < lastBlock; ++i) {
        WideRevoluteBlock& k = s.wideRevolutes[static_cast<std::size_t>(i)];
        auto [A, B, r, K] = gatherHinges(states, k, kept);
        const Float4 cdx = (B.vx - B.w * r.rBy) - (A.vx - A.w * r.rAy);
        const Float4 cdy = (B.vy + B.w * r.rBx) - (A.vy + A.w * r.rAx);
        const Float4 sepx = (B.dpx - A.dpx) + (r.rBx - r.rAx) + load4(k.dcx);
        const Float4 sepy = (B.dpy - A.dpy) + (r.rBy - r.rAy) + load4(k.dcy);
        const Float4 bx = cdx + bias * sepx, by = cdy + bias * sepy;
        const Float4 x = K.inv * (K.k22 * bx - K.k12 * by), y = K.inv * (K.k11 * by - K.k12 * bx);
        const Float4 px = load4(k.px), py = load4(k.py);
        const Float4 ix = -(massScale * x) - impulseScale * px;
        const Float4 iy = -(massScale * y) - impulseScale * py;
        store4(k.px, px + ix);
        store4(k.py, py + iy);
        applyWide(k, r, ix, iy, A, B);
        scatterVelocities(states, k.a, A, k.mA, k.iA);
        scatterVelocities(states, k.b, B, k.mB, k.iB);
    }
}

void storeWideRevolutes(WorldState& w, float h) {
    const float invH = 1.0f / h;
    for (const WideRevoluteBlock& k : w.solver.wideRevolutes)
        for (int lane = 0; lane < 4; ++lane) {
            if (k.joint[lane] < 0) continue;
            Joint& joint = w.joints[k.joint[lane]];
            joint.impulses = JointImpulses{};
            joint.impulses.linear = {k.px[lane], k.py[lane]};
            joint.reactionForce = invH * joint.impulses.linear;
            joint.reactionTorque = 0.0f;
            joint.motorEffort = 0.0f;
            joint.lastForce = length(joint.reactionForce);
        }
}

void dropWideImpulses(SolverArrays& s, const std::vector<char>& bad) {
    for (WideRevoluteBlock& k : s.wideRevolutes)
        for (int lane = 0; lane < 4; ++lane)
            if (bad[static_cast<std::size_t>(k.a[lane])] || bad[static_cast<std::size_t>(k.b[lane])])
                k.px[lane] = k.py[lane] = 0.0f;
}

}  // namespace i2d::detail
