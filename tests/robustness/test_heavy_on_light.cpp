// A heavy body landing on a light one pinned to the world by a revolute
// joint (hard-cases issue: a passive system never gains energy). One
// Gauss-Seidel sweep moves the light body by its own mass, so the landing
// drags the pin open; the stretched joint's soft push, a velocity given to
// the light body, was handed on by the contact to the heavy body, which the
// relax pass does not reach, and threw it back up faster than it came (a
// 1.9 kg capsule onto a 17 g one: +131 %). Such a joint is now a deep joint
// (isDeepJoint, engine/src/world_state.hpp): rigid in the biased pass, its
// error pushed on pseudo-velocities. docs/joints.md, "A stretched joint
// beside a contact".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <impulse2d/impulse2d.hpp>

namespace {

using namespace i2d;

enum class Kind { box, circle, capsule };

/// A shape centred on its body, lying along x: a box of half-extents (a, b),
/// a circle of radius a, a capsule of half-length a and radius b.
struct ShapeSpec {
    Kind kind;
    float a, b, density;
};

struct Layout {
    ShapeSpec light;  ///< its centre at (0, 3), level
    float pinX;       ///< the pin, at (pinX, 3), through the light body's point (pinX, 0)
    ShapeSpec heavy;  ///< dropped from rest
    Vec2 heavyAt;
    float heavyAngle;
};

void addShape(World& w, BodyId body, const ShapeSpec& s) {
    const ShapeDef def{.density = s.density, .friction = 0.6f};
    switch (s.kind) {
        case Kind::box: w.createPolygonShape(body, def, makeBox(s.a, s.b)); break;
        case Kind::circle: w.createCircleShape(body, def, Circle{{0.0f, 0.0f}, s.a}); break;
        case Kind::capsule: w.createCapsuleShape(body, def, Capsule{{-s.a, 0.0f}, {s.a, 0.0f}, s.b}); break;
    }
}

/// Kinetic plus potential energy of the dynamic bodies (J), the potential
/// from height y0.
double energy(const World& w, double y0) {
    const Vec2 g = w.settings().gravity;
    double e = 0.0;
    for (BodyId b : w.bodies()) {
        if (w.bodyType(b) != BodyType::dynamic_body) continue;
        const double m = w.mass(b);
        const Vec2 v = w.linearVelocity(b);
        const double om = w.angularVelocity(b);
        const Vec2 c = w.worldCenterOfMass(b);
        e += 0.5 * m * (double(v.x) * v.x + double(v.y) * v.y) + 0.5 * w.rotationalInertia(b) * om * om;
        e -= m * (double(g.x) * c.x + double(g.y) * (double(c.y) - y0));
    }
    return e;
}

struct Outcome {
    double rise = 0.0;       ///< the largest energy over the start, less one, relative to the start
    float finalOpening = 0;  ///< the pin's anchors apart at the end (m)
};

/// A world with sleeping off (sleep would hide a gain) and `substeps`, and a
/// static ground whose top is y = 0 from x = −20 to 20 m.
World worldWithGround(int substeps) {
    WorldSettings s;
    s.enableSleep = false;
    s.substeps = substeps;
    World w(s);
    const BodyId ground = w.createBody({});
    w.createPolygonShape(ground, {}, makeOffsetBox(20.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    return w;
}

/// 10 s at 60 Hz, sleeping off, with `substeps`.
Outcome run(const Layout& l, int substeps) {
    World w = worldWithGround(substeps);
    const BodyId light = w.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 3.0f}});
    addShape(w, light, l.light);
    const BodyId pin = w.createBody({.position = {l.pinX, 3.0f}});
    w.createRevoluteJoint({.bodyA = pin, .bodyB = light, .localAnchorB = {l.pinX, 0.0f}});
    const BodyId heavy = w.createBody({.type = BodyType::dynamic_body, .position = l.heavyAt, .angle = l.heavyAngle});
    addShape(w, heavy, l.heavy);
    double lowest = 1e30;
    for (BodyId b : w.bodies()) lowest = std::min(lowest, double(w.position(b).y));
    const double start = energy(w, lowest);
    double peak = start;
    for (int i = 0; i < 600; ++i) {
        w.step(1.0f / 60.0f);
        peak = std::max(peak, energy(w, lowest));
    }
    const Vec2 anchor = w.position(light) + rotate(makeRot(w.angle(light)), Vec2{l.pinX, 0.0f});
    return {(peak - start) / std::max(std::abs(start), 1.0), distance(anchor, Vec2{l.pinX, 3.0f})};
}

// The bound: a passive system's energy never rises more than 1 %
// above its start.
constexpr double kEnergyBound = 0.01;
// A pin that holds: the soft point row under the swinging light body opens
// by its load over m_eff·ω², ω = 2π·60 Hz at 4 substeps but capped at a
// quarter of the substep rate, 2π·15 Hz, at one (16 times softer): up to
// 5 mm measured at the end here; a joint that came apart opens by metres.
constexpr float kOpeningBound = 0.01f;

// Layouts that gained before, each at the substep count where it did
// (measured: +180 %, +6.1 %, +3.2 %, +71 %, +9.8 %).
TEST(HeavyOnLight, LandingOnAPinnedBodyGainsNoEnergy) {
    struct Case {
        Layout layout;
        int substeps;
    };
    const Case cases[] = {
        {{{Kind::box, 0.403402418f, 0.121776655f, 0.517901182f},
          0.376295298f,
          {Kind::capsule, 0.560276568f, 0.193798304f, 9.4574194f},
          {0.210190803f, 5.01819706f},
          2.23973751f},
         1},
        {{{Kind::box, 0.320766181f, 0.161336079f, 0.105658829f},
          0.215845734f,
          {Kind::capsule, 0.642214119f, 0.179685712f, 9.32163811f},
          {-0.256301641f, 5.4901495f},
          2.91407251f},
         2},
        {{{Kind::circle, 0.108874336f, 0.0f, 0.1264759f},
          0.322906673f,
          {Kind::capsule, 0.792682946f, 0.181717739f, 6.50786591f},
          {0.301841795f, 4.08601856f},
          2.64867067f},
         4},
        {{{Kind::capsule, 1.48353219f, 0.0709745586f, 0.124424309f},
          -0.831214368f,
          {Kind::circle, 0.998230398f, 0.0f, 2.58713818f},
          {-0.676978111f, 7.5203948f},
          -0.978487492f},
         2},
        {{{Kind::capsule, 0.470916182f, 0.0580426902f, 0.242123052f},
          0.424089402f,
          {Kind::box, 0.897665143f, 0.086688444f, 6.36556292f},
          {0.451832622f, 5.89566755f},
          0.282932758f},
         4},
    };
    for (const Case& c : cases) {
        const Outcome o = run(c.layout, c.substeps);
        std::printf("[figure] pinned %.2f kg/m², landed on by %.2f kg/m², %d substeps: energy at most %+.3f %%, "
                    "pin open %.4f m at the end\n",
                    double(c.layout.light.density), double(c.layout.heavy.density), c.substeps, 100.0 * o.rise,
                    double(o.finalOpening));
        EXPECT_LE(o.rise, kEnergyBound) << c.substeps << " substeps";
        EXPECT_LE(o.finalOpening, kOpeningBound) << c.substeps << " substeps";
    }
}

// Random layouts of the same kind, none of them used to build the fix: a
// box, circle or capsule of density 0.05 to 0.55 pinned anywhere along it,
// a box, circle or capsule of density 1 to 11 dropped onto it from rest,
// clear of it, at 4, 2 and 1 substeps. Before the fix 3 to 5 of every
// 3,000 such layouts gained more than 1 % (up to +180 %).
TEST(HeavyOnLight, RandomLandingsOnPinnedBodiesGainNoEnergy) {
    std::mt19937 rng(20261203u);
    auto r = [&](float lo, float hi) { return lo + (hi - lo) * std::uniform_real_distribution<float>(0, 1)(rng); };
    auto shape = [&](float density) {
        const int kind = static_cast<int>(r(0.0f, 2.999f));
        if (kind == 0) return ShapeSpec{Kind::box, r(0.2f, 1.5f), r(0.02f, 0.25f), density};
        if (kind == 1) return ShapeSpec{Kind::circle, r(0.1f, 1.0f), 0.0f, density};
        return ShapeSpec{Kind::capsule, r(0.2f, 1.5f), r(0.02f, 0.2f), density};
    };
    int worst = 0;
    double worstRise = 0.0;
    for (int i = 0; i < 400; ++i) {
        Layout l;
        l.light = shape(r(0.05f, 0.55f));
        const float reach = l.light.a;  // the half-length or the radius
        l.pinX = r(-reach, reach);
        l.heavy = shape(r(1.0f, 11.0f));
        // Clear of the light body (each reaches at most 1.75 m from its centre).
        l.heavyAt = {r(-reach, reach), 3.0f + 3.6f + r(0.0f, 2.0f)};
        l.heavyAngle = r(-3.0f, 3.0f);
        for (int substeps : {4, 2, 1}) {
            const Outcome o = run(l, substeps);
            if (o.rise > worstRise) worstRise = o.rise, worst = i;
            EXPECT_LE(o.rise, kEnergyBound) << "layout " << i << " at " << substeps << " substeps";
        }
    }
    std::printf("[figure] 400 random landings on a pinned body at 4, 2 and 1 substeps: energy at most %+.3f %% "
                "(layout %d)\n",
                100.0 * worstRise, worst);
}

// A 2.9 kg capsule joined to a 15 g disc on the ground by a slider whose
// limit stops the capsule as it falls (from a probe of random jointed pairs
// dropped on the ground). Held rigid by the exact tree, the limit pressed the
// light disc 6.5 cm into the ground: the contact's sweep moves it by its own
// mass alone. The push out of the ground then went through the rigid limit
// to the capsule, thrown back up with 14 % more energy than it fell with. A
// slider's or a rope's limit is left to its sweep row while a body of its
// joint touches something (joint_tree.cpp).
TEST(HeavyOnLight, ALimitStoppingAHeavyBodyOnALightOneGainsNoEnergy) {
    for (int substeps : {4, 2, 1}) {
        WorldSettings s;
        s.enableSleep = false;  // sleep would hide a gain
        s.substeps = substeps;
        World w(s);
        const BodyId ground = w.createBody({});
        w.createPolygonShape(ground, {}, makeOffsetBox(40.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
        const BodyId heavy = w.createBody(
            {.type = BodyType::dynamic_body, .position = {0.0f, 2.1354f}, .angle = 2.4479f});
        w.createCapsuleShape(heavy, {.density = 13.383f, .friction = 0.1046f},
                             Capsule{{-0.25246f, 0.0f}, {0.25246f, 0.0f}, 0.14623f});
        const BodyId light = w.createBody(
            {.type = BodyType::dynamic_body, .position = {0.0062f, 0.4565f}, .angle = 2.4063f});
        w.createCircleShape(light, {.density = 0.023258f, .friction = 0.24265f}, Circle{{0.0f, 0.0f}, 0.45234f});
        w.createPrismaticJoint({.bodyA = heavy,
                                .bodyB = light,
                                .localAnchorA = {-0.73794f, 0.92957f},
                                .localAnchorB = {0.35486f, -0.34291f},
                                .localAxisA = {-0.47867f, 0.87799f},
                                .referenceAngle = -0.041636f,
                                .enableLimit = true,
                                .lowerTranslation = -1.1383f,
                                .upperTranslation = 1.1775f});
        const double start = energy(w, 0.0);
        double peak = start;
        for (int i = 0; i < 600; ++i) {
            w.step(1.0f / 60.0f);
            peak = std::max(peak, energy(w, 0.0));
        }
        // Measured: never above the start; +13.7 % with the limit held rigid.
        EXPECT_LE(peak - start, kEnergyBound * start) << substeps << " substeps";
    }
}

// A heavy body dropped onto a pile of one to three light bodies on the
// ground, with no joints (mass ratios 10 to 1,000): the landings the impact
// stage's shock pass stops, which holds each light body immovable for the
// body above it (docs/impacts.md, "Shock propagation"). Its strikes never add
// energy, and a pass that would is undone; so does the whole step, at 4 and
// 1 substeps, sleeping off.
TEST(HeavyOnLight, RandomHeavyLandingsOnLightPilesGainNoEnergy) {
    std::mt19937 rng(20261204u);
    auto r = [&](float lo, float hi) { return lo + (hi - lo) * std::uniform_real_distribution<float>(0, 1)(rng); };
    int worst = 0;
    double worstRise = 0.0;
    for (int i = 0; i < 60; ++i) {
        const int lights = 1 + static_cast<int>(r(0.0f, 2.999f));
        const float ratio = std::pow(10.0f, r(1.0f, 3.0f));
        const float drop = r(0.5f, 8.0f);
        const float offset = r(-0.4f, 0.4f);
        const float tilt = r(-0.3f, 0.3f);
        const bool circles = r(0.0f, 1.0f) < 0.3f;
        for (int substeps : {4, 1}) {
            World w = worldWithGround(substeps);
            float top = 0.0f;
            for (int k = 0; k < lights; ++k) {
                const BodyId b = w.createBody({.type = BodyType::dynamic_body, .position = {0.0f, top + 0.5f}});
                addShape(w, b,
                         circles ? ShapeSpec{Kind::circle, 0.5f, 0.0f, 1.0f} : ShapeSpec{Kind::box, 0.5f, 0.5f, 1.0f});
                top += 1.0f;
            }
            // A 2 × 1 m box of density ratio / 2: `ratio` times a light
            // box's mass (1 kg; a light disc's is 0.79 kg).
            const BodyId heavy = w.createBody(
                {.type = BodyType::dynamic_body, .position = {offset, top + 0.5f + drop}, .angle = tilt});
            addShape(w, heavy, ShapeSpec{Kind::box, 1.0f, 0.5f, ratio / 2.0f});
            const double start = energy(w, 0.0);
            double peak = start;
            for (int step = 0; step < 300; ++step) {
                w.step(1.0f / 60.0f);
                peak = std::max(peak, energy(w, 0.0));
            }
            const double rise = (peak - start) / std::max(std::abs(start), 1.0);
            if (rise > worstRise) worstRise = rise, worst = i;
            EXPECT_LE(rise, kEnergyBound) << "layout " << i << " at " << substeps << " substeps";
        }
    }
    std::printf("[figure] 60 heavy landings on piles of light bodies at 4 and 1 substeps: energy at most %+.3f %% "
                "(layout %d)\n",
                100.0 * worstRise, worst);
}

}  // namespace
