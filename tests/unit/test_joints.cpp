// Joints held against closed-form physics: a revolute pendulum's period, a
// motor against a load within its torque cap, a limit under load, a
// frictionless slider on an incline, gear ratios, a pulley's rope length, a
// wheel's suspension frequency, a soft weld's frequency, the mouse joint's
// approach; stability of a swinging chain with a heavy end; refused input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "world_fixtures.hpp"

namespace {

using namespace i2d;

constexpr float kPi = 3.14159265f;
constexpr float kG = 10.0f;  // the default gravity's magnitude (m/s²)

BodyId dynamicDisc(World& w, Vec2 p, float radius = 0.1f, float density = 1.0f) {
    BodyId b = w.createBody({.type = BodyType::dynamic_body, .position = p});
    w.createCircleShape(b, {.density = density}, {{0.0f, 0.0f}, radius});
    return b;
}

/// Times of the downward zero crossings of f over n steps of h.
std::vector<float> crossings(World& w, float h, int n, const std::function<float()>& f) {
    std::vector<float> t;
    float prev = f();
    for (int i = 1; i <= n; ++i) {
        w.step(h);
        const float x = f();
        if (prev > 0.0f && x <= 0.0f) t.push_back(static_cast<float>(i) * h);
        prev = x;
    }
    return t;
}

float meanPeriod(const std::vector<float>& t) { return (t.back() - t.front()) / static_cast<float>(t.size() - 1); }

// A 2 m pendulum released at 5°: T = 2π√(L/g)·(1 + θ₀²/16)·√(1 + r²/(2L²)) (finite
// amplitude and the bob's own inertia). Tolerance 0.1 %: the crossing times are
// quantised by h = 1/240 s over 8 periods (1.9e-4 relative), the joint's 60 Hz
// softness stretches the rod by g/ω² ≈ 7e-5 m (2e-5 relative), semi-implicit
// Euler's period error is O((ωh)²/24) ≈ 4e-6.
TEST(Joints, RevolutePendulumPeriod) {
    World w;
    BodyId ground = w.createBody({});
    const float L = 2.0f, r = 0.05f, theta0 = 5.0f * kPi / 180.0f;
    const Vec2 p{L * std::sin(theta0), -L * std::cos(theta0)};
    BodyId bob = dynamicDisc(w, p, r);
    w.createRevoluteJoint({.bodyA = ground, .bodyB = bob, .localAnchorB = {-p.x, -p.y}});
    const std::vector<float> t = crossings(w, 1.0f / 240.0f, 240 * 25, [&] { return w.position(bob).x; });
    ASSERT_GE(t.size(), 8u);
    const float expected = 2.0f * kPi * std::sqrt(L / kG) * (1.0f + theta0 * theta0 / 16.0f) *
                           std::sqrt(1.0f + r * r / (2.0f * L * L));
    EXPECT_NEAR(meanPeriod(t), expected, 1.0e-3f * expected);
}

// A pendulum's energy as the integrator keeps it. A body that touches
// nothing has its forces split around its drift (split_kick.hpp): the
// substep is RATTLE, the velocity Verlet method for constrained motion, whose
// velocity is the bob's true one. Störmer–Verlet keeps
// H̃ = E + h²·((1/12)·V'²/I − (1/24)·V''·θ̇²) to fourth order (its modified
// Hamiltonian; Hairer, Lubich and Wanner (2006), Geometric Numerical
// Integration, chapter IX), here in the swing's angle θ, I = m·L² and
// V = −m·g·L·cos θ: (1/12)·m·g²·sin²θ − (1/24)·m·g·L·cos θ·θ̇². From a release
// at 60° (θ̇² ≤ 2·g/L) that term spans at most h²·m·g²/6, so E never rises
// more than that above its start: 0.09 % of the swing's energy for a 1 m
// pendulum at one substep, 1.9 % for a 5 cm one there (ωh = 0.23), 0.12 % at
// four. Semi-implicit Euler, which gave the velocity the whole kick before
// the drift, let E itself rise by (h/2)·m·g·v_y while the bob rose, first
// order in h however passive the solver: 1.3 % of the swing's energy for a 1
// m pendulum on a hinge at one substep, 0.6 % at four, and the hard-cases
// issue's bar is 1 %. Measured now: E never above its start.
TEST(Joints, APendulumNeverRaisesItsEnergy) {
    for (bool hinge : {true, false})
        for (float length : {0.05f, 0.2f, 1.0f})
            for (int substeps : {1, 2, 4}) {
                WorldSettings s;
                s.enableSleep = false;
                s.substeps = substeps;
                World w(s);
                BodyId ground = w.createBody({});
                // Released 30° below level: 60° from hanging.
                const float below = kPi / 6.0f;
                const Vec2 p{length * std::cos(below), -length * std::sin(below)};
                BodyId bob = dynamicDisc(w, p, 0.1f * length);
                if (hinge)
                    w.createRevoluteJoint({.bodyA = ground, .bodyB = bob, .localAnchorB = {-p.x, -p.y}});
                else
                    w.createDistanceJoint({.bodyA = ground, .bodyB = bob, .length = length});
                const double m = w.mass(bob), g = kG;
                const double h = 1.0 / 60.0 / substeps;
                auto energy = [&] { return test::totalEnergy(w, {bob}); };
                const double swing = m * g * length * (1.0 - std::sin(below));
                const double start = energy();
                double peak = start;
                for (int i = 0; i < 600; ++i) {
                    w.step(1.0f / 60.0f);
                    peak = std::max(peak, energy());
                }
                const char* kind = hinge ? "hinge" : "distance";
                std::printf("[figure] %s pendulum %.2f m, %d substeps: E at most %+.4f %% of the swing's energy\n",
                            kind, double(length), substeps, 100.0 * (peak - start) / swing);
                const double bound = h * h * m * g * g / 6.0;
                EXPECT_LE(peak - start, bound) << kind << " pendulum " << length << " m, " << substeps << " substeps";
            }
}

// A bob that swings past a floor within its contact's speculative margin,
// without touching it: near the bottom of each swing it has a contact row
// and takes the whole kick before the solve, away from the floor its forces
// are split (split_kick.hpp). Its velocity must change meaning at each
// switch: taken as it was, the switch added m·g·h·|v_y| at the entry and at
// the exit, and a 1 m pendulum 1 cm above the floor, released at 10°, gained
// 166 % of its swing's energy in 20 s at one substep (semi-implicit Euler
// alone: −8 %). Bound: the hard-cases issue's 1 % of the swing's energy,
// against which the whole kick's own swing of (h/2)·m·g·v_y (up to 1.2 % at
// one substep, 0.6 % at four) counts only while the bob is near the floor.
TEST(Joints, APendulumGrazingAFloorNeverGainsEnergy) {
    for (bool hinge : {true, false})
        for (float gap : {0.001f, 0.005f, 0.01f, 0.02f})
            for (float degrees : {10.0f, 30.0f, 60.0f})
                for (int substeps : {1, 4}) {
                    WorldSettings s;
                    s.enableSleep = false;
                    s.substeps = substeps;
                    World w(s);
                    test::makeGround(w);
                    const float length = 1.0f, radius = 0.1f, release = degrees * kPi / 180.0f;
                    const Vec2 pivot{0.0f, length + radius + gap};
                    const BodyId frame = w.createBody({.position = pivot});
                    const Vec2 p{length * std::sin(release), pivot.y - length * std::cos(release)};
                    const BodyId bob = dynamicDisc(w, p, radius);
                    if (hinge)
                        w.createRevoluteJoint({.bodyA = frame, .bodyB = bob, .localAnchorB = pivot - p});
                    else
                        w.createDistanceJoint({.bodyA = frame, .bodyB = bob, .length = length});
                    const double swing = w.mass(bob) * kG * length * (1.0 - std::cos(release));
                    const double start = test::totalEnergy(w, {bob});
                    double peak = start;
                    for (int i = 0; i < 1200; ++i) {
                        w.step(1.0f / 60.0f);
                        peak = std::max(peak, test::totalEnergy(w, {bob}));
                    }
                    EXPECT_LE(peak - start, 0.01 * swing) << (hinge ? "hinge" : "distance") << ", gap " << gap << " m, "
                                                          << degrees << "°, " << substeps << " substeps";
                }
}

// A disc on a motorised hinge against a constant load torque. Within its cap
// the motor holds its speed (1 %: the motor row solves the speed exactly each
// substep; the relax pass leaves the load's h·τ/I = 0.04 rad/s of the last
// substep, 0.8 % of 5 rad/s). Below the load the disc accelerates backwards at
// (τ_load − τ_max)/I (2 %: the speed at 1 s is a sum of 240 equal increments).
TEST(Joints, RevoluteMotorAgainstLoad) {
    for (float maxTorque : {10.0f, 0.2f}) {
        WorldSettings s;
        s.gravity = {0.0f, 0.0f};
        World w(s);
        BodyId ground = w.createBody({});
        BodyId disc = dynamicDisc(w, {0.0f, 0.0f}, 0.5f);
        JointId j = w.createRevoluteJoint(
            {.bodyA = ground, .bodyB = disc, .enableMotor = true, .motorSpeed = 5.0f, .maxMotorTorque = maxTorque});
        const float load = 0.5f, inertia = w.rotationalInertia(disc);
        for (int i = 0; i < 60; ++i) {
            w.applyTorque(disc, -load);
            w.step(1.0f / 60.0f);
        }
        if (maxTorque > load) {
            EXPECT_NEAR(w.angularVelocity(disc), 5.0f, 0.05f) << "cap " << maxTorque;
            EXPECT_NEAR(w.jointMotorEffort(j), load, 0.05f * load);
        } else {
            const float expected = -(load - maxTorque) / inertia * 1.0f;
            EXPECT_NEAR(w.angularVelocity(disc), expected, 0.02f * std::abs(expected));
            EXPECT_NEAR(std::abs(w.jointMotorEffort(j)), maxTorque, 1.0e-3f);
        }
    }
}

// A 2 m rod hinged at one end, released horizontal, with the angle limited to
// [−0.1, 0.1] rad: it must rest on the lower limit. Its static sag beyond the
// limit is τ/(I ω_j²) = 1.5 g/(L (2π·60 Hz)²) ≈ 5e-5 rad; 0.005 rad allows the
// speculative row's one-step overshoot at the first arrival.
TEST(Joints, RevoluteLimitHoldsUnderLoad) {
    WorldSettings s;
    s.enableSleep = false;
    World w(s);
    BodyId ground = w.createBody({});
    BodyId rod = w.createBody({.type = BodyType::dynamic_body, .position = {1.0f, 0.0f}});
    w.createPolygonShape(rod, {}, makeBox(1.0f, 0.05f));
    JointId j = w.createRevoluteJoint({.bodyA = ground,
                                       .bodyB = rod,
                                       .localAnchorB = {-1.0f, 0.0f},
                                       .enableLimit = true,
                                       .lowerAngle = -0.1f,
                                       .upperAngle = 0.1f});
    float lowest = 0.0f;
    for (int i = 0; i < 180; ++i) {
        w.step(1.0f / 60.0f);
        lowest = std::min(lowest, w.revoluteJointAngle(j));
    }
    EXPECT_GE(lowest, -0.1f - 0.005f);
    EXPECT_NEAR(w.revoluteJointAngle(j), -0.1f, 0.005f);
    // The limit carries the rod's weight moment m·g·L/2 about the hinge.
    EXPECT_NEAR(w.jointReactionTorque(j), w.mass(rod) * kG * 1.0f, 0.02f * w.mass(rod) * kG);
}

// A small body on a long arm swung into its limit stops there, at any speed
// and substep count, and the stop gives no energy back. The limit row used
// to act on the body's own inertia about its centre, which the point row then
// gave back in all but I/(I + m·r²) (here 0.4 %): the bob passed a 0.5 rad
// limit by 0.2 rad at 8 m/s, and past π the wrapped angle put it beyond the
// other limit, which threw it on (energy ×14 at 50 m/s, ×1.7 at 20 m/s with
// one substep). Bounds: the angle within 1e-3 rad of the limit, over three
// times the limit's static sag under the bob's weight at one substep, g·sin
// θ/(L·ω²) = 2.5e-4 rad with ω = 2π·15 Hz (the joint stiffness cap at a
// quarter of a 60 Hz substep); the energy (from the lowest point the bob can
// reach) within the 1 % of its start.
TEST(Joints, RevoluteLimitStopsASmallBodyOnALongArm) {
    const float L = 2.0f;
    for (int substeps : {1, 4})
        for (float limit : {0.5f, 2.0f, 3.0f})
            for (float speed : {4.0f, 20.0f, 80.0f}) {  // joint speed, rad/s
                WorldSettings s;
                s.enableSleep = false;
                s.substeps = substeps;
                World w(s);
                const Vec2 pivot{0.0f, 10.0f};
                BodyId ground = w.createBody({.position = pivot});
                BodyId bob = w.createBody({.type = BodyType::dynamic_body,
                                           .position = pivot - Vec2{0.0f, L},
                                           .linearVelocity = {speed * L, 0.0f},
                                           .angularVelocity = speed});
                w.createPolygonShape(bob, {.density = 3.0f}, makeBox(0.1f, 0.05f));
                JointId j = w.createRevoluteJoint({.bodyA = ground,
                                                   .bodyB = bob,
                                                   .localAnchorB = {0.0f, L},
                                                   .enableLimit = true,
                                                   .lowerAngle = -limit,
                                                   .upperAngle = limit});
                auto energy = [&] {
                    const float m = w.mass(bob), om = w.angularVelocity(bob);
                    return 0.5f * m * lengthSquared(w.linearVelocity(bob)) + 0.5f * w.rotationalInertia(bob) * om * om +
                           m * kG * (w.position(bob).y - (pivot.y - L));
                };
                const float start = energy();
                float widest = 0.0f, most = start;
                for (int i = 0; i < 3 * 60; ++i) {
                    w.step(1.0f / 60.0f);
                    widest = std::max(widest, std::abs(w.revoluteJointAngle(j)));
                    most = std::max(most, energy());
                }
                const std::string what = std::to_string(substeps) + " substeps, limit " + std::to_string(limit) + ", " +
                                         std::to_string(speed) + " rad/s";
                EXPECT_LE(widest, limit + 1.0e-3f) << what;
                EXPECT_LE(most, 1.01f * start) << what;
            }
}

// A box on a frictionless prismatic joint along a 30° incline slides down at
// g·sin θ: s(t) = ½ g sin θ t². Semi-implicit Euler over n substeps of h gives
// ½ a t² (1 + h/t) exactly; tolerance h/t + 0.1 % (the joint's 60 Hz softness
// lets the perpendicular rows sag by g cos θ/ω² ≈ 6e-5 m).
TEST(Joints, PrismaticSliderOnIncline) {
    World w;
    BodyId ground = w.createBody({});
    BodyId box = w.createBody({.type = BodyType::dynamic_body});
    w.createPolygonShape(box, {}, makeBox(0.2f, 0.2f));
    const float theta = kPi / 6.0f;
    const Vec2 down{std::cos(theta), -std::sin(theta)};
    JointId j = w.createPrismaticJoint({.bodyA = ground, .bodyB = box, .localAxisA = down});
    for (int i = 0; i < 60; ++i) w.step(1.0f / 60.0f);
    const float expected = 0.5f * kG * std::sin(theta);
    const float h = 1.0f / 240.0f;
    EXPECT_NEAR(w.jointTranslation(j), expected, (h + 1.0e-3f) * expected);
    EXPECT_NEAR(w.jointTranslationSpeed(j), kG * std::sin(theta), 1.0e-3f * kG);
    EXPECT_NEAR(w.angle(box), 0.0f, 1.0e-4f);
}

// Two discs on hinges coupled by a gear of ratio 2: θ₁ + 2θ₂ is held, so
// ω₂ = −ω₁/2 while a motor drives disc 1. A rack (prismatic) geared to a
// pinion: x + r·θ held. 1 %: the gear row is solved with the joint softness.
TEST(Joints, GearRatio) {
    WorldSettings s;
    s.gravity = {0.0f, 0.0f};
    World w(s);
    BodyId ground = w.createBody({});
    BodyId d1 = dynamicDisc(w, {0.0f, 0.0f}, 0.5f), d2 = dynamicDisc(w, {2.0f, 0.0f}, 0.5f);
    JointId r1 = w.createRevoluteJoint(
        {.bodyA = ground, .bodyB = d1, .enableMotor = true, .motorSpeed = 3.0f, .maxMotorTorque = 100.0f});
    JointId r2 = w.createRevoluteJoint({.bodyA = ground, .bodyB = d2, .localAnchorA = {2.0f, 0.0f}});
    w.createGearJoint({.joint1 = r1, .joint2 = r2, .ratio = 2.0f});
    BodyId rack = w.createBody({.type = BodyType::dynamic_body, .position = {0.0f, -2.0f}});
    w.createPolygonShape(rack, {}, makeBox(1.0f, 0.1f));
    JointId slide = w.createPrismaticJoint({.bodyA = ground, .bodyB = rack, .localAnchorA = {0.0f, -2.0f}});
    w.createGearJoint({.joint1 = slide, .joint2 = r1, .ratio = 0.5f});
    for (int i = 0; i < 120; ++i) w.step(1.0f / 60.0f);
    EXPECT_NEAR(w.angularVelocity(d1), 3.0f, 0.03f);
    EXPECT_NEAR(w.angularVelocity(d2), -1.5f, 0.015f);
    EXPECT_NEAR(w.linearVelocity(rack).x, -1.5f, 0.015f);
}

// Two boxes of 1 and 2 kg on a pulley of ratio 1: the heavier falls at
// g·(m₂ − m₁)/(m₁ + m₂) and lengthA + lengthB stays constant. 1 mm: the rigid
// row sags by about g/ω_j² ≈ 7e-5 m at the joint's 60 Hz.
TEST(Joints, PulleyKeepsRopeLength) {
    World w;
    BodyId ground = w.createBody({});
    BodyId a = w.createBody({.type = BodyType::dynamic_body, .position = {-2.0f, 0.0f}});
    BodyId b = w.createBody({.type = BodyType::dynamic_body, .position = {2.0f, 0.0f}});
    w.createPolygonShape(a, {.density = 1.0f}, makeBox(0.5f, 0.5f));
    w.createPolygonShape(b, {.density = 2.0f}, makeBox(0.5f, 0.5f));
    JointId j = w.createPulleyJoint({.bodyA = a,
                                     .bodyB = b,
                                     .groundAnchorA = {-2.0f, 5.0f},
                                     .groundAnchorB = {2.0f, 5.0f},
                                     .lengthA = 5.0f,
                                     .lengthB = 5.0f});
    (void)ground;
    for (int i = 0; i < 60; ++i) {
        w.step(1.0f / 60.0f);
        EXPECT_NEAR(w.pulleyJointLengthA(j) + w.pulleyJointLengthB(j), 10.0f, 1.0e-3f) << "step " << i;
    }
    const float accel = kG * (2.0f - 1.0f) / 3.0f;
    EXPECT_NEAR(w.linearVelocity(b).y, -accel, 0.01f * accel);
}

// A wheel hung on its suspension (static frame, vertical axis, 2 Hz, no
// damping) bounces at 2 Hz: the spring's softness is set by frequency, so the
// wheel's mass does not enter. 1 %: implicit Euler lengthens the period of a
// spring at ω·h = 0.05 by O((ωh)²) ≈ 0.3 %; crossings are quantised by h/8.
TEST(Joints, WheelSuspensionFrequency) {
    World w;
    BodyId frame = w.createBody({});
    BodyId wheel = dynamicDisc(w, {0.0f, 0.0f}, 0.3f);
    w.createWheelJoint({.bodyA = frame, .bodyB = wheel, .hertz = 2.0f, .dampingRatio = 0.0f});
    const std::vector<float> t = crossings(w, 1.0f / 240.0f, 240 * 5, [&] { return w.linearVelocity(wheel).y; });
    ASSERT_GE(t.size(), 6u);
    EXPECT_NEAR(meanPeriod(t), 0.5f, 0.005f);
}

// A box welded to the ground at its centre with a 1 Hz angular spring (linear
// part rigid), turned 0.2 rad and released, swings at 1 Hz. Tolerance as above.
TEST(Joints, SoftWeldFrequency) {
    WorldSettings s;
    s.gravity = {0.0f, 0.0f};
    World w(s);
    BodyId ground = w.createBody({});
    BodyId box = w.createBody({.type = BodyType::dynamic_body, .angle = 0.2f});
    w.createPolygonShape(box, {}, makeBox(0.5f, 0.2f));
    w.createWeldJoint({.bodyA = ground, .bodyB = box, .angularHertz = 1.0f, .angularDampingRatio = 0.0f});
    const std::vector<float> t = crossings(w, 1.0f / 240.0f, 240 * 6, [&] { return w.angle(box); });
    ASSERT_GE(t.size(), 4u);
    EXPECT_NEAR(meanPeriod(t), 1.0f, 0.01f);
    EXPECT_NEAR(w.position(box).x, 0.0f, 1.0e-3f);
}

// A mouse joint at 2 Hz, critically damped, pulls a free box 1 m: the gap
// closes as (1 + ωt)e^{−ωt}. At t = 0.25 s that is 0.179 m; ±0.02 m for
// implicit Euler at ω·h = 0.05 per substep.
TEST(Joints, MouseJointApproach) {
    WorldSettings s;
    s.gravity = {0.0f, 0.0f};
    World w(s);
    BodyId ground = w.createBody({});
    BodyId box = w.createBody({.type = BodyType::dynamic_body});
    w.createPolygonShape(box, {}, makeBox(0.2f, 0.2f));
    JointId j = w.createMouseJoint(
        {.bodyA = ground, .bodyB = box, .target = {0.0f, 0.0f}, .hertz = 2.0f, .dampingRatio = 1.0f, .maxForce = 1e4f});
    w.setMouseJointTarget(j, {1.0f, 0.0f});
    for (int i = 0; i < 15; ++i) w.step(1.0f / 60.0f);
    const float omegaT = 2.0f * kPi * 2.0f * 0.25f;
    EXPECT_NEAR(1.0f - w.position(box).x, (1.0f + omegaT) * std::exp(-omegaT), 0.02f);
}

float energy(const World& w) {
    float e = 0.0f;
    for (BodyId b : w.bodies()) {
        if (w.bodyType(b) != BodyType::dynamic_body) continue;
        const Vec2 v = w.linearVelocity(b);
        const float om = w.angularVelocity(b);
        e += 0.5f * w.mass(b) * dot(v, v) + 0.5f * w.rotationalInertia(b) * om * om +
             w.mass(b) * kG * w.worldCenterOfMass(b).y;
    }
    return e;
}

// 20 links and a ball of 100× a link's mass, released horizontal, sleeping
// off: a passive system never gains energy (1 % allows the float sum of 21
// bodies' energies, about 1e-5 relative, with room). Both with revolute
// joints (hinges at the link ends) and with distance joints (link centre to
// link centre, rest length the spacing, so the chain starts unstretched).
//
// Joint error: every joint within 5 cm at the defaults. The chain is a tree
// with a mass ratio of 100, so its equality rows are solved exactly
// (joint_tree.cpp); swept by Gauss-Seidel instead (exactJointMassRatio = ∞)
// the revolute chain reached 7.2 cm, which the second loop shows: the exact
// solve must keep at least a third less error than the sweep, or it is not
// what holds the chain.
/// The largest joint error (m) and energy gain (relative) of the swinging
/// chain over 10 s.
struct ChainSwing {
    float worstGain = 0.0f, worstError = 0.0f;
};
ChainSwing swingHeavyChain(bool revolute, float exactJointMassRatio) {
    {
        WorldSettings s;
        s.enableSleep = false;
        s.exactJointMassRatio = exactJointMassRatio;
        World w(s);
        BodyId prev = w.createBody({});
        const Vec2 anchor{0.0f, 20.0f};
        std::vector<JointId> joints;
        for (int i = 0; i < 20; ++i) {
            BodyId link = w.createBody(
                {.type = BodyType::dynamic_body, .position = {anchor.x + 0.5f * i + 0.25f, anchor.y}});
            w.createCapsuleShape(link, {.density = 20.0f}, {{-0.2f, 0.0f}, {0.2f, 0.0f}, 0.05f});
            if (revolute)
                joints.push_back(w.createRevoluteJoint({.bodyA = prev,
                                                        .bodyB = link,
                                                        .localAnchorA = i == 0 ? anchor : Vec2{0.25f, 0.0f},
                                                        .localAnchorB = {-0.25f, 0.0f}}));
            else
                joints.push_back(w.createDistanceJoint({.bodyA = prev,
                                                        .bodyB = link,
                                                        .localAnchorA = i == 0 ? anchor : Vec2{},
                                                        .length = i == 0 ? 0.25f : 0.5f}));
            prev = link;
        }
        const float linkMass = w.mass(prev);
        BodyId ball = dynamicDisc(w, {anchor.x + 10.5f, anchor.y}, 0.5f);
        MassData md = w.massData(ball);
        md.rotationalInertia *= 100.0f * linkMass / md.mass;
        md.mass = 100.0f * linkMass;
        w.setMassData(ball, md);
        if (revolute)
            joints.push_back(w.createRevoluteJoint(
                {.bodyA = prev, .bodyB = ball, .localAnchorA = {0.25f, 0.0f}, .localAnchorB = {-0.5f, 0.0f}}));
        else
            joints.push_back(w.createDistanceJoint({.bodyA = prev, .bodyB = ball, .length = 0.75f}));
        const float e0 = energy(w);
        float worstGain = 0.0f, worstError = 0.0f;
        for (int i = 0; i < 600; ++i) {
            w.step(1.0f / 60.0f);
            worstGain = std::max(worstGain, (energy(w) - e0) / std::abs(e0));
            for (JointId j : joints) {
                float error;
                if (revolute) {
                    const RevoluteJointDef d = w.revoluteJointDef(j);
                    error = distance(transformPoint(w.transform(d.bodyA), d.localAnchorA),
                                     transformPoint(w.transform(d.bodyB), d.localAnchorB));
                } else {
                    error = std::abs(w.distanceJointCurrentLength(j) - w.distanceJointDef(j).length);
                }
                worstError = std::max(worstError, error);
            }
        }
        return {worstGain, worstError};
    }
}

TEST(Joints, SwingingHeavyChainNeverGainsEnergy) {
    for (bool revolute : {true, false}) {
        const ChainSwing exact = swingHeavyChain(revolute, WorldSettings{}.exactJointMassRatio);
        const ChainSwing swept = swingHeavyChain(revolute, INFINITY);
        const char* kind = revolute ? "revolute" : "distance";
        std::printf("[figure] %s chain: joint error %.3f m solved exactly, %.3f m swept; energy gain %.4f\n", kind,
                    exact.worstError, swept.worstError, exact.worstGain);
        EXPECT_LE(exact.worstGain, 0.01f) << kind << " chain";
        EXPECT_LE(swept.worstGain, 0.01f) << kind << " chain";
        EXPECT_LE(exact.worstError, 0.05f) << kind << " chain";
        EXPECT_LT(exact.worstError, 0.67f * swept.worstError) << kind << " chain";
    }
}

// Refused input leaves the world as it was.
// A small disc hung by a distance joint from a point far off its centre:
// most of the row's effective mass along the rope is the disc's turning,
// I⁻¹(r × n)², which changes as fast as the disc turns. The row took its
// mass from the step's start for all four substeps: released with the arm
// level, the disc whipped round, a pass applied a hundred times the impulse
// its anchor needed, and it spun up to the rotation limit (energy 2,700 times
// the start by 2 s). The mass is now the substep's (axialMassOf).
TEST(Joints, ADiscHungFarOffItsCentreKeepsItsEnergy) {
    for (float arm : {0.5f, 0.865f, 1.5f, 3.0f}) {
        WorldSettings s;
        s.enableSleep = false;  // sleep would hide a gain
        World w(s);
        const float length = 0.5f;
        const BodyId hook = w.createBody({.position = {arm, 3.0f + length}});
        const BodyId disc = dynamicDisc(w, {0.0f, 3.0f}, 0.116f, 0.47f);
        w.createDistanceJoint({.bodyA = hook, .bodyB = disc, .localAnchorB = {arm, 0.0f}, .length = length});
        // Energy above the lowest the centre can reach (rope and arm hanging
        // straight down): the start is what the disc has to give, m·g·arm.
        const float lowest = 3.0f - arm;
        auto energy = [&] {
            const Vec2 v = w.linearVelocity(disc);
            const float om = w.angularVelocity(disc);
            return 0.5f * w.mass(disc) * dot(v, v) + 0.5f * w.rotationalInertia(disc) * om * om +
                   w.mass(disc) * kG * (w.worldCenterOfMass(disc).y - lowest);
        };
        const float start = energy();
        float peak = start;
        for (int i = 0; i < 600; ++i) {
            w.step(1.0f / 60.0f);
            peak = std::max(peak, energy());
        }
        std::printf("[figure] disc hung %.3f m off its centre: energy at most %+.3f %% of its start\n", double(arm),
                    100.0 * double((peak - start) / start));
        // The hard-cases issue's bound: a passive system never gains more than
        // 1 % (measured: never above the start at these arms; up to 9,300
        // times it before).
        EXPECT_LE(peak, 1.01f * start) << "arm " << arm;
    }
}

// A spring along a joint's axis on a disc held by a point 1.5 m off its
// centre (a wheel, a slider, a springy rope): the row's effective mass
// along the axis changes a hundredfold as the arm turns. The spring took its
// stiffness m_eff·ω² from it, so it was far stiffer stretched than where it
// was released, and gave back more than it took: energy 200 to 3,600,000
// times the release's own scale. Its stiffness is now the bodies' reduced
// mass times ω² (makeSpring), a constant, and the energy with the spring's
// own, ½·k·C², never rises. Not yet met, so not held here: the rope at one
// substep, whose disc turns up to a radian a step (docs/validation.md).
TEST(Joints, ASpringOnALongArmNeverGainsEnergy) {
    enum class Kind { wheel, slider, rope };
    for (Kind kind : {Kind::wheel, Kind::slider, Kind::rope})
        for (int substeps : {4, 2, 1})
            for (auto [hertz, zeta] : {std::pair{3.6f, 0.0f}, std::pair{1.0f, 0.7f}}) {
                if (kind == Kind::rope && substeps == 1) continue;
                WorldSettings s;
                s.enableSleep = false;  // sleep would hide a gain
                s.substeps = substeps;
                World w(s);
                const BodyId frame = w.createBody({});
                const BodyId disc = dynamicDisc(w, {-1.5f, 0.0f}, 0.17f, 9.3f);
                const Vec2 arm{1.5f, 0.0f};  // the disc's anchor, at the frame's origin
                if (kind == Kind::wheel) {
                    w.createWheelJoint({.bodyA = frame,
                                        .bodyB = disc,
                                        .localAnchorB = arm,
                                        .localAxisA = {0.0f, 1.0f},
                                        .enableSpring = true,
                                        .hertz = hertz,
                                        .dampingRatio = zeta});
                } else if (kind == Kind::slider) {
                    w.createPrismaticJoint({.bodyA = frame,
                                            .bodyB = disc,
                                            .localAnchorB = arm,
                                            .localAxisA = {0.0f, 1.0f},
                                            .enableSpring = true,
                                            .hertz = hertz,
                                            .dampingRatio = zeta});
                } else {
                    w.createDistanceJoint({.bodyA = frame,
                                           .bodyB = disc,
                                           .localAnchorA = {0.0f, 1.0f},
                                           .localAnchorB = arm,
                                           .length = 1.0f,
                                           .enableSpring = true,
                                           .hertz = hertz,
                                           .dampingRatio = zeta});
                }
                const float m = w.mass(disc);
                const float k = m * (2.0f * kPi * hertz) * (2.0f * kPi * hertz);
                // The spring's extension: along the axis (the anchor's height),
                // or the rope's length over its rest length.
                auto extension = [&] {
                    const Vec2 anchor = w.position(disc) + rotate(makeRot(w.angle(disc)), arm);
                    return kind == Kind::rope ? distance(anchor, Vec2{0.0f, 1.0f}) - 1.0f : anchor.y;
                };
                auto energy = [&] {
                    const Vec2 v = w.linearVelocity(disc);
                    const float om = w.angularVelocity(disc), c = extension();
                    return 0.5 * m * dot(v, v) + 0.5 * w.rotationalInertia(disc) * om * om +
                           m * kG * w.worldCenterOfMass(disc).y + 0.5 * k * c * c;
                };
                const double start = energy();
                double peak = start;
                for (int i = 0; i < 600; ++i) {
                    w.step(1.0f / 60.0f);
                    peak = std::max(peak, energy());
                }
                // The energy a release from rest at the rest length exchanges:
                // the spring's at twice the static sag s = m·g/k, ½·k·(2s)².
                const double sag = m * kG / k, scale = 2.0 * k * sag * sag;
                std::printf(
                    "[figure] spring %d, %d substeps, %.1f Hz, zeta %.1f: energy at most %+.4f of the release's\n",
                    static_cast<int>(kind), substeps, double(hertz), double(zeta), (peak - start) / scale);
                // The hard-cases issue's bound, 1 %, of that scale (measured: never above the start).
                EXPECT_LE(peak - start, 0.01 * scale) << static_cast<int>(kind) << " at " << substeps << " substeps";
            }
}

// A small body held by a soft weld to a point far off its centre (up to
// 30 times its own size). The weld's linear spring took its stiffness from
// the anchors' effective mass K⁻¹, which the arm makes a hundredth of the
// body's mass across it and all of it along it, and which turns with the
// body: the spring was far stiffer in some directions than others, and the
// body gained 5 to 590 times its energy (these layouts, from a probe of 2,000
// random single-joint layouts; 6 of them at four substeps). The spring now has
// the stiffness m·ω² in every direction (makePointSpring, soft_constraint.hpp),
// capped only where the step cannot follow it.
TEST(Joints, ASoftWeldOnALongArmNeverGainsEnergy) {
    struct Layout {
        bool capsule;                 // else a disc
        float size, radius, density;  // a disc's radius (size); a capsule's half-length and radius
        float angle;
        Vec2 anchor;  // on the body, in its frame; held at the world origin
        float hertz, zeta, angularHertz, angularZeta;
    };
    const Layout layouts[] = {
        {false, 0.0664f, 0.0f, 0.530f, -1.324f, {0.718f, -0.333f}, 4.32f, 0.343f, 2.47f, 0.648f},
        {false, 0.1023f, 0.0f, 0.100f, 2.389f, {-0.853f, 1.911f}, 3.32f, 0.361f, 3.21f, 0.555f},
        {true, 0.1172f, 0.0786f, 0.221f, -1.629f, {1.638f, 0.749f}, 4.28f, 0.913f, 3.81f, 0.892f},
        {false, 0.1886f, 0.0f, 9.501f, -2.277f, {-0.273f, -2.066f}, 2.73f, 0.964f, 4.58f, 0.850f},
        {false, 0.0639f, 0.0f, 6.213f, -2.962f, {-1.559f, 1.813f}, 6.73f, 0.555f, 0.0f, 0.0f},
        {true, 0.1066f, 0.0733f, 9.704f, 2.096f, {1.598f, 2.391f}, 8.78f, 0.886f, 3.83f, 0.268f},
        {false, 0.3515f, 0.0f, 0.425f, 2.002f, {2.538f, 0.531f}, 2.43f, 0.231f, 2.23f, 0.734f},
    };
    for (int substeps : {4, 2, 1})
        for (const Layout& l : layouts) {
            WorldSettings s;
            s.enableSleep = false;  // sleep would hide a gain
            s.substeps = substeps;
            World w(s);
            const BodyId pin = w.createBody({});
            const Vec2 centre = -rotate(makeRot(l.angle), l.anchor);
            const BodyId body = w.createBody({.type = BodyType::dynamic_body, .position = centre, .angle = l.angle});
            if (l.capsule)
                w.createCapsuleShape(body, {.density = l.density}, Capsule{{-l.size, 0.0f}, {l.size, 0.0f}, l.radius});
            else
                w.createCircleShape(body, {.density = l.density}, Circle{{0.0f, 0.0f}, l.size});
            w.createWeldJoint({.bodyA = pin,
                               .bodyB = body,
                               .localAnchorB = l.anchor,
                               .referenceAngle = l.angle,
                               .linearHertz = l.hertz,
                               .linearDampingRatio = l.zeta,
                               .angularHertz = l.angularHertz,
                               .angularDampingRatio = l.angularZeta});
            // Kinetic and gravitational energy. The springs start at rest, so
            // their energy, never negative, starts at zero: the total never
            // rising means this part never rises above its start.
            const float m = w.mass(body);
            auto energy = [&] {
                const Vec2 v = w.linearVelocity(body);
                const float om = w.angularVelocity(body);
                return 0.5 * m * dot(v, v) + 0.5 * w.rotationalInertia(body) * om * om +
                       m * kG * w.worldCenterOfMass(body).y;
            };
            const double start = energy();
            double peak = start;
            for (int i = 0; i < 600; ++i) {
                w.step(1.0f / 60.0f);
                peak = std::max(peak, energy());
            }
            // The scale the body's motion exchanges: its centre falling
            // through its arm, m·g·|arm|. The bound is the hard-cases issue's
            // 1 % of it (measured: never above the start).
            const double scale = m * kG * length(l.anchor);
            EXPECT_LE(peak - start, 0.01 * scale) << "layout " << (&l - layouts) << " at " << substeps
                                                  << " substeps: gained " << (peak - start) / scale << " of m·g·|arm|";
        }
}

TEST(Joints, BadInputIsRefused) {
    World w;
    BodyId ground = w.createBody({});
    BodyId wall = w.createBody({});
    BodyId a = dynamicDisc(w, {0.0f, 1.0f}), b = dynamicDisc(w, {1.0f, 1.0f});
    JointId weld = w.createWeldJoint({.bodyA = ground, .bodyB = a});
    JointId hinge = w.createRevoluteJoint({.bodyA = ground, .bodyB = b});
    const int joints = w.jointCount();
    const float nan = std::nanf("");
    EXPECT_THROW(w.createRevoluteJoint({.bodyA = ground, .bodyB = a, .localAnchorA = {nan, 0.0f}}), Error);
    EXPECT_THROW(w.createRevoluteJoint({.bodyA = ground, .bodyB = a, .lowerAngle = 0.5f, .upperAngle = 0.1f}), Error);
    // An inverted range is refused with the limit off too (it could be enabled later).
    EXPECT_THROW(w.createDistanceJoint({.bodyA = ground, .bodyB = a, .minLength = 5.0f, .maxLength = 1.0f}), Error);
    EXPECT_THROW(w.createPrismaticJoint({.bodyA = ground, .bodyB = a, .localAxisA = {0.0f, 0.0f}}), Error);
    EXPECT_THROW(
        w.createPrismaticJoint({.bodyA = ground, .bodyB = a, .lowerTranslation = 1.0f, .upperTranslation = 0.0f}),
        Error);
    EXPECT_THROW(w.createWheelJoint({.bodyA = ground, .bodyB = a, .hertz = -1.0f}), Error);
    EXPECT_THROW(w.createMotorJoint({.bodyA = ground, .bodyB = a, .maxForce = INFINITY}), Error);
    EXPECT_THROW(w.createMouseJoint({.bodyA = ground, .bodyB = a, .hertz = 0.0f}), Error);
    EXPECT_THROW(w.createPulleyJoint({.bodyA = a, .bodyB = b, .ratio = 0.0f}), Error);
    EXPECT_THROW(w.createPulleyJoint({.bodyA = a, .bodyB = b, .ratio = nan}), Error);
    EXPECT_THROW(w.createGearJoint({.joint1 = hinge, .joint2 = weld}), Error);  // a weld cannot be geared
    EXPECT_THROW(w.createGearJoint({.joint1 = hinge, .joint2 = hinge}), Error);
    EXPECT_THROW(w.createGearJoint({.joint1 = hinge, .joint2 = hinge, .ratio = 0.0f}), Error);
    EXPECT_THROW(w.createWeldJoint({.bodyA = ground, .bodyB = wall}), Error);  // two static bodies
    EXPECT_THROW(w.createWeldJoint({.bodyA = a, .bodyB = a}), Error);
    EXPECT_THROW(w.revoluteJointDef(weld), Error);
    EXPECT_THROW(w.enableJointMotor(weld, true), Error);
    RevoluteJointDef moved = w.revoluteJointDef(hinge);
    moved.bodyB = a;
    EXPECT_THROW(w.setRevoluteJointDef(hinge, moved), Error);
    EXPECT_EQ(w.jointCount(), joints);
    // A joint on a destroyed body.
    BodyId gone = dynamicDisc(w, {5.0f, 5.0f});
    w.destroyBody(gone);
    EXPECT_THROW(w.createRevoluteJoint({.bodyA = ground, .bodyB = gone}), Error);
    EXPECT_EQ(w.jointCount(), joints);
}

// Destroying a body destroys its joints and the gear joints built on them;
// destroying a joint destroys its gears.
TEST(Joints, DestroyingCascadesToGears) {
    World w;
    BodyId ground = w.createBody({});
    BodyId d1 = dynamicDisc(w, {0.0f, 0.0f}), d2 = dynamicDisc(w, {2.0f, 0.0f}), d3 = dynamicDisc(w, {4.0f, 0.0f});
    JointId r1 = w.createRevoluteJoint({.bodyA = ground, .bodyB = d1});
    JointId r2 = w.createRevoluteJoint({.bodyA = ground, .bodyB = d2, .localAnchorA = {2.0f, 0.0f}});
    JointId r3 = w.createRevoluteJoint({.bodyA = ground, .bodyB = d3, .localAnchorA = {4.0f, 0.0f}});
    JointId g12 = w.createGearJoint({.joint1 = r1, .joint2 = r2});
    JointId g23 = w.createGearJoint({.joint1 = r2, .joint2 = r3});
    EXPECT_EQ(w.jointCount(), 5);
    w.destroyJoint(r3);
    EXPECT_FALSE(w.isValid(g23));
    EXPECT_TRUE(w.isValid(g12));
    w.destroyBody(d1);
    EXPECT_FALSE(w.isValid(r1));
    EXPECT_FALSE(w.isValid(g12));
    EXPECT_TRUE(w.isValid(r2));
    EXPECT_EQ(w.jointCount(), 1);
    for (int i = 0; i < 10; ++i) w.step(1.0f / 60.0f);
}

}  // namespace

namespace {

// Every correction mode holds every rigid joint: a hinge, a slider, a weld, a
// wheel, a pulley and a gear in one scene, 5 s at 60 Hz; no joint drifts by
// more than 2 cm (baumgarte and split correct a fraction β = 0.2 of the error
// per step, so a steady load leaves an error of about (g h²)/β ≈ 1.4 mm; 2 cm
// allows the swings' transients) and the passive scene never gains energy.
// The pendulum carries a welded disc on a 3 m arm. With 0.2 m discs (the arm
// 3 m, so I/(m L²) = 0.002) baumgarte at its default 8 iterations does not
// converge and spins up to the speed limit; it holds at 30 iterations, and
// soft_step and split hold at their defaults. Here the discs are 0.5 m.
TEST(Joints, EveryCorrectionModeHoldsTheJoints) {
    for (PositionCorrection mode :
         {PositionCorrection::soft_step, PositionCorrection::baumgarte, PositionCorrection::split}) {
        WorldSettings s;
        s.positionCorrection = mode;
        s.enableSleep = false;
        World w(s);
        BodyId ground = w.createBody({});
        BodyId pendulum = dynamicDisc(w, {1.0f, 0.0f}, 0.5f);
        JointId hinge = w.createRevoluteJoint({.bodyA = ground, .bodyB = pendulum, .localAnchorB = {-1.0f, 0.0f}});
        BodyId slider = dynamicDisc(w, {3.0f, 0.0f}, 0.2f);
        w.createPrismaticJoint(
            {.bodyA = ground, .bodyB = slider, .localAnchorA = {3.0f, 0.0f}, .localAxisA = {1.0f, -1.0f}});
        BodyId welded = dynamicDisc(w, {-2.0f, 0.0f}, 0.5f);
        w.createWeldJoint({.bodyA = pendulum, .bodyB = welded, .localAnchorA = {-3.0f, 0.0f}});
        BodyId wheel = dynamicDisc(w, {-4.0f, 0.0f}, 0.2f);
        w.createWheelJoint({.bodyA = ground, .bodyB = wheel, .localAnchorA = {-4.0f, 0.0f}, .hertz = 3.0f});
        BodyId left = dynamicDisc(w, {6.0f, 0.0f}, 0.2f), right = dynamicDisc(w, {8.0f, 0.0f}, 0.2f);
        JointId pulley = w.createPulleyJoint({.bodyA = left,
                                              .bodyB = right,
                                              .groundAnchorA = {6.0f, 4.0f},
                                              .groundAnchorB = {8.0f, 4.0f},
                                              .lengthA = 4.0f,
                                              .lengthB = 4.0f});
        BodyId d1 = dynamicDisc(w, {10.0f, 0.0f}, 0.5f), d2 = dynamicDisc(w, {12.0f, 0.0f}, 0.5f);
        JointId r1 = w.createRevoluteJoint({.bodyA = ground, .bodyB = d1, .localAnchorA = {10.0f, 0.0f}});
        JointId r2 = w.createRevoluteJoint({.bodyA = ground, .bodyB = d2, .localAnchorA = {12.0f, 0.0f}});
        w.createGearJoint({.joint1 = r1, .joint2 = r2, .ratio = 1.0f});
        w.setAngularVelocity(d1, 2.0f);
        w.setAngularVelocity(d2, -2.0f);
        const float e0 = energy(w);
        float worst[5] = {}, gain = 0.0f;
        for (int i = 0; i < 300; ++i) {
            w.step(1.0f / 60.0f);
            const RevoluteJointDef d = w.revoluteJointDef(hinge);
            const Vec2 p = w.position(slider) - Vec2{3.0f, 0.0f};
            const float errors[5] = {distance(transformPoint(w.transform(ground), d.localAnchorA),
                                              transformPoint(w.transform(pendulum), d.localAnchorB)),
                                     std::abs(w.pulleyJointLengthA(pulley) + w.pulleyJointLengthB(pulley) - 8.0f),
                                     std::abs(distance(w.position(welded), w.position(pendulum)) - 3.0f),
                                     std::abs(p.x + p.y) / std::sqrt(2.0f),  // off the slider's line
                                     std::abs(w.position(wheel).x + 4.0f)};  // off the wheel's vertical axis
            for (int k = 0; k < 5; ++k) worst[k] = std::max(worst[k], errors[k]);
            gain = std::max(gain, (energy(w) - e0) / std::abs(e0));
        }
        const char* names[5] = {"hinge", "pulley", "weld", "slider", "wheel"};
        for (int k = 0; k < 5; ++k) EXPECT_LE(worst[k], 0.02f) << names[k] << ", mode " << static_cast<int>(mode);
        EXPECT_LE(gain, 0.01f) << "mode " << static_cast<int>(mode);
        EXPECT_NEAR(w.angularVelocity(d1) + w.angularVelocity(d2), 0.0f, 0.02f) << "mode " << static_cast<int>(mode);
    }
}

}  // namespace
