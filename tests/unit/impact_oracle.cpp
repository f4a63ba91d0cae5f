// Test-only oracle: marches the 2D impulse equation in the normal impulse.
//
// Baber (2011), "A Correction To Brian Mirtich's Thesis 'Impulse-based
// Dynamic Simulation of Rigid Body Systems'", §3.3: while the contact slides, dp/dp_n = n − μ·σ·t (σ the sign of
// the slip u·t), and u(p) follows from equation (1) applied to the bodies.
// §3.4: the normal force does work dW/dp_n = u·n (equation (4)), counted as
// compression work W_c while u·n < 0 and decompression work W_d while u·n > 0;
// the impact ends when W_d = −e²·W_c (Stronge). §3.5–3.7: when the slip
// reaches 0 the contact sticks if the impulse that keeps the slip 0 lies in the
// friction cone, otherwise it leaves along the diverging ray (§3.8 test).
//
// Differences from the literal §4 loop, each made so the error can be stated:
//   * u is recomputed from the accumulated impulse by applying it to the
//     bodies (no drift), rather than incremented;
//   * the work over a step uses the trapezoid rule, which is exact because u
//     is linear in p_n within a step of constant direction; a step in which
//     u·n changes sign is split at its zero so each part goes to the right W;
//   * a step in which the slip changes sign is shortened to end exactly at
//     slip 0 (u·t is linear in the step length);
//   * the end test also requires u·n ≥ 0: with e = 0 the §4 test
//     W_d ≥ −e² W_c reads 0 ≥ 0 and would stop after the first step.
// What is left is the last step's overshoot: the march stops at the first
// step end past the exact end, so its impulse exceeds the exact one by h·d,
// 0 ≤ h < step, d the final direction dp/dp_n.
#include "impact_oracle.hpp"

#include <cmath>
#include <initializer_list>

namespace i2d_test {
namespace {

struct V {
    double x = 0.0, y = 0.0;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y}; }
V operator*(double s, V a) { return {s * a.x, s * a.y}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y; }
double crossZ(V a, V b) { return a.x * b.y - a.y * b.x; }
V perp(V r) { return {-r.y, r.x}; }  // ω × r = ω·perp(r) for ω along z
V fromApi(i2d::Vec2d v) { return {v.x, v.y}; }

struct Velocities {
    V vA, vB;
    double wA, wB;
};

// Equation (1): the bodies' velocities after A receives p and B receives −p.
Velocities applyImpulse(const i2d::ImpactInput& in, V p, bool fromRest) {
    Velocities s{};
    const V vA0 = fromRest ? V{} : fromApi(in.a.v), vB0 = fromRest ? V{} : fromApi(in.b.v);
    const double wA0 = fromRest ? 0.0 : in.a.w, wB0 = fromRest ? 0.0 : in.b.w;
    s.vA = vA0 + in.a.invMass * p;
    s.wA = wA0 + in.a.invInertia * crossZ(fromApi(in.a.r), p);
    s.vB = vB0 - in.b.invMass * p;
    s.wB = wB0 - in.b.invInertia * crossZ(fromApi(in.b.r), p);
    return s;
}

// §3.2: u = (v_A + ω_A × r_A) − (v_B + ω_B × r_B).
V separation(const i2d::ImpactInput& in, const Velocities& s) {
    return (s.vA + s.wA * perp(fromApi(in.a.r))) - (s.vB + s.wB * perp(fromApi(in.b.r)));
}

struct Pass {
    bool ended = false;
    bool reachedSticking = false;
    bool failed = false;
    V p{};
    int steps = 0;
};

Pass march(const i2d::ImpactInput& in, V n, V t, double h, int maxSteps) {
    Pass out;
    const double mu = in.friction, e2 = in.restitution * in.restitution;
    auto uAt = [&](V p) { return separation(in, applyImpulse(in, p, false)); };
    auto Kmul = [&](V x) { return separation(in, applyImpulse(in, x, true)); };  // K·x, equation (2)

    V p{};
    V u = uAt(p);
    double un = dot(u, n), ut = dot(u, t);
    double Wc = 0.0, Wd = 0.0;

    enum class Mode { slide, stick } mode = Mode::slide;
    double sigma = 0.0;  // sign of the slip while sliding
    V d{};               // dp/dp_n of the current segment

    // §3.5–3.8 at slip 0: choose the impulse direction.
    auto decideAtOrigin = [&]() {
        out.reachedSticking = true;
        const V Kt = Kmul(t), Kn = Kmul(n);
        const double Ktt = dot(t, Kt), Ktn = dot(t, Kn), Knn = dot(n, Kn);
        const double det = Ktt * Knn - Ktn * Ktn;
        const double invTN = -Ktn / det, invNN = Ktt / det;  // entries of K⁻¹ in the (t, n) basis
        if (invTN * invTN <= mu * mu * invNN * invNN) {
            // §3.6 stable sticking: dp_t/dp_n = (K⁻¹)_tn / (K⁻¹)_nn keeps the slip at 0.
            mode = Mode::stick;
            d = n + (invTN / invNN) * t;
            return;
        }
        // §3.7/§3.8: unstable; the ray θ ∈ {0, π} (slip ±t) on which u·du/dp_n > 0.
        int found = 0;
        for (double sg : {1.0, -1.0}) {
            const V dir = n - (mu * sg) * t;
            if (sg * dot(t, Kmul(dir)) > 0.0) {
                ++found;
                sigma = sg;
                d = dir;
            }
        }
        if (found != 1) out.failed = true;  // §3.10 proves exactly one exists
        mode = Mode::slide;
    };

    if (ut == 0.0) {
        decideAtOrigin();
    } else {
        sigma = ut > 0.0 ? 1.0 : -1.0;
        d = n - (mu * sigma) * t;
    }

    while (out.steps < maxSteps && !out.failed) {
        double hs = h;
        V pNew = p + hs * d;
        V uNew = uAt(pNew);
        double utNew = dot(uNew, t);
        bool hitOrigin = false;
        if (mode == Mode::slide && sigma * utNew <= 0.0 && ut != 0.0) {
            // Shorten the step to end where the slip is 0.
            hs = h * (ut / (ut - utNew));
            pNew = p + hs * d;
            uNew = uAt(pNew);
            utNew = 0.0;
            hitOrigin = true;
        }
        const double unNew = dot(uNew, n);
        // Equation (4), trapezoid over the step (exact: u·n linear in the step).
        if ((un < 0.0 && unNew > 0.0) || (un > 0.0 && unNew < 0.0)) {
            const double g = un / (un - unNew);  // fraction of the step before u·n = 0
            const double first = 0.5 * un * g * hs, second = 0.5 * unNew * (1.0 - g) * hs;
            (un < 0.0 ? Wc : Wd) += first;
            (unNew < 0.0 ? Wc : Wd) += second;
        } else {
            const double w = 0.5 * (un + unNew) * hs;
            (un + unNew < 0.0 ? Wc : Wd) += w;
        }
        p = pNew;
        un = unNew;
        ut = utNew;
        ++out.steps;
        if (hitOrigin) decideAtOrigin();
        // §3.4 end: W_d = −e² W_c, once decompressing.
        if (un >= 0.0 && Wd >= -e2 * Wc) {
            out.ended = true;
            break;
        }
    }
    out.p = p;
    return out;
}

}  // namespace

OracleResult marchImpact(const i2d::ImpactInput& in, int targetSteps) {
    OracleResult res;
    const double len = std::hypot(in.normal.x, in.normal.y);
    const V n{in.normal.x / len, in.normal.y / len};
    const V t{n.y, -n.x};  // any unit tangent works; friction uses the sign of u·t
    const V u0 = separation(in, applyImpulse(in, V{}, false));
    const double un0 = dot(u0, n);
    res.vA = in.a.v;
    res.vB = in.b.v;
    res.wA = in.a.w;
    res.wB = in.b.w;
    if (!(un0 < 0.0)) return res;
    res.colliding = true;

    // Pass 1: find the size of the normal impulse with a coarse step. Start
    // from 1/64 of the frictionless compression impulse |u·n|/(n·K·n) and
    // enlarge the step until the march ends within 4096 steps.
    const double Knn = dot(n, separation(in, applyImpulse(in, n, true)));
    double h = -un0 / Knn / 64.0;
    Pass coarse;
    for (int tries = 0; tries < 60; ++tries) {
        coarse = march(in, n, t, h, 4096);
        if (coarse.ended || coarse.failed) break;
        h *= 8.0;
    }
    if (!coarse.ended) {
        res.failed = true;
        return res;
    }
    // Pass 2: targetSteps steps over the coarse estimate of the normal impulse.
    h = dot(coarse.p, n) / targetSteps;
    const Pass fine = march(in, n, t, h, 4 * targetSteps + 16);
    if (!fine.ended) {
        res.failed = true;
        return res;
    }
    res.step = h;
    res.steps = fine.steps;
    res.reachedSticking = fine.reachedSticking;
    res.impulse = {fine.p.x, fine.p.y};
    const Velocities after = applyImpulse(in, fine.p, false);
    res.vA = {after.vA.x, after.vA.y};
    res.vB = {after.vB.x, after.vB.y};
    res.wA = after.wA;
    res.wB = after.wB;
    return res;
}

}  // namespace i2d_test
