// Test-only oracle for the 2D impact law: marches the impulse differential
// equation of Baber (2011), "A Correction To Brian Mirtich's Thesis
// 'Impulse-based Dynamic Simulation of Rigid Body Systems'", §3.3–3.7 (specialised to 2D) in small steps of the
// normal impulse, as §4 does, instead of using the closed forms of §5.
// It shares no code with engine/src/impact_law.cpp; it only reads the same input
// aggregate.
#pragma once

#include "impulse2d/impact.hpp"

namespace i2d_test {

struct OracleResult {
    bool colliding = false;
    i2d::Vec2d impulse{};  ///< received by A, world frame
    i2d::Vec2d vA{}, vB{};
    double wA = 0.0, wB = 0.0;
    /// Step in the normal impulse used by the final pass (N·s). The oracle's
    /// only truncation error is the last step's overshoot: its impulse exceeds
    /// the exact one by h·d with 0 ≤ h < step and d = dp/dp_n of the final
    /// segment (|d| ≤ sqrt(1 + μ²)).
    double step = 0.0;
    int steps = 0;                 ///< steps taken by the final pass
    bool reachedSticking = false;  ///< slip became 0 at some point
    bool failed = false;           ///< the march did not end (should never happen)
};

/// March the impact with about `targetSteps` steps over the whole impulse.
OracleResult marchImpact(const i2d::ImpactInput& input, int targetSteps = 20000);

}  // namespace i2d_test
