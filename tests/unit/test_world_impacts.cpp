// The closed-form impact law inside the world: several points and bodies at
// once, against the restitution-as-velocity-bias model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "world_fixtures.hpp"

using namespace i2d;

namespace {

double kineticEnergy(const World& w, BodyId b) {
    Vec2 v = w.linearVelocity(b);
    double om = w.angularVelocity(b);
    return 0.5 * w.mass(b) * dot(v, v) + 0.5 * w.rotationalInertia(b) * om * om;
}

double totalEnergy(const World& w) {
    double e = 0.0;
    for (BodyId b : w.bodies()) {
        if (w.bodyType(b) != BodyType::dynamic_body) continue;
        e += kineticEnergy(w, b) - w.mass(b) * dot(w.gravity(), w.worldCenterOfMass(b));
    }
    return e;
}

/// Drops a unit box (bottom at height h) on ground, both with restitution e;
/// returns the apex of the first rebound (bottom height) and the largest spin seen.
std::pair<float, float> dropBox(ImpactModel model, float e, float h, float dt) {
    WorldSettings s;
    s.impactModel = model;
    s.enableSleep = false;
    World world(s);
    BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {.restitution = e}, makeOffsetBox(50, 1, {0, -1}, 0));
    BodyId box = world.createBody({.type = BodyType::dynamic_body, .position = {0, 0.5f + h}});
    world.createPolygonShape(box, {.restitution = e}, makeBox(0.5f, 0.5f));
    float spin = 0.0f, previous = 0.0f;
    bool rising = false;
    for (int i = 0; i < static_cast<int>(10.0f / dt); ++i) {
        world.step(dt);
        float vy = world.linearVelocity(box).y;
        spin = std::max(spin, std::abs(world.angularVelocity(box)));
        if (vy > 0.0f) rising = true;
        if (rising && previous > 0.0f && vy <= 0.0f) return {world.position(box).y - 0.5f, spin};
        previous = vy;
    }
    return {-1.0f, spin};
}

}  // namespace

TEST(WorldImpacts, BoxDroppedFlatBouncesFlat) {
    auto [apex, spin] = dropBox(ImpactModel::closed_form, 0.5f, 2.0f, 1.0f / 60.0f);
    EXPECT_GT(apex, 0.3f);
    // Both corners strike together: the impact point is the manifold's centre
    // line, so no torque about the centre of mass (rounding only).
    EXPECT_LT(spin, 1e-3f);
}

TEST(WorldImpacts, ReboundHeightIsESquaredH) {
    // The law gives exactly v⁺ = e·v⁻ (test_impact.cpp), applied at the moment
    // of impact to the true velocity and stored staggered as semi-implicit
    // Euler needs (impact_stage.cpp): the flights are exact parabolas and the
    // apex is e²h to rounding, where before it was low by about v·Δt/2 (0.16 %
    // at 960 Hz). 60 Hz and 240 Hz figures are in docs/impacts.md.
    const float h = 2.0f;
    for (float e : {0.5f, 0.75f, 1.0f}) {
        auto [apex, spin] = dropBox(ImpactModel::closed_form, e, h, 1.0f / 960.0f);
        EXPECT_NEAR(apex, e * e * h, 0.02f * e * e * h) << "e = " << e;
    }
}

namespace {

/// The apexes of a height sampled once a step (`y`, with the vertical
/// velocity `vy` at the same steps): each where the velocity turns down,
/// refined with the parabola through the highest sample and its neighbours.
std::vector<double> apexesOf(const std::vector<double>& y, const std::vector<double>& vy) {
    std::vector<double> apexes;
    for (std::size_t k = 1; k + 1 < y.size(); ++k) {
        if (!(vy[k - 1] > 0.0 && vy[k] <= 0.0)) continue;
        const std::size_t m = y[k] >= y[k - 1] ? k : k - 1;
        const double a = y[m - 1], b = y[m], c = y[m + 1], den = a - 2.0 * b + c;
        apexes.push_back(den < 0.0 ? b - 0.125 * (a - c) * (a - c) / den : b);
    }
    return apexes;
}

/// Apexes (bottom height) of the successive rebounds of a body dropped from
/// h0 onto the ground, both with restitution e; a circle of radius 0.5 or a
/// unit box landing flat (apexesOf).
std::vector<double> reboundApexes(bool circle, float e, float h0, float dt) {
    World world({.enableSleep = false});
    BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {.restitution = e}, makeOffsetBox(50, 1, {0, -1}, 0));
    BodyId body = world.createBody({.type = BodyType::dynamic_body, .position = {0, 0.5f + h0}});
    if (circle)
        world.createCircleShape(body, {.restitution = e}, Circle{{0, 0}, 0.5f});
    else
        world.createPolygonShape(body, {.restitution = e}, makeBox(0.5f, 0.5f));
    std::vector<double> y, vy;
    for (int i = 0; i < static_cast<int>(8.0f / dt); ++i) {
        world.step(dt);
        y.push_back(world.position(body).y - 0.5);
        vy.push_back(world.linearVelocity(body).y);
    }
    return apexesOf(y, vy);
}

}  // namespace

// The hard-cases issue: apexes 1 to 4 within 3 % of e^(2n)·h0 at 60 Hz. The
// law acts at the moment of impact within the step and the rebound is stored
// staggered by half a substep of gravity, as semi-implicit Euler needs
// (impact_stage.cpp); continuous collision gives a body put back to its time
// of impact the velocity it had then (continuous.cpp). Checked here at step
// rates, heights and coefficients the validation cases do not use, for a
// circle and for a box landing flat; every impact is above the 1 m/s
// threshold (the fourth at 1.75 m/s and more).
TEST(WorldImpacts, ReboundApexesFollowESquaredNAtEveryStepRate) {
    for (bool circle : {true, false})
        for (float dt : {1.0f / 30.0f, 1.0f / 60.0f, 1.0f / 120.0f})
            for (float e : {0.6f, 0.8f}) {
                const float h0 = 3.3f;
                const std::vector<double> apexes = reboundApexes(circle, e, h0, dt);
                ASSERT_GE(apexes.size(), 4u) << "e " << e << ", " << 1.0f / dt << " Hz";
                for (int n = 1; n <= 4; ++n) {
                    const double expected = std::pow(e, 2 * n) * h0;
                    EXPECT_NEAR(apexes[n - 1], expected, 0.03 * expected)
                        << (circle ? "circle" : "box") << ", e " << e << ", " << 1.0f / dt << " Hz, apex " << n;
                }
            }
}

// A box landing flat on a wide static box bounced off true: the contact took
// the falling box's bottom face as its reference (the first shape of the
// pair), and the ground's top face, clipped against it, reached the box's
// frame from vertices 100 m away, with the rounding of such coordinates in
// its points. The box left its first impact turning at 1e-4 to 3e-3 rad/s,
// which every later impact grew until it landed on a corner: e = 0.75 from
// 5 m, a box of half-size 0.25 m reached its fourth apex 28 % low, one of
// 0.1 m 46 %, a rounded box 67 %, on a ground of half-width 100 m (on one
// of 50 m the 0.1 m box as well, the 0.25 m one not). A pair of like shapes now takes the immovable body's shape as
// the reference (contact.cpp). The bar is the hard-cases issue's (apexes 1 to
// 4 within 3 % of e^(2n)·h0), the box's tilt within 0.01 rad (a flat landing
// gives it none).
TEST(WorldImpacts, FlatBoxesBounceFlatOnAWideGround) {
    const float e = 0.75f, h0 = 5.0f, dt = 1.0f / 60.0f;
    for (const float half : {0.1f, 0.25f, 0.3f})
        for (const bool rounded : {false, true}) {
            World world({.enableSleep = false});
            const BodyId ground = world.createBody({});
            world.createPolygonShape(ground, {.restitution = e}, makeOffsetBox(100.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
            const BodyId box = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, half + h0}});
            world.createPolygonShape(box, {.restitution = e},
                                     rounded ? makeRoundedBox(0.8f * half, 0.8f * half, 0.2f * half)
                                             : makeBox(half, half));
            std::vector<double> y, vy;
            double tilt = 0.0;
            for (int i = 0; i < static_cast<int>(8.0f / dt); ++i) {
                world.step(dt);
                y.push_back(world.position(box).y - half);
                vy.push_back(world.linearVelocity(box).y);
                tilt = std::max(tilt, std::abs(double(world.angle(box))));
            }
            const std::vector<double> apexes = apexesOf(y, vy);
            const char* kind = rounded ? "rounded box" : "box";
            ASSERT_GE(apexes.size(), 4u) << kind << " of half-size " << half;
            for (int n = 1; n <= 4; ++n) {
                const double expected = std::pow(e, 2 * n) * h0;
                EXPECT_NEAR(apexes[n - 1], expected, 0.03 * expected)
                    << kind << " of half-size " << half << ", apex " << n;
            }
            EXPECT_LT(tilt, 0.01) << kind << " of half-size " << half;
        }
}

// impactThreshold is a speed at the moment of impact. The stage judged it by
// the approach when the step began, up to g·Δt (0.17 m/s) slower than the
// landing: a ball with e = 0.5 dropped from 3.9 to 4.3 m met the ground at
// 1.10 to 1.16 m/s on its fourth impact and did not bounce (20 of 154 drop
// heights from 0.3 to 8 m gave a bounce count other than the number of
// impacts faster than 1 m/s, 52 of 154 with e = 0.75). Each impact's speed
// here comes from the height it falls from (the drop, then each measured
// apex): u = √(2·g·h). The flight is exact (the ball's forces are split
// around its drift while it touches nothing, and the impact stage moves its
// velocity to the lagging one it times by: split_kick.hpp), so what is
// uncertain is the apex, sampled at the steps' ends: at most g·(Δt/2)²/2 =
// 0.35 mm below the true one, 0.35 % of the speed of a 1 m/s impact (a 5 cm
// fall). Within 0.5 % of the threshold either outcome is right. (It was 3 %
// while the ball flew by semi-implicit Euler, whose velocity lags the fall
// by half a substep of gravity; and the last relax of a step then judged a
// gap's approach by its speed a step before the impact, up to g·Δt slower:
// contact_solver.cpp, leftApproachSpeed.)
TEST(WorldImpacts, ABallBouncesExactlyWhenItLandsFasterThanTheThreshold) {
    const double threshold = WorldSettings{}.impactThreshold, g = 10.0;
    int judged = 0;
    for (const float e : {0.5f, 0.75f})
        for (int k = 0; k <= 22; ++k) {
            const float h0 = 0.5f + 0.25f * static_cast<float>(k);
            std::vector<double> apexes;
            for (const double a : reboundApexes(true, e, h0, 1.0f / 60.0f))
                if (a > 1.0e-3) apexes.push_back(a);  // (a bounce at 1 m/s rises 1.25 cm at e = 0.5)
            double height = h0;
            for (std::size_t n = 0;; ++n) {
                const double u = std::sqrt(2.0 * g * height);
                const bool bounced = n < apexes.size();
                if (u > 1.005 * threshold) {
                    EXPECT_TRUE(bounced) << "e " << e << ", h0 " << h0 << ": impact " << n + 1 << " at " << u << " m/s";
                    ++judged;
                } else if (u < 0.995 * threshold) {
                    EXPECT_FALSE(bounced)
                        << "e " << e << ", h0 " << h0 << ": impact " << n + 1 << " at " << u << " m/s";
                    ++judged;
                }
                if (!bounced) break;
                height = apexes[n];
            }
        }
    EXPECT_GT(judged, 200);
}

TEST(WorldImpacts, NewtonsCradlePassesTheMomentumAlong) {
    World world({.gravity = {0, 0}, .enableSleep = false});
    std::vector<BodyId> balls;
    for (int i = 0; i < 5; ++i) {
        // Touching neighbours (centres 1 m apart, radius 0.5); the first ball starts 1 m back.
        BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = {static_cast<float>(i) - (i == 0 ? 1.0f : 0.0f), 0}});
        world.createCircleShape(b, {.friction = 0.0f, .restitution = 1.0f}, {{0, 0}, 0.5f});
        balls.push_back(b);
    }
    world.setLinearVelocity(balls[0], {2.0f, 0.0f});
    for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f);
    // One ball in, one ball out: the elastic law between equal masses swaps
    // velocities exactly, and the sweep passes it down the line (float rounding).
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(world.linearVelocity(balls[static_cast<std::size_t>(i)]).x, 0.0f, 1e-4f) << i;
    EXPECT_NEAR(world.linearVelocity(balls[4]).x, 2.0f, 1e-4f);
}

TEST(WorldImpacts, BallStrikingARestingStackNeverRaisesTotalEnergy) {
    World world({.enableSleep = false});
    test::makeGround(world);
    for (int i = 0; i < 5; ++i) test::makeBox(world, {0.0f, 0.5f + static_cast<float>(i)});
    for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
    BodyId ball = world.createBody({.type = BodyType::dynamic_body, .position = {0.2f, 8.0f}});
    world.createCircleShape(ball, {.density = 2.0f, .restitution = 0.8f}, {{0, 0}, 0.3f});
    const double e0 = totalEnergy(world);
    for (int i = 0; i < 240; ++i) {
        world.step(1.0f / 60.0f);
        // Single-precision positions of ~10 m carry ~1e-6 relative rounding in
        // the potential energy: allow 1e-5 of it, nothing more.
        ASSERT_LE(totalEnergy(world), e0 * (1.0 + 1e-5)) << "step " << i;
    }
}

TEST(WorldImpacts, ObliqueSpinningRodGainsEnergyOnlyUnderTheBiasModel) {
    // A slender box (2·0.33 × 0.1 m) nearly upright, spinning fast, strikes the
    // ground on a corner with friction μ = 1.46 and e = 0.96, no gravity, so
    // kinetic energy is the whole energy. Newton restitution applied as a
    // velocity bias with Coulomb friction is known to create energy in such
    // impacts (Kane's paradox); Stronge's energetic law cannot.
    auto peakRatio = [](ImpactModel model) {
        WorldSettings s;
        s.impactModel = model;
        s.enableSleep = false;
        s.gravity = {0, 0};
        World world(s);
        BodyId ground = world.createBody({});
        world.createPolygonShape(ground, {.friction = 1.46f, .restitution = 0.96f}, makeOffsetBox(50, 1, {0, -1}, 0));
        const float angle = 1.47f, hx = 0.33f, hy = 0.05f;
        float lowest = std::abs(std::sin(angle)) * hx + std::abs(std::cos(angle)) * hy;
        BodyId rod = world.createBody({.type = BodyType::dynamic_body,
                                       .position = {0, lowest + 0.001f},
                                       .angle = angle,
                                       .linearVelocity = {-4.23f, -3.72f},
                                       .angularVelocity = 13.68f});
        world.createPolygonShape(rod, {.friction = 1.46f, .restitution = 0.96f}, makeBox(hx, hy));
        double k0 = kineticEnergy(world, rod), peak = k0;
        for (int i = 0; i < 20; ++i) {
            world.step(1.0f / 60.0f);
            peak = std::max(peak, kineticEnergy(world, rod));
        }
        return peak / k0;
    };
    double bias = peakRatio(ImpactModel::velocity_bias);
    double law = peakRatio(ImpactModel::closed_form);
    EXPECT_GT(bias, 1.05);       // the bias model creates over 5 % energy here
    EXPECT_LE(law, 1.0 + 1e-5);  // the law never does (float rounding of ½mv²)
}

// A body struck early in a step by one neighbour and late by another: each
// body's start is moved by its whole change of velocity times its earliest
// impact (impact_stage.cpp, shiftStart). With the time of the impact the
// sweeps happened to strike first (here the late one: its contact was made
// first), the struck box kept its old velocity until the late impact while
// the early neighbour stopped against it, and the two began the solver's
// substeps 3.1 cm inside each other. Unit boxes, no gravity: B at rest, A
// closing on it at 10 m/s from 1 cm (meets it after 1 ms), C at 10 m/s from
// 15 cm (after 15 ms).
TEST(WorldImpacts, BodyStruckEarlyAndLateInAStepEndsOutsideBoth) {
    for (bool lateContactFirst : {true, false}) {
        World world({.gravity = {0, 0}, .enableSleep = false});
        const Polygon box = makeBox(0.5f, 0.5f);
        auto make = [&](float x, float v) {
            BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {x, 0}, .linearVelocity = {v, 0}});
            world.createPolygonShape(b, {.friction = 0.6f}, box);
            return b;
        };
        BodyId a{}, b{}, c{};
        if (lateContactFirst) {
            c = make(1.15f, -10.0f);
            b = make(0.0f, 0.0f);
            a = make(-1.01f, 10.0f);
        } else {
            a = make(-1.01f, 10.0f);
            b = make(0.0f, 0.0f);
            c = make(1.15f, -10.0f);
        }
        auto overlap = [&](BodyId p, BodyId q) {
            const Manifold m = collidePolygons(box, world.transform(p), box, world.transform(q), 0.0f);
            float d = 0.0f;
            for (int j = 0; j < m.pointCount; ++j) d = std::min(d, m.points[j].separation);
            return -d;
        };
        for (int i = 0; i < 30; ++i) {
            world.step(1.0f / 60.0f);
            // The soft rows leave an overlap up to the penetration slop
            // unpushed; any deeper one here was made by the impact timing.
            const float slop = world.settings().penetrationSlop;
            ASSERT_LE(overlap(a, b), slop) << "step " << i << (lateContactFirst ? ", late contact first" : "");
            ASSERT_LE(overlap(b, c), slop) << "step " << i << (lateContactFirst ? ", late contact first" : "");
        }
    }
}

// A body at rest struck in a step runs into a neighbour it was a few
// centimetres from. The contact between the two had no point when the step
// began (neither moved: its margin was the speculative distance, 2 cm), so
// nothing stopped the struck body: knocked at 10 m/s from 5 cm away, it went
// 11.6 cm into its neighbour in the step (a paddle at 20 rad/s in a box of
// small boxes pressed them 9 to 15 cm into each other that way). Such a
// contact now gets its manifold again at the struck body's new velocity
// after each sweep of the impact stage (refreshStruckContacts, contact.cpp),
// and the next sweep strikes it. Without gravity, so that every overlap
// past the penetration slop (which the soft rows leave unpushed) is the
// strike's. Restitution 0: the three move on together at a third of the
// striker's speed.
TEST(WorldImpacts, ABodyKnockedIntoANeighbourMeetsIt) {
    for (const bool circles : {false, true}) {
        World world({.gravity = {0, 0}, .enableSleep = false});
        auto make = [&](float x, float v) {
            BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {x, 0}, .linearVelocity = {v, 0}});
            if (circles)
                world.createCircleShape(b, {}, Circle{{0.0f, 0.0f}, 0.5f});
            else
                world.createPolygonShape(b, {}, makeBox(0.5f, 0.5f));
            return b;
        };
        const float gap = 0.05f;  // between the neighbour and the body struck (m)
        const BodyId neighbour = make(-1.0f - gap, 0.0f);
        const BodyId struck = make(0.0f, 0.0f);
        const BodyId striker = make(1.001f, -20.0f);  // 1 mm away: struck at the step's start
        const std::pair<BodyId, BodyId> pairs[] = {{neighbour, struck}, {struck, striker}};
        for (int i = 0; i < 10; ++i) {
            world.step(1.0f / 60.0f);
            const float slop = world.settings().penetrationSlop;
            for (const auto& [p, q] : pairs) {
                const Manifold m = circles ? collideCircles(Circle{{0, 0}, 0.5f}, world.transform(p),
                                                            Circle{{0, 0}, 0.5f}, world.transform(q), 0.0f)
                                           : collidePolygons(makeBox(0.5f, 0.5f), world.transform(p),
                                                             makeBox(0.5f, 0.5f), world.transform(q), 0.0f);
                float depth = 0.0f;
                for (int j = 0; j < m.pointCount; ++j) depth = std::max(depth, -m.points[j].separation);
                ASSERT_LE(depth, slop) << (circles ? "circles" : "boxes") << ", step " << i;
            }
        }
        // The neighbour was reached and pushed on: momentum 20 kg·m/s over
        // three equal masses (the solver's rows hold them together to within
        // a hundredth of that).
        const float together = -20.0f / 3.0f;
        EXPECT_NEAR(world.linearVelocity(neighbour).x, together, 0.07f) << (circles ? "circles" : "boxes");
    }
}

// The same struck body in a row of elastic balls (restitution 1, no
// friction), each 5 cm from the next: a Newton's cradle with gaps. The
// strikes pass the striker's velocity from ball to ball within the step, and
// the last ball leaves with it, as it does with no gaps
// (NewtonsCradlePassesTheMomentumAlong). Stopped in the solver instead, by a
// row without restitution, the struck ball and its neighbour went on together
// with half the energy.
TEST(WorldImpacts, AnElasticRowWithGapsPassesTheStrikeAlong) {
    World world({.gravity = {0, 0}, .enableSleep = false});
    auto make = [&](float x, float v) {
        BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {x, 0}, .linearVelocity = {v, 0}});
        world.createCircleShape(b, {.friction = 0.0f, .restitution = 1.0f}, Circle{{0.0f, 0.0f}, 0.5f});
        return b;
    };
    const float gap = 0.05f;
    std::vector<BodyId> row;
    for (int k = 3; k >= 1; --k) row.push_back(make(-static_cast<float>(k) * (1.0f + gap), 0.0f));
    row.push_back(make(0.0f, 0.0f));
    const BodyId striker = make(1.001f, -20.0f);
    for (int i = 0; i < 30; ++i) {
        world.step(1.0f / 60.0f);
        for (std::size_t k = 0; k + 1 < row.size(); ++k) {
            const float centres = length(world.position(row[k + 1]) - world.position(row[k]));
            ASSERT_GE(centres, 1.0f - world.settings().penetrationSlop) << "balls " << k << ", step " << i;
        }
    }
    // The law is exact for each pair (1e-4 m/s in the cradle without gaps).
    EXPECT_NEAR(world.linearVelocity(row.front()).x, -20.0f, 1e-3f);
    for (std::size_t k = 1; k < row.size(); ++k) EXPECT_NEAR(world.linearVelocity(row[k]).x, 0.0f, 1e-3f) << k;
    EXPECT_NEAR(world.linearVelocity(striker).x, 0.0f, 1e-3f);
}

namespace {

/// Largest total energy over 5 s, relative to its start, of two boxes (half
/// sides 0.1 to 0.4 m) welded rigidly at the midpoint of their centres, the
/// second `ratio` times as dense, dropped at random angles onto the ground
/// from 1.5 to 3 m (the second 0.5 to 1 m from the first in a random
/// direction, kept above 1 m); restitution 0. The potential is measured from
/// 1 m below the ground's top, so the energy is never negative.
double weldedPairPeakEnergy(unsigned seed, int substeps, float ratio) {
    std::mt19937 rng(seed);
    auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {}, makeOffsetBox(60.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    std::vector<BodyId> bodies;
    Vec2 at{0.0f, uniform(1.5f, 3.0f)};
    for (int i = 0; i < 2; ++i) {
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = at, .angle = uniform(-3.0f, 3.0f)});
        world.createPolygonShape(b,
                                 {.density = i == 1 ? ratio : 1.0f, .restitution = 0.0f, .filter = {.groupIndex = -1}},
                                 makeBox(uniform(0.1f, 0.4f), uniform(0.1f, 0.4f)));
        if (i > 0) {
            const BodyId a = bodies.back();
            const Vec2 mid = 0.5f * (at + world.position(a));
            world.createWeldJoint({.bodyA = a,
                                   .bodyB = b,
                                   .localAnchorA = invTransformPoint(world.transform(a), mid),
                                   .localAnchorB = invTransformPoint(world.transform(b), mid),
                                   .referenceAngle = std::remainder(world.angle(b) - world.angle(a), 6.2831853f)});
        }
        bodies.push_back(b);
        const float heading = uniform(0.0f, 6.2832f);
        at = at + uniform(0.5f, 1.0f) * Vec2{std::cos(heading), std::sin(heading)};
        if (at.y < 1.0f) at.y = 1.0f + uniform(0.0f, 1.0f);
    }
    return test::peakEnergyOver5s(world, bodies, -1.0);
}

}  // namespace

// Bodies welded rigidly are struck by the impact law as one rigid body
// (impact_stage.cpp, findWeldClusters). Struck one at a time as free bodies,
// the light box's rebound was worked out with its own mass and its start
// shifted to fly at it, and the weld took that back from there: of these 200
// drops of a pair 100 times as dense at one end, 13, 9 and 0 gained more than
// 1 % at 4, 2 and 1 substeps, the worst thrown up with 2.2 times its start
// (30 times as dense: 6, 5 and 0). A passive system (restitution 0): the
// hard-cases issue's bound, 1 % over 5 s.
TEST(WorldImpacts, RigidlyWeldedPairsLandWithoutGainingEnergy) {
    for (float ratio : {30.0f, 100.0f})
        for (int substeps : {4, 2, 1}) {
            double worst = 0.0;
            for (unsigned seed = 1; seed <= 200; ++seed) {
                const double peak = weldedPairPeakEnergy(seed, substeps, ratio);
                worst = std::max(worst, peak);
                EXPECT_LE(peak, 1.01) << "seed " << seed << ", " << substeps << " substeps, " << ratio << ":1";
            }
            std::printf("[figure] %g:1, %d substeps: 200 welded pairs dropped, at most %.4f times their start\n",
                        double(ratio), substeps, worst);
        }
}
