// Hard cases that must not explode (docs/robustness.md, "Hard cases"). Each
// test measures a figure, prints it, and asserts a bound whose reason is
// given next to it. Default settings throughout: soft step, 4 substeps,
// 60 Hz, closed-form impacts, sleep on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "unit/world_fixtures.hpp"

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;

float maxSpeed(const World& world, const std::vector<BodyId>& bodies) {
    float v = 0.0f;
    for (BodyId b : bodies) v = std::max(v, length(world.linearVelocity(b)));
    return v;
}

/// A pyramid of square boxes of half-extent `half` (density 1) standing on the
/// ground at y = 0, `base` boxes in its bottom row, each row centred on the
/// one below and resting on it; built bottom row first, left to right, so the
/// top box is the last. `built` holds where each box was created.
struct BoxPyramid {
    std::vector<BodyId> boxes;
    std::vector<Vec2> built;
};
BoxPyramid buildPyramid(World& world, int base, float half, float friction = 0.6f) {
    BoxPyramid p;
    const float size = 2.0f * half;
    for (int row = 0; row < base; ++row) {
        const int n = base - row;
        for (int i = 0; i < n; ++i) {
            const Vec2 at{size * (static_cast<float>(i) - 0.5f * static_cast<float>(n - 1)),
                          half + size * static_cast<float>(row)};
            p.boxes.push_back(test::makeBox(world, at, half, 1.0f, friction));
            p.built.push_back(at);
        }
    }
    return p;
}

bool allFinite(const World& world) {
    for (BodyId b : world.bodies())
        if (!isFinite(world.position(b)) || !isFinite(world.linearVelocity(b)) ||
            !std::isfinite(world.angularVelocity(b)))
            return false;
    return true;
}

// 100 unit boxes created at one point. Measured at the default settings
// (soft step) and with the single-frame push factor (split), where the push
// is solved on pseudo-velocities that are dropped after the step.
struct PileResult {
    float peakSpeed = 0.0f;  ///< m/s, over the whole run
    float restTime = -1.0f;  ///< s until everything sleeps, −1 if never within 60 s
    float minDistance = 0.0f;
    bool finite = false;
};

PileResult pileOfHundred(PositionCorrection mode) {
    World world(WorldSettings{.positionCorrection = mode});
    test::makeGround(world, 100.0f);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 100; ++i) boxes.push_back(test::makeBox(world, {0.0f, 5.0f}));
    PileResult r;
    for (int step = 0; step < 60 * 60; ++step) {
        world.step(kDt);
        r.peakSpeed = std::max(r.peakSpeed, maxSpeed(world, boxes));
        if (world.awakeBodyCount() == 0) {
            r.restTime = (step + 1) * kDt;
            break;
        }
    }
    r.finite = allFinite(world);
    r.minDistance = 1e9f;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            r.minDistance = std::min(r.minDistance, distance(world.position(boxes[i]), world.position(boxes[j])));
    return r;
}

TEST(HardCases, HundredBoxesAtOnePointSeparateAndRestWithSplitImpulses) {
    PileResult r = pileOfHundred(PositionCorrection::split);
    std::printf(
        "[figure] 100 boxes at one point, split: peak speed %.2f m/s, asleep after %.2f s, closest centres %.3f m\n",
        r.peakSpeed, r.restTime, r.minDistance);
    ASSERT_TRUE(r.finite);
    // 20 m/s: the speed of a free fall from 20 m, four times the height at
    // which the boxes are created; faster would be energy from the solver,
    // not from gravity (measured 13.3 m/s).
    EXPECT_LT(r.peakSpeed, 20.0f);
    // At rest (everything asleep) within 20 s of simulated time (measured 9.4 s).
    EXPECT_GE(r.restTime, 0.0f);
    EXPECT_LT(r.restTime, 20.0f);
    // Separated: unit boxes at rest overlap by at most the slop, so centres
    // are ~1 m apart; 0.9 m allows for a box resting rotated against another.
    EXPECT_GT(r.minDistance, 0.9f);
}

// The same with the default soft step. Before a body's deep contacts shared
// the push cap, the 99 coincident contacts of each box added their capped
// pushes and launched boxes at 40-60 m/s (some never came to rest).
TEST(HardCases, HundredBoxesAtOnePointSeparateAndRestWithSoftStep) {
    PileResult r = pileOfHundred(PositionCorrection::soft_step);
    std::printf("[figure] 100 boxes at one point, soft step: peak speed %.2f m/s, asleep after %.2f s, closest centres "
                "%.3f m\n",
                r.peakSpeed, r.restTime, r.minDistance);
    ASSERT_TRUE(r.finite);
    EXPECT_LT(r.peakSpeed, 20.0f);  // as with split impulses
    EXPECT_GE(r.restTime, 0.0f);
    EXPECT_LT(r.restTime, 20.0f);
    EXPECT_GT(r.minDistance, 0.9f);
}

// A box created with 90% of its height inside the ground is pushed out at
// the limited push speed and ends resting on top, without being launched.
TEST(HardCases, BodyDeepInsideTheGroundIsPushedOutNotLaunched) {
    World world;
    test::makeGround(world);
    BodyId box = test::makeBox(world, {0.0f, -0.4f});  // bottom at −0.9 m, top at 0.1 m
    float topY = -1e9f;
    float peakUp = 0.0f;
    for (int step = 0; step < 5 * 60; ++step) {
        world.step(kDt);
        topY = std::max(topY, world.position(box).y);
        peakUp = std::max(peakUp, world.linearVelocity(box).y);
    }
    ASSERT_TRUE(allFinite(world));
    const float finalY = world.position(box).y;
    std::printf(
        "[figure] box 0.9 m deep in the ground: peak upward speed %.3f m/s, highest centre %.4f m, final %.4f m\n",
        peakUp, topY, finalY);
    // Resting on top: centre at the half-extent 0.5 m, within 1 cm (slop 5 mm plus soft-contact sag).
    EXPECT_NEAR(finalY, 0.5f, 0.01f);
    // Not launched: never more than 5 cm above its resting height, and never
    // faster upward than the push-out speed limit (maxPushSpeed, 3 m/s) plus 10%.
    EXPECT_LT(topY, 0.55f);
    EXPECT_LT(peakUp, 1.1f * world.settings().maxPushSpeed);
}

// A stack of 20 unit boxes with the top one 100 times heavier than each box
// below (a 1:100 mass ratio), documented in docs/robustness.md. It collapsed
// in about a third of a second in every position-correction mode; since
// contacts sunk deeper than 5 cm are held by rigid rows and pushed only
// beyond what their load explains (deep_overlap.cpp), it stands in the soft
// step, its top 0.52 m lower after 60 s (its contacts' compliance; 1.03 m
// before the impact stage's shock pass): it still drops half a box, by
// sinking, at 0.45 s. The tests
// measure when the top box has dropped by half a box and how far it has sunk
// after 1/6 s, and assert that it stays finite and bounded and sinks no
// sooner than before.
struct StackResult {
    float fallTime = -1.0f;  ///< s until the top box is 0.5 m below its start, −1 if never
    float earlySink = 0.0f;  ///< m the top box has sunk after 10 steps (1/6 s)
    float topY = 0.0f;
    float peakSpeed = 0.0f;
    bool finite = false;
};

StackResult heavyTopStack() {
    World world;
    test::makeGround(world);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 20; ++i)
        boxes.push_back(test::makeBox(world, {0.0f, 0.5f + static_cast<float>(i)}, 0.5f, i == 19 ? 100.0f : 1.0f));
    StackResult r;
    for (int step = 0; step < 10 * 60; ++step) {
        world.step(kDt);
        r.peakSpeed = std::max(r.peakSpeed, maxSpeed(world, boxes));
        if (r.fallTime < 0.0f && world.position(boxes.back()).y < 19.0f) r.fallTime = (step + 1) * kDt;
        if (step == 9) r.earlySink = 19.5f - world.position(boxes.back()).y;
    }
    r.topY = world.position(boxes.back()).y;
    r.finite = allFinite(world);
    return r;
}

TEST(HardCases, StackOfTwentyWithHeavyTopCollapsesBoundedly) {
    StackResult r = heavyTopStack();
    std::printf(
        "[figure] stack 20, top 100x heavier: top dropped 0.5 m after %.2f s, top at y %.3f after 10 s, peak speed %.2f m/s\n",
        r.fallTime, r.topY, r.peakSpeed);
    ASSERT_TRUE(r.finite);
    // Free fall from the top box's height gives √(2·10·19.5) = 19.7 m/s; a
    // collapse may reach it (measured 20.6 m/s: the heavy box lands on
    // tumbling boxes), an explosion goes far beyond 1.5 times it.
    EXPECT_LT(r.peakSpeed, 30.0f);
}

// The target is a stack that stands (the top never drops by half a box, and
// sinks by no more than the few millimetres of 20 compressed contacts). Until
// then this test holds today's figures so that a change cannot make the
// collapse come sooner. Measured at the default settings: the top sinks
// 0.137 m in the first 1/6 s (a stack of 20 equal boxes: 0.080 m) and has
// dropped half a box after 0.350 s (21 steps); since the shock pass (below,
// StackOfTwentyWithHeavyTopStandsWithSleepingOff) 0.126 m and 0.450 s,
// by compression alone; since its rows hold the loads they were built with
// (engine/src/rest_load.hpp: the rows between the light boxes, not the heavy
// top's, whose masses differ a hundredfold) 0.111 m and 0.533 s, after which
// it stands 0.47 m lower. Asserted with a margin of
// three steps for compilers and flags that round differently: fall no sooner
// than 0.30 s (18 steps), and a sink after 1/6 s under 0.16 m.
//
// Why it falls: soft_step's contacts are springs whose stiffness is scaled to
// each contact's effective mass (Box2D v3's mass-independent softness). Under
// the heavy top every contact carries 100 times the weight its stiffness was
// scaled for, so each one compresses by centimetres, the compressions of the
// 20 contacts add up, and the boxes slide off each other's corners. More
// substeps do not help (8, 16, 32 substeps: 0.37 s); stiffer contacts only
// delay it (contactHertz 120, capped at 60 Hz with 4 substeps: 0.42 s); rigid
// contacts solved to convergence nearly hold it (split with 50 velocity
// iterations: 5.2 s). What would fix it: softness scaled to the load a contact
// carries (or to the heavier body's mass) instead of its own effective mass,
// or a block or direct solver for the normal rows of a column of contacts, so
// that the 1:100 ratio no longer stalls Gauss-Seidel. Then replace the bounds
// below by the target: fallTime < 0 and topY within 0.05 m of 19.5.
TEST(HardCases, StackOfTwentyWithHeavyTopFallsNoSoonerThanToday) {
    StackResult r = heavyTopStack();
    std::printf("[figure] stack 20, top 100x heavier: sank %.3f m in 1/6 s, dropped 0.5 m after %.3f s\n", r.earlySink,
                r.fallTime);
    ASSERT_TRUE(r.finite);
    if (r.fallTime < 0.0f) {
        std::printf("[figure] the heavy-top stack stands: make its target the assertion\n");
    } else {
        EXPECT_GE(r.fallTime, 0.30f);  // measured 0.350 s
    }
    EXPECT_LT(r.earlySink, 0.16f);  // measured 0.137 m
}

// The same column with sleeping off for 60 s. Since the impact stage's shock
// pass stops the heavy top closing on the box below it in every step
// (docs/impacts.md, "Shock propagation") it stands (before: 1.03 m lower).
// Without the loads it was built with held in its rows (rest_load.hpp) it
// sinks by its contacts' compliance, load over m_eff·ω²: the 19 contacts
// between boxes (m_eff 0.5 kg, 50 Hz) carry 100 to 118 kg, Σ = 2,071 kg, so
// 2071·10/(0.5·(2π·50)²) = 0.420 m; the ground's (1 kg, 100 Hz) 0.003 m; and
// 20 slops of 5 mm: 0.523 m in all (measured 0.516 m). Nothing moves faster
// than a free fall through that sink, √(2·10·0.523) = 3.2 m/s (measured 1.5),
// and the top stays within the 1 cm sideways for a column of 20.
// Built touching, the rows between its light boxes now hold the loads they
// were built with, not the heavy top's (a hundredfold unlike): 0.472 m.
TEST(HardCases, StackOfTwentyWithHeavyTopStandsWithSleepingOff) {
    World world(WorldSettings{.enableSleep = false});
    test::makeGround(world);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 20; ++i)
        boxes.push_back(test::makeBox(world, {0.0f, 0.5f + static_cast<float>(i)}, 0.5f, i == 19 ? 100.0f : 1.0f));
    float peak = 0.0f, sway = 0.0f;
    for (int step = 0; step < 60 * 60; ++step) {
        world.step(kDt);
        peak = std::max(peak, maxSpeed(world, boxes));
        sway = std::max(sway, std::abs(world.position(boxes.back()).x));
    }
    const float drop = 19.5f - world.position(boxes.back()).y;
    std::printf("[figure] stack 20, top 100x heavier, 60 s, sleeping off: top %.3f m lower, %.4f m sideways, "
                "peak speed %.2f m/s\n",
                drop, sway, peak);
    ASSERT_TRUE(allFinite(world));
    EXPECT_LT(drop, 0.523f + 0.01f);  // plus 1 cm for the float sums of 20 contacts' sags
    EXPECT_LT(sway, 0.01f);
    EXPECT_LT(peak, 3.2f);
}

// Light stacks under tops 200 to 400 times their boxes' mass (issue: the
// largest ratio that stands). Stacks of 3, 5 and 8 boxes 0.5 to 1.5 m
// across and high (three layouts each) under a 0.5 × 1 m top 200 and 300
// times their mean mass, and four unit boxes under a 2 × 2 m top of density
// 100 (400 times), 30 s, sleeping off. With the contacts' tilt left to their
// soft rows, whose stiffness follows the light boxes' effective mass, each
// contact bent under the top's load and the lean grew about four times a
// second: 9 of these 19 fell (docs/validation.md, "Columns solved as one").
// Bounds: the for a heavy top, within 5 cm sideways and a drop
// under 0.5 m (the contacts' sag, load over m_eff·ω² summed down the stack:
// measured up to 0.45 m for 8 boxes under 300 times); the energy never above
// its start (a passive system, the audit's 1 %).
TEST(HardCases, LightStacksUnderTopsTwoToFourHundredTimesHeavierStand) {
    struct Layout {
        int boxes, seed;
        float ratio;
    };
    std::vector<Layout> layouts;
    for (int boxes : {3, 5, 8})
        for (int seed = 1; seed <= 3; ++seed)
            for (float ratio : {200.0f, 300.0f}) layouts.push_back({boxes, seed, ratio});
    layouts.push_back({4, 0, 400.0f});  // the unit boxes under a 2 × 2 m top
    for (const Layout& l : layouts) {
        World world(WorldSettings{.enableSleep = false});
        test::makeGround(world, 100.0f);
        std::vector<BodyId> bodies;
        std::uint32_t state = static_cast<std::uint32_t>(l.seed) * 2654435761u;
        auto uniform = [&] {  // a small LCG: the same layouts on every platform
            state = state * 1664525u + 1013904223u;
            return static_cast<float>(state >> 8) / 16777216.0f;
        };
        float y = 0.0f, mass = 0.0f;
        for (int i = 0; i < l.boxes; ++i) {
            const float hx = l.seed == 0 ? 0.5f : 0.25f + 0.5f * uniform();
            const float hy = l.seed == 0 ? 0.5f : 0.25f + 0.5f * uniform();
            BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, y + hy}});
            world.createPolygonShape(b, {.density = 1.0f, .friction = 0.6f}, makeBox(hx, hy));
            y += 2.0f * hy;
            mass += 4.0f * hx * hy;
            bodies.push_back(b);
        }
        const Vec2 topHalf = l.seed == 0 ? Vec2{1.0f, 1.0f} : Vec2{0.25f, 0.5f};
        const float topDensity = l.ratio * (mass / static_cast<float>(l.boxes)) / (4.0f * topHalf.x * topHalf.y);
        BodyId top = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, y + topHalf.y}});
        world.createPolygonShape(top, {.density = topDensity, .friction = 0.6f}, makeBox(topHalf.x, topHalf.y));
        bodies.push_back(top);
        const Vec2 start = world.position(top);
        const double e0 = test::totalEnergy(world, bodies);
        float sway = 0.0f;
        double energy = 0.0;
        for (int step = 0; step < 30 * 60; ++step) {
            world.step(kDt);
            sway = std::max(sway, std::abs(world.position(top).x - start.x));
            energy = std::max(energy, test::totalEnergy(world, bodies) / e0);
        }
        const float drop = start.y - world.position(top).y;
        SCOPED_TRACE(std::to_string(l.boxes) + " boxes, layout " + std::to_string(l.seed) + ", top " +
                     std::to_string(l.ratio) + " times");
        std::printf("[figure] %d boxes (layout %d) under a top %.0f times their mass: sway %.4f m, drop %.3f m, "
                    "energy at most %.5f of its start\n",
                    l.boxes, l.seed, l.ratio, sway, drop, energy);
        ASSERT_TRUE(allFinite(world));
        EXPECT_LT(sway, 0.05f);
        EXPECT_LT(drop, 0.5f);
        EXPECT_LT(energy, 1.01);
    }
}

// Box2D v3's HighMassRatio2: a 20 × 20 m box (400 kg) dropped from 26 m
// (its bottom 15 m above two 1 × 1 m boxes of 1 kg at x = ±9) lands at
// 17 m/s. Each pairwise strike between it and a light box takes a 400th of
// its approach; before the impact stage's shock pass the light boxes were
// driven half a metre into the ground, and through a segment ground
// (docs/impacts.md, "Shock propagation"). Sleeping off.
TEST(HardCases, HeavyBoxLandingOnLightBoxesIsStoppedByTheGround) {
    for (bool segmentGround : {true, false}) {
        World world(WorldSettings{.enableSleep = false});
        BodyId ground = world.createBody({});
        if (segmentGround)
            world.createSegmentShape(ground, {.friction = 0.6f}, Segment{{-20.0f, 0.0f}, {20.0f, 0.0f}});
        else
            world.createPolygonShape(ground, {.friction = 0.6f}, makeOffsetBox(40.0f, 2.0f, {0.0f, -2.0f}, 0.0f));
        std::vector<BodyId> light{test::makeBox(world, {-9.0f, 0.5f}), test::makeBox(world, {9.0f, 0.5f})};
        BodyId big = test::makeBox(world, {0.0f, 26.0f}, 10.0f);
        float lowestLight = 1e9f, downAfterLanding = 0.0f, bigYLastSecond = 0.0f;
        bool landed = false;
        float lastSecondLow = 1e9f, lastSecondHigh = -1e9f;
        for (int step = 0; step < 10 * 60; ++step) {
            const float before = world.linearVelocity(big).y;
            world.step(kDt);
            for (BodyId b : light) lowestLight = std::min(lowestLight, world.position(b).y);
            if (!landed && world.linearVelocity(big).y > before + 1.0f) {
                landed = true;
                downAfterLanding = -world.linearVelocity(big).y;
            }
            if (step >= 9 * 60) {
                bigYLastSecond += world.position(big).y / 60.0f;
                lastSecondLow = std::min(lastSecondLow, world.position(big).y);
                lastSecondHigh = std::max(lastSecondHigh, world.position(big).y);
            }
        }
        std::printf(
            "[figure] 400 kg box on two 1 kg boxes (%s ground): lowest light box %.4f m, big box at %.4f m over the "
            "last second (moving %.5f m), going down at %.3f m/s after the step it lands\n",
            segmentGround ? "segment" : "box", lowestLight, bigYLastSecond, lastSecondHigh - lastSecondLow,
            downAfterLanding);
        ASSERT_TRUE(allFinite(world));
        ASSERT_TRUE(landed);
        // Stopped in the step it lands: it leaves that step going down no
        // faster than one step of free fall after the strike (g·Δt =
        // 0.167 m/s) plus the shock pass's residual (0.01 m/s); before, it
        // kept 2.3 to 2.5 m/s for 20 steps (measured 0.104 m/s).
        EXPECT_LT(downAfterLanding, 10.0f * kDt + 0.01f);
        // Box2D v3's bar for this sample: the light boxes end within 1 cm of
        // resting on the ground (measured 0.6 cm).
        for (BodyId b : light) EXPECT_NEAR(world.position(b).y, 0.5f, 0.01f);
        // At no time deeper than their rows' compliance: each light box's
        // ground row carries half the big box's weight, 2,000 N, and sinks
        // F/(m·ω²) = 2000/(1·(2π·100 Hz)²) = 0.51 cm (the static doubled
        // 50 Hz) below the 0.5 cm slop: 1.01 cm (measured 0.65 cm; 1.8 cm
        // while the big box still bounced on them, before the shock pass
        // stopped it in every step; before any shock pass, 0.5 m and through).
        EXPECT_GT(lowestLight, 0.5f - 0.0101f);
        // The big box rests on them as low as the two rows' compliance and
        // slops allow: 2000/(1·(2π·50)²) = 2.03 cm into each light box,
        // 0.51 cm of the light box into the ground and 0.5 cm of slop at each
        // contact: 3.5 cm below 11 m (measured 3.2 cm; Box2D v3's bar of
        // 1 cm is below what a contact softened to 50 Hz can give). And at
        // rest there, Box2D v3's other bar: over the last second it moves
        // less than a millimetre (measured under 0.01 mm; it bounced at 3 Hz for
        // seconds, 4 cm at first, before the shock pass stopped it closing on
        // the light boxes in every step).
        EXPECT_NEAR(bigYLastSecond, 11.0f, 0.035f);
        EXPECT_LT(lastSecondHigh - lastSecondLow, 0.001f);
    }
}

// Box2D v3's HighMassRatio1: three pyramids of 55 boxes 2 × 2 m (base 10)
// on a segment ground, whose top box, 100, 200 and 300 times as dense as the
// rest, is dropped from 2 m above its place. Before the impact stage's shock
// pass the landings of the 200 and 300 tops drove the boxes below apart and
// both pyramids collapsed (boxes ended 26 and 79 m from where they were
// built, the tops 18 m down).
// Sleeping off.
TEST(HardCases, PyramidsWithHeavyTopsDroppedOnThemStand) {
    World world(WorldSettings{.enableSleep = false});
    BodyId ground = world.createBody({});
    world.createSegmentShape(ground, {.friction = 0.6f}, Segment{{-66.0f, 0.0f}, {66.0f, 0.0f}});
    struct Pyramid {
        std::vector<BodyId> boxes;
        std::vector<Vec2> start;
        BodyId top{};
        float topRestY = 0.0f;  ///< where the top box rests on the pyramid
    };
    std::vector<Pyramid> pyramids;
    const float densities[] = {100.0f, 200.0f, 300.0f};
    for (int k = 0; k < 3; ++k) {
        Pyramid p;
        const float x0 = -40.0f + 40.0f * static_cast<float>(k);
        constexpr int kBase = 10;
        for (int row = 0; row < kBase; ++row)
            for (int i = 0; i < kBase - row; ++i) {
                const bool top = row == kBase - 1;
                const float y = 1.0f + 2.0f * static_cast<float>(row);
                const Vec2 at{x0 + 2.0f * (static_cast<float>(i) - 0.5f * static_cast<float>(kBase - row - 1)),
                              top ? y + 2.0f : y};
                BodyId b = test::makeBox(world, at, 1.0f, top ? densities[k] : 1.0f);
                p.boxes.push_back(b);
                p.start.push_back(at);
                if (top) p.top = b, p.topRestY = y;
            }
        pyramids.push_back(p);
    }
    for (int step = 0; step < 10 * 60; ++step) world.step(kDt);
    ASSERT_TRUE(allFinite(world));
    for (int k = 0; k < 3; ++k) {
        const Pyramid& p = pyramids[static_cast<std::size_t>(k)];
        float sideways = 0.0f;
        for (std::size_t i = 0; i < p.boxes.size(); ++i)
            sideways = std::max(sideways, std::abs(world.position(p.boxes[i]).x - p.start[i].x));
        const float sink = p.topRestY - world.position(p.top).y;
        std::printf("[figure] pyramid of 55 with a top %g times as dense dropped on it: top %.3f m below its place, "
                    "boxes at most %.3f m sideways after 10 s\n",
                    densities[k], sink, sideways);
        // Standing: no box a quarter of its width (0.5 m) from where it was
        // built, where a collapse moves boxes by metres (measured 0.16 to
        // 0.19 m: the lower rows spread under the heavy top); the top no
        // more than a quarter of a box below its place, where a collapse
        // drops it by many (measured 2.3, 5.3 and 6.9 cm).
        EXPECT_LT(sideways, 0.5f) << "top density " << densities[k];
        EXPECT_LT(sink, 0.5f) << "top density " << densities[k];
    }
}

// A 10-link chain (distance joints, 1 kg links) hanging from a static anchor
// and holding a body 1000 times heavier than a link; given a sideways kick
// it swings and must stay connected, its stretch measured.
TEST(HardCases, ChainHoldsABodyAThousandTimesHeavier) {
    World world;
    BodyId anchor = world.createBody({.position = {0.0f, 20.0f}});
    const float linkLength = 0.5f;
    std::vector<BodyId> links;
    std::vector<JointId> joints;
    BodyId previous = anchor;
    for (int i = 0; i < 10; ++i) {
        BodyId link = world.createBody(
            {.type = BodyType::dynamic_body, .position = {0.0f, 20.0f - linkLength * (i + 1)}});
        // 1 kg: capsule area 2·r·L + π r² with r = 0.05, L = 0.4 is 0.0479 m².
        world.createCapsuleShape(link, {.density = 1.0f / 0.0478540f}, {{0.0f, -0.2f}, {0.0f, 0.2f}, 0.05f});
        joints.push_back(world.createDistanceJoint({.bodyA = previous, .bodyB = link, .length = linkLength}));
        links.push_back(link);
        previous = link;
    }
    BodyId heavy = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 20.0f - linkLength * 11}});
    world.createCircleShape(heavy, {.density = 1.0f}, {{0.0f, 0.0f}, 0.5f});
    world.setMassData(heavy,
                      {.mass = 1000.0f, .center = {}, .rotationalInertia = 125.0f});  // 1000 kg, a solid disc of r 0.5
    joints.push_back(world.createDistanceJoint({.bodyA = previous, .bodyB = heavy, .length = linkLength}));
    world.applyLinearImpulseToCenter(heavy, {5000.0f, 0.0f});  // 5 m/s sideways

    float worstStretch = 0.0f;  // largest relative length error of one joint
    float worstTotal = 0.0f;    // largest relative error of the anchor–heavy distance
    for (int step = 0; step < 10 * 60; ++step) {
        world.step(kDt);
        float total = 0.0f;
        for (JointId j : joints) {
            float len = world.distanceJointCurrentLength(j);
            total += len;
            worstStretch = std::max(worstStretch, std::abs(len - linkLength) / linkLength);
        }
        worstTotal = std::max(worstTotal, std::abs(total - 11 * linkLength) / (11 * linkLength));
    }
    ASSERT_TRUE(allFinite(world));
    std::printf(
        "[figure] chain of 10 x 1 kg holding 1000 kg, 10 s swinging: worst joint stretch %.2f%%, worst chain length error %.2f%%\n",
        100.0f * worstStretch, 100.0f * worstTotal);
    // Known weakness, documented in docs/robustness.md: at 4 substeps the
    // chain stretches to about three times its length (joint 214%, chain
    // 194% measured) and then holds there; at 8 or more substeps ~50%.
    // Bounded: no joint beyond 3.5 times its length at any time (a chain
    // that let go would stretch without bound as the body fell away).
    EXPECT_LT(worstStretch, 2.5f);
    // The joints stay finite and present.
    EXPECT_EQ(world.jointCount(), 11);
}

// Box2D v3's Ball & Chain sample: 40 capsule links (1 m, radius 0.125 m,
// density 20: 5.98 kg) hinged end to end from a static anchor, a ball of
// radius 8 m and density 20 (4,021 kg, 672:1) on the last, released level,
// links not colliding with each other, sleeping off. The sample's bar: the
// chain's summed joint error under 1 % of its length while it swings. The
// tree is solved exactly and rigid (joint_tree.cpp); its soft rows, soft
// relative to each link's own mass, held 1.02 % at 4 substeps, and the links
// under the ball's pull (up to 120 kN at the lowest point) whipped and flung
// the chain apart at 2 and 1 substeps (294 % and 826 %) until the tension's
// geometric stiffness was added to their inertia (measured now: 0.00, 0.01
// and 0.04 %). Energy: a passive system, so never 1 % above its start (the
// issue's bar), measured from the lowest the ball can hang.
TEST(HardCases, BallAndChainHoldsItsLengthWhileSwinging) {
    for (int substeps : {4, 2, 1}) {
        WorldSettings settings;
        settings.enableSleep = false;
        settings.substeps = substeps;
        World world(settings);
        const BodyId anchor = world.createBody({});
        const int links = 40;
        const float y = 20.0f, radius = 8.0f;
        ShapeDef def{.density = 20.0f, .filter = {.groupIndex = -1}};
        std::vector<BodyId> bodies;
        std::vector<JointId> joints;
        BodyId previous = anchor;
        for (int i = 0; i < links; ++i) {
            const BodyId link = world.createBody(
                {.type = BodyType::dynamic_body, .position = {0.5f + static_cast<float>(i), y}});
            world.createCapsuleShape(link, def, Capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.125f});
            joints.push_back(world.createRevoluteJoint({.bodyA = previous,
                                                        .bodyB = link,
                                                        .localAnchorA = i == 0 ? Vec2{0.0f, y} : Vec2{0.5f, 0.0f},
                                                        .localAnchorB = {-0.5f, 0.0f}}));
            bodies.push_back(link);
            previous = link;
        }
        const BodyId ball = world.createBody(
            {.type = BodyType::dynamic_body, .position = {static_cast<float>(links) + radius, y}});
        world.createCircleShape(ball, def, Circle{{0.0f, 0.0f}, radius});
        joints.push_back(world.createRevoluteJoint(
            {.bodyA = previous, .bodyB = ball, .localAnchorA = {0.5f, 0.0f}, .localAnchorB = {-radius, 0.0f}}));
        bodies.push_back(ball);
        const double lowest = y - (links + 2.0f * radius);
        auto energy = [&] { return test::totalEnergy(world, bodies, lowest); };
        const double start = energy();
        double peak = start;
        float worst = 0.0f;
        for (int step = 0; step < 10 * 60; ++step) {
            world.step(kDt);
            float open = 0.0f;
            for (JointId j : joints) {
                const RevoluteJointDef d = world.revoluteJointDef(j);
                open += length(transformPoint(world.transform(d.bodyB), d.localAnchorB) -
                               transformPoint(world.transform(d.bodyA), d.localAnchorA));
            }
            worst = std::max(worst, open);
            peak = std::max(peak, energy());
        }
        ASSERT_TRUE(allFinite(world));
        std::printf("[figure] Ball & Chain, %d substeps: joints open %.3f %% of the chain at most, energy at most "
                    "%.5f times its start\n",
                    substeps, 100.0f * worst / static_cast<float>(links), peak / start);
        EXPECT_LT(worst, 0.01f * static_cast<float>(links)) << substeps << " substeps";
        EXPECT_LE(peak, 1.01 * start) << substeps << " substeps";
    }
}

// A small fast circle against a thin static wall, no gravity. With
// continuous collision (the default) it must not tunnel at any speed up to
// the world's speed limit. Without it the speculative contact alone stops a
// circle shot straight at the wall: the ball's fat box holds its motion over
// the coming step from its creation on (broad_phase.cpp, comingBox), so the
// pair exists before the step that would carry it past, and the contact's
// margin covers that step's travel. Before, it tunnelled from 15 m/s, once a
// step carried it past the wall before its fat box had the wall.
bool tunnels(float speed, bool continuous) {
    World world(WorldSettings{.gravity = {0.0f, 0.0f}, .enableContinuous = continuous});
    BodyId wall = world.createBody({.position = {5.0f, 0.0f}});
    world.createPolygonShape(wall, {}, makeBox(0.05f, 2.0f));  // 10 cm thick
    BodyId ball = world.createBody(
        {.type = BodyType::dynamic_body, .position = {0.0f, 0.0f}, .linearVelocity = {speed, 0.0f}});
    world.createCircleShape(ball, {}, {{0.0f, 0.0f}, 0.05f});  // 10 cm across
    for (int step = 0; step < 120; ++step) {
        world.step(kDt);
        if (world.position(ball).x > 5.0f) return true;
    }
    return false;
}

TEST(HardCases, ThinWallTunnellingSpeedIsMeasured) {
    // Speeds from 1 m/s up in steps of 1 m/s to the world's speed limit.
    float firstTunnel = -1.0f, firstTunnelContinuous = -1.0f;
    for (float v = 1.0f; v <= 400.0f; v += 1.0f) {
        if (firstTunnel < 0.0f && tunnels(v, false)) firstTunnel = v;
        if (firstTunnelContinuous < 0.0f && tunnels(v, true)) firstTunnelContinuous = v;
    }
    std::printf("[figure] 10 cm ball vs 10 cm wall at 60 Hz: continuous off: %s (first at %.0f m/s); continuous on: "
                "%s\n",
                firstTunnel < 0.0f ? "never up to 400 m/s" : "TUNNELS", firstTunnel,
                firstTunnelContinuous < 0.0f ? "never up to 400 m/s" : "TUNNELS");
    // Continuous collision (the default) stops it at every speed up to the limit.
    EXPECT_LT(firstTunnelContinuous, 0.0f) << "tunnels at " << firstTunnelContinuous << " m/s";
    // Without it, so does the speculative contact, straight on.
    EXPECT_LT(firstTunnel, 0.0f) << "tunnels at " << firstTunnel << " m/s without continuous collision";
}

// The same pyramid at the origin and 10 km away settles the same way: the
// solver works in positions relative to each step's start, so only the
// float spacing at 1e4 m (~1 mm) separates the two.
TEST(HardCases, WorldFarFromTheOriginBehavesLikeAtTheOrigin) {
    auto settle = [](Vec2 offset) {
        World world;
        BodyId ground = world.createBody({.position = offset});
        world.createPolygonShape(ground, {}, makeOffsetBox(20.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
        std::vector<BodyId> boxes;
        const int base = 10;
        for (int row = 0; row < base; ++row)
            for (int i = 0; i < base - row; ++i)
                boxes.push_back(
                    test::makeBox(world, offset + Vec2{(i - 0.5f * (base - row - 1)) * 1.05f, 0.5f + row * 1.0f}));
        for (int step = 0; step < 5 * 60; ++step) world.step(kDt);
        std::vector<Vec2> relative;
        for (BodyId b : boxes) relative.push_back(world.position(b) - offset);
        return relative;
    };
    const std::vector<Vec2> near = settle({0.0f, 0.0f});
    const std::vector<Vec2> far = settle({1.0e4f, 0.0f});
    float worst = 0.0f;
    for (std::size_t i = 0; i < near.size(); ++i) worst = std::max(worst, distance(near[i], far[i]));
    std::printf("[figure] pyramid of 55 boxes at x = 0 and x = 1e4 m after 5 s: largest position difference %.4f m\n",
                worst);
    // 1 cm: ten times the float spacing at 1e4 m (0.98 mm), the resolution
    // with which the far world can even place a box.
    EXPECT_LT(worst, 0.01f);
}

// A disc rolling on flat ground keeps its height (the hard-cases issue:
// within 0.5 mm over 10 s, sleeping off). Its resting sag is its weight over
// the static contact's stiffness, m·g / (m·(2π·60 Hz)²) = 0.07 mm; anything
// beyond is the solver reading the disc's spin as a gap opening under it,
// or, on a floor with seams (a chain, segments laid end to end, adjacent
// boxes, every 2 m), a vertex normal at a seam taken for the floor's face
// (docs/validation.md, "A rolling disc"): that lifted the disc up to 2 mm at
// 10 m/s and 6 mm at 20 m/s.
enum class DiscFloor { box, chain, segments, boxes };

void buildDiscFloor(World& world, DiscFloor floor) {
    BodyId ground = world.createBody({});
    switch (floor) {
        case DiscFloor::box:
            world.createPolygonShape(ground, {}, makeOffsetBox(500.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
            break;
        case DiscFloor::chain: {
            std::vector<Vec2> points;  // right to left: the chain's solid side is below
            for (int i = 100; i >= -150; --i) points.push_back({2.0f * static_cast<float>(i), 0.0f});
            world.createChain(ground, {.points = points});
            break;
        }
        case DiscFloor::segments:
            for (int i = -150; i < 100; ++i)
                world.createSegmentShape(ground, {}, Segment{{2.0f * i, 0.0f}, {2.0f * i + 2.0f, 0.0f}});
            break;
        case DiscFloor::boxes:
            for (int i = -150; i < 100; ++i)
                world.createPolygonShape(ground, {}, makeOffsetBox(1.0f, 1.0f, {2.0f * i + 1.0f, -1.0f}, 0.0f));
            break;
    }
}

TEST(HardCases, RollingDiscKeepsItsHeight) {
    const char* names[] = {"one box", "a chain", "segments end to end", "adjacent boxes"};
    for (DiscFloor floor : {DiscFloor::box, DiscFloor::chain, DiscFloor::segments, DiscFloor::boxes})
        for (float speed : {1.0f, 5.0f, 10.0f, 20.0f}) {
            World world({.enableSleep = false});
            buildDiscFloor(world, floor);
            const float r = 0.5f;
            BodyId disc = world.createBody({.type = BodyType::dynamic_body,
                                            .position = {-280.0f, r},
                                            .linearVelocity = {speed, 0.0f},
                                            .angularVelocity = -speed / r});
            world.createCircleShape(disc, {}, Circle{{0.0f, 0.0f}, r});
            float lowest = r, highest = r;
            for (int i = 0; i < 10 * 60; ++i) {
                world.step(kDt);
                lowest = std::min(lowest, world.position(disc).y);
                highest = std::max(highest, world.position(disc).y);
            }
            const std::string what = std::to_string(static_cast<int>(speed)) + " m/s on " +
                                     names[static_cast<int>(floor)];
            std::printf("[figure] disc rolling at %s for 10 s: height between %+.3f and %+.3f mm of its radius\n",
                        what.c_str(), 1000.0f * (lowest - r), 1000.0f * (highest - r));
            EXPECT_GT(lowest, r - 0.0005f) << what;
            EXPECT_LT(highest, r + 0.0005f) << what;
        }
}

// Pyramids settle without leaning (the hard-cases issue, item 4: pyramid100's
// top within 5 cm sideways). A mirror-symmetric pyramid has no sideways
// force; any sway is the order in which one Gauss-Seidel sweep meets the
// rows: the rows met first take the larger share of each change in load, the
// same way every step, and the whole pyramid leaned and rocked on its
// compliant contacts. Measured at the defaults, sleeping off, over the first
// 10 s: pyramid100 (base 100, 1 m boxes) swayed 9.2 cm, a base-60 pyramid of
// 0.5 m boxes 4.2 cm. Swept backward every other step (solver.cpp,
// sweepBackward): 0.5 cm and 0.4 cm (at 30 Hz; 1.1 cm for pyramid100 at the
// default 50 Hz). The bound is the 5 cm for boxes of 1 m, in
// proportion for the smaller ones (the same lean angle).
// pyramid100's top also drops at most the 0.3 m (item 4, at the
// defaults): the contacts' sag, load over m_eff·ω², summed over its 100 rows;
// 0.73 m at 30 Hz, 0.30 m at the default 50 Hz (docs/validation.md, "The
// pyramid's compliance"). Only for it: the bar is set for that pyramid.
TEST(HardCases, PyramidsSettleWithoutLeaning) {
    struct Case {
        int base;
        float halfExtent;
    };
    for (const Case c : {Case{100, 0.5f}, Case{60, 0.25f}}) {
        World world({.enableSleep = false});
        test::makeGround(world, 2.0f * c.halfExtent * static_cast<float>(c.base));
        const float size = 2.0f * c.halfExtent;
        const BodyId top = buildPyramid(world, c.base, c.halfExtent).boxes.back();
        const float y0 = world.position(top).y;
        float sway = 0.0f;
        for (int i = 0; i < 10 * 60; ++i) {
            world.step(kDt);
            sway = std::max(sway, std::abs(world.position(top).x));
        }
        const float drop = y0 - world.position(top).y;
        std::printf("[figure] pyramid of base %d, boxes %.1f m, 10 s: top sway %.4f m, drop %.3f m\n", c.base, size,
                    sway, drop);
        EXPECT_TRUE(allFinite(world));
        EXPECT_LT(sway, 0.05f * size) << "base " << c.base;
        if (c.base == 100) {
            EXPECT_LE(drop, 0.3f);
        }
    }
}

// A pyramid with friction 0.3 stands (the hard-cases issue, item 1). Friction
// is what holds it: at friction 0 both pyramids here fall, their boxes ending
// 39 and 265 widths (39 m and 133 m) from where they were built; at 0.05 they
// stand, at most 0.06 of a width aside. The bar of standing: no box moves a
// quarter of its width sideways (each rests on the two below with half its
// width on each, so a quarter keeps it on both; the Tiny Pyramid's bar
// below), and the top drops less than half a box. Measured at 0.3, 20 s,
// sleeping off: base 20 of 1 m boxes at most 1.6 mm aside, the top 11 mm
// lower; base 40 of 0.5 m boxes 18 mm, 50 mm.
TEST(HardCases, PyramidsWithFrictionPointThreeStand) {
    struct Case {
        int base;
        float halfExtent;
    };
    constexpr float kFriction = 0.3f;
    for (const Case c : {Case{20, 0.5f}, Case{40, 0.25f}}) {
        World world({.enableSleep = false});
        const float size = 2.0f * c.halfExtent;
        test::makeGround(world, size * static_cast<float>(c.base), kFriction);
        const auto [boxes, built] = buildPyramid(world, c.base, c.halfExtent, kFriction);
        float aside = 0.0f;
        for (int step = 0; step < 20 * 60; ++step) {
            world.step(kDt);
            for (std::size_t i = 0; i < boxes.size(); ++i)
                aside = std::max(aside, std::abs(world.position(boxes[i]).x - built[i].x));
        }
        const float drop = built.back().y - world.position(boxes.back()).y;
        std::printf("[figure] pyramid of base %d, boxes %.1f m, friction %.1f, 20 s: largest sideways move %.4f m, "
                    "top drop %.4f m\n",
                    c.base, size, double(kFriction), aside, drop);
        EXPECT_TRUE(allFinite(world));
        EXPECT_LT(aside, 0.25f * size) << "base " << c.base;
        EXPECT_LT(drop, 0.5f * size) << "base " << c.base;
    }
}

// Box2D v3's Tiny Pyramid: 465 squares of 5 cm, a base of 30, friction 0.6;
// its bar: the pyramid stands 10 s with no contact deeper than 2.5 mm. At
// rest the deepest contact is the bottom rows' sag under the rows above,
// load over m_eff·ω², the same in millimetres at any scale: 2.0 mm here.
// The settling went deeper: the boxes start without contact impulses, and
// one sweep a substep carried the support up a few rows a step, so the upper
// rows fell a little before they were held and pressed the lower ones past
// their rest (3.5 mm at 0.13 s), and the pyramid rang for about 1.5 s, up to
// 2.8 mm deep. Contacts that begin touching at rest are now swept until
// they carry their load in their first step (settleColdContacts,
// contact_solver.cpp): the bar holds from the first step, and in the
// settled pyramid as before. The pyramid stands: no box ends more than a
// quarter of its width sideways from where it was built.
TEST(HardCases, TinyPyramidStaysWithinTheSamplesDepth) {
    constexpr int kBase = 30;
    constexpr float kHalf = 0.025f;
    World world({.enableSleep = false});
    test::makeGround(world, 2.0f);
    const auto [boxes, built] = buildPyramid(world, kBase, kHalf);
    float transient = 0.0f, settled = 0.0f;
    for (int i = 0; i < 10 * 60; ++i) {
        world.step(kDt);
        float deepest = 0.0f;
        for (const ContactData& c : world.contacts())
            for (int k = 0; k < c.manifold.pointCount; ++k)
                deepest = std::max(deepest, -c.manifold.points[k].separation);
        float& worst = i < 2 * 60 ? transient : settled;  // the first 2 s, then the rest
        worst = std::max(worst, deepest);
    }
    float sideways = 0.0f;
    for (std::size_t k = 0; k < boxes.size(); ++k)
        sideways = std::max(sideways, std::abs(world.position(boxes[k]).x - built[k].x));
    std::printf("[figure] tiny pyramid: deepest %.2f mm in the first 2 s, %.2f mm after; sideways %.2f mm\n",
                1000.0f * transient, 1000.0f * settled, 1000.0f * sideways);
    EXPECT_TRUE(allFinite(world));
    EXPECT_LT(transient, 0.0025f);
    EXPECT_LT(settled, 0.0025f);
    EXPECT_LT(sideways, 0.5f * kHalf);
}

// The same at the scale of the shipped pyramid20 (base 20, unit boxes,
// friction 0.6): built at rest, its top box fell before the rows below it
// carried their loads and dipped 1.9 cm before resting 1.1 cm down, 8 mm past
// its rest. With the contacts that begin touching at rest settled in their
// first step (settleColdContacts) it sinks straight to its rest: its lowest
// point over 5 s is within 1 mm of where it ends (1 mm: a tenth of that
// overshoot, and ten times the top's drift once settled, which is below
// 0.1 mm).
TEST(HardCases, PyramidBuiltAtRestSinksNoFurtherThanItsRest) {
    constexpr int kBase = 20;
    World world({.enableSleep = false});
    test::makeGround(world, 20.0f);
    const BodyId top = buildPyramid(world, kBase, 0.5f).boxes.back();
    const float y0 = world.position(top).y;
    float lowest = y0;
    for (int i = 0; i < 5 * 60; ++i) {
        world.step(kDt);
        lowest = std::min(lowest, world.position(top).y);
    }
    const float rest = world.position(top).y;
    std::printf("[figure] pyramid of base 20 built at rest: top rests %.2f cm down, at most %.2f cm past that\n",
                100.0f * (y0 - rest), 100.0f * (rest - lowest));
    EXPECT_TRUE(allFinite(world));
    EXPECT_LT(rest - lowest, 0.001f);
}

// Box2D v3's Warm Start Energy: three circles of radius 0.5 m stacked on a
// segment, the top one 100 times as dense, destroyed after 2 s. The contacts
// below kept impulses found for its weight and re-applied them as their warm
// start in every substep: the circles left rose at 0.22 m/s (both, the bottom
// one leaving the ground by 9 mm) or 0.94 m/s (the middle one), by the
// direction of that step's sweep. A contact the game destroys now takes its
// load out of the contacts below it (contact.cpp, releaseLostLoads). What is
// left is the soft rows' push out of the compression the load had made, at
// most biasRate·depth for the row of that depth (soft_constraint.hpp: ω/(2ζ
// + hω), against the ground at twice the hertz): about 0.13 m/s here. The
// relax sweep takes that push back, but one sweep in colour order left part
// of it in the circles: they rose at 0.054 and 0.059 m/s, above the scene's
// bar (0.05 m/s, the hard cases' reference for Solver2D's scene). The blocks
// of the contacts that lost load are now relaxed again for three of their
// rows' time constants (solver.cpp, listRelaxedAgainBlocks): 0.016 and
// 0.014 m/s. Both sweep directions (destroyed after 120 and after 121
// steps), sleeping off; the bottom circle never leaves the ground (its
// centre never above 0.5 m, where it would just touch it). The circles are
// dropped 1 cm onto each other, so that the rows are pressed in, and built
// touching: the heavy circle's row joins masses a hundredfold unlike and
// holds no load it was built with (rest_load.cpp), so that run is pressed in
// as the dropped one is (0.016 and 0.014 m/s). (Built touching with a record
// in every row, it was not pressed in at all and rose at 0.0000 m/s, 0.0024
// m/s without the destroyed load taking its part of the records:
// AColumnWhoseLoadIsTakenAwayDoesNotJump holds that part now.)
TEST(HardCases, CirclesLeftUnderADestroyedHeavyOneDoNotJump) {
    for (const auto& [at, gap] :
         {std::pair{120, 0.01f}, std::pair{121, 0.01f}, std::pair{120, 0.0f}, std::pair{121, 0.0f}}) {
        World world({.enableSleep = false});
        BodyId ground = world.createBody({});
        world.createSegmentShape(ground, {.friction = 0.6f}, Segment{{-10, 0}, {10, 0}});
        BodyId c[3];
        for (int i = 0; i < 3; ++i) {
            c[i] = world.createBody(
                {.type = BodyType::dynamic_body, .position = {0, 0.5f + static_cast<float>(i) * (1.0f + gap)}});
            world.createCircleShape(c[i], {.density = i == 2 ? 100.0f : 1.0f, .friction = 0.6f}, Circle{{0, 0}, 0.5f});
        }
        for (int i = 0; i < at; ++i) world.step(1.0f / 60.0f);
        // The compression the heavy circle made: the depth of each lower row.
        float middleDepth = 0.0f, groundDepth = 0.0f;
        for (const ContactData& cd : world.contacts()) {
            if (cd.manifold.pointCount == 0) continue;
            const BodyId a = world.shapeBody(cd.shapeA), b = world.shapeBody(cd.shapeB);
            const float depth = -cd.manifold.points[0].separation;
            if ((a == c[0] && b == c[1]) || (a == c[1] && b == c[0])) middleDepth = depth;
            if (a == ground || b == ground) groundDepth = depth;
        }
        if (gap > 0.0f) {
            ASSERT_GT(middleDepth, 0.01f) << "the heavy circle presses the rows in";
        }
        const WorldSettings& set = world.settings();
        const float h = 1.0f / 60.0f / static_cast<float>(set.substeps);
        auto biasRate = [&](float hertz) {
            const float omega = 2.0f * 3.14159265f * std::min(hertz, 0.25f / h);
            return omega / (2.0f * set.contactDampingRatio + h * omega);
        };
        const float pushOut = std::max(biasRate(set.contactHertz) * middleDepth,
                                       biasRate(2.0f * set.contactHertz) * groundDepth);
        world.destroyBody(c[2]);
        float rise = 0.0f, bottomHighest = 0.0f;
        for (int i = 0; i < 480; ++i) {
            world.step(1.0f / 60.0f);
            for (int k = 0; k < 2; ++k) rise = std::max(rise, world.linearVelocity(c[k]).y);
            bottomHighest = std::max(bottomHighest, world.position(c[0]).y);
        }
        std::printf("[figure] %s, destroyed after %d steps: rise %.4f m/s (push-out bound %.4f), bottom's highest "
                    "%.4f m\n",
                    gap > 0.0f ? "dropped" : "built touching", at, rise, pushOut, bottomHighest);
        EXPECT_LE(rise, pushOut) << "destroyed after " << at << " steps";
        EXPECT_LT(rise, 0.05f) << "destroyed after " << at << " steps (the scene's bar)";
        EXPECT_LE(bottomHighest, 0.5f) << "destroyed after " << at << " steps";
    }
}

// The same for a chain: ten revolute links (capsules 0.8 m long, density 1)
// holding a disc 100 or 1,000 times as dense, destroyed after 3 s. Warm-
// started with the impulses found for the disc's weight, the links were
// thrown up at 4.7 and 36 m/s; a destroyed joint now takes its load out of
// the joints above it (lost_load.hpp), which brought them to 1.9 and 2.3 m/s:
// the joints' stretch under the disc (10 and 12 cm, the soft rows' compliance
// relative to each link's own mass) pulled back in. The chain is now an exact
// tree solved rigid (joint_tree.cpp): the disc stretches it by less than a
// millimetre. Once the disc is gone the links are alike, their joints go back
// to soft rows and the chain settles by those rows' compliance under its own
// weight: joint j carrying the n_j links below it opens n_j·m·g/(m_eff·ω²)
// (m_eff the row's own effective mass along the chain, m/2 between two links
// and m at the anchor; ω the joint stiffness, its hertz capped at a quarter of
// the substep rate). No link can take more kinetic energy than the chain's
// settling releases, at most the chain's weight times the summed opening X:
// ½·m·v² ≤ M·g·X. Here X ≈ 5.6 mm and the bound 0.99 m/s; measured 0.14 m/s.
TEST(HardCases, ChainLeftUnderADestroyedHeavyEndDoesNotJump) {
    for (float ratio : {100.0f, 1000.0f}) {
        World world({.enableSleep = false});
        BodyId previous = world.createBody({});
        std::vector<BodyId> links;
        const int count = 10;
        for (int i = 0; i < count; ++i) {
            const bool end = i == count - 1;
            BodyId b = world.createBody(
                {.type = BodyType::dynamic_body, .position = {0, 19.5f - static_cast<float>(i)}});
            if (end)
                world.createCircleShape(b, {.density = ratio}, Circle{{0, 0}, 0.25f});
            else
                world.createCapsuleShape(b, {.density = 1.0f}, Capsule{{0, -0.4f}, {0, 0.4f}, 0.05f});
            world.createRevoluteJoint({.bodyA = previous,
                                       .bodyB = b,
                                       .localAnchorA = i == 0 ? Vec2{0, 20} : Vec2{0, -0.5f},
                                       .localAnchorB = {0, 0.5f}});
            links.push_back(b);
            previous = b;
        }
        for (int i = 0; i < 180; ++i) world.step(1.0f / 60.0f);
        // Unstretched, the disc's hinge hangs count − 1 metres below the anchor.
        const float hinge = world.transform(links.back()).p.y + 0.5f;
        const float stretch = (20.0f - hinge) - static_cast<float>(count - 1);
        // 1 mm: a ten-thousandth of the 9 m chain, far above float round-off
        // (about 1e-6 of it) and far below the 10 and 12 cm of the soft rows.
        EXPECT_LT(stretch, 0.001f) << "the exact tree holds the disc's weight without stretching";
        const WorldSettings& set = world.settings();
        const float h = 1.0f / 60.0f / static_cast<float>(set.substeps);
        const float omega = 2.0f * 3.14159265f * std::min(set.jointHertz, 0.25f / h);
        const float m = world.mass(links.front()), g = -set.gravity.y;
        const int left = count - 1;
        float settle = 0.0f;  // X
        for (int j = 0; j < left; ++j) {
            const float carried = static_cast<float>(left - j) * m * g;
            const float effectiveMass = j == 0 ? m : 0.5f * m;
            settle += carried / (effectiveMass * omega * omega);
        }
        const float bound = std::sqrt(2.0f * static_cast<float>(left) * g * settle);
        world.destroyBody(links.back());
        links.pop_back();
        float fastest = 0.0f;
        for (int i = 0; i < 180; ++i) {
            world.step(1.0f / 60.0f);
            for (BodyId b : links) fastest = std::max(fastest, length(world.linearVelocity(b)));
        }
        std::printf(
            "[figure] chain under a %.0fx disc, destroyed: stretch %.4f m, fastest link %.3f m/s (bound %.3f)\n",
            static_cast<double>(ratio), stretch, fastest, bound);
        EXPECT_LE(fastest, bound) << ratio;
    }
}

// A load the game takes away takes itself out of the contacts that held the
// body against it, as a destroyed body's does (lost_load.hpp,
// releaseRemovedForces): a force it stops applying, the world's gravity it
// turns off, a body's gravity scale it sets to zero. A column of unit boxes
// (one, five or twenty) resting on the ground, then: its top pressed down
// for half a second with 10 kN, 100 N or 1 kN and let go; or, for twenty
// boxes, gravity turned off (the world's, or each box's scale set to zero).
// Warm-started with the impulses found for the load, the single pressed box
// was thrown 4.7 cm above its rest at 0.82 m/s, a box of the five-box column
// rose at 0.33 m/s after 100 N and 1.18 m/s after 1 kN, and the weightless
// columns at 0.60 m/s. What may be left is the soft rows' push out of the
// compression the load made, each row at most biasRate·depth (as in
// CirclesLeftUnderADestroyedHeavyOneDoNotJump; against the ground at twice
// the hertz); a box is pushed by the rows below it, so no box rises faster
// than their sum over the column. Now 0.0005, 0.023, 0.29 and 0.061 m/s.
// Built touching, the columns' rows hold the loads they were built with
// (rest_load.hpp), and a load taken away takes its part of those too
// (lost_load.cpp): without that the weightless columns rose at 0.023 m/s
// against a push-out bound of 0.0017.
// (The 1 kN column's rows are pressed in so far that their bound, 1.18 m/s,
// does not tell the two apart; the other cases do.)
TEST(HardCases, AColumnWhoseLoadIsTakenAwayDoesNotJump) {
    enum class Take { press, worldGravity, gravityScale };
    struct Case {
        int boxes;
        Take take;
        float force;  // N, on the top box's centre (press)
    };
    for (const Case k : {Case{1, Take::press, 1.0e4f}, Case{5, Take::press, 100.0f}, Case{5, Take::press, 1.0e3f},
                         Case{20, Take::worldGravity, 0.0f}, Case{20, Take::gravityScale, 0.0f}}) {
        World world({.enableSleep = false});
        BodyId ground = world.createBody({});
        world.createPolygonShape(ground, {.friction = 0.6f}, makeBox(10.0f, 0.5f));
        std::vector<BodyId> boxes;
        for (int i = 0; i < k.boxes; ++i) {
            boxes.push_back(
                world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 1.0f + static_cast<float>(i)}}));
            world.createPolygonShape(boxes.back(), {.density = 1.0f, .friction = 0.6f}, makeBox(0.5f, 0.5f));
        }
        for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
        if (k.take == Take::press)
            for (int i = 0; i < 30; ++i) {
                world.applyForceToCenter(boxes.back(), {0.0f, -k.force});
                world.step(1.0f / 60.0f);
            }
        const WorldSettings& set = world.settings();
        const float h = 1.0f / 60.0f / static_cast<float>(set.substeps);
        auto biasRate = [&](float hertz) {
            const float omega = 2.0f * 3.14159265f * std::min(hertz, 0.25f / h);
            return omega / (2.0f * set.contactDampingRatio + h * omega);
        };
        // Each row's push out of its compression: the deepest point of each
        // manifold of the column, the ground's row at twice the hertz.
        float pushOut = 0.0f;
        for (const ContactData& cd : world.contacts()) {
            float depth = 0.0f;
            for (int j = 0; j < cd.manifold.pointCount; ++j) depth = std::max(depth, -cd.manifold.points[j].separation);
            const bool onGround = world.shapeBody(cd.shapeA) == ground || world.shapeBody(cd.shapeB) == ground;
            pushOut += biasRate(onGround ? 2.0f * set.contactHertz : set.contactHertz) * depth;
        }
        if (k.take == Take::worldGravity) world.setGravity({0.0f, 0.0f});
        if (k.take == Take::gravityScale)
            for (BodyId b : boxes) world.setGravityScale(b, 0.0f);
        float fastest = 0.0f;
        for (int i = 0; i < 120; ++i) {
            world.step(1.0f / 60.0f);
            for (BodyId b : boxes) fastest = std::max(fastest, world.linearVelocity(b).y);
        }
        const char* what = k.take == Take::press          ? "let go after a press"
                           : k.take == Take::worldGravity ? "with the world's gravity turned off"
                                                          : "with their gravity scales set to zero";
        std::printf("[figure] %d boxes %s (%.0f N): fastest up %.4f m/s (push-out bound %.4f)\n", k.boxes, what,
                    static_cast<double>(k.force), fastest, pushOut);
        EXPECT_LE(fastest, pushOut) << k.boxes << " boxes " << what;
    }
}

}  // namespace
}  // namespace i2d
