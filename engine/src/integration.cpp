// Integration of the solver's bodies (integration.hpp).
#include "integration.hpp"

#include <cmath>
#include <vector>

namespace i2d::detail {

namespace {

/// The lanes of four bodies (their velocities transposed) where v.x, v.y or
/// ω is not finite (as nonFiniteLanes: x·0 is NaN for a non-finite x).
Mask4 nonFiniteVelocities(Float4 vx, Float4 vy, Float4 w) {
    const Float4 zero = splat(0.0f);
    return nonZero(vx * zero + vy * zero + w * zero);
}

/// integrateVelocities (without a lift to pay) for the four bodies at
/// `states` and `in`, in Float4, when all four are moved by forces and none ends
/// faster than maxSpeed (else false, nothing changed): the scalar loop's
/// operations in its order, so bit-identical.
bool integrateFourVelocities(BodyState* states, const BodyIntegration* in, float h, float maxSpeed2) {
    static_assert(offsetof(BodyIntegration, torque) == 8 && offsetof(BodyIntegration, invInertia) == 12 &&
                  offsetof(BodyIntegration, linearDampingFactor) == 16 &&
                  offsetof(BodyIntegration, angularDampingFactor) == 20);
    if (!(in[0].movedByForces && in[1].movedByForces && in[2].movedByForces && in[3].movedByForces)) return false;
    // Each record read by two four-float loads, (a.x, a.y, τ, 1/I) and
    // (1/I, linear, angular damping, the flag's word), and transposed: written
    // into arrays one float at a time and read back four at once, they
    // stalled on store forwarding.
    Float4 ax = load4(&in[0].linearAcceleration.x), ay = load4(&in[1].linearAcceleration.x),
           torque = load4(&in[2].linearAcceleration.x), invI = load4(&in[3].linearAcceleration.x);
    transpose(ax, ay, torque, invI);
    Float4 unused = load4(&in[0].invInertia), linear = load4(&in[1].invInertia), angular = load4(&in[2].invInertia),
           flagWord = load4(&in[3].invInertia);
    transpose(unused, linear, angular, flagWord);
    float* f = &states[0].v.x;
    Float4 vx = load4(f), vy = load4(f + 8), w = load4(f + 16), up = load4(f + 24);
    transpose(vx, vy, w, up);
    if (laneBits(nonFiniteVelocities(vx, vy, w)) != 0) return false;  // not finite: the scalar loop says so
    const Float4 step = splat(h);
    vx = (vx + step * ax) * linear;
    vy = (vy + step * ay) * linear;
    if (laneBits(vx * vx + vy * vy > splat(maxSpeed2)) != 0) return false;  // limitSpeed acts
    w = (w + step * invI * torque) * angular;
    transpose(vx, vy, w, up);
    store4(f, vx);
    store4(f + 8, vy);
    store4(f + 16, w);
    store4(f + 24, up);
    return true;
}

/// integratePositions for the four bodies at `states`, in Float4, when none
/// of them is faster than the limits (else false, nothing changed). The
/// same operations in the same order as the scalar loop (integrateRotation):
/// bit-identical. A position update is a square root and a division per
/// body; one at a time they were 7 % of a 1,000-circle scene's step.
bool integrateFourPositions(BodyState* states, float h, float maxSpeed2, float maxAngular) {
    static_assert(sizeof(BodyState) == 8 * sizeof(float) && offsetof(BodyState, dp) == 16 &&
                  offsetof(BodyState, dq) == 24);
    float* f = &states[0].v.x;
    Float4 vx = load4(f), vy = load4(f + 8), w = load4(f + 16), up = load4(f + 24);
    transpose(vx, vy, w, up);
    const Float4 fast = vx * vx + vy * vy;  // lengthSquared, as limitSpeed
    const Float4 absW = select(w < splat(0.0f), -w, w);
    // Limited, or not finite (the scalar loop says so).
    if (laneBits((fast > splat(maxSpeed2)) | (absW > splat(maxAngular)) | nonFiniteVelocities(vx, vy, w)) != 0)
        return false;
    Float4 dpx = load4(f + 4), dpy = load4(f + 12), c = load4(f + 20), sn = load4(f + 28);
    transpose(dpx, dpy, c, sn);
    const Float4 step = splat(h);
    dpx = dpx + step * vx;  // mulAdd(dp, h, v)
    dpy = dpy + step * vy;
    const Float4 angle = step * w;  // integrateRotation(dq, h·w)
    const Float4 rc = c - angle * sn, rs = sn + angle * c;
    const Float4 mag = sqrt4(rc * rc + rs * rs);
    const Float4 inv = select(mag > splat(0.0f), splat(1.0f) / mag, splat(0.0f));
    Float4 outC = rc * inv, outS = rs * inv;
    transpose(dpx, dpy, outC, outS);
    store4(f + 4, dpx);
    store4(f + 12, dpy);
    store4(f + 20, outC);
    store4(f + 28, outS);
    return true;
}

#if defined(I2D_AVX2_KERNEL)
bool avx2Lanes() { return wideLanes() == 8; }
#endif

}  // namespace

#if defined(I2D_AVX2_KERNEL)
// wide_avx2.cpp: the four-body functions above for eight bodies (bodies i
// and i + 4 in the two halves of each register), the same bits.
bool integrateEightVelocitiesAvx2(BodyState* states, const BodyIntegration* in, float h, float maxSpeed2);
bool integrateEightPositionsAvx2(BodyState* states, float h, float maxSpeed2, float maxAngular);
#endif

/// Bodies [begin, end) of the solver arrays (each body on its own: a stage
/// the workers may share). `payLift`: pay the last substep's push lift first
/// (soft_step, payPushLift), up being against gravity.
void integrateVelocities(SolverArrays& s, float h, float maxSpeed, std::size_t begin, std::size_t end, bool payLift,
                         Vec2 up, std::atomic<bool>& nonFinite) {
    auto integrate = [&](std::size_t i) {
        const BodyIntegration& in = s.integration[i];
        BodyState& st = s.states[i];
        if (nonFiniteVelocity(st)) {  // left as it is for stopNonFiniteBodies
            nonFinite.store(true, std::memory_order_relaxed);
            return;
        }
        if (!in.movedByForces) return;
        if (payLift) payPushLift(s, i, st, in.linearAcceleration, up, h);
        kickVelocity(st, in, h, maxSpeed);
    };
    auto four = [&](std::size_t i) {
        if (integrateFourVelocities(&s.states[i], &s.integration[i], h, maxSpeed * maxSpeed)) return;
        for (std::size_t k = i; k < i + 4; ++k) integrate(k);  // kinematic, or limited
    };
    std::size_t i = begin;
    if (!payLift) {
#if defined(I2D_AVX2_KERNEL)
        if (avx2Lanes())
            for (; i + 8 <= end; i += 8) {
                if (integrateEightVelocitiesAvx2(&s.states[i], &s.integration[i], h, maxSpeed * maxSpeed)) continue;
                four(i);
                four(i + 4);
            }
#endif
        for (; i + 4 <= end; i += 4) four(i);
    }
    for (; i < end; ++i) integrate(i);
}

void integratePositions(SolverArrays& s, float h, float maxSpeed, std::size_t begin, std::size_t end,
                        std::atomic<bool>& nonFinite) {
    const float maxAngular = kMaxRotationPerStep / h;
    auto integrate = [&](std::size_t i) {
        BodyState& st = s.states[i];
        if (nonFiniteVelocity(st)) {  // not moved; stopNonFiniteBodies stops it
            nonFinite.store(true, std::memory_order_relaxed);
            return;
        }
        clampVelocity(st, maxSpeed, maxAngular);
        // Eq. 3.2.3-3.2.4 with the new velocities.
        st.dp = mulAdd(st.dp, h, st.v);
        st.dq = integrateRotation(st.dq, h * st.w);
    };
    auto four = [&](std::size_t i) {
        if (integrateFourPositions(&s.states[i], h, maxSpeed * maxSpeed, maxAngular)) return;
        for (std::size_t k = i; k < i + 4; ++k) integrate(k);  // one of them is limited
    };
    std::size_t i = begin;
#if defined(I2D_AVX2_KERNEL)
    if (avx2Lanes())
        for (; i + 8 <= end; i += 8) {
            if (integrateEightPositionsAvx2(&s.states[i], h, maxSpeed * maxSpeed, maxAngular)) continue;
            four(i);
            four(i + 4);
        }
#endif
    for (; i + 4 <= end; i += 4) four(i);
    for (; i < end; ++i) integrate(i);
}

/// As integratePositions, moving each body by its velocity plus its
/// pseudo-velocity (split mode's push, or the soft step's push of deep
/// overlaps, deep_overlap.cpp), which is not kept: the body keeps only its
/// velocity.
void integratePositionsPushed(SolverArrays& s, float h, float maxSpeed, Vec2 up) {
    const float maxAngular = kMaxRotationPerStep / h;
    const std::size_t n = s.stateBodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        BodyState& st = s.states[i];
        clampVelocity(st, maxSpeed, maxAngular);
        // Kept for payPushLift (only steps with a deep overlap pay); the
        // pseudo-velocity's own lift is paid by pushDeepOverlaps.
        st.upBeforeRelax = dot(st.v, up);
        // The limits hold for the motion including the push: a light, small
        // body's pseudo-velocity could otherwise turn it by an angle whose
        // square overflows (fuzz_world: NaN rotation).
        BodyState moved = st;
        moved.v = st.v + s.biasV[i];
        moved.w = st.w + s.biasW[i];
        clampVelocity(moved, maxSpeed, maxAngular);
        st.dp = mulAdd(st.dp, h, moved.v);
        st.dq = integrateRotation(st.dq, h * moved.w);
    }
}

/// A sweep that left a body's velocity non-finite stops that body and drops
/// the accumulated impulses of every row on it, so all bodies stay finite.
/// Degenerate input gets there: fuzz_world found a prismatic joint between a
/// 0.24 kg and a 250 kg body of tiny inertia diverging in baumgarte until its
/// impulses overflowed, and welds on a body of inertia 7e-23 kg·m² driving
/// contact impulses to infinity. Looked for over the contiguous states, not
/// row by row (a per-row check cost 8 % of joint_grid): after each sweep in
/// baumgarte and split, by the integrations in the soft step (solver.cpp).
void stopNonFiniteBodies(SolverArrays& s) {
    const std::size_t n = s.stateBodies.size();
    Mask4 nonFinite = nonFiniteLanes(s.states[n]);  // the zero state
    for (std::size_t i = 0; i < n; ++i) nonFinite = nonFinite | nonFiniteLanes(s.states[i]);
    if ((laneBits(nonFinite) & kVelocityLanes) == 0) [[likely]]
        return;
    s.states[n] = BodyState{};
    std::vector<char> bad(n + 1, 0);  // the zero state, just reset, is not marked
    for (std::size_t i = 0; i < n; ++i) {
        BodyState& st = s.states[i];
        if ((laneBits(nonFiniteLanes(st)) & kVelocityLanes) == 0) continue;
        bad[i] = 1;
        st.v = Vec2{};
        st.w = 0.0f;
    }
    auto touches = [&](int index) { return index >= 0 && bad[static_cast<std::size_t>(index)]; };
    for (JointConstraint& jc : s.joints)
        if (touches(jc.a) || touches(jc.b) || touches(jc.c) || touches(jc.d)) jc.impulses = JointImpulses{};
    dropWideImpulses(s, bad);
    dropWideContactImpulses(s, bad);
    for (ContactConstraint& cc : s.constraints) {
        if (!touches(cc.a) && !touches(cc.b)) continue;
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            cp.normalImpulse = cp.tangentImpulse = cp.maxNormalImpulse = cp.biasImpulse = 0.0f;
        }
    }
}

/// As stopNonFiniteBodies for split mode's pseudo-velocities: a diverging
/// push is dropped for this step.
void dropNonFinitePush(SolverArrays& s) {
    for (std::size_t i = 0; i < s.stateBodies.size(); ++i) {
        if (std::isfinite(s.biasV[i].x + s.biasV[i].y + s.biasW[i])) continue;
        s.biasV[i] = Vec2{};
        s.biasW[i] = 0.0f;
    }
}

}  // namespace i2d::detail
