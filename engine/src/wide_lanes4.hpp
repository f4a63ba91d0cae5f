// One block of a wide sweep in the four lanes of Float4 (wide_lanes.hpp):
// SSE2 on x86-64, the portable scalar path elsewhere.
#pragma once

#include "float4.hpp"
#include "wide_body.hpp"
#include "wide_contact.hpp"
#include "wide_lanes.hpp"

namespace i2d::detail {

/// One block in the lanes of Float4.
template <class Block>
struct Lanes4 {
    using V = Float4;
    using M = Mask4;
    Block* k;
    WideContactCold* cold = nullptr;  ///< a contact block's cold part (its sweeps only)
    static V splat(float x) { return detail::splat(x); }
    V load(float (Block::*f)[4]) const { return load4(k->*f); }
    void store(float (Block::*f)[4], V x) const { store4(k->*f, x); }
    /// A contact block's point j.
    V load(int j, float (WideContactPoint::*f)[4]) const { return load4(k->points[j].*f); }
    void store(int j, float (WideContactPoint::*f)[4], V x) const { store4(k->points[j].*f, x); }
    /// The lanes whose flags (a contact block's) have every bit of `bits`.
    M flags(std::uint32_t bits) const { return hasBits(k->flags, bits); }
    /// A contact block's largest normal impulse of point j (WideContactCold).
    V loadMax(int j) const { return load4(cold->maxNormalImpulse[j]); }
    void storeMax(int j, V x) const { store4(cold->maxNormalImpulse[j], x); }
    WideBodyT<V> gather(const BodyState* states, bool sideA) const {
        const WideBody b = gatherBodies(states, sideA ? k->a : k->b);
        return {b.vx, b.vy, b.w, b.reserved, b.dpx, b.dpy, b.qc, b.qs};
    }
    void scatter(BodyState* states, bool sideA, const WideBodyT<V>& b) const {
        const WideBody w{b.vx, b.vy, b.w, b.reserved, b.dpx, b.dpy, b.qc, b.qs};
        if (sideA)
            scatterVelocities(states, k->a, w, k->mA, k->iA);
        else
            scatterVelocities(states, k->b, w, k->mB, k->iB);
    }
};

}  // namespace i2d::detail
