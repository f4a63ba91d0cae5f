// Integration of the solver's bodies (Tamis and Maggiore (2015),
// Constraint based physics solver, §3.2: semi-implicit Euler), the speed
// limits, and the stop of bodies a sweep left with a non-finite velocity.
// Each function reads and writes the solver arrays of bodies [begin, end)
// only, so the workers may share a pass.
#pragma once

#include <atomic>
#include <cmath>
#include <cstddef>

#include "float4.hpp"
#include "solver.hpp"

namespace i2d::detail {

/// The soft rows' push lifts a body without paying for it: within a
/// substep the positions move with the velocity the biased pass left, v_b,
/// and the relax pass then takes the push out of the velocity, not out of the
/// height. A body pushed up by h·(v_b − v)·u (u up, against gravity) while it
/// falls (v·u < 0) gains m·g·lift of potential energy, and a pile created
/// overlapping on the ground gained energy so while its bodies fell onto
/// each other (8 circles: 1.059 times the start plus the lift out of the
/// ground). That lift is paid from the fall, as the push of deep overlaps
/// pays its own (deep_overlap.cpp): the falling speed f becomes
/// √(max(f² − 2·g·lift, 0)), g the body's acceleration down. A body pushed up
/// while it rises or rests keeps its velocity (nothing to pay from). Only
/// bodies with contact rows pay (contactColourMasks): a joint's push takes
/// back the drift of a turning body's anchors (docs/joints.md), which is not
/// a lift to pay for, and paid for it a free pendulum lost energy and swung
/// slower (Joints.RevolutePendulumPeriod). Paid only in steps with an
/// overlap deeper than kDeepOverlap, while a pile created overlapping is
/// being separated: in a resting pile every contact's push of its few
/// centimetres of sag lifts its body by micrometres a substep, and paying for
/// those cost a pile of 1,000 circles 2 to 5 % of its step.
inline void payPushLift(const SolverArrays& s, std::size_t i, BodyState& st, Vec2 a, Vec2 up, float h) {
    const float v = dot(st.v, up);
    if (!(v < 0.0f) || !(st.upBeforeRelax > v)) return;  // not falling, or not pushed up
    const float lift = h * (st.upBeforeRelax - v);
    const float gravity = -dot(a, up);
    if (!(gravity > 0.0f) || s.contactColourMasks[static_cast<std::size_t>(s.stateBodies[i])] == 0) return;
    st.v += fallPaidForLift(-v, gravity, lift) * up;
}

/// Lanes 0 to 2 of the result hold where v.x, v.y or w of the state is not
/// finite: x·0 is 0 for a finite x and NaN otherwise, and NaN ≠ 0. One
/// four-float load, multiply and compare per body with no dependency between
/// bodies (the masks are or-ed); summed as floats and tested with isfinite,
/// each body waited on two additions, and the scans (then three of their own
/// per substep) took 4 % of a 1,000-circle scene's step. Lane 3 is
/// upBeforeRelax, not tested.
inline Mask4 nonFiniteLanes(const BodyState& st) {
    static_assert(offsetof(BodyState, v) == 0 && offsetof(BodyState, w) == 8 &&
                  offsetof(BodyState, upBeforeRelax) == 12);
    return nonZero(load4(&st.v.x) * splat(0.0f));
}
inline constexpr int kVelocityLanes = 0b0111;
/// Whether a state's velocity is not finite (nonFiniteLanes, one body).
inline bool nonFiniteVelocity(const BodyState& st) { return (laneBits(nonFiniteLanes(st)) & kVelocityLanes) != 0; }

// The speed limits hold for the velocities the positions are integrated with,
// after the constraints have acted: a joint or contact impulse can exceed what
// integrateVelocities clamped (a fuzzed distance joint launched a body at
// 1750 m/s and 55,000 rad/s). Angular: at most π/4 (an eighth of a turn) per (sub)step,
// beyond which the rotation integration and the narrowphase lose the body's
// orientation (Box2D v3 uses the same bound).
inline constexpr float kMaxRotationPerStep = 0.25f * 3.14159265f;

/// Velocity limited to maxSpeed, angular speed to maxAngularSpeed.
inline void clampVelocity(BodyState& s, float maxSpeed, float maxAngularSpeed) {
    s.v = limitSpeed(s.v, maxSpeed);
    if (std::abs(s.w) > maxAngularSpeed) s.w = s.w > 0.0f ? maxAngularSpeed : -maxAngularSpeed;
}

/// One body's velocity over a (sub)step h (Eq. 3.2.1-3.2.2 in velocities):
/// v += h·(g·scale + F/m), ω += h·τ/I, damping as the exact-for-linear-drag
/// factor's Padé form (v /= 1 + h·c), then the speed limit.
inline void kickVelocity(BodyState& st, const BodyIntegration& in, float h, float maxSpeed) {
    Vec2 v = st.v + h * in.linearAcceleration;
    float av = st.w + h * in.invInertia * in.torque;
    v *= in.linearDampingFactor;
    av *= in.angularDampingFactor;
    st.v = limitSpeed(v, maxSpeed);
    st.w = av;
}

/// Velocities of bodies [begin, end) over a (sub)step h: forces, gravity and
/// damping (Eq. 3.2.1-3.2.2), then the speed limit. `payLift`: pay the last
/// substep's push lift first (payPushLift), up being against gravity. A body
/// whose velocity is not finite is left as it is and `nonFinite` set, for
/// stopNonFiniteBodies.
void integrateVelocities(SolverArrays& s, float h, float maxSpeed, std::size_t begin, std::size_t end, bool payLift,
                         Vec2 up, std::atomic<bool>& nonFinite);

/// Positions of bodies [begin, end) over h with their velocities, within the
/// speed limits (Eq. 3.2.3-3.2.4). A body whose velocity is not finite is not
/// moved and `nonFinite` set, for stopNonFiniteBodies.
void integratePositions(SolverArrays& s, float h, float maxSpeed, std::size_t begin, std::size_t end,
                        std::atomic<bool>& nonFinite);

/// As integratePositions for every body, moving each by its velocity plus its
/// pseudo-velocity (SolverArrays::biasV, biasW), which is not kept.
void integratePositionsPushed(SolverArrays& s, float h, float maxSpeed, Vec2 up);

/// Stops every body whose velocity is not finite and drops the accumulated
/// impulses of every row on it, so that all bodies stay finite.
void stopNonFiniteBodies(SolverArrays& s);

/// As stopNonFiniteBodies for the pseudo-velocities: a diverging push is
/// dropped for this step.
void dropNonFinitePush(SolverArrays& s);

}  // namespace i2d::detail
