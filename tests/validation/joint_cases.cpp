// Validation suite — the joint cases. Every scene is built in code as a
// tb::SceneDesc, so the same joints run in Impulse2D and in Box2D 2.4.1, and
// every figure is read from tb::Simulation body samples taken after each step.
//
// What the tolerances below are made of:
//   - Impulse2D (soft step, 4 substeps of h = 1/240 s): a rigid joint row is a
//     spring-damper at WorldSettings::jointHertz = 60 Hz, damping ratio 2 (the
//     cap of a quarter of the substep rate is 60 Hz, so it applies as given):
//     under a steady load it sags by (load acceleration)/ω_j², ω_j = 2π·60 Hz,
//     and each substep's relax pass then removes the row's velocity error.
//   - Box2D 2.4.1 (one step of h = 1/60 s): rigid rows, 8 velocity and 3
//     position iterations; the position pass leaves errors below b2_linearSlop
//     (5 mm) and b2_angularSlop (2°) alone.
//   - Springs (wheel, soft weld, mouse) are soft constraints, i.e. implicit
//     Euler on the spring: each engine is held against its own scheme run on
//     the spring alone (softSpringScheme), whose departure from the continuous
//     answer is shown as the error against the analytic value.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "case_support.hpp"

namespace val {

namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kJointOmega = 2.0 * kPi * 60.0;  // ω of Impulse2D's rigid joint rows (60 Hz)

/// `v` printed with `spec` (for the `why` texts).
std::string fmt(double v, const char* spec) {
    char buf[32];
    std::snprintf(buf, sizeof buf, spec, v);
    return buf;
}

/// A disc of mass `mass` (kg), frictionless, elastic-free.
tb::ShapeDesc disc(float radius, float mass) {
    return circleShape(radius, mass / (static_cast<float>(kPi) * radius * radius), 0.0f, 0.0f);
}

/// A static body without shapes at `p`: the frame joints are anchored to.
tb::BodyDesc ground(i2d::Vec2 p = {0.0f, 0.0f}) { return body("ground", i2d::BodyType::static_body, p, {}); }

tb::JointDesc joint(int a, int b) {
    tb::JointDesc j;
    j.bodyA = a;
    j.bodyB = b;
    return j;
}

/// Accumulated angle of a body from its per-step changes (Impulse2D reports
/// the angle in (−π, π], Box2D 2.4.1 the integrated angle).
struct Unwrapped {
    double total = 0.0, last = 0.0;
    explicit Unwrapped(double a0) : total(a0), last(a0) {}
    double add(double a) {
        total += std::remainder(a - last, 2.0 * kPi);
        last = a;
        return total;
    }
};

/// A lone spring row of frequency ω and damping ratio ζ on a unit mass, x the
/// spring's extension, stepped as each engine steps a soft row. Both use the
/// soft-constraint coefficients of a spring-damper over a (sub)step h (Catto's
/// soft constraints; soft_constraint.hpp): a1 = 2ζ + hω, a2 = hω·a1,
/// bias rate ω/a1, mass scale a2/(1 + a2), impulse scale 1/(1 + a2), and an
/// impulse −massScale·(v + biasRate·x) − impulseScale·λ added to the
/// accumulated λ. Box2D 2.4.1 solves it once per 1/60 s step before the
/// position update, which is exactly implicit Euler on the spring-damper.
/// Impulse2D solves it in each 1/240 s substep before the position update
/// (warm-started with λ) and again after it, in the relax pass. Returns x
/// after each step.
std::vector<double> softSpringScheme(EngineKind kind, double omega, double zeta, double x, double v, long steps) {
    const int n = isBox2D(kind) ? 1 : 4;
    const double h = static_cast<double>(kDt) / n;
    const double a1 = 2.0 * zeta + h * omega, a2 = h * omega * a1;
    const double biasRate = omega / a1, massScale = a2 / (1.0 + a2), impulseScale = 1.0 / (1.0 + a2);
    double lambda = 0.0;
    auto solve = [&] {
        const double impulse = -massScale * (v + biasRate * x) - impulseScale * lambda;
        lambda += impulse;
        v += impulse;
    };
    std::vector<double> xs;
    for (long i = 0; i < steps; ++i) {
        for (int k = 0; k < n; ++k) {
            v += lambda;  // warm start
            solve();
            x += h * v;
            if (!isBox2D(kind)) solve();  // relax pass
        }
        xs.push_back(x);
    }
    return xs;
}

/// Period of that scheme's undamped oscillation, from the same up-crossings
/// as the measurement.
double softSpringPeriod(EngineKind kind, double omega, double x0, double seconds) {
    const long steps = std::lround(seconds / kDt);
    const std::vector<double> xs = softSpringScheme(kind, omega, 0.0, x0, 0.0, steps);
    UpCrossings up;
    for (long i = 0; i < steps; ++i) up.add(static_cast<double>(i + 1) * kDt, xs[static_cast<std::size_t>(i)]);
    return up.period();
}

// ---------------------------------------------------------------------------
// Revolute pendulum: a disc of radius r on a revolute joint, anchor L from its
// centre. A physical pendulum: I_pivot = m r²/2 + m L², equivalent length
// L + r²/(2L), and the large-amplitude period of the simple pendulum of that length.

constexpr double kPendL = 1.0, kPendR = 0.1;

tb::SceneDesc revolutePendulumScene(double degrees) {
    tb::SceneDesc d = emptyScene("revolute_pendulum", {0.0f, -10.0f});
    const double th = degrees * kDeg;
    const float bx = static_cast<float>(kPendL * std::sin(th)), by = static_cast<float>(-kPendL * std::cos(th));
    d.bodies.push_back(ground());
    d.bodies.push_back(body("bob", i2d::BodyType::dynamic_body, {bx, by}, {disc(static_cast<float>(kPendR), 1.0f)}));
    tb::JointDesc j = joint(0, 1);
    i2d::RevoluteJointDef& r = j.def.emplace<i2d::RevoluteJointDef>();
    r.localAnchorB = {-bx, -by};
    d.joints.push_back(j);
    return d;
}

/// Period (s) from the upward zero crossings of the bob's x over 12 s; with
/// `amplitude`, also the largest angle (°) over the last full swing.
double revolutePendulumPeriod(EngineKind kind, double degrees, double* amplitude = nullptr) {
    const tb::SceneDesc d = revolutePendulumScene(degrees);
    auto sim = make(d, kind);
    UpCrossings up;
    std::vector<std::pair<double, double>> angles;
    run(*sim, d, std::lround(12.0 / d.dt), [&](double t, tb::Simulation& s) {
        const tb::BodySample b = s.sample(1);
        up.add(t, b.x);
        angles.emplace_back(t, std::atan2(b.x, -b.y) / kDeg);
    });
    if (amplitude && up.times.size() >= 2) {
        *amplitude = 0.0;
        for (const auto& [t, deg] : angles)
            if (t >= up.times[up.times.size() - 2]) *amplitude = std::max(*amplitude, std::abs(deg));
    }
    return up.period();
}

double revolutePendulumTheory(double degrees) {
    const double Leq = kPendL + kPendR * kPendR / (2.0 * kPendL);
    return 2.0 * kPi * std::sqrt(Leq / kG) * 2.0 * ellipticK(std::sin(degrees * kDeg / 2.0)) / kPi;
}

// ---------------------------------------------------------------------------
// Lever on a revolute joint: a 1 m × 0.1 m, 1 kg bar pivoted at its left end,
// starting horizontal. Gravity's torque about the pivot is m g d cos φ
// (d = 0.5 m): at most 5 N·m. I_pivot = m (L² + w²)/12 + m d².

constexpr double kLeverM = 1.0, kLeverD = 0.5;
const double kLeverI = kLeverM * (1.0 + 0.01) / 12.0 + kLeverM * kLeverD * kLeverD;
const double kLeverLoad = kLeverM * kG * kLeverD;  // N·m, horizontal

tb::SceneDesc leverScene(const i2d::RevoluteJointDef& def) {
    tb::SceneDesc d = emptyScene("lever", {0.0f, -10.0f});
    d.bodies.push_back(ground());
    d.bodies.push_back(body("lever", i2d::BodyType::dynamic_body, {0.5f, 0.0f}, {boxShape(0.5f, 0.05f, 10.0f, 0, 0)}));
    tb::JointDesc j = joint(0, 1);
    i2d::RevoluteJointDef& r = j.def.emplace<i2d::RevoluteJointDef>(def);
    r.localAnchorA = {0.0f, 0.0f};
    r.localAnchorB = {-0.5f, 0.0f};
    d.joints.push_back(j);
    return d;
}

constexpr double kMotorSpeed = 2.0;

/// Motor at 2 rad/s with a 10 N·m cap, lifting the lever round and round: the
/// ω sample furthest from the motor speed over [1 s, 4 s].
double motorWithinCap(EngineKind kind) {
    i2d::RevoluteJointDef r;
    r.enableMotor = true;
    r.motorSpeed = static_cast<float>(kMotorSpeed);
    r.maxMotorTorque = 10.0f;
    const tb::SceneDesc d = leverScene(r);
    auto sim = make(d, kind);
    double worst = kMotorSpeed;
    run(*sim, d, std::lround(4.0 / d.dt), [&](double t, tb::Simulation& s) {
        const double w = s.sample(1).w;
        if (t >= 1.0 - 1e-9 && std::abs(w - kMotorSpeed) > std::abs(worst - kMotorSpeed)) worst = w;
    });
    return worst;
}

constexpr double kWeakTorque = 2.0, kCapSeconds = 0.1;

/// Motor at 2 rad/s capped at 2 N·m < m g d: the lever falls. Mean angular
/// acceleration over the first 0.1 s, ω(0.1 s)/0.1 s (rad/s²).
double motorBeyondCap(EngineKind kind) {
    i2d::RevoluteJointDef r;
    r.enableMotor = true;
    r.motorSpeed = static_cast<float>(kMotorSpeed);
    r.maxMotorTorque = static_cast<float>(kWeakTorque);
    const tb::SceneDesc d = leverScene(r);
    auto sim = make(d, kind);
    for (long i = 0; i < std::lround(kCapSeconds / d.dt); ++i) sim->step(d.dt);
    return sim->sample(1).w / kCapSeconds;
}

constexpr double kLimitDeg = -30.0;

/// The lever dropped from horizontal onto a lower angle limit of −30°: its
/// angle (°) after 3 s.
double limitRestAngle(EngineKind kind) {
    i2d::RevoluteJointDef r;
    r.enableLimit = true;
    r.lowerAngle = static_cast<float>(kLimitDeg * kDeg);
    r.upperAngle = static_cast<float>(30.0 * kDeg);
    const tb::SceneDesc d = leverScene(r);
    auto sim = make(d, kind);
    for (long i = 0; i < std::lround(3.0 / d.dt); ++i) sim->step(d.dt);
    return sim->sample(1).angle / kDeg;
}

// ---------------------------------------------------------------------------
// Prismatic slider on a 30° incline: a box on a prismatic joint whose axis
// rises at 30°, no contact, no friction.

constexpr double kSlope = 30.0 * kDeg;

double prismaticSlideAcceleration(EngineKind kind) {
    tb::SceneDesc d = emptyScene("prismatic_incline", {0.0f, -10.0f});
    d.bodies.push_back(ground());
    d.bodies.push_back(body("slider", i2d::BodyType::dynamic_body, {0.0f, 0.0f}, {boxShape(0.2f, 0.1f, 1.0f, 0, 0)}));
    tb::JointDesc j = joint(0, 1);
    i2d::PrismaticJointDef& p = j.def.emplace<i2d::PrismaticJointDef>();
    p.localAxisA = {static_cast<float>(std::cos(kSlope)), static_cast<float>(std::sin(kSlope))};
    d.joints.push_back(j);
    auto sim = make(d, kind);
    std::vector<double> ts, ss;
    run(*sim, d, std::lround(1.25 / d.dt), [&](double t, tb::Simulation& s) {
        if (t < 0.25 - 1e-9) return;
        const tb::BodySample b = s.sample(1);
        ts.push_back(t);
        ss.push_back(-(b.x * std::cos(kSlope) + b.y * std::sin(kSlope)));
    });
    return fittedAcceleration(ts, ss);
}

// ---------------------------------------------------------------------------
// Gears (zero gravity). Two discs on revolute joints to the ground, coupled by
// a gear of ratio 2 (θ₁ + 2θ₂ constant); joint 1 is driven by a motor at
// 3 rad/s. And a rack and pinion: a pinion of radius 0.5 m driven at 2 rad/s,
// a rack on a horizontal prismatic joint, ratio −1/R = −2 (θ − 2x constant:
// the rack moves at ωR).

constexpr double kGearRatio = 2.0, kGearSpeed = 3.0;
/// The motors bring the gears to speed within 0.1 s; the coordinate is held
/// from 0.5 s on (during the spin-up Impulse2D's soft gear row gives by up to
/// 4e-3 rad under the motor's 100 N·m, and takes it back within 0.1 s).
constexpr double kSpinUp = 0.5;

struct GearFigures {
    double ratio;  ///< ω₂/ω₁ at 2 s
    double drift;  ///< largest |θ₁ + ratio·θ₂| from 0.5 s to 5 s (rad)
};

GearFigures gearRun(EngineKind kind) {
    tb::SceneDesc d = emptyScene("gear", {0.0f, 0.0f});
    d.bodies.push_back(ground());
    d.bodies.push_back(body("gear1", i2d::BodyType::dynamic_body, {-2.0f, 0.0f}, {disc(0.5f, 1.0f)}));
    d.bodies.push_back(body("gear2", i2d::BodyType::dynamic_body, {2.0f, 0.0f}, {disc(1.0f, 4.0f)}));
    tb::JointDesc j1 = joint(0, 1), j2 = joint(0, 2), g = joint(1, 2);
    i2d::RevoluteJointDef& r1 = j1.def.emplace<i2d::RevoluteJointDef>();
    r1.localAnchorA = {-2.0f, 0.0f};
    r1.enableMotor = true;
    r1.motorSpeed = static_cast<float>(kGearSpeed);
    r1.maxMotorTorque = 100.0f;
    j2.def.emplace<i2d::RevoluteJointDef>().localAnchorA = {2.0f, 0.0f};
    g.joint1 = 0;
    g.joint2 = 1;
    g.def.emplace<i2d::GearJointDef>().ratio = static_cast<float>(kGearRatio);
    d.joints = {j1, j2, g};
    auto sim = make(d, kind);
    Unwrapped a1(sim->sample(1).angle), a2(sim->sample(2).angle);
    GearFigures f{kNone, 0.0};
    run(*sim, d, std::lround(5.0 / d.dt), [&](double t, tb::Simulation& s) {
        const tb::BodySample b1 = s.sample(1), b2 = s.sample(2);
        const double c = a1.add(b1.angle) + kGearRatio * a2.add(b2.angle);
        if (t >= kSpinUp - 1e-9) f.drift = std::max(f.drift, std::abs(c));
        if (std::abs(t - 2.0) < 0.5 * d.dt) f.ratio = static_cast<double>(b2.w) / b1.w;
    });
    return f;
}

constexpr double kPinionR = 0.5, kPinionSpeed = 2.0;

struct RackFigures {
    double lead;   ///< v_rack/ω_pinion at 2 s (m)
    double drift;  ///< largest |θ + ratio·x| from 0.5 s to 5 s (rad)
};

RackFigures rackRun(EngineKind kind) {
    tb::SceneDesc d = emptyScene("rack_and_pinion", {0.0f, 0.0f});
    d.bodies.push_back(ground());
    d.bodies.push_back(
        body("pinion", i2d::BodyType::dynamic_body, {0.0f, 0.5f}, {disc(static_cast<float>(kPinionR), 1.0f)}));
    d.bodies.push_back(body("rack", i2d::BodyType::dynamic_body, {0.0f, -0.06f}, {boxShape(2.0f, 0.05f, 5.0f, 0, 0)}));
    tb::JointDesc j1 = joint(0, 1), j2 = joint(0, 2), g = joint(1, 2);
    i2d::RevoluteJointDef& r = j1.def.emplace<i2d::RevoluteJointDef>();
    r.localAnchorA = {0.0f, 0.5f};
    r.enableMotor = true;
    r.motorSpeed = static_cast<float>(kPinionSpeed);
    r.maxMotorTorque = 100.0f;
    i2d::PrismaticJointDef& p = j2.def.emplace<i2d::PrismaticJointDef>();
    p.localAnchorA = {0.0f, -0.06f};
    p.localAxisA = {1.0f, 0.0f};
    g.joint1 = 0;
    g.joint2 = 1;
    const double ratio = -1.0 / kPinionR;
    g.def.emplace<i2d::GearJointDef>().ratio = static_cast<float>(ratio);
    d.joints = {j1, j2, g};
    auto sim = make(d, kind);
    Unwrapped a(sim->sample(1).angle);
    const double x0 = sim->sample(2).x;
    RackFigures f{kNone, 0.0};
    run(*sim, d, std::lround(5.0 / d.dt), [&](double t, tb::Simulation& s) {
        const tb::BodySample p1 = s.sample(1), r2 = s.sample(2);
        const double c = a.add(p1.angle) + ratio * (r2.x - x0);
        if (t >= kSpinUp - 1e-9) f.drift = std::max(f.drift, std::abs(c));
        if (std::abs(t - 2.0) < 0.5 * d.dt) f.lead = static_cast<double>(r2.vx) / p1.w;
    });
    return f;
}

// ---------------------------------------------------------------------------
// Pulley, ratio 2: m₁ = 1 kg on side A, m₂ = 3 kg on side B, both hanging
// 5 m below their ground anchors. With L_A + r L_B constant, ẏ_A = −r ẏ_B; the
// rope pulls A up by T and B up by rT:
//   m₁ a_A = T − m₁ g, m₂ a_B = rT − m₂ g, a_A = −r a_B
//   ⇒ B descends at a = g (m₂ − r m₁)/(m₂ + r² m₁), A rises at r a.

constexpr double kPulleyRatio = 2.0, kPulleyM1 = 1.0, kPulleyM2 = 3.0;

struct PulleyFigures {
    double accelB;  ///< B's downward acceleration, fitted over [0.25 s, 1.25 s]
    double drift;   ///< largest |L_A + r L_B − (L_A + r L_B)₀| over those 1.25 s (m)
};

PulleyFigures pulleyRun(EngineKind kind) {
    tb::SceneDesc d = emptyScene("pulley", {0.0f, -10.0f});
    const i2d::Vec2 gA{-2.0f, 10.0f}, gB{2.0f, 10.0f};
    d.bodies.push_back(ground());
    d.bodies.push_back(body("m1", i2d::BodyType::dynamic_body, {-2.0f, 5.0f}, {disc(0.3f, 1.0f)}));
    d.bodies.push_back(body("m2", i2d::BodyType::dynamic_body, {2.0f, 5.0f}, {disc(0.3f, 3.0f)}));
    tb::JointDesc j = joint(1, 2);
    i2d::PulleyJointDef& p = j.def.emplace<i2d::PulleyJointDef>();
    p.groundAnchorA = gA;
    p.groundAnchorB = gB;
    p.lengthA = p.lengthB = 5.0f;
    p.ratio = static_cast<float>(kPulleyRatio);
    d.joints.push_back(j);
    auto sim = make(d, kind);
    auto total = [&](tb::Simulation& s) {
        const tb::BodySample a = s.sample(1), b = s.sample(2);
        return std::hypot(a.x - gA.x, a.y - gA.y) + kPulleyRatio * std::hypot(b.x - gB.x, b.y - gB.y);
    };
    const double c0 = 5.0 + kPulleyRatio * 5.0;
    PulleyFigures f{kNone, 0.0};
    std::vector<double> ts, ss;
    run(*sim, d, std::lround(1.25 / d.dt), [&](double t, tb::Simulation& s) {
        f.drift = std::max(f.drift, std::abs(total(s) - c0));
        if (t < 0.25 - 1e-9) return;
        ts.push_back(t);
        ss.push_back(-static_cast<double>(s.sample(2).y));
    });
    f.accelB = fittedAcceleration(ts, ss);
    return f;
}

double pulleyTheory() {
    const double r = kPulleyRatio, m1 = kPulleyM1, m2 = kPulleyM2;
    return kG * (m2 - r * m1) / (m2 + r * r * m1);
}

// ---------------------------------------------------------------------------
// Wheel suspension: a 1 kg wheel on a 1 Hz undamped suspension (vertical axis)
// to a static frame, released at the spring's rest length under gravity: it
// oscillates about the sag g/ω² with amplitude g/ω².

constexpr double kWheelHertz = 1.0, kWheelSeconds = 4.0;

double wheelPeriod(EngineKind kind) {
    tb::SceneDesc d = emptyScene("wheel_suspension", {0.0f, -10.0f});
    d.bodies.push_back(ground());
    d.bodies.push_back(body("wheel", i2d::BodyType::dynamic_body, {0.0f, 0.0f}, {disc(0.3f, 1.0f)}));
    tb::JointDesc j = joint(0, 1);
    i2d::WheelJointDef& w = j.def.emplace<i2d::WheelJointDef>();
    w.localAxisA = {0.0f, 1.0f};
    w.enableSpring = true;
    w.hertz = static_cast<float>(kWheelHertz);
    w.dampingRatio = 0.0f;
    d.joints.push_back(j);
    auto sim = make(d, kind);
    const double omega = 2.0 * kPi * kWheelHertz, sag = kG / (omega * omega);
    UpCrossings up;
    run(*sim, d, std::lround(kWheelSeconds / d.dt),
        [&](double t, tb::Simulation& s) { up.add(t, s.sample(1).y + sag); });
    return up.period();
}

// ---------------------------------------------------------------------------
// Soft weld: a 1 m square of 1 kg welded at its centre to the ground with
// angularHertz 1 and no damping, released turned by 0.2 rad (gravity on: the
// rigid point rows carry the weight, which has no torque about the centre).

constexpr double kWeldHertz = 1.0, kWeldSeconds = 4.0;

double weldPeriod(EngineKind kind) {
    tb::SceneDesc d = emptyScene("soft_weld", {0.0f, -10.0f});
    d.bodies.push_back(ground());
    tb::BodyDesc b = body("plate", i2d::BodyType::dynamic_body, {0.0f, 0.0f}, {boxShape(0.5f, 0.5f, 1.0f, 0, 0)});
    b.def.angle = 0.2f;
    d.bodies.push_back(b);
    tb::JointDesc j = joint(0, 1);
    i2d::WeldJointDef& w = j.def.emplace<i2d::WeldJointDef>();
    w.angularHertz = static_cast<float>(kWeldHertz);
    w.angularDampingRatio = 0.0f;
    d.joints.push_back(j);
    auto sim = make(d, kind);
    UpCrossings up;
    Unwrapped a(sim->sample(1).angle);
    run(*sim, d, std::lround(kWeldSeconds / d.dt),
        [&](double t, tb::Simulation& s) { up.add(t, a.add(s.sample(1).angle)); });
    return up.period();
}

// ---------------------------------------------------------------------------
// Mouse joint, critically damped (ζ = 1) at ω = 10 rad/s. Both engines anchor
// the mouse on the point of body B at the target when the joint is created,
// so the gap starts at 0: the 1 kg disc is launched from the target at
// 1 m/s (zero gravity). Then x(t) = v₀ t e^{−ωt}: it turns back at t = 1/ω,
// at rest, and from there closes as x(1/ω)(1 + ωs)e^{−ωs}, s = t − 1/ω —
// the approach of a body let go at rest at that gap. The figure: the gap at
// s = 2/ω (t = 0.3 s) over the gap at the turn (t = 0.1 s), 3e^{−2}.

constexpr double kMouseOmega = 10.0, kMouseV0 = 1.0;

/// Gap (m) after each step (0.1 s and 0.3 s are steps 6 and 18).
std::vector<double> mouseGaps(EngineKind kind) {
    tb::SceneDesc d = emptyScene("mouse", {0.0f, 0.0f});
    d.bodies.push_back(ground());
    tb::BodyDesc b = body("disc", i2d::BodyType::dynamic_body, {0.0f, 0.0f}, {disc(0.1f, 1.0f)});
    b.def.linearVelocity = {static_cast<float>(kMouseV0), 0.0f};
    d.bodies.push_back(b);
    tb::JointDesc j = joint(0, 1);
    i2d::MouseJointDef& m = j.def.emplace<i2d::MouseJointDef>();
    m.target = {0.0f, 0.0f};
    m.hertz = static_cast<float>(kMouseOmega / (2.0 * kPi));
    m.dampingRatio = 1.0f;
    m.maxForce = 1000.0f;
    d.joints.push_back(j);
    auto sim = make(d, kind);
    std::vector<double> gaps;
    run(*sim, d, 30, [&](double, tb::Simulation& s) {
        const tb::BodySample p = s.sample(1);
        gaps.push_back(std::hypot(p.x, p.y));
    });
    return gaps;
}

double mouseApproach(EngineKind kind) {
    const std::vector<double> g = mouseGaps(kind);
    return g[17] / g[5];
}

/// The same ratio for the engine's soft-spring scheme itself.
double mouseApproachScheme(EngineKind kind) {
    const std::vector<double> x = softSpringScheme(kind, kMouseOmega, 1.0, 0.0, kMouseV0, 18);
    return x[17] / x[5];
}

}  // namespace

std::vector<Case> jointCases() {
    std::vector<Case> cases;

    // Revolute pendulum ----------------------------------------------------------------
    {
        const std::string group = "Revolute joint: pendulum (disc r = 0.1 m, 1 kg, on a revolute joint 1 m from its "
                                  "centre)";
        const char* whyBox2D90 =
            "Box2D 2.4.1 solves the rigid pivot on velocities once per 1/60 s step: the bob's velocity along the "
            "rod's old direction is projected out every step, a loss of about (ωh)² of the kinetic energy per step. "
            "From 90° the swing decays (next row) and a smaller swing has a shorter period. Impulse2D's 1/240 s "
            "substeps make that loss 16 times smaller.";
        for (int deg : {5, 90}) {
            Case c;
            c.id = "revolute_pendulum_" + std::to_string(deg);
            c.group = group;
            c.quantity = "period at " + std::to_string(deg) + "° (s)";
            c.formula = "2π√(L′/g) · 2K(sin(θ₀/2))/π, L′ = L + r²/(2L)";
            c.analytic = revolutePendulumTheory(deg);
            c.measure = [deg](EngineKind k) { return revolutePendulumPeriod(k, deg); };
            // Velocity Verlet (Impulse2D's bob touches nothing: its forces are
            // split around the drift) and semi-implicit Euler (Box2D) both
            // shorten an oscillation's period by (ωh)²/24:
            // 7e-6 at h = 1/240 s, 1.2e-4 at 1/60 s (ω = √(g/L′) = 3.15 rad/s). The
            // soft pivot (60 Hz) stretches under at most 3mg by 3g/ω_j² = 2e-4 m,
            // lengthening L′ by 2e-4 and T by 1e-4. 0.05 % covers both.
            c.impulse2d.tolerance = c.box2d.tolerance = 5e-4 * c.analytic;
            c.impulse2d.why = "0.05 %: velocity Verlet's (ωh)²/24 = 7e-6 at h = 1/240 s, and the soft pivot "
                              "(60 Hz), which stretches under at most 3mg by 3g/ω_j² = 2e-4 m, lengthening the "
                              "period by 1e-4";
            c.box2d.why = "0.05 %: semi-implicit Euler's (ωh)²/24 = 1.2e-4 at h = 1/60 s; the pivot is rigid";
            if (deg == 90) {
                // Measured −0.174 s (−7.4 %); held at 0.19 s.
                c.box2d.knownIssue =
                    "from 90° Box2D 2.4.1's revolute pendulum swings 7.4 % fast (2.177 s against 2.351 s): its "
                    "velocity-level pivot at 1/60 s removes about (ωh)² of the kinetic energy per step, the swing "
                    "decays (revolute_pendulum_90_amplitude) and a smaller swing is a shorter one";
                c.box2d.issueTolerance = 0.19;
            }
            c.whyTheyDiffer = whyBox2D90;
            cases.push_back(c);
        }
        Case a;
        a.id = "revolute_pendulum_90_amplitude";
        a.group = group;
        a.quantity = "amplitude over the last swing in 12 s, from 90° (°)";
        a.formula = "θ₀ (no friction)";
        a.analytic = 90.0;
        a.measure = [](EngineKind k) {
            double amplitude = kNone;
            revolutePendulumPeriod(k, 90.0, &amplitude);
            return amplitude;
        };
        a.impulse2d.tolerance = a.box2d.tolerance = 0.005 * 90.0;
        a.impulse2d.why = a.box2d.why = "0.45° = 0.5 %, the bar of < 1 % amplitude loss per 10 periods "
                                        "(HARD_CASES 5.2) over the 5 periods run";
        a.box2d.knownIssue = "the same cause: the 1/60 s velocity-level pivot loses energy every step; from 90° "
                             "the amplitude falls to 59.7° within 12 s";
        a.box2d.issueTolerance = 31.0;  // measured 59.7°: 30.3° short
        a.whyTheyDiffer = whyBox2D90;
        cases.push_back(a);
    }
    // Revolute motor and limit -----------------------------------------------------------
    {
        const std::string group = "Revolute joint: motor and limit (1 kg bar, 1 m × 0.1 m, pivoted at one end, "
                                  "gravity torque ≤ m g d = 5 N·m, I_pivot = 0.334 kg m²)";
        Case c;
        c.id = "revolute_motor_speed";
        c.group = group;
        c.quantity = "ω furthest from the motor speed over 1-4 s, 2 rad/s, cap 10 N·m (rad/s)";
        c.formula = "motor speed (the load never exceeds the cap)";
        c.analytic = kMotorSpeed;
        c.measure = motorWithinCap;
        // The motor row is solved before the pivot rows in every pass; the
        // pivot's last correction turns the bar by a fraction of one (sub)step's
        // gravity impulse about the pivot, m g d h/I_pivot: 0.062 rad/s at
        // 1/240 s, 0.25 rad/s at 1/60 s. 2e-3 rad/s (0.1 %) allows 3 % and 1 %
        // of them.
        const double kick = kLeverLoad / kLeverI;
        c.impulse2d.tolerance = c.box2d.tolerance = 2e-3;
        c.impulse2d.why = "2e-3 rad/s (0.1 %): the pivot rows, solved after the motor row (Gauss-Seidel), turn the "
                          "bar by a fraction of one substep's gravity impulse m g d h/I_pivot = " +
                          fmt(kick * kDt / 4.0, "%.2g") + " rad/s; 2e-3 is 3 % of it";
        c.box2d.why = "2e-3 rad/s: the same Gauss-Seidel residual after 8 velocity iterations, 1 % of one step's "
                      "gravity impulse m g d h/I_pivot = " +
                      fmt(kick * kDt, "%.2g") + " rad/s";
        cases.push_back(c);

        Case a;
        a.id = "revolute_motor_beyond_cap";
        a.group = group;
        a.quantity = "angular acceleration from horizontal over 0.1 s, motor at 2 rad/s capped at 2 N·m (rad/s²)";
        a.formula = "(τ_max − m g d)/I_pivot";
        a.analytic = (kWeakTorque - kLeverLoad) / kLeverI;
        a.measure = motorBeyondCap;
        // The bar turns by φ = |α| T²/2 = 0.045 rad in T = 0.1 s, so gravity's
        // torque m g d cos φ falls short of m g d by at most m g d φ²/2: a bound
        // on the error of ω(T)/T. The motor's impulse is exactly h·τ_max per
        // (sub)step in both engines and a constant torque is integrated exactly.
        const double phi = 0.5 * std::abs(a.analytic) * kCapSeconds * kCapSeconds;
        const double cosBound = kLeverLoad * phi * phi / 2.0 / kLeverI;
        a.impulse2d.tolerance = a.box2d.tolerance = cosBound;
        a.impulse2d.why = a.box2d.why = "the bar turns by φ = |α|T²/2 = 0.045 rad in the 0.1 s, so gravity's torque "
                                        "falls short of m g d by at most m g d φ²/2: " +
                                        fmt(cosBound, "%.3f") +
                                        " rad/s²; the capped motor impulse (h·τ_max per (sub)step) and a constant "
                                        "torque are integrated exactly";
        cases.push_back(a);

        Case l;
        l.id = "revolute_limit_rest";
        l.group = group;
        l.quantity = "rest angle after 3 s on a lower limit of −30°, dropped from horizontal (°)";
        l.formula = "lower limit";
        l.analytic = kLimitDeg;
        l.measure = limitRestAngle;
        // Impulse2D: the limit row is soft at 60 Hz over the row's mass
        // 1/(I_A⁻¹ + I_B⁻¹) = I_cm; under gravity's torque m g d cos 30° it
        // gives by τ/(I_cm ω_j²). The pivot gives by about g/ω_j² = 7e-5 m,
        // 0.004° at 1 m: 0.01° covers it and rounding.
        const double Icm = kLeverM * (1.0 + 0.01) / 12.0;
        const double sag = kLeverLoad * std::cos(30.0 * kDeg) / (Icm * kJointOmega * kJointOmega) / kDeg;
        l.impulse2d.tolerance = sag + 0.01;
        l.impulse2d.why = "the soft limit row (60 Hz over the row's mass I_cm) gives under gravity's torque by "
                          "m g d cos 30°/(I_cm ω_j²) = " +
                          fmt(sag, "%.3f") + "°; + 0.01° for the soft pivot's 7e-5 m and rounding";
        l.box2d.tolerance = 2.0;
        l.box2d.why = "b2_angularSlop = 2°: the velocity row stops the bar at the limit and the position pass "
                      "corrects a limit only beyond 2°";
        l.whyTheyDiffer = "Impulse2D's limit is a stiff spring (60 Hz) that gives by the load over ω²; Box2D 2.4.1's "
                          "limit row is rigid and its position pass leaves errors under its 2° slop.";
        cases.push_back(l);
    }

    // Prismatic -----------------------------------------------------------------------
    {
        Case c;
        c.id = "prismatic_incline";
        c.group = "Prismatic joint: frictionless slider (0.4 × 0.2 m box) on an axis rising at 30°";
        c.quantity = "acceleration down the axis (m/s²)";
        c.formula = "g sin θ";
        c.analytic = kG * std::sin(kSlope);
        c.measure = prismaticSlideAcceleration;
        // Nothing acts along the axis but gravity: each engine samples an exact
        // quadratic (semi-implicit Euler under a constant force), the rows
        // across the axis carry g cos θ and do no work along it.
        c.impulse2d.tolerance = c.box2d.tolerance = 1e-3;
        c.impulse2d.why = c.box2d.why = "1e-3 m/s²: the fit of the exact quadratic has no truncation error; "
                                        "positions up to 4 m round to 2.4e-7 m per update, which moves a quadratic "
                                        "fitted over 1 s by far less";
        cases.push_back(c);
    }

    // Gears ---------------------------------------------------------------------------
    {
        const std::string group = "Gear joint (zero gravity; joint 1 driven by a motor, 100 N·m cap)";
        Case c;
        c.id = "gear_ratio";
        c.group = group;
        c.quantity = "two revolutes (discs of 0.125 and 2 kg m²), ratio 2: ω₂/ω₁ at 2 s";
        c.formula = "−1/ratio (θ₁ + ratio·θ₂ constant)";
        c.analytic = -1.0 / kGearRatio;
        c.measure = [](EngineKind k) { return gearRun(k).ratio; };
        c.impulse2d.tolerance = c.box2d.tolerance = 1e-5;
        c.impulse2d.why = c.box2d.why = "1e-5, rounding: the gear is created last, so its velocity row is solved "
                                        "last and holds ω₁ + ratio·ω₂ = 0 to float precision";
        cases.push_back(c);

        Case g = c;
        g.id = "gear_drift";
        g.quantity = "largest |θ₁ + 2θ₂| from 0.5 s to 5 s, after the spin-up (rad)";
        g.formula = "0";
        g.analytic = 0.0;
        g.measure = [](EngineKind k) { return gearRun(k).drift; };
        g.impulse2d.tolerance = g.box2d.tolerance = 1e-4;
        g.impulse2d.why = "1e-4 rad: angles reach 15 rad (ulp 1e-6); the soft gear row (60 Hz, ζ = 2) pulls back "
                          "its error, so rounding does not accumulate; 100 ulp";
        g.box2d.why = "1e-4 rad: rounding, as for Impulse2D; the position pass corrects the gear's coordinate";
        cases.push_back(g);

        Case r = c;
        r.id = "rack_and_pinion_lead";
        r.quantity = "rack and pinion (R = 0.5 m, revolute + prismatic, ratio −1/R): v_rack/ω at 2 s (m)";
        r.formula = "−1/ratio = R";
        r.analytic = kPinionR;
        r.measure = [](EngineKind k) { return rackRun(k).lead; };
        cases.push_back(r);

        Case rd = g;
        rd.id = "rack_and_pinion_drift";
        rd.quantity = "largest |θ − 2x| from 0.5 s to 5 s (rad)";
        rd.measure = [](EngineKind k) { return rackRun(k).drift; };
        cases.push_back(rd);
    }

    // Pulley --------------------------------------------------------------------------
    {
        const std::string group = "Pulley joint, ratio r = 2 (m₁ = 1 kg on side A, m₂ = 3 kg on side B, both 5 m "
                                  "below their ground anchors)";
        Case c;
        c.id = "pulley_acceleration";
        c.group = group;
        c.quantity = "B's downward acceleration (m/s²)";
        c.formula = "g (m₂ − r m₁)/(m₂ + r² m₁)";
        c.analytic = pulleyTheory();
        c.measure = [](EngineKind k) { return pulleyRun(k).accelB; };
        c.impulse2d.tolerance = c.box2d.tolerance = 1e-3;
        c.impulse2d.why = c.box2d.why = "1e-3 m/s²: constant forces, so each engine samples an exact quadratic "
                                        "(the soft rope's steady stretch is constant too); float rounding of "
                                        "positions moves the fit by far less";
        cases.push_back(c);

        // Rope tension T = m₁(g + r a); the soft row (60 Hz over the row's mass
        // m_eff = 1/(1/m₁ + r²/m₂)) stretches by T/(m_eff ω_j²).
        const double a = pulleyTheory();
        const double tension = kPulleyM1 * (kG + kPulleyRatio * a);
        const double mEff = 1.0 / (1.0 / kPulleyM1 + kPulleyRatio * kPulleyRatio / kPulleyM2);
        const double stretch = tension / (mEff * kJointOmega * kJointOmega);
        // Rounding of lengths up to 5 m: 75 steps × ulp(5 m) = 3.6e-5 m.
        const double rounding = 5e-5;
        Case l = c;
        l.id = "pulley_length";
        l.quantity = "largest change of L_A + r L_B over 1.25 s (m)";
        l.formula = "0";
        l.analytic = 0.0;
        l.measure = [](EngineKind k) { return pulleyRun(k).drift; };
        l.impulse2d.tolerance = stretch + rounding;
        l.impulse2d.why = "the soft rope row (60 Hz over m_eff = 1/(1/m₁ + r²/m₂) = 0.43 kg) stretches under the "
                          "tension T = m₁(g + r a) = 12.9 N by T/(m_eff ω_j²) = " +
                          fmt(stretch, "%.1e") + " m; + 5e-5 m rounding (75 steps × ulp(5 m))";
        l.box2d.tolerance = rounding;
        l.box2d.why = "5e-5 m: rigid (one row, its velocity iterations converge), rounding of lengths near 5 m over "
                      "75 steps";
        l.whyTheyDiffer = "Impulse2D's rope is a stiff spring (60 Hz, damping ratio 2) that stretches under the "
                          "tension by T/(m_eff ω²); Box2D 2.4.1's rope row is rigid.";
        cases.push_back(l);
    }

    // Springs -------------------------------------------------------------------------
    {
        const std::string group = "Joint springs (soft constraints): undamped wheel and weld, critically damped mouse";
        const double w = 2.0 * kPi * kWheelHertz, sag = kG / (w * w);
        const std::string schemeWhy =
            "held against its own soft-spring scheme, run on the spring alone: implicit Euler per 1/60 s step "
            "(Box2D 2.4.1)";
        Case c;
        c.id = "wheel_suspension_period";
        c.group = group;
        c.quantity = "wheel joint, 1 Hz suspension, static frame, released at rest length: period (s)";
        c.formula = "1/hertz";
        c.analytic = 1.0 / kWheelHertz;
        c.measure = wheelPeriod;
        c.impulse2d.reference = softSpringPeriod(EngineKind::impulse2d, w, sag, kWheelSeconds);
        c.box2d.reference = softSpringPeriod(EngineKind::box2d, w, sag, kWheelSeconds);
        c.impulse2d.tolerance = c.box2d.tolerance = 1e-4;
        c.impulse2d.why = "held against its own scheme run on the spring alone: per 1/240 s substep a soft solve "
                          "(warm-started) before the position update and one after it (relax), period 1 + 3.1e-4 s; "
                          "1e-4 s = rounding and the crossings' interpolation";
        c.box2d.why = "held against its own scheme: implicit Euler per 1/60 s step, period 2πh/atan(ωh) = 1 + "
                      "3.6e-3 s; the stiffness from b2LinearStiffness (m ω², m the wheel's mass, the frame static) "
                      "gives ω = 2π·hertz; 1e-4 s = rounding and interpolation";
        c.whyTheyDiffer = "Both are soft constraints (implicit Euler on the spring), whose period exceeds 1/hertz by "
                          "about (ωh)²/3: h = 1/240 s in Impulse2D (plus its relax pass), 1/60 s in Box2D 2.4.1.";
        cases.push_back(c);

        const double ww = 2.0 * kPi * kWeldHertz;
        Case s = c;
        s.id = "soft_weld_period";
        s.quantity = "weld joint, angularHertz 1, 1 m square welded at its centre, turned 0.2 rad: period (s)";
        s.formula = "1/angularHertz";
        s.analytic = 1.0 / kWeldHertz;
        s.measure = weldPeriod;
        s.impulse2d.reference = softSpringPeriod(EngineKind::impulse2d, ww, 0.2, kWeldSeconds);
        s.box2d.reference = softSpringPeriod(EngineKind::box2d, ww, 0.2, kWeldSeconds);
        s.box2d.why = "held against its own scheme: implicit Euler per 1/60 s step, 2πh/atan(ωh); the stiffness "
                      "from b2AngularStiffness (I ω², I the plate's inertia, the ground static) gives "
                      "ω = 2π·angularHertz; 1e-4 s = rounding and interpolation";
        cases.push_back(s);

        Case m = c;
        m.id = "mouse_approach";
        m.quantity = "mouse joint, ζ = 1, ω = 10 rad/s, disc launched from the target at 1 m/s: gap 2/ω after "
                     "the turn (t = 0.3 s) over the gap at the turn (t = 1/ω = 0.1 s)";
        m.formula = "(1 + ωs)e^(−ωs) at ωs = 2";
        m.analytic = 3.0 * std::exp(-2.0);
        m.measure = mouseApproach;
        m.impulse2d.reference = mouseApproachScheme(EngineKind::impulse2d);
        m.box2d.reference = mouseApproachScheme(EngineKind::box2d);
        m.impulse2d.tolerance = m.box2d.tolerance = 1e-4;
        m.impulse2d.why = "held against its own scheme run on the spring alone (soft solve before and after the "
                          "position update in each 1/240 s substep): " +
                          fmt(m.impulse2d.reference, "%.4f") +
                          ", 5 % above the analytic value (first-order scheme, ωh = 0.042, ζ = 1); 1e-4 = rounding";
        m.box2d.why = "held against its own scheme, implicit Euler per 1/60 s step (ωh = 0.17): " +
                      fmt(m.box2d.reference, "%.4f") +
                      ", 16 % above the analytic value; stiffness and damping from b2LinearStiffness over the "
                      "disc's mass; 1e-4 = rounding";
        m.whyTheyDiffer = "Both close the gap more slowly than the continuous critically damped spring: implicit "
                          "Euler is first order and over-damps, by about ωh; Box2D 2.4.1's step is 4 times "
                          "Impulse2D's substep. Impulse2D's second (relax) solve per substep adds 1 % of its own.";
        cases.push_back(m);
    }
    return cases;
}

}  // namespace val
