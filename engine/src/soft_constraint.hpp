// What the contact and joint rows share: the solver pass a row is solved in,
// and the coefficients of a soft (spring-damped) constraint.
#pragma once

#include <cmath>

namespace i2d::detail {

/// The pass a constraint row is solved in; it selects the row's velocity target.
enum class SolvePass {
    soft_bias,        ///< soft_step, solve stage: soft push towards zero error
    soft_relax,       ///< soft_step, relax stage: no push, removes its velocity
    soft_relax_last,  ///< the last relax of the step (leaves fast approaches to the impact law)
    baumgarte,        ///< the push factor in the velocity target
    no_push,          ///< split mode's velocity pass: the push is solved separately
};

/// Soft constraint coefficients for a spring of frequency `hertz` and damping
/// ratio ζ over a step h (implicit Euler of a spring-damper, in the
/// mass-independent form of Catto's Solver2D and Box2D v3 soft step):
///   ω = 2π·hertz, a1 = 2ζ + hω, a2 = hω·a1, a3 = 1/(1 + a2)
///   biasRate = ω/a1, massScale = a2·a3, impulseScale = a3
/// and a row's impulse is −massScale·m_eff·(Jv + biasRate·C) − impulseScale·λ_acc.
/// hertz 0 is a rigid row (massScale 1, no bias, no impulse feedback).
struct Softness {
    float biasRate = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
};

inline Softness makeSoft(float hertz, float zeta, float h) {
    constexpr float kPi = 3.14159265358979f;
    if (hertz == 0.0f) return {0.0f, 1.0f, 0.0f};
    float omega = 2.0f * kPi * hertz;
    float a1 = 2.0f * zeta + h * omega;
    float a2 = h * omega * a1;
    float a3 = 1.0f / (1.0f + a2);
    // A spring so weak (a denormal hertz) that a1 underflows to 0 has no
    // stiffness and no damping: no bias, no force (ω/a1 would be 0/0 = NaN;
    // found by fuzz_world on a weld's angular hertz).
    if (!(a1 > 0.0f)) return {0.0f, 0.0f, 1.0f};
    return {omega / a1, a2 * a3, a3};
}

/// A physical spring along a row whose effective mass m_eff changes as the
/// bodies turn (a distance, prismatic or wheel joint's axis with its lever
/// arms): its stiffness k = m·ω² and damping c = 2·m·ζ·ω are set from a mass
/// m that does not turn, the bodies' reduced mass 1/(m_A⁻¹ + m_B⁻¹), and
/// `ratio` = m/m_eff (≥ 1). Implicit Euler of that spring-damper, in the
/// form makeSoft gives for m_eff: a2 grows by the ratio, biasRate stays.
/// With the row's own mass instead, the stiffness followed the arms: a disc
/// hung 1.5 m off its centre by a wheel joint's spring, its arm turning from
/// across the axis to along it, met a spring 156 times stiffer while
/// stretched and left at 25 m/s (energy ×68,000). Ratio 1: makeSoft's bits.
inline Softness makeSpring(float hertz, float zeta, float h, float ratio) {
    constexpr float kPi = 3.14159265358979f;
    if (hertz == 0.0f) return {0.0f, 1.0f, 0.0f};
    float omega = 2.0f * kPi * hertz;
    float a1 = 2.0f * zeta + h * omega;
    float a2 = h * omega * a1 * ratio;
    if (!(a1 > 0.0f)) return {0.0f, 0.0f, 1.0f};           // (as makeSoft: no stiffness, no damping)
    if (!(a2 < 3.0e38f)) return {omega / a1, 1.0f, 0.0f};  // a spring far stiffer than its row: rigid
    float a3 = 1.0f / (1.0f + a2);
    return {omega / a1, a2 * a3, a3};
}

/// A physical spring on a point (a soft weld's anchors): stiffness k = m·ω²
/// and damping c = 2·m·ζ·ω in every direction, m the bodies' reduced mass
/// 1/`invMassSum`, whatever the anchors' arms. Implicit Euler of that
/// spring-damper in compliance form (Catto (2011), Soft Constraints): the
/// point's impulse solves (K + γ·1)·Δλ = −(Jv + biasRate·C + γ·λ) with
/// γ = 1/(h(c + hk)) = invMassSum/a2 and biasRate = k/(c + hk) = ω/a1 (a1, a2
/// as in makeSoft). Where K = invMassSum·1 (no arms) this is makeSoft's row.
/// With K⁻¹ in place of m, the row's own mass, the spring was as stiff as the
/// anchors' effective mass, which changes as the bodies turn: a 7 g disc
/// held 1.5 m off its centre by a soft weld gained 590 times its energy.
///
/// The point's fastest mode then has ω_K = ω·√(m·λ_max(K)), far above ω on
/// a long arm (the body turning about the anchor); past about 2 rad per
/// substep the turn is no longer resolved and that mode gained energy at one
/// substep (×5,000). So ω is capped where ω_K·h would pass 2, with
/// λ_max(K) ≤ trace K = `traceK`: a spring that stiff is as stiff as the step
/// can follow, and only there does its stiffness follow the arms again.
struct PointSpring {
    float biasRate = 0.0f;
    float gamma = 0.0f;  ///< compliance added to K's diagonal (1/kg)
};
/// False when there is no spring to make (no stiffness and no damping, or no
/// mass that translates): the caller keeps makeSoft's row.
inline bool makePointSpring(float hertz, float zeta, float h, float invMassSum, double traceK, PointSpring& out) {
    constexpr float kPi = 3.14159265358979f;
    constexpr double kMostTurnPerSubstep = 2.0;  // ω_K·h (rad), see above
    if (!(invMassSum > 0.0f) || !(h > 0.0f)) return false;
    float omega = 2.0f * kPi * hertz;
    const double fastest = kMostTurnPerSubstep / (double(h) * std::sqrt(traceK / invMassSum));
    if (omega > fastest) omega = static_cast<float>(fastest);
    const float a1 = 2.0f * zeta + h * omega;
    const float a2 = h * omega * a1;
    if (!(a1 > 0.0f) || !(a2 > 0.0f)) return false;
    out.biasRate = omega / a1;
    out.gamma = invMassSum / a2;
    return out.gamma < 3.0e38f;
}

}  // namespace i2d::detail
