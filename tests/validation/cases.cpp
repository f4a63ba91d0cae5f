// Validation suite — the cases. Every figure is read through tb::Simulation
// body samples taken after each step, with the same code for both engines.
#include "cases.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "case_support.hpp"
#include "run_command.hpp"
#include "scene_loader.hpp"

namespace val {

double ellipticK(double k) {
    double a = 1.0, b = std::sqrt(1.0 - k * k);
    for (int i = 0; i < 40 && std::abs(a - b) > 1e-16 * a; ++i) {
        const double an = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = an;
    }
    return 3.14159265358979323846 / (2.0 * a);
}

namespace {

/// The vertex of the parabola through three equally spaced samples a, b, c
/// (b the largest): the apex of a free flight, which semi-implicit Euler
/// samples on an exact parabola, without the sampling error of max(b).
double parabolaPeak(double a, double b, double c) {
    const double den = a - 2.0 * b + c;
    if (den >= 0.0) return b;
    const double p = 0.5 * (a - c) / den;
    return b - 0.25 * (a - c) * p;
}

// ---------------------------------------------------------------------------
// Free fall and projectile

tb::SceneDesc fallScene(i2d::Vec2 velocity) {
    tb::SceneDesc d = emptyScene("free_fall", {0.0f, -10.0f});
    tb::BodyDesc b = body("ball", i2d::BodyType::dynamic_body, {0.0f, 0.0f}, {circleShape(0.5f, 1.0f, 0.6f, 0.0f)});
    b.def.linearVelocity = velocity;
    d.bodies.push_back(b);
    return d;
}

/// Drop (m) after `steps` steps from rest at y = 0.
double freeFallDrop(EngineKind kind, long steps) {
    tb::SceneDesc d = fallScene({0.0f, 0.0f});
    auto sim = make(d, kind);
    for (long i = 0; i < steps; ++i) sim->step(d.dt);
    return -static_cast<double>(sim->sample(0).y);
}

/// Semi-implicit Euler from rest: v_k = v_{k−1} − g h, y_k = y_{k−1} + h v_k, so
/// after N (sub)steps the drop is g h² N(N+1)/2 = g t²/2 + g h t/2.
double discreteDrop(EngineKind kind, long steps) {
    const Integrator in = integrator(kind, fallScene({0, 0}));
    const double n = static_cast<double>(steps) * in.perStep;
    return kG * in.h * in.h * n * (n + 1.0) / 2.0;
}

/// Rounding bound of a float free fall of N (sub)steps reaching |y| ≤ Y at
/// speed ≤ V: each position update rounds by ≤ ½ ulp(Y), each velocity
/// update by ≤ ½ ulp(V), which is then carried over the remaining time t:
/// N·ulp(Y)/2 + N·t·ulp(V)/2, with ulp(x) ≤ 2·eps·x.
double fallRounding(double n, double Y, double V, double t) { return n * kEps * Y + n * t * kEps * V; }

constexpr double kProjectileSpeed = 10.0, kProjectileAngle = kPi / 4.0;

/// Range (m) of a projectile launched from y = 0 at 10 m/s and 45°: x where y
/// comes back to 0, from the parabola through the last three samples (the
/// step-end samples of semi-implicit Euler lie on an exact parabola).
double projectileRange(EngineKind kind) {
    const float vx = static_cast<float>(kProjectileSpeed * std::cos(kProjectileAngle));
    const float vy = static_cast<float>(kProjectileSpeed * std::sin(kProjectileAngle));
    tb::SceneDesc d = fallScene({vx, vy});
    auto sim = make(d, kind);
    double y0 = 0, t1 = 0, y1 = 0;
    for (long i = 1; i < 600; ++i) {
        sim->step(d.dt);
        const double t2 = i * static_cast<double>(d.dt), y2 = sim->sample(0).y;
        if (i >= 2 && y2 < 0.0) {
            // y(t) = y1 + B (t − t1) + C (t − t1)² through the samples at t1 − h, t1, t1 + h; root after t1.
            const double h = t2 - t1;
            const double C = (y2 - 2.0 * y1 + y0) / (2.0 * h * h);
            const double B = (y2 - y0) / (2.0 * h);
            const double tau = (-B - std::sqrt(B * B - 4.0 * C * y1)) / (2.0 * C);
            // x is linear in time (no force along x).
            return static_cast<double>(sim->sample(0).vx) * (t1 + tau);
        }
        y0 = y1;
        t1 = t2;
        y1 = y2;
    }
    return kNone;
}

// ---------------------------------------------------------------------------
// Pendulum (shipped scene `pendulum`)

/// Period (s) of bob NAME from the upward zero crossings of x − x_pivot over
/// `seconds`; with amplitude != nullptr, also the largest angle (degrees) over
/// the last full swing.
double pendulumPeriod(const tb::SceneDesc& desc, EngineKind kind, const std::string& bob, double seconds,
                      double* lastAmplitude = nullptr) {
    const int ib = indexOf(desc, "bob" + bob), ip = indexOf(desc, "pivot" + bob);
    auto sim = make(desc, kind);
    const tb::BodySample pivot = sim->sample(ip);
    UpCrossings up;
    std::vector<std::pair<double, double>> angles;  // (t, degrees)
    run(*sim, desc, std::lround(seconds / desc.dt), [&](double t, tb::Simulation& s) {
        const tb::BodySample b = s.sample(ib);
        up.add(t, b.x - pivot.x);
        angles.emplace_back(t, std::atan2(b.x - pivot.x, pivot.y - b.y) * 180.0 / kPi);
    });
    if (lastAmplitude && up.times.size() >= 2) {
        double a = 0.0;
        for (const auto& [t, deg] : angles)
            if (t >= up.times[up.times.size() - 2]) a = std::max(a, std::abs(deg));
        *lastAmplitude = a;
    }
    return up.period();
}

/// Simple pendulum: T = T0 · 2K(sin(θ0/2))/π with T0 = 2π√(L/g).
double pendulumTheory(double length, double degrees) {
    const double T0 = 2.0 * kPi * std::sqrt(length / kG);
    return T0 * 2.0 * ellipticK(std::sin(degrees * kPi / 360.0)) / kPi;
}

// ---------------------------------------------------------------------------
// Incline and rolling (shipped scenes `incline` and `rolling`)

/// Distance travelled down a slope of angle θ (position projected on the
/// down-slope direction (−cos θ, −sin θ)).
double downSlope(const tb::BodySample& s, double theta) { return -(s.x * std::cos(theta) + s.y * std::sin(theta)); }

/// Acceleration (m/s²) down the slope of body NAME, fitted over [t0, t1].
double slopeAcceleration(const tb::SceneDesc& desc, EngineKind kind, const std::string& name, double theta, double t0,
                         double t1) {
    const int i = indexOf(desc, name);
    auto sim = make(desc, kind);
    std::vector<double> ts, ss;
    run(*sim, desc, std::lround(t1 / desc.dt), [&](double t, tb::Simulation& s) {
        if (t >= t0 - 1e-9) {
            ts.push_back(t);
            ss.push_back(downSlope(s.sample(i), theta));
        }
    });
    return fittedAcceleration(ts, ss);
}

/// How far (m) body NAME moved down the slope between t = 0.5 s (contacts
/// settled) and `seconds`.
double slopeCreep(const tb::SceneDesc& desc, EngineKind kind, const std::string& name, double theta, double seconds) {
    const int i = indexOf(desc, name);
    auto sim = make(desc, kind);
    double start = kNone, end = kNone;
    run(*sim, desc, std::lround(seconds / desc.dt), [&](double t, tb::Simulation& s) {
        const double d = downSlope(s.sample(i), theta);
        if (std::abs(t - 0.5) < 0.5 * desc.dt) start = d;
        end = d;
    });
    return end - start;
}

/// Tangential slip of the rolling disc at `seconds`, as a fraction of its
/// speed: (|v_t| − ω r)/|v_t| with v_t the centre's velocity along the slope.
double rollingSlip(const tb::SceneDesc& desc, EngineKind kind, double theta, double radius, double seconds) {
    const int i = indexOf(desc, "rolling");
    auto sim = make(desc, kind);
    for (long k = 0; k < std::lround(seconds / desc.dt); ++k) sim->step(desc.dt);
    const tb::BodySample s = sim->sample(i);
    const double vt = -(s.vx * std::cos(theta) + s.vy * std::sin(theta));  // down the slope
    return (vt - s.w * radius) / vt;
}

// ---------------------------------------------------------------------------
// Bounce (shipped scene `bounce`)

/// Apex heights (m, bottom of the ball above the ground) of ball NAME after
/// each bounce, over 8 s.
std::vector<double> bounceApexes(const tb::SceneDesc& desc, EngineKind kind, const std::string& name) {
    const int i = indexOf(desc, name);
    const double radius = desc.bodies[static_cast<std::size_t>(i)].shapes[0].circle.radius;
    auto sim = make(desc, kind);
    std::vector<double> y, vy;
    run(*sim, desc, std::lround(8.0 / desc.dt), [&](double, tb::Simulation& s) {
        const tb::BodySample b = s.sample(i);
        y.push_back(b.y - radius);
        vy.push_back(b.vy);
    });
    // An apex lies between samples k−1 (rising) and k (not rising); refine it
    // with the parabola through the largest sample and its two neighbours.
    // Stop at the first apex below 1 mm: the ball is resting.
    std::vector<double> apexes;
    for (std::size_t k = 1; k + 1 < y.size(); ++k) {
        if (!(vy[k - 1] > 0.0 && vy[k] <= 0.0)) continue;
        const std::size_t m = y[k] >= y[k - 1] ? k : k - 1;
        const double apex = m >= 1 ? parabolaPeak(y[m - 1], y[m], y[m + 1]) : y[m];
        if (apex < 1e-3) break;
        apexes.push_back(apex);
    }
    return apexes;
}

// ---------------------------------------------------------------------------
// Head-on collisions

/// Two discs in zero gravity, no friction: m1 = 1 kg at 4 m/s strikes
/// m2 = 3 kg at rest, restitution e. Returns (v1', v2') after 0.5 s.
std::pair<double, double> headOn(EngineKind kind, float e) {
    tb::SceneDesc d = emptyScene("head_on", {0.0f, 0.0f});
    const float r = 0.5f, area = static_cast<float>(kPi) * r * r;
    tb::BodyDesc a = body("m1", i2d::BodyType::dynamic_body, {-2.0f, 0.0f}, {circleShape(r, 1.0f / area, 0.0f, e)});
    a.def.linearVelocity = {4.0f, 0.0f};
    d.bodies.push_back(a);
    d.bodies.push_back(body("m2", i2d::BodyType::dynamic_body, {0.0f, 0.0f}, {circleShape(r, 3.0f / area, 0.0f, e)}));
    auto sim = make(d, kind);
    for (int i = 0; i < 30; ++i) sim->step(d.dt);
    return {sim->sample(0).vx, sim->sample(1).vx};
}

/// 1D collision with Newton's e along the line of centres:
/// v1' = (m1 v1 + m2 v2 − m2 e (v1 − v2)) / (m1 + m2), v2' = (m1 v1 + m2 v2 + m1 e (v1 − v2)) / (m1 + m2).
/// (For central frictionless impacts Stronge's and Newton's e coincide.)
std::pair<double, double> headOnTheory(double e) {
    const double m1 = 1, m2 = 3, v1 = 4, v2 = 0, p = m1 * v1 + m2 * v2;
    return {(p - m2 * e * (v1 - v2)) / (m1 + m2), (p + m1 * e * (v1 - v2)) / (m1 + m2)};
}

// ---------------------------------------------------------------------------
// Newton's cradle (shipped scene `newtons_cradle`)

/// Rise (m) of the last ball over its first swing out, and the largest rise
/// of the three middle balls over the same time.
std::pair<double, double> cradleRises(const tb::SceneDesc& desc, EngineKind kind) {
    int ib[5];
    for (int k = 0; k < 5; ++k) ib[k] = indexOf(desc, "ball" + std::to_string(k));
    auto sim = make(desc, kind);
    double y0[5];
    for (int k = 0; k < 5; ++k) y0[k] = sim->sample(ib[k]).y;
    double lastRise = 0.0, middleRise = 0.0;
    bool out = false, done = false;
    run(*sim, desc, std::lround(4.0 / desc.dt), [&](double, tb::Simulation& s) {
        if (done) return;
        const tb::BodySample last = s.sample(ib[4]);
        if (last.vx > 0.05f) out = true;
        if (out && last.vx <= 0.0f) done = true;  // the last ball's first apex
        lastRise = std::max(lastRise, last.y - y0[4]);
        for (int k = 1; k <= 3; ++k) middleRise = std::max(middleRise, s.sample(ib[k]).y - y0[k]);
    });
    return {lastRise, middleRise};
}

// ---------------------------------------------------------------------------
// Free spin

constexpr double kSpin = 10.0, kSpinSeconds = 10.0;

/// A 1 × 0.2 m box spinning at 10 rad/s in zero gravity for 10 s: final ω
/// and the total angle turned (unwrapped from the per-step changes).
std::pair<double, double> freeSpin(EngineKind kind) {
    tb::SceneDesc d = emptyScene("spin", {0.0f, 0.0f});
    tb::BodyDesc b = body("box", i2d::BodyType::dynamic_body, {0.0f, 0.0f}, {boxShape(0.5f, 0.1f, 1.0f, 0.6f, 0.0f)});
    b.def.angularVelocity = static_cast<float>(kSpin);
    d.bodies.push_back(b);
    auto sim = make(d, kind);
    double turned = 0.0, last = sim->sample(0).angle;
    run(*sim, d, std::lround(kSpinSeconds / d.dt), [&](double, tb::Simulation& s) {
        const double a = s.sample(0).angle;
        turned += std::remainder(a - last, 2.0 * kPi);
        last = a;
    });
    return {sim->sample(0).w, turned};
}

// ---------------------------------------------------------------------------
// Spring (soft distance constraint)

constexpr double kSpringHertz = 1.0, kSpringSeconds = 10.0, kSpringStretch = 0.1;

/// A 1 kg disc on a 1 Hz undamped spring (rest length 1 m) to a fixed anchor,
/// zero gravity, released 0.1 m stretched. Returns the period (s) and the
/// amplitude after 10 s as a fraction of the initial one.
std::pair<double, double> springRun(EngineKind kind) {
    tb::SceneDesc d = emptyScene("spring", {0.0f, 0.0f});
    const float r = 0.1f;
    d.bodies.push_back(body("anchor", i2d::BodyType::static_body, {0.0f, 0.0f}, {}));
    d.bodies.push_back(body("mass", i2d::BodyType::dynamic_body, {1.0f + static_cast<float>(kSpringStretch), 0.0f},
                            {circleShape(r, 1.0f / (static_cast<float>(kPi) * r * r), 0.0f, 0.0f)}));
    tb::JointDesc j;
    j.bodyA = 0;
    j.bodyB = 1;
    i2d::DistanceJointDef& spring = j.as<i2d::DistanceJointDef>();
    spring.length = 1.0f;
    spring.enableSpring = true;
    spring.hertz = static_cast<float>(kSpringHertz);
    spring.dampingRatio = 0.0f;
    d.joints.push_back(j);
    auto sim = make(d, kind);
    UpCrossings up;
    double lastAmplitude = 0.0;
    run(*sim, d, std::lround(kSpringSeconds / d.dt), [&](double t, tb::Simulation& s) {
        const double x = s.sample(1).x - 1.0;
        up.add(t, x);
        if (t > kSpringSeconds - 1.0 / kSpringHertz) lastAmplitude = std::max(lastAmplitude, std::abs(x));
    });
    return {up.period(), lastAmplitude / kSpringStretch};
}

/// The soft constraint is implicit Euler on the spring force: per (sub)step of
/// length h its eigenvalues are (1 ± iωh)/(1 + ω²h²), modulus (1 + ω²h²)^(−1/2),
/// so after N (sub)steps the amplitude is (1 + ω²h²)^(−N/2), and the phase
/// advances atan(ωh) per (sub)step: period 2πh/atan(ωh).
double implicitEulerAmplitude(double h, double seconds) {
    const double w = 2.0 * kPi * kSpringHertz;
    return std::pow(1.0 + w * w * h * h, -0.5 * seconds / h);
}
double implicitEulerPeriod(double h) {
    const double w = 2.0 * kPi * kSpringHertz;
    return 2.0 * kPi * h / std::atan(w * h);
}

// ---------------------------------------------------------------------------
// Spinning rod impact (HARD_CASES 5.8 case A)

/// A uniform rod L = 1 m, m = 1 kg at 45°, v = (0, −1), ω = 4 rad/s, its lower
/// end just touching the ground, zero gravity, μ = 0.5, e = 1. Returns the
/// kinetic energy after the impact over the one before. The rod is a box
/// 1 × 0.004 m (thin, yet thicker than Box2D's 2.5 mm vertex welding): its
/// corner is 2 mm from the ideal rod's end.
double spinningRodEnergyRatio(EngineKind kind) {
    tb::SceneDesc d = emptyScene("spinning_rod", {0.0f, 0.0f});
    const float hx = 0.5f, hy = 0.002f, angle = static_cast<float>(kPi / 4.0);
    tb::BodyDesc ground = body("ground", i2d::BodyType::static_body, {0.0f, -1.0f},
                               {boxShape(20.0f, 1.0f, 1.0f, 0.5f, 1.0f)});
    d.bodies.push_back(ground);
    // Lowest corner (−hx, −hy) rotated by 45° lies at (−hx cos − (−hy) sin, ...); put it at y = +1e-4.
    const double lowest = -(hx * std::sin(angle) + hy * std::cos(angle));
    tb::BodyDesc rod = body("rod", i2d::BodyType::dynamic_body, {0.0f, static_cast<float>(-lowest + 1e-4)},
                            {boxShape(hx, hy, 1.0f / (4.0f * hx * hy), 0.5f, 1.0f)});
    rod.def.angle = angle;
    rod.def.linearVelocity = {0.0f, -1.0f};
    rod.def.angularVelocity = 4.0f;
    d.bodies.push_back(rod);
    auto sim = make(d, kind);
    auto kinetic = [](const tb::BodySample& s) {
        return 0.5 * s.mass * (double(s.vx) * s.vx + double(s.vy) * s.vy) + 0.5 * s.inertia * double(s.w) * s.w;
    };
    const double before = kinetic(sim->sample(1));
    // 0.1 s: the impact is over and the rod is in free flight (no gravity, so
    // its kinetic energy is constant until it lands again, well after).
    for (int i = 0; i < 6; ++i) sim->step(d.dt);
    return kinetic(sim->sample(1)) / before;
}

// ---------------------------------------------------------------------------
// Stacks and pyramids (shipped scenes), through tb::runScene

struct StackFigures {
    double topY = kNone;   ///< the body named `top`: final height of its origin (m)
    double topDx = kNone;  ///< its largest horizontal excursion |x − x0| (m)
    int displaced = -1;    ///< bodies that moved more than 0.5 m
};

StackFigures stackRun(const tb::SceneDesc& desc, EngineKind kind, double seconds) {
    tb::RunReport r = tb::runScene(desc, std::lround(seconds / desc.dt), kind);
    StackFigures f;
    f.displaced = r.displaced;
    for (const auto& n : r.named)
        if (n.name == "top") {
            f.topY = n.y;
            f.topDx = n.maxDx;
        }
    return f;
}

}  // namespace

double oneSubstepFreeFallLead() {
    tb::SceneDesc d = fallScene({0.0f, 0.0f});
    d.settings.substeps = 1;
    auto a = make(d, EngineKind::impulse2d), b = make(d, EngineKind::box2d);
    double worst = 0.0;
    for (int i = 1; i <= 60; ++i) {
        a->step(d.dt);
        b->step(d.dt);
        const double t = i * static_cast<double>(d.dt);
        const double lead = static_cast<double>(a->sample(0).y) - b->sample(0).y;
        worst = std::max(worst, std::abs(lead - 0.5 * kG * static_cast<double>(d.dt) * t));
    }
    return worst;
}

// ---------------------------------------------------------------------------

namespace {
const char* const kPendulumWhy =
    "Box2D 2.4.1 solves the rigid joint on velocities once per 1/60 s step and then corrects the length on "
    "positions: the velocity the bob had along the rod's old direction is projected out every step, a loss of "
    "about (ωh)² of the kinetic energy per step (0.5 % at ω = 4.5 rad/s), so the 90° swing decays (next row) and its "
    "period shortens with it (T/T₀ = 1.07 at 60° against 1.18 at 90°). Impulse2D's 1/240 s substeps "
    "make that per-step loss 16 times smaller; its soft joint keeps the amplitude within the 0.45° bar.";
}  // namespace

std::vector<Case> allCases(const std::string& assetsDir) {
    std::vector<Case> cases;
    auto scene = [&](const std::string& name) { return tb::loadSceneDesc(name, assetsDir); };

    // Free fall ---------------------------------------------------------------
    {
        const long steps = 60;
        const tb::SceneDesc d = fallScene({0, 0});
        Case c;
        c.id = "free_fall";
        c.group = "Free fall and projectile";
        c.quantity = "drop after 1 s from rest (m)";
        c.formula = "g t²/2";
        c.analytic = kG / 2.0;
        c.measure = [=](EngineKind k) { return freeFallDrop(k, steps); };
        for (EngineKind k : {EngineKind::impulse2d, EngineKind::box2d}) {
            const Integrator in = integrator(k, d);
            const double n = static_cast<double>(steps) * in.perStep;
            Check& ch = k == EngineKind::box2d ? c.box2d : c.impulse2d;
            if (isBox2D(k)) {
                ch.reference = discreteDrop(k, steps);
                ch.tolerance = fallRounding(n, 8.0, 16.0, 1.0);
                ch.why = "held against its own integrator: semi-implicit Euler gives g h² N(N+1)/2 exactly (h = 1/60 "
                         "s, N steps), i.e. g t²/2 + g h t/2; tolerance = float rounding over N steps, "
                         "N·ulp(8 m)/2 + N·t·ulp(16 m/s)/2";
            } else {
                ch.reference = c.analytic;
                // Two half kicks per substep: twice the velocity roundings.
                ch.tolerance = fallRounding(n, 8.0, 2.0 * 16.0, 1.0);
                ch.why = "g t²/2 exactly: a body that touches nothing takes its forces in two halves around each "
                         "substep's drift (velocity Verlet, exact for a constant acceleration); tolerance = float "
                         "rounding over N = 240 substeps, N·ulp(8 m)/2 + 2·N·t·ulp(16 m/s)/2";
            }
        }
        c.whyTheyDiffer = "Box2D 2.4.1 integrates by semi-implicit Euler, whose drop exceeds g t²/2 by g h t/2 (h = "
                          "1/60 s); Impulse2D splits a free body's forces around the drift (velocity Verlet), which "
                          "falls on the parabola itself. At one substep each, Box2D's drop exceeds Impulse2D's by "
                          "exactly g h t/2 (test FreeFall.BoxTwoDsDropLeadsByHalfAStepOfGravity).";
        cases.push_back(c);
    }
    {
        const tb::SceneDesc d = fallScene({0, 0});
        const double vx = kProjectileSpeed * std::cos(kProjectileAngle);
        Case c;
        c.id = "projectile_range";
        c.group = "Free fall and projectile";
        c.quantity = "range at 10 m/s, 45° (m)";
        c.formula = "v² sin 2θ / g";
        c.analytic = kProjectileSpeed * kProjectileSpeed * std::sin(2 * kProjectileAngle) / kG;
        c.measure = projectileRange;
        for (EngineKind k : {EngineKind::impulse2d, EngineKind::box2d}) {
            const Integrator in = integrator(k, d);
            Check& ch = k == EngineKind::box2d ? c.box2d : c.impulse2d;
            // ≈ 1.41 s of flight: N (sub)steps, |x|, |y| ≤ 10 m, |v| ≤ 10 m/s.
            const double n = 1.5 / in.h;
            if (isBox2D(k)) {
                // y = v_y t − g t²/2 − g h t/2 vanishes at t = 2 v_y/g − h: range R − v_x h.
                ch.reference = c.analytic - vx * in.h;
                ch.tolerance = fallRounding(n, 10.0, 10.0, 1.5);
                ch.why = "held against its own integrator: the step-end samples lie on y = v_y t − g t²/2 − g h t/2, "
                         "which lands at t = 2v_y/g − h, range R − v_x h; tolerance: float rounding as for the free "
                         "fall, N·ulp(10 m)/2 + N·t·ulp(10 m/s)/2 over the flight";
            } else {
                ch.reference = c.analytic;
                ch.tolerance = fallRounding(n, 10.0, 2.0 * 10.0, 1.5);
                ch.why = "R exactly: the step-end samples lie on the flight's own parabola (velocity Verlet, as the "
                         "free fall); tolerance: float rounding as for the free fall, N·ulp(10 m)/2 + "
                         "2·N·t·ulp(10 m/s)/2 over the flight";
            }
        }
        c.whyTheyDiffer = "Box2D 2.4.1's semi-implicit Euler lands h = 1/60 s early, the range short by v_x h; "
                          "Impulse2D's velocity Verlet flies the parabola itself.";
        cases.push_back(c);
    }

    // Pendulum ------------------------------------------------------------------
    {
        const tb::SceneDesc d = scene("pendulum");
        for (int deg : {5, 90}) {
            Case c;
            c.id = "pendulum_" + std::to_string(deg);
            c.group = "Pendulum (scene pendulum, rigid distance joint, L = 1 m)";
            c.quantity = "period at " + std::to_string(deg) + "° (s)";
            c.formula = "2π√(L/g) · 2K(sin(θ₀/2))/π";
            c.analytic = pendulumTheory(1.0, deg);
            c.measure = [d, deg](EngineKind k) { return pendulumPeriod(d, k, std::to_string(deg), 12.0); };
            c.impulse2d.tolerance = 0.005 * c.analytic;
            c.impulse2d.why =
                "0.5 %: velocity Verlet (the bob touches nothing: its forces are split around the "
                "drift) shortens an oscillation's period by (ωh)²/24 (2e-6 at h = 1/240 s), as "
                "semi-implicit Euler does; the rest is the soft joint (30 Hz, 1/8 of the substep rate), which "
                "stretches by m v²/(L k) at the bottom and lengthens the pendulum";
            c.box2d.tolerance = 0.005 * c.analytic;
            c.box2d.why = "0.5 %: (ωh)²/24 = 3e-5 at h = 1/60 s; the rest is the joint's position correction";
            if (deg == 90) {
                c.box2d.asserted = false;
                c.box2d.why += "; reported only at 90°: Box2D 2.4.1 loses a third of the amplitude in 5 swings "
                               "(next row) and a smaller swing is a shorter one";
            }
            c.whyTheyDiffer = kPendulumWhy;
            cases.push_back(c);
        }
        Case c;
        c.id = "pendulum_90_amplitude";
        c.group = "Pendulum (scene pendulum, rigid distance joint, L = 1 m)";
        c.quantity = "amplitude after 5 swings from 90° (°)";
        c.formula = "θ₀ (no friction)";
        c.analytic = 90.0;
        c.measure = [d](EngineKind k) {
            double a = kNone;
            pendulumPeriod(d, k, "90", 12.0, &a);
            return a;
        };
        // HARD_CASES 5.2: amplitude loss < 1 % per 10 periods with joint softness on; 5 swings: 0.5 %.
        c.impulse2d.tolerance = c.box2d.tolerance = 0.005 * 90.0;
        c.impulse2d.why = "0.45° = 0.5 %, the HARD_CASES 5.2 bar of < 1 % amplitude loss per 10 periods for a soft "
                          "joint (it dissipates: damping ratio 2 on the joint's position error)";
        c.box2d.why = "0.45°, as for Impulse2D; reported only (see the period at 90°)";
        c.box2d.asserted = false;
        c.whyTheyDiffer = kPendulumWhy;
        cases.push_back(c);
    }

    // Incline -------------------------------------------------------------------
    {
        const tb::SceneDesc d = scene("incline");
        const double theta = 30.0 * kPi / 180.0;
        for (const char* mu : {"0.0", "0.3", "0.5"}) {
            const double m = std::stod(mu);
            Case c;
            c.id = std::string("incline_slide_mu") + (mu[2] == '0' ? "0" : std::string(1, mu[2]));
            c.group = "Box on a 30° incline (scene incline)";
            c.quantity = std::string("acceleration, μ = ") + mu + " (m/s²)";
            c.formula = "g (sin θ − μ cos θ)";
            c.analytic = kG * (std::sin(theta) - m * std::cos(theta));
            const std::string name = std::string("box_mu") + mu;
            c.measure = [d, name, theta](EngineKind k) { return slopeAcceleration(d, k, name, theta, 0.25, 1.25); };
            const std::string why = "1 %: a constant force gives an exact quadratic under semi-implicit Euler and the "
                                    "fit has no truncation error; what is left is how exactly the friction row "
                                    "holds |λ_t| = μ λ_n after the iterations";
            c.impulse2d.tolerance = c.box2d.tolerance = 0.01 * kG;  // 1 % of g
            c.impulse2d.why = c.box2d.why = why + " (1 % of g = 0.1 m/s²)";
            cases.push_back(c);
        }
        for (const char* mu : {"0.6", "0.8"}) {
            Case c;
            c.id = std::string("incline_stick_mu") + mu[2];
            c.group = "Box on a 30° incline (scene incline)";
            c.quantity = std::string("creep from 0.5 s to 3 s, μ = ") + mu + " ≥ tan 30° (m)";
            c.formula = "0 (static friction holds)";
            c.analytic = 0.0;
            const std::string name = std::string("box_mu") + mu;
            c.measure = [d, name, theta](EngineKind k) { return slopeCreep(d, k, name, theta, 3.0); };
            c.impulse2d.tolerance = c.box2d.tolerance = 0.005;
            c.impulse2d.why = c.box2d.why = "5 mm = the penetration slop: a sticking contact must not drift more "
                                            "than the engines' own position tolerance";
            cases.push_back(c);
        }
    }

    // Rolling -------------------------------------------------------------------
    {
        const tb::SceneDesc d = scene("rolling");
        const double theta = 30.0 * kPi / 180.0;
        Case c;
        c.id = "rolling_disc";
        c.group = "Disc on a 30° incline (scene rolling)";
        c.quantity = "acceleration rolling without slipping, μ = 0.6 (m/s²)";
        c.formula = "(2/3) g sin θ";
        c.analytic = 2.0 / 3.0 * kG * std::sin(theta);
        c.measure = [d, theta](EngineKind k) { return slopeAcceleration(d, k, "rolling", theta, 0.25, 1.25); };
        c.impulse2d.tolerance = c.box2d.tolerance = 0.01 * c.analytic;
        c.impulse2d.why = c.box2d.why = "1 % (HARD_CASES 5.4): exact quadratic fit as for the incline; the static "
                                        "friction row must hold the contact point still";
        cases.push_back(c);

        Case s = c;
        s.id = "rolling_slip_speed";
        s.quantity = "slip (v − ωr)/v at 1.25 s, μ = 0.6";
        s.formula = "0";
        s.analytic = 0.0;
        s.measure = [d, theta](EngineKind k) { return rollingSlip(d, k, theta, 0.5, 1.25); };
        s.impulse2d.tolerance = s.box2d.tolerance = 0.02;
        s.impulse2d.why = "2 %: the contact is solved at one point per substep while the disc turns up to ωΔt = "
                          "0.14 rad per step; the contact point's material anchor rises by r(1 − cos ωΔt) within "
                          "the step and the contact runs partly speculative (see Known issues)";
        s.box2d.why = "2 %: Box2D's contact point is midway into its 1 cm polygon skin overlap, so the disc rolls "
                      "on a radius about 4.5 mm (0.9 %) short of r";
        s.whyTheyDiffer = "Opposite signs: Box2D's disc rolls on a radius shortened by its skin overlap (ω r > v); "
                          "Impulse2D's slides slightly ahead of its rotation (v > ω r) while its rolling contact "
                          "runs speculative within the step.";
        cases.push_back(s);

        Case p = c;
        p.id = "slipping_disc";
        p.quantity = "acceleration slipping, μ = 0.1 < tan θ/3 (m/s²)";
        p.formula = "g (sin θ − μ cos θ)";
        p.analytic = kG * (std::sin(theta) - 0.1 * std::cos(theta));
        p.measure = [d, theta](EngineKind k) { return slopeAcceleration(d, k, "slipping", theta, 0.25, 1.25); };
        cases.push_back(p);
    }

    // Bounce --------------------------------------------------------------------
    {
        const tb::SceneDesc d = scene("bounce");
        const double h0 = 5.0;
        struct B {
            const char* name;  ///< the ball in the scene
            const char* tag;   ///< e in the case id
            double e;
            int n;  ///< apex number
        };
        for (B b :
             {B{"e0.25", "025", 0.25, 1}, B{"e0.5", "05", 0.5, 1}, B{"e0.5", "05", 0.5, 2}, B{"e0.5", "05", 0.5, 3},
              B{"e0.5", "05", 0.5, 4}, B{"e0.75", "075", 0.75, 1}, B{"e0.75", "075", 0.75, 2},
              B{"e0.75", "075", 0.75, 3}, B{"e0.75", "075", 0.75, 4}, B{"e1", "1", 1.0, 1}, B{"e1", "1", 1.0, 3}}) {
            Case c;
            const std::string e = std::string(b.name).substr(1);
            c.id = std::string("bounce_e") + b.tag + "_h" + std::to_string(b.n);
            c.group = "Bounce (scene bounce, h₀ = 5 m)";
            c.quantity = "apex " + std::to_string(b.n) + ", e = " + e + " (m)";
            c.formula = "e^(2n) h₀";
            c.analytic = std::pow(b.e, 2 * b.n) * h0;
            const std::string name = b.name;
            const std::size_t n = static_cast<std::size_t>(b.n);
            c.measure = [d, name, n](EngineKind k) {
                std::vector<double> a = bounceApexes(d, k, name);
                return a.size() >= n ? a[n - 1] : kNone;
            };
            // Each tolerance from this bounce's own rebound speed u = eⁿ v₀
            // (v₀ = 10 m/s). Impulse2D times the impact within the step and
            // launches the rebound with semi-implicit Euler's half-substep of
            // gravity (impact_stage.cpp), so its flights are exact parabolas:
            // held to the 3 % of the hard-cases issue. Box2D 2.4.1 launches
            // the rebound as if g h/2 slower, which costs an apex of u²/2g
            // about u h/2: u h/2 with h = 1/60 s, + 2 %.
            const double v0 = std::sqrt(2.0 * kG * h0);
            const double u = std::pow(b.e, b.n) * v0;
            c.impulse2d.tolerance = 0.03 * c.analytic;
            c.impulse2d.why = "3 % (the hard-cases issue's bar for bounces 1 to 4; each flight is an exact parabola)";
            c.box2d.tolerance = u * (1.0 / 60.0) / 2.0 + 0.02 * c.analytic;
            c.box2d.why = "u h/2 with u = eⁿ v₀ this bounce's rebound speed and h = 1/60 s (semi-implicit Euler's "
                          "low apex), + 2 %";
            // Box2D 2.4.1 puts a ball swept to the ground back to its time of
            // impact with the speed of the step's end, too fast by up to g·Δt:
            // at e = 0.75 its third and fourth apexes are 7.1 % and 9.6 % high.
            // Reported, as Box2D's other figures beyond its own bound are.
            if (b.e == 0.75 && b.n >= 3) c.box2d.asserted = false;
            c.whyTheyDiffer = "Both engines bring a ball that moves further in a step than the speculative distance "
                              "to the ground's surface by continuous collision, so the impact happens there; "
                              "Box2D's restitution is Newton's e applied to that approach speed, Impulse2D's is "
                              "Stronge's e in the impact law followed by 1/240 s substeps. Impulse2D applies the law "
                              "at the moment of impact within the step and stores the rebound staggered by half a "
                              "substep of gravity as semi-implicit Euler needs, and its continuous collision gives "
                              "a body put back to its time of impact the velocity it had then: its apexes are "
                              "within 0.1 %. Box2D 2.4.1 moves a ball swept to the ground back to its time of "
                              "impact keeping the velocity of the step's end (b2Body::Advance moves only the "
                              "pose), up to g·Δt too fast, and its later apexes come out high.";
            cases.push_back(c);
        }
    }

    // Head-on collisions ----------------------------------------------------------
    for (double e : {1.0, 0.0, 0.5}) {
        const auto [t1, t2] = headOnTheory(e);
        for (int which : {1, 2}) {
            Case c;
            const std::string es = e == 1.0 ? "1" : e == 0.0 ? "0" : "0.5";
            c.id = "head_on_e" + std::string(e == 0.5 ? "05" : es) + "_v" + std::to_string(which);
            c.group = "Head-on collision, m₁ = 1 kg at 4 m/s onto m₂ = 3 kg at rest, no friction";
            c.quantity = std::string(which == 1 ? "v₁'" : "v₂'") + ", e = " + es + " (m/s)";
            c.formula = which == 1 ? "(m₁v₁ − m₂ e v₁)/(m₁+m₂)" : "(m₁v₁ + m₁ e v₁)/(m₁+m₂)";
            c.analytic = which == 1 ? t1 : t2;
            c.measure = [e, which](EngineKind k) {
                const auto [v1, v2] = headOn(k, static_cast<float>(e));
                return which == 1 ? v1 : v2;
            };
            c.impulse2d.tolerance = 1e-5;
            c.impulse2d.why = "float rounding (the closed-form law is exact for a central frictionless impact)";
            c.box2d.tolerance = 1e-5;
            c.box2d.why = "float rounding (one contact point: the velocity iteration is exact in one pass)";
            cases.push_back(c);
        }
    }

    // Newton's cradle -----------------------------------------------------------------
    {
        const tb::SceneDesc d = scene("newtons_cradle");
        Case c;
        c.id = "cradle_last_ball_rise";
        c.group = "Newton's cradle (scene newtons_cradle, 5 balls, e = 1, 3 m rods, ball 0 from 60°)";
        c.quantity = "rise of ball 4 on its first swing (m)";
        c.formula = "L (1 − cos 60°) (one ball in, one out)";
        c.analytic = 3.0 * (1.0 - std::cos(kPi / 3.0));
        c.measure = [d](EngineKind k) { return cradleRises(d, k).first; };
        c.impulse2d.tolerance = 0.02 * c.analytic;
        c.impulse2d.why = "2 %: the rods are soft joints (they dissipate a little, see the pendulum amplitude) "
                          "and the swing is integrated at 1/240 s";
        c.box2d.tolerance = 0.02 * c.analytic;
        c.box2d.why = "2 %, as for Impulse2D; reported only: Box2D 2.4.1's contact solver does not propagate "
                      "the impulse down the line";
        c.box2d.asserted = false;
        c.whyTheyDiffer = "Box2D 2.4.1 solves the four touching contacts together by iterated velocity constraints "
                          "with restitution as a velocity target; the balls come out with spread velocities, not "
                          "one ball out. Impulse2D resolves each contact by the impact law in sequence (Gauss-Seidel "
                          "sweeps), which passes the whole momentum along, as in the ideal cradle.";
        cases.push_back(c);
        Case m = c;
        m.id = "cradle_middle_balls_rise";
        m.quantity = "largest rise of balls 1-3 meanwhile (m)";
        m.formula = "0";
        m.analytic = 0.0;
        m.measure = [d](EngineKind k) { return cradleRises(d, k).second; };
        m.impulse2d.tolerance = m.box2d.tolerance = 0.01;
        m.impulse2d.why = "1 cm: a middle ball keeping 1/10 of the speed would rise 1.5 cm";
        m.box2d.why = m.impulse2d.why + "; reported only, as above";
        cases.push_back(m);
    }

    // Free spin, spring -----------------------------------------------------------------
    {
        Case c;
        c.id = "free_spin_omega";
        c.group = "Free rigid body and spring (zero gravity)";
        c.quantity = "ω after 10 s of free spin at 10 rad/s (rad/s)";
        c.formula = "ω₀ (angular momentum kept)";
        c.analytic = kSpin;
        c.measure = [](EngineKind k) { return freeSpin(k).first; };
        c.impulse2d.tolerance = c.box2d.tolerance = 1e-5;
        c.impulse2d.why = c.box2d.why = "float rounding: no torque acts, ω is never changed";
        cases.push_back(c);

        Case a;
        a.id = "free_spin_angle";
        a.group = c.group;
        a.quantity = "angle turned in those 10 s (rad)";
        a.formula = "ω₀ t";
        a.analytic = kSpin * kSpinSeconds;
        a.measure = [](EngineKind k) { return freeSpin(k).second; };
        // Impulse2D rotates q ← normalize(q + hω q⊥): atan(hω) per substep.
        const double h = kDt / 4.0, n = kSpinSeconds / h;
        a.impulse2d.reference = n * std::atan(h * kSpin);
        a.impulse2d.tolerance = n * 4.0 * kEps;
        a.impulse2d.why = "held against its own integrator: the rotation advances atan(hω) per substep (h = 1/240 s), "
                          "N atan(hω) in all; tolerance: rounding of the unit rotation, ≤ 4 eps per substep";
        a.box2d.reference = kSpin * static_cast<double>(kDt) * std::lround(kSpinSeconds / kDt);
        a.box2d.tolerance = 600 * kEps * 100.0;
        a.box2d.why = "Box2D 2.4.1 adds hω to the angle, exact; tolerance: rounding of an angle ≤ 100 rad, "
                      "600 steps × ulp(100)/2";
        a.whyTheyDiffer = "Impulse2D integrates the rotation as Box2D v3 does (normalised q + hω q⊥, advancing "
                          "atan(hω) per substep, a lag of (hω)³/3 per substep); Box2D 2.4.1 integrates the angle "
                          "itself, exactly.";
        cases.push_back(a);

        Case p;
        p.id = "spring_period";
        p.group = c.group;
        p.quantity = "period of a 1 Hz undamped spring (s)";
        p.formula = "1/f";
        p.analytic = 1.0 / kSpringHertz;
        p.measure = [](EngineKind k) { return springRun(k).first; };
        p.impulse2d.reference = implicitEulerPeriod(kDt / 4.0);
        p.box2d.reference = implicitEulerPeriod(kDt);
        p.impulse2d.tolerance = p.box2d.tolerance = 1e-3;
        p.impulse2d.why = p.box2d.why = "held against the soft constraint's own scheme (implicit Euler on the "
                                        "spring: 2πh/atan(ωh)); 1 ms = crossing interpolation and rounding";
        p.whyTheyDiffer = "The soft constraint is implicit Euler on the spring force: period 2πh/atan(ωh), longer by "
                          "(ωh)²/3; Impulse2D's substep is 4× smaller.";
        cases.push_back(p);

        Case m = p;
        m.id = "spring_amplitude";
        m.quantity = "amplitude after 10 periods / initial";
        m.formula = "1 (undamped)";
        m.analytic = 1.0;
        m.measure = [](EngineKind k) { return springRun(k).second; };
        m.impulse2d.reference = implicitEulerAmplitude(kDt / 4.0, kSpringSeconds);
        m.box2d.reference = implicitEulerAmplitude(kDt, kSpringSeconds);
        m.impulse2d.tolerance = m.box2d.tolerance = 0.02;
        m.impulse2d.why = m.box2d.why = "reported against implicit Euler's decay (1 + ω²h²)^(−N/2); 0.02 = the "
                                        "largest sample within a swing misses the peak by ≤ 1 − cos(ωΔt/2) = 1.4 % "
                                        "at 60 Hz";
        m.impulse2d.asserted = m.box2d.asserted = false;
        m.whyTheyDiffer = "Both damp an undamped spring numerically. One implicit Euler step multiplies the amplitude "
                          "by (1 + ω²h²)^(−1/2): over 10 s that leaves 44 % at h = 1/240 s and 4 % at 1/60 s. "
                          "Impulse2D applies the spring in both the solve and the relax pass of each substep (as "
                          "Box2D v3 does), which damps more than one implicit step per substep; Box2D 2.4.1 takes "
                          "one soft solve per 1/60 s step.";
        cases.push_back(m);
    }

    // Impact with slip reversal ---------------------------------------------------------
    {
        Case c;
        c.id = "spinning_rod_energy";
        c.group = "Spinning rod striking the ground (HARD_CASES 5.8 case A: 45°, v = (0, −1), ω = 4, μ = 0.5, e = 1)";
        c.quantity = "kinetic energy after / before the impact";
        c.formula = "Stronge: 0.848487 / 1.166667 J (Newton's e: 1.821997 / 1.166667)";
        c.analytic = 0.848487 / 1.166667;
        c.measure = spinningRodEnergyRatio;
        c.impulse2d.tolerance = 0.01;
        c.impulse2d.why =
            "0.01: the 4 mm thick box's corner lies 2 mm (0.4 % of the 0.5 m lever arm) off the ideal rod's "
            "end, and its inertia differs by 2e-5";
        c.box2d.reference = 1.821997 / 1.166667;
        c.box2d.tolerance = 0.1;
        c.box2d.asserted = false;
        c.box2d.why = "reported against Newton's e with Coulomb friction, the law Box2D applies (velocity bias)";
        c.whyTheyDiffer = "Box2D applies restitution as a velocity bias (Newton's e) with Coulomb friction, which "
                          "creates energy when the slip reverses during the impact (Kane's paradox); Impulse2D's "
                          "closed-form law uses Stronge's energetic e and loses energy, as a real impact does.";
        cases.push_back(c);
    }

    // Stacks and pyramids ---------------------------------------------------------------
    {
        // Box2D 2.4.1 gives every polygon a 1 cm skin and lets contacts rest
        // linearSlop = 5 mm deep into it: each contact layer stands 1.5 cm taller.
        const double skin = 0.015;
        struct S {
            const char* scene;
            double rigidTop;  ///< top's height for rigid bodies stacked exactly
            int layers;       ///< contacts between the ground and the top
        };
        for (S s : {S{"stack5", 4 * 2.4 + 1.2, 5}, S{"tall_stack20", 19.5, 20}, S{"pyramid20", 19.5, 20}}) {
            const tb::SceneDesc d = scene(s.scene);
            const std::string name = s.scene;
            Case c;
            c.id = name + "_top_height";
            c.group = "Stacks and pyramids (shipped scenes, 10 s)";
            c.quantity = name + ": height of the top box (m)";
            c.formula = "rigid boxes resting exactly";
            c.analytic = s.rigidTop;
            c.measure = [d](EngineKind k) { return stackRun(d, k, 10.0).topY; };
            // A soft contact is a spring of contactHertz (the default): carrying k boxes
            // of mass m it compresses by k m g/(m ω²) = k g/ω² beyond the slop.
            const double hertz = i2d::WorldSettings{}.contactHertz;
            const double w = 2.0 * kPi * hertz;
            c.impulse2d.tolerance = 0.005 * s.layers + kG / (w * w) * s.layers * (s.layers + 1) / 2.0;
            c.impulse2d.why = "soft contacts: per layer the 5 mm slop plus the " + std::to_string(std::lround(hertz)) +
                              " Hz contact spring's compression under the k boxes above, k g/ω², summed over " +
                              std::to_string(s.layers) + " layers";
            c.box2d.reference = s.rigidTop + skin * s.layers;
            c.box2d.tolerance = 0.005 * s.layers;
            c.box2d.why = "held against rigid + 1.5 cm per layer (1 cm skin each side, 5 mm rest depth); ≤ 5 mm per "
                          "layer beyond";
            c.whyTheyDiffer = "Box2D 2.4.1's polygons carry a 1 cm skin (b2_polygonRadius) and rest 5 mm into it, so "
                              "each contact layer stands about 1.5 cm taller than the boxes' vertices say.";
            if (name == "tall_stack20") {
                c.box2d.asserted = false;
                c.box2d.why += "; reported only: the stack falls in Box2D 2.4.1 (next row)";
                c.whyTheyDiffer = "The stack falls in Box2D 2.4.1 (next row).";
            }
            cases.push_back(c);

            Case st = c;
            if (name == "pyramid20") {
                st.id = name + "_displaced";
                st.quantity = name + ": boxes moved more than 0.5 m";
                st.formula = "0 (it stands)";
                st.analytic = 0.0;
                st.measure = [d](EngineKind k) { return static_cast<double>(stackRun(d, k, 10.0).displaced); };
                st.impulse2d.reference = st.box2d.reference = kNone;
                st.impulse2d.tolerance = st.box2d.tolerance = 0.0;
                st.impulse2d.why = st.box2d.why = "none may fall";
            } else {
                st.id = name + "_top_drift";
                st.quantity = name + ": largest sideways drift of the top box (m)";
                st.formula = "0 (it stands)";
                st.analytic = 0.0;
                st.measure = [d](EngineKind k) { return stackRun(d, k, 10.0).topDx; };
                st.impulse2d.reference = st.box2d.reference = kNone;
                st.impulse2d.tolerance = st.box2d.tolerance = 0.05;
                st.impulse2d.why = st.box2d.why = "5 cm, 1/10 of the half-width a box would need to move to fall";
                // Known issue: since the contacts are solved colour by colour
                // (which took pyramid100's sway from 0.64 m to 0.09 m), the
                // settling of these dropped stacks leaves the top box leaning:
                // 6.4 cm (stack5) and 11 cm (tall_stack20) against 4.3 cm and
                // 0.5 cm in creation order. Held to 0.15 m, under a third of the
                // half-width at which a box tips, so it cannot grow unnoticed.
                st.impulse2d.knownIssue =
                    "colour-ordered Gauss-Seidel (adopted for the pyramids' sway) lets the dropped stack settle "
                    "leaning; creation order kept it within 5 cm but swayed pyramid100 by 0.64 m";
                st.impulse2d.issueTolerance = 0.15;
                if (name == "tall_stack20") {
                    st.box2d.asserted = false;
                    st.box2d.why += "; reported only: Box2D 2.4.1 topples this stack at 8 velocity iterations";
                    st.whyTheyDiffer = "The boxes drop through 0.1 m gaps onto each other with alternating 1 cm "
                                       "offsets (Solver2D's vertical stack). Box2D 2.4.1 at 8 velocity and 3 position "
                                       "iterations lets the top creep sideways and the stack falls after about 5 s "
                                       "(it stands with 50 velocity iterations); Impulse2D's substepped soft contacts "
                                       "hold it.";
                }
            }
            cases.push_back(st);
        }
    }

    // Joints (joint_cases.cpp) ------------------------------------------------------------
    for (Case& c : jointCases()) cases.push_back(std::move(c));
    return cases;
}

}  // namespace val
