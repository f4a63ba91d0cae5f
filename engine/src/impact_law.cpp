// Impulse2D — the closed-form 2D frictional impact law of Baber (2011),
// A Correction To Brian Mirtich's Thesis "Impulse-based Dynamic Simulation
// of Rigid Body Systems", §5.2, with Stronge's energetic coefficient of
// restitution. (The stage that applies it to a world's contacts is
// impact_stage.cpp.)
//
// The algorithm follows the ten steps of Baber's §5.2 in order. Step numbers
// in the comments refer to §5.2; equation numbers refer to §3. Two places
// compute a quantity of the paper by a different but algebraically identical
// formula, because the paper's formula loses precision or needs K⁻¹:
//   * the impulse p is accumulated segment by segment (Δp = Δp_y·(dp_x/dp_y, 1))
//     instead of p = K⁻¹(u − u₀) of Step 9; by equation (2) both are equal;
//   * det K and the normal rate k_y on a diverging ray are evaluated as sums
//     of non-negative terms, so they keep their sign for ill-conditioned K.
// docs/impacts.md lists these and the paper's ambiguities.
#include "impulse2d/impact.hpp"

#include <cmath>
#include <string>

#include "impulse2d/error.hpp"

namespace i2d {
namespace {

bool finite(double x) { return std::isfinite(x); }
bool finite(const Vec2d& v) { return finite(v.x) && finite(v.y); }

[[noreturn]] void bodyError(const char* name, const char* what) {
    throw Error(std::string("resolveImpact: body ") + name + what);
}

void validateBody(const ImpactBody& b, const char* name) {
    // The message is built only when throwing: this runs on every impact.
    if (!finite(b.invMass) || !finite(b.invInertia) || !finite(b.r) || !finite(b.v) || !finite(b.w))
        bodyError(name, " has a non-finite value");
    if (b.invMass < 0.0) bodyError(name, " has a negative inverse mass");
    if (b.invInertia < 0.0) bodyError(name, " has a negative inverse inertia");
}

void validate(const ImpactInput& in) {
    if (!finite(in.restitution) || !finite(in.friction) || !finite(in.normal))
        throw Error("resolveImpact: restitution, friction or normal is not finite");
    validateBody(in.a, "A");
    validateBody(in.b, "B");
    if (in.a.invMass == 0.0 && in.a.invInertia == 0.0 && in.b.invMass == 0.0 && in.b.invInertia == 0.0)
        throw Error("resolveImpact: both bodies are immovable (inverse mass and inertia 0)");
    // sqrt rather than hypot (several times faster); a huge component
    // overflows to inf and fails the test, as it should.
    const double len = std::sqrt(in.normal.x * in.normal.x + in.normal.y * in.normal.y);
    if (!(std::abs(len - 1.0) <= 1e-6))
        throw Error("resolveImpact: the normal must be a unit vector (length differs from 1 by more than 1e-6)");
    if (in.restitution < 0.0 || in.restitution > 1.0) throw Error("resolveImpact: restitution e must lie in [0, 1]");
    if (in.friction < 0.0) throw Error("resolveImpact: friction mu must be >= 0");
}

double cross(const Vec2d& a, const Vec2d& b) { return a.x * b.y - a.y * b.x; }

/// det K / trace² below which a K of two rotations alone is singular (resolveImpact).
constexpr double kSingularDetRatio = 1e-12;

}  // namespace

const char* toString(ImpactCase kind) {
    switch (kind) {
        case ImpactCase::converging_compression: return "converging_compression";
        case ImpactCase::converging_decompression: return "converging_decompression";
        case ImpactCase::decompression_ended: return "decompression_ended";
        case ImpactCase::stable_sticking: return "stable_sticking";
        case ImpactCase::unstable_sticking: return "unstable_sticking";
        case ImpactCase::diverging: return "diverging";
        case ImpactCase::not_colliding: return "not_colliding";
    }
    return "unknown";
}

ImpactResult resolveImpact(const ImpactInput& in) {
    validate(in);

    const double e = in.restitution;
    const double mu = in.friction;
    const double iMA = in.a.invMass, iIA = in.a.invInertia;
    const double iMB = in.b.invMass, iIB = in.b.invInertia;

    // Step 1: rotate so the normal is (0, 1): R = [[f_y, −f_x], [f_x, f_y]].
    // The normal is renormalised first (it may be off by up to 1e-6) so that R
    // is an exact rotation and the impact cannot gain energy through it.
    const double len = std::sqrt(in.normal.x * in.normal.x + in.normal.y * in.normal.y);
    const double fx = in.normal.x / len, fy = in.normal.y / len;
    auto toLocal = [&](const Vec2d& w) { return Vec2d{fy * w.x - fx * w.y, fx * w.x + fy * w.y}; };
    const Vec2d rA = toLocal(in.a.r), rB = toLocal(in.b.r);
    const Vec2d vA = toLocal(in.a.v), vB = toLocal(in.b.v);
    // Angular velocities are unchanged by a 2D rotation (det R = +1).

    // Step 2: collision matrix
    //   K = (1/m_A + 1/m_B)·I + (1/I_A)[[r_Ay², −r_Ax r_Ay], [−r_Ax r_Ay, r_Ax²]] + (same for B).
    const double m = iMA + iMB;
    const double K11 = m + iIA * rA.y * rA.y + iIB * rB.y * rB.y;
    const double K12 = -iIA * rA.x * rA.y - iIB * rB.x * rB.y;
    const double K22 = m + iIA * rA.x * rA.x + iIB * rB.x * rB.x;
    // det K = K11·K22 − K12², expanded: each rotational term has determinant
    // 0, and the cross terms collapse to (r_A × r_B)², so
    //   det K = m² + m·(|r_A|²/I_A + |r_B|²/I_B) + (r_A × r_B)²/(I_A·I_B) ≥ 0,
    // a sum of non-negative terms with no cancellation. It is 0 exactly when
    // K is singular (e.g. two bodies that can only spin about their centres
    // with parallel lever arms); §3.2 needs K positive definite (App. B).
    const double rA2 = rA.x * rA.x + rA.y * rA.y, rB2 = rB.x * rB.x + rB.y * rB.y;
    const double rAxrB = cross(rA, rB);
    const double detK = m * m + m * (iIA * rA2 + iIB * rB2) + iIA * iIB * rAxrB * rAxrB;
    // With both inverse masses zero, K is a sum of two rank-one terms, singular
    // when the lever arms are parallel; rotated into the normal's frame,
    // exactly parallel arms keep a rounding-sized det K (about 1e-24 for arms
    // of 4.6 and 14 m), which passed a test for 0 and made the law divide by
    // it: 1.3e5 J in, 2e10 J out (fuzz_impact). Such a K is singular to
    // double precision: refused when its condition number, at least
    // trace²/det, passes 1e12 (a K⁻¹ then keeps no more than 4 of its 16
    // digits). With a mass to move, det K ≥ m² and K is well conditioned.
    const double trace = K11 + K22;
    if (!(detK > 0.0) || (m == 0.0 && !(detK > kSingularDetRatio * trace * trace)))
        throw Error("resolveImpact: the collision matrix K is singular (neither body can move the contact point "
                    "in every direction: zero inverse masses and parallel or zero lever arms)");

    // Step 2: initial separation velocity u₀ = v_A + ω_A(−r_Ay, r_Ax) − v_B − ω_B(−r_By, r_Bx).
    const Vec2d u0{vA.x - in.a.w * rA.y - vB.x + in.b.w * rB.y, vA.y + in.a.w * rA.x - vB.y - in.b.w * rB.x};

    ImpactResult out;
    out.vA = in.a.v;
    out.wA = in.a.w;
    out.vB = in.b.v;
    out.wB = in.b.w;
    // Step 2 (note): a separating or resting normal velocity is not a collision.
    if (!(u0.y < 0.0)) {
        out.kind = ImpactCase::not_colliding;
        return out;
    }

    double ux = u0.x, uy = u0.y;
    double Wc = 0.0, Wd = 0.0;  // work of the normal force in compression / decompression (§3.4)
    double px = 0.0, py = 0.0;  // impulse so far, rotated frame
    const double e2 = e * e;

    // k = K·(s, 1): the rate du/dp_y when dp_x/dp_y = s (equation (3) in 2D).
    auto rate = [&](double s, double& kx, double& ky) {
        kx = K11 * s + K12;
        ky = K12 * s + K22;
    };
    // (s, 1)·K·(s, 1)ᵀ = m(1 + s²) + (r_A × (s, 1))²/I_A + (r_B × (s, 1))²/I_B,
    // a sum of non-negative terms (used for k_y on a diverging ray, below).
    auto quad = [&](double s) {
        const double a = rA.x - rA.y * s, b = rB.x - rB.y * s;
        return m * (1.0 + s * s) + iIA * a * a + iIB * b * b;
    };
    // On a diverging or stationary ray s·k_x ≤ 0 (s = −μ with k_x ≥ 0, or
    // s = μ with k_x ≤ 0), so k_y = (s,1)K(s,1)ᵀ − s·k_x is a sum of
    // non-negative terms and > 0 (the §3.9 argument that k_z > 0). Computing
    // it this way keeps that sign under rounding.
    auto divergingKy = [&](double s, double kx) { return quad(s) - s * kx; };

    double s = 0.0, kx = 0.0, ky = 0.0;  // current segment: dp_x/dp_y and k = du/dp_y
    bool sticking = false;
    bool done = false;

    // Step 3: which kind of ray are we on?
    if (ux == 0.0) {
        // Step 3(a): sticking from the start.
        sticking = true;
    } else {
        // Step 3(b)/(c): sliding; Coulomb friction opposes u_x, so
        // dp/dp_y = (−μ·sign u_x, 1) (§3.3 in 2D).
        s = ux > 0.0 ? -mu : mu;
        rate(s, kx, ky);
        const bool converging = ux > 0.0 ? kx < 0.0 : kx > 0.0;
        if (converging) {
            // Step 4: converging ray; u moves on a straight line towards u_x = 0.
            // Step 4(a): u_origin, the u_y reached when u_x becomes 0.
            const double uOrigin = uy - ky / kx * ux;
            const double dpyToOrigin = -ux / kx;  // > 0 on a converging ray
            if (uOrigin <= 0.0) {
                // Step 4(b): the origin is reached while still compressing.
                // W_c = ∫ u_y dp_y = u_y·P + k_y·P²/2 with P = −u_x/k_x, which is
                // Baber's −u_x u_y/k_x + k_y u_x²/(2k_x²).
                Wc = uy * dpyToOrigin + 0.5 * ky * dpyToOrigin * dpyToOrigin;
                px += s * dpyToOrigin;
                py += dpyToOrigin;
                ux = 0.0;
                uy = uOrigin;
                sticking = true;
                out.kind = ImpactCase::converging_compression;
            } else if (uOrigin < -e * uy) {
                // Step 4(c): compression ends, then the origin is reached before
                // W_d = −e² W_c. Equation (8): W_c = −u_y²/(2k_y), W_d = u_origin²/(2k_y).
                // (u_origin > 0 > u_y forces k_y > 0 here.)
                Wc = -uy * uy / (2.0 * ky);
                Wd = uOrigin * uOrigin / (2.0 * ky);
                px += s * dpyToOrigin;
                py += dpyToOrigin;
                ux = 0.0;
                uy = uOrigin;
                sticking = true;
                out.kind = ImpactCase::converging_decompression;
            } else {
                // Step 4(d): restitution ends first. With the whole impact on one
                // line, W_d = −e² W_c and (8) give u_y,end = −e·u_y, and
                // u_x,end = u_x − (1 + e)(k_x/k_y)·u_y.
                const double uyEnd = -e * uy;
                const double dpy = (uyEnd - uy) / ky;
                px += s * dpy;
                py += dpy;
                ux = ux - (1.0 + e) * (kx / ky) * uy;
                uy = uyEnd;
                done = true;
                out.kind = ImpactCase::decompression_ended;
            }
        } else {
            // Step 3(b)/(c): diverging (k_x·u_x > 0) or stationary (k_x = 0) ray.
            ky = divergingKy(s, kx);
            out.kind = ImpactCase::diverging;
        }
    }

    if (sticking && !done) {
        // Step 5: stable sticking iff |K12| ≤ μ K11, the 2D form of the §3.5
        // condition ((K⁻¹)₁₂)² ≤ μ²((K⁻¹)₂₂)² with (K⁻¹)₁₂ = −K12/det K, (K⁻¹)₂₂ = K11/det K.
        const bool initially = (out.kind == ImpactCase::not_colliding);
        if (std::abs(K12) <= mu * K11) {
            // Step 6: k = (0, 1/(K⁻¹)₂₂) = (0, det K / K11) (equation (5)); the
            // impulse keeps u_x = 0 with dp_x/dp_y = (K⁻¹)₁₂/(K⁻¹)₂₂ = −K12/K11 (§3.5).
            s = -K12 / K11;
            kx = 0.0;
            ky = detK / K11;
            if (initially) out.kind = ImpactCase::stable_sticking;
        } else {
            // Step 7: unstable sticking; leave along the unique diverging ray
            // (§3.7, §3.10): the +u_x ray if K·(−μ, 1) has k_x > 0, else the −u_x ray.
            s = -mu;
            rate(s, kx, ky);
            if (!(kx > 0.0)) {
                s = mu;
                rate(s, kx, ky);
            }
            ky = divergingKy(s, kx);
            if (initially) out.kind = ImpactCase::unstable_sticking;
        }
    }

    if (!done) {
        // Step 8: a diverging/stationary ray or stable sticking: straight line to the end.
        // Step 8(a):
        const double uOld = uy;
        if (uy < 0.0) {
            // Step 8(b): finish compression; (6)/(8) with u_y(t_e) = 0.
            Wc += -uy * uy / (2.0 * ky);
            uy = 0.0;
        }
        // Step 8(c): decompression until W_d = −e² W_c, by (8):
        //   u_y,end = sqrt(2 k_y (−e² W_c − W_d) + u_y²).
        // The radicand is ≥ 0 in exact arithmetic (4(c) guarantees W_d < −e² W_c);
        // clamp the rounding.
        const double radicand = 2.0 * ky * (-e2 * Wc - Wd) + uy * uy;
        uy = std::sqrt(radicand > 0.0 ? radicand : 0.0);
        const double dpy = (uy - uOld) / ky;
        px += s * dpy;
        py += dpy;
        ux = kx / ky * (uy - uOld) + ux;
    }
    (void)ux;  // the final u is implied by p (equation (2)); velocities come from p.

    // Step 10 (applied to p): back to the world frame, p_world = Rᵀ·p.
    const Vec2d p{fy * px + fx * py, -fx * px + fy * py};

    // Step 9 / equation (1): v_A += p/m_A, ω_A += (r_A × p)/I_A, v_B −= p/m_B, ω_B −= (r_B × p)/I_B.
    // Done in the world frame: the cross product is invariant under rotation.
    out.impulse = p;
    out.vA = {in.a.v.x + iMA * p.x, in.a.v.y + iMA * p.y};
    out.wA = in.a.w + iIA * cross(in.a.r, p);
    out.vB = {in.b.v.x - iMB * p.x, in.b.v.y - iMB * p.y};
    out.wB = in.b.w - iIB * cross(in.b.r, p);

    if (!finite(out.impulse) || !finite(out.vA) || !finite(out.vB) || !finite(out.wA) || !finite(out.wB))
        throw Error("resolveImpact: the result overflows double precision (inputs too large)");
    return out;
}

}  // namespace i2d
