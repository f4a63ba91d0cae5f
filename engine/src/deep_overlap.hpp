// Deep overlaps in the soft step: bodies created or driven into each other
// deeper than kDeepOverlap are pushed apart on pseudo-velocities that move
// the positions for one substep and are then dropped (deep_overlap.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "impulse2d/math.hpp"

namespace i2d::detail {

struct WorldState;

/// A pushed body's pseudo-velocity across gravity (in any direction without
/// gravity) may reach this many times WorldSettings::maxPushSpeed c; along
/// gravity it is held to c (pushDeepOverlaps). At the defaults (c = 3 m/s,
/// 60 Hz, 4 substeps) a body slides at most 45 m/s: 19 cm a substep, 75 cm
/// a step. Why and the figures: deep_overlap.cpp.
inline constexpr float kSidewaysPushFactor = 15.0f;

/// How much of a falling speed `falling` (m/s, along −up) a body loses when a
/// push lifts it by `lift` (m) against an acceleration g: the new speed is
/// √(max(f² − 2·g·lift, 0)), so the kinetic energy pays the potential energy
/// the lift adds, or all of it. A fall beyond the speed limit (clamped
/// later) whose square overflows is left as it is: paid for, it became −∞
/// along up, NaN across (fuzz_world). Used by the deep push and by the soft
/// rows' push (solver.cpp, payPushLift).
inline float fallPaidForLift(float falling, float g, float lift) {
    const float fall2 = falling * falling;
    if (!(fall2 < std::numeric_limits<float>::max())) return 0.0f;
    return falling - std::sqrt(std::max(fall2 - 2.0f * g * lift, 0.0f));
}

/// A deep contact between two moving bodies pushed apart sideways
/// (perpendicular to gravity) instead of along its normal.
struct SidePush {
    int row;                   ///< in SolverArrays::constraints
    Vec2 axis;                 ///< unit, from A's side towards B's
    float depth;               ///< overlap of the two shapes' extents along axis at step start (m)
    float invMassA, invMassB;  ///< how the row splits the move between A and B (prepareDeepOverlaps)
};

/// A deep contact's push impulses at the end of a step, which the next step's
/// push starts from (pushDeepOverlaps).
struct PushCarry {
    int contact;  ///< slot, with its shapes (a slot reused by another pair is not matched)
    int shapeA, shapeB;
    bool sideways;     ///< pushed as a SidePush (its impulse in impulse[0])
    float impulse[2];  ///< per point, as ContactPointConstraint::biasImpulse
    Vec2 apart;        ///< B's centre less A's at that step's start (m)
};

/// Once per step, after the rows are prepared, in a step with a deep overlap:
/// which deep rows are pushed sideways (SolverArrays::sidePushes).
void prepareDeepOverlaps(WorldState& w);

/// The push of every deep contact, solved by a few Gauss-Seidel sweeps on
/// the pseudo-velocities SolverArrays::biasV/biasW (zeroed here first); each
/// body's pseudo-velocity is then limited to WorldSettings::maxPushSpeed, and
/// a supported body lifted by it while falling loses the fall the lift pays
/// for over the substep h.
void pushDeepOverlaps(WorldState& w, float h);

}  // namespace i2d::detail
