// Bodies created overlapping separate gently (the hard-cases issue, item 2;
// docs/validation.md, "Overlaps"). Defaults, sleeping off, 60 Hz, 20 s. For
// each pile (boxes, circles, capsules; at one point in the air, scattered on
// the ground, deep inside the ground) the test measures:
//  - separated: when the deepest contact first comes within 2 cm (by 2 s),
//    and the deepest contact at 2 s (at most 2 cm);
//  - nothing thrown: how far a body rises above where it was created (for a
//    body created inside the ground: above where it is just out of it; at
//    most 0.5 m), and how much faster than a free fall from the highest point
//    it reached allows, plus the push cap (maxPushSpeed), a body ever moves
//    (never);
//  - no energy: the largest total energy (potential from the ground's top)
//    over its start plus the potential energy that lifting the bodies just
//    out of the ground needs (at most 1.02; for piles in the air that is the
//    start).
// The piles deep in the ground and the 12-body piles in the air meet every
// bound (InTheAirAtOnePoint says how fast hits stay shallow), as do the piles
// of 50 in FiftyAtOnePointPartWithinTwoSeconds; the piles on the ground meet
// the rise and speed bounds, and the others with the exceptions OnTheGround
// gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "unit/world_fixtures.hpp"

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kG = 10.0f;

enum class Kind { box, circle, capsule };

const char* kindName(Kind k) { return k == Kind::box ? "boxes" : k == Kind::circle ? "circles" : "capsules"; }

/// A unit box, circle or capsule (1 m across; the capsule 1.5 m long, 0.5 m
/// thick), or one `size` times that.
BodyId makeBody(World& world, Kind kind, Vec2 p, float angle, float size = 1.0f) {
    BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = p, .angle = angle});
    const ShapeDef def{.density = 1.0f, .friction = 0.6f};
    const float half = 0.5f * size;
    if (kind == Kind::box) world.createPolygonShape(b, def, makeBox(half, half));
    if (kind == Kind::circle) world.createCircleShape(b, def, Circle{{0.0f, 0.0f}, half});
    if (kind == Kind::capsule) world.createCapsuleShape(b, def, Capsule{{-half, 0.0f}, {half, 0.0f}, 0.25f * size});
    return b;
}

struct PileFigures {
    float deepestAt2s = 0.0f;   ///< m
    float separatedAt = -1.0f;  ///< s: first time the deepest contact is within 2 cm, −1 if never in 20 s
    float rise = 0.0f;          ///< largest rise of a body above where it was created, out of the ground (m)
    float speedExcess = 0.0f;   ///< largest speed beyond free fall from the highest point reached + cap (m/s)
    float energyRatio = 0.0f;   ///< largest E / (E start + lift out of the ground)
};

float deepest(const World& world) {
    float d = 0.0f;
    for (const ContactData& c : world.contacts())
        for (int j = 0; j < c.manifold.pointCount; ++j) d = std::min(d, c.manifold.points[j].separation);
    return -d;
}

/// Steps the world 20 s and measures the figures over `bodies`. A body's rise
/// is measured from where it was created, raised by how deep its lowest point
/// was below the ground's top: a body created inside the ground has to rise
/// that far to get out (the issue asks the same of it). The energy
/// is compared with the start plus the potential energy that lifting each
/// body just out of the ground needs (m·g times the depth of its lowest
/// point below the ground's top, where it was created): no push can separate
/// a body from the ground without it, and for a pile created above the ground
/// it is zero, so there the bound is the issue's "never above 1.02 times the
/// initial". (A body created inside the ground starts with a negative
/// potential energy, to which no ratio applies.)
PileFigures measure(World& world, const std::vector<BodyId>& bodies) {
    const float cap = world.settings().maxPushSpeed;
    auto energy = [&] {
        double e = 0.0;
        for (BodyId b : bodies) {
            const float m = world.mass(b), w = world.angularVelocity(b);
            e += 0.5 * m * lengthSquared(world.linearVelocity(b)) + 0.5 * world.rotationalInertia(b) * w * w +
                 m * kG * world.position(b).y;
        }
        return e;
    };
    std::vector<float> created, highest, base;
    double lift = 0.0;
    for (BodyId b : bodies) {
        created.push_back(world.position(b).y);
        float lowest = 0.0f;
        for (ShapeId sh : world.bodyShapes(b)) lowest = std::min(lowest, world.shapeAABB(sh).lower.y);
        base.push_back(created.back() - lowest);
        lift += world.mass(b) * kG * -lowest;
    }
    highest = created;
    const double e0 = energy();
    double eMax = e0;
    PileFigures f;
    for (int step = 1; step <= 20 * 60; ++step) {
        world.step(kDt);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            const float y = world.position(bodies[i]).y;
            highest[i] = std::max(highest[i], y);
            const float allowed = std::sqrt(2.0f * kG * (highest[i] - y)) + cap;
            f.speedExcess = std::max(f.speedExcess, length(world.linearVelocity(bodies[i])) - allowed);
        }
        eMax = std::max(eMax, energy());
        if (step == 2 * 60) f.deepestAt2s = deepest(world);
        if (f.separatedAt < 0.0f && deepest(world) <= 0.02f) f.separatedAt = step * kDt;
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) f.rise = std::max(f.rise, highest[i] - base[i]);
    f.energyRatio = static_cast<float>(eMax / (e0 + lift));
    return f;
}

void print(const PileFigures& f, const std::string& what) {
    std::printf("[figure] %s: within 2 cm after %.2f s, deepest at 2 s %.4f m, rise above created %.3f m, speed "
                "beyond free fall + cap %+.2f m/s, energy %.4f x start + lift out of the ground\n",
                what.c_str(), f.separatedAt, f.deepestAt2s, f.rise, f.speedExcess, f.energyRatio);
}

/// The bounds on what a pile throws: rise, speed and energy.
void expectNothingThrown(const PileFigures& f, const std::string& what) {
    print(f, what);
    EXPECT_LE(f.rise, 0.5f) << what;
    EXPECT_LE(f.speedExcess, 0.0f) << what;
    EXPECT_LE(f.energyRatio, 1.02f) << what;
}

/// The bounds: nothing thrown, and the deepest contact at 2 s within 2 cm.
void expectGentle(const PileFigures& f, const std::string& what) {
    expectNothingThrown(f, what);
    EXPECT_LE(f.deepestAt2s, 0.02f) << what;
}

/// The time: the deepest contact within 2 cm by 2 s (and at all).
void expectPartedInTime(const PileFigures& f, const std::string& what) {
    EXPECT_GE(f.separatedAt, 0.0f) << what;
    EXPECT_LE(f.separatedAt, 2.0f) << what;
}

// `count` square boxes of half-width `half` resting on a ground of friction
// `friction` in `world`, each half inside the next (centres `half` apart),
// the first centred at `firstX`.
std::vector<BodyId> rowHalfOverlapping(World& world, int count, float half, float firstX, float friction) {
    test::makeGround(world, 200.0f, friction);
    std::vector<BodyId> boxes;
    for (int i = 0; i < count; ++i)
        boxes.push_back(test::makeBox(world, {half * static_cast<float>(i) + firstX, half}, half, 1.0f, friction));
    return boxes;
}

// `count` bodies created within 1 cm of one point `height` m above the ground.
PileFigures airPile(Kind kind, int count, float height, unsigned seed) {
    World world({.enableSleep = false});
    test::makeGround(world, 200.0f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.01f, 0.01f);
    std::vector<BodyId> bodies;
    for (int i = 0; i < count; ++i) bodies.push_back(makeBody(world, kind, {jitter(rng), height + jitter(rng)}, 0.0f));
    return measure(world, bodies);
}

// `count` bodies at random places and angles on the ground, their centres
// within a rectangle `width` by `height` whose bottom is 0.3 m above the
// ground (3 m by 1 m for 8 bodies, 5 m by 2 m for 20): they overlap each
// other, and the lowest overlap the ground. `size` scales the bodies and the
// rectangle alike.
PileFigures groundPile(Kind kind, int count, unsigned seed, float size = 1.0f) {
    World world({.enableSleep = false});
    test::makeGround(world, 200.0f);
    std::mt19937 rng(seed);
    const float width = (count > 8 ? 5.0f : 3.0f) * size, height = (count > 8 ? 2.0f : 1.0f) * size;
    std::uniform_real_distribution<float> x(-0.5f * width, 0.5f * width), y(0.3f * size, 0.3f * size + height),
        angle(-3.14159f, 3.14159f);
    std::vector<BodyId> bodies;
    for (int i = 0; i < count; ++i) {
        const float px = x(rng), py = y(rng);
        bodies.push_back(makeBody(world, kind, {px, py}, angle(rng), size));
    }
    return measure(world, bodies);
}

// Nothing is thrown and no energy is made; the overlaps the pile was created
// with are gone before 2 s, and the deepest contact at 2 s is within the
// issue's 2 cm. Bodies sliding off the heap hit others at 5-7 m/s, which a
// step carries 8-12 cm: with a fixed 2 cm speculative distance such hits were
// 2 to 7 cm deep for a step or two. A contact's margin now follows how far its
// bodies can close in the step (contact.cpp), so the hit is met at the
// surfaces, as far as the velocities at the step's start show it; what they
// do not show (a body knocked within the step by a third, a turn bringing
// another corner in) stays within the soft contacts' usual sag. No tolerance
// is added to the bound: over 36 layouts not used to develop this
// (12 boxes, circles and capsules at one point 5 and 10 m up, seeds 1009,
// 2003, 3001, 4007, 5003, 6007) the deepest at 2 s was at most 1.3 cm; here
// 0.6 cm.
TEST(OverlapPiles, InTheAirAtOnePoint) {
    for (Kind kind : {Kind::box, Kind::circle, Kind::capsule})
        for (unsigned seed : {11u, 23u}) {
            const std::string what = std::string("12 ") + kindName(kind) + " at one point 4 m up, seed " +
                                     std::to_string(seed);
            const PileFigures f = airPile(kind, 12, 4.0f, seed);
            print(f, what);
            expectPartedInTime(f, what);
            EXPECT_LE(f.deepestAt2s, 0.02f) << what;
            EXPECT_LE(f.rise, 0.5f) << what;
            EXPECT_LE(f.speedExcess, 0.0f) << what;
            EXPECT_LE(f.energyRatio, 1.02f) << what;
        }
}

// Piles created on the ground: 8 bodies within 3 m by 1 m and 20 within 5 m
// by 2 m, seeds 31, 47, 59, 83, 101 and 113 of each kind (36 layouts; the
// seeds the fix below was developed on, docs/validation.md gives six more it
// was not). Pushed along their contact normals such piles were stacked into
// leaning columns that toppled; deep rows between two moving bodies whose
// lower one is supported are pushed sideways instead when lifting would raise
// the upper one above the highest it has been (deep_overlap.cpp). That
// sideways push was refused when the move was longer than the narrower body's
// width, so a body created almost wholly inside another was lifted out of it
// (rise up to 0.83 m; 8 of the 36 layouts beyond 0.5 m), and a supported body
// lifted by the push while its velocity went on falling gained m·g·u·h per
// substep (energy up to 1.067 times the start plus the lift out of the
// ground; 9 beyond 1.02). Now each body's share of a sideways move is held to
// its own width, and a supported body's lift is paid from its fall. The
// issue's bounds, no tolerance added. One layout of circles (8, seed 31)
// gained 1.02002 as they part and was held at 1.025 (1.039 at 30 Hz with
// ζ 10, the defaults before; 1.059 before the soft rows' lift was paid from
// the fall: docs/validation.md, "Overlaps that separate gently"): the relax
// sweep passed the soft rows' push out of the ground on to the circles
// resting on the pushed ones, and a step with a deep overlap now relaxes
// its deep rows until they settle (contact_solver.cpp, relaxDeepContacts):
// 1.0101. The last overlaps of one 20-box layout (seed 83) took until 2.15 s
// to come within 2 cm at 30 Hz; at the default 50 Hz, ζ 25, every pile is
// within 2 cm by 1.7 s.
TEST(OverlapPiles, OnTheGround) {
    for (Kind kind : {Kind::box, Kind::circle, Kind::capsule})
        for (int count : {8, 20})
            for (unsigned seed : {31u, 47u, 59u, 83u, 101u, 113u}) {
                const std::string what = std::to_string(count) + " " + kindName(kind) +
                                         " scattered on the ground, seed " + std::to_string(seed);
                const PileFigures f = groundPile(kind, count, seed);
                print(f, what);
                expectPartedInTime(f, what);
                EXPECT_LE(f.deepestAt2s, 0.02f) << what;
                EXPECT_LE(f.speedExcess, 0.0f) << what;
                EXPECT_LE(f.rise, 0.5f) << what;
                EXPECT_LE(f.energyRatio, 1.02f) << what;
            }
}

// Twelve capsules created at one point 5 or 6 m up part on the way down but
// land as a lump still overlapping by 2 to 18 cm. The impact stage struck
// those overlaps as impacts, one pair after another along their alternating
// normals, and passed the landing up through the lump: the top capsules left
// it at 5 to 7 m/s up and 9 m/s sideways (no energy was made: the lump's
// bottom stopped dead). A contact that has overlapped since its first touch
// is now no impact (Contact::overlapFromStart, impact_stage.hpp); the
// solver's rows stop its closing and push it apart.
// These are the three worst of 100 such piles (seeds 1001 to 1199, odd; 12
// capsules from 4 m plus the seed's remainder by 3) before the change: 7.1,
// 6.8 and 5.4 m/s beyond a free fall plus the cap, rising 1.6, 2.8 and
// 0.37 m; 14 of the 100 broke the speed bound then, none after (one still
// rises 0.59 m; docs/validation.md, "Overlaps that separate gently"). The
// issue's bounds, no tolerance added.
TEST(OverlapPiles, ALandingLumpIsNotThrownThroughItsOverlaps) {
    for (const auto& [seed, height] : {std::pair{1059u, 6.0f}, std::pair{1121u, 5.0f}, std::pair{1181u, 5.0f}}) {
        const std::string what = "12 capsules at one point " + std::to_string(static_cast<int>(height)) +
                                 " m up, seed " + std::to_string(seed);
        const PileFigures f = airPile(Kind::capsule, 12, height, seed);
        print(f, what);
        EXPECT_LE(f.rise, 0.5f) << what;
        EXPECT_LE(f.speedExcess, 0.0f) << what;
        EXPECT_LE(f.energyRatio, 1.02f) << what;
    }
}

// Of 50 capsules created at one point 5 m up (seed 2003) the pile landed as
// one lump and bounced back up almost elastically: one capsule rose 1.63 m
// above where it was created and moved 2.0 m/s faster than a fall from its
// highest point allows. The warm start of the rigid deep rows between the
// pile's bodies re-applied, every substep, the impulses that had stopped the
// lump (150 N·s in about 300 rows, a hundred times the pile's weight), which
// one Gauss-Seidel sweep could not take back. A deep point being pushed apart
// is now warm-started with the smaller of its last two substeps' impulses,
// which carries a load but not an impact (contact_solver.cpp,
// carryDeepLoads): a rise of 0.24 m and no speed beyond a free fall, here
// and in the other five layouts of 50 capsules from 5 m (seeds 1009, 3001,
// 4007, 5003, 6007, which with this one were used to choose among the rules
// tried; docs/validation.md, "Overlaps that separate gently"). The issue's
// bounds, no tolerance added.
TEST(OverlapPiles, FiftyCapsulesAtOnePointAreNotThrown) {
    expectNothingThrown(airPile(Kind::capsule, 50, 5.0f, 2003u), "50 capsules at one point 5 m up, seed 2003");
}

// 50 boxes created at one point 3 m up (seed 20012): once the pile rested on
// the ground, a box whose velocity stayed at zero was pushed up on
// pseudo-velocities from 2.7 to 3.7 m, 0.45 m above the highest it had been,
// and rose 0.66 m above where it was created. No body is now lifted above
// the highest it has been, unless a row pushes it out of something that
// cannot move (deep_overlap.cpp): 0.10 m. The bounds for rise, speed
// and energy, no tolerance added. (Not its 2 cm at 2 s: 10 cm;
// docs/validation.md, "Variants beyond the layouts".)
TEST(OverlapPiles, ABoxOfAPileAtRestIsNotPushedAboveItsHighest) {
    expectNothingThrown(airPile(Kind::box, 50, 3.0f, 20012u), "50 boxes at one point 3 m up, seed 20012");
}

// 50 bodies created at one point 5 m up part within 2 s. With four push
// sweeps per substep the pile's outer bodies, pushed through it at the cap,
// moved out together while its core stayed about a metre deep for the first
// second: 50 boxes (seed 3001) were still 0.17 m deep at 2 s, 50 capsules
// (seed 1009) 3.6 cm. With sixteen (deep_overlap.cpp, kPushSweeps) they were
// 0.6 and 0.8 cm deep, and are 1.2 and 0.9 cm since bodies resting on
// nothing may be pushed sideways at three times the cap (docs/validation.md
// gives 684 layouts in all). The bounds, no tolerance added.
TEST(OverlapPiles, FiftyAtOnePointPartWithinTwoSeconds) {
    for (auto [kind, seed] : {std::pair{Kind::box, 3001u}, std::pair{Kind::capsule, 1009u}}) {
        const PileFigures f = airPile(kind, 50, 5.0f, seed);
        expectGentle(f, std::string("50 ") + kindName(kind) + " at one point 5 m up, seed " + std::to_string(seed));
        EXPECT_GE(f.separatedAt, 0.0f);
        EXPECT_LE(f.separatedAt, 2.0f);
    }
}

// 20 bodies created at one point on the ground (centres 0.5 m up, within
// 1 cm) must spread along it in one layer about 20 m long: its ends 10 m
// out, 1.1 s at the sideways push limit of 3c (0.7 s at today's 5c,
// kSidewaysPushFactor). Seeds 1 to 3 of each kind,
// not used in developing what follows. While a deep overlap stopped being
// deep at the deep depth (5 cm), the soft rows took over the rest of each
// overlap and pushed it out through the velocities, and the pushes along
// the pile's chains stayed in them where the relax pass could not take them
// back: these piles rose to 1.07 to 1.12 times their energy (boxes and
// circles; the circles rolled apart with 4 % of it), and at the supported
// bodies' old limit of 2c their edges took 1.6 s to get out, the piles
// 2.1 to 2.7 s to part. A deep overlap now stays deep to a quarter of that
// depth (kDeepExitFraction, engine/src/contact.hpp): within 2 cm after 1.73
// to 1.97 s, energy at most 1.015 times the start; since a manifold's two
// points are pushed together and the push may not drive a body into the
// ground (deep_overlap.cpp), 1.70 to 1.93 s and 1.013. The bounds, no
// tolerance added.
TEST(OverlapPiles, TwentyAtOnePointOnTheGroundPartWithinTwoSeconds) {
    for (Kind kind : {Kind::box, Kind::circle, Kind::capsule})
        for (unsigned seed : {1u, 2u, 3u}) {
            const PileFigures f = airPile(kind, 20, 0.5f, seed);
            const std::string what = std::string("20 ") + kindName(kind) + " at one point on the ground, seed " +
                                     std::to_string(seed);
            expectGentle(f, what);
            expectPartedInTime(f, what);
        }
}

// 20 capsules created at one point on the ground, seeds 1 to 40. They
// spread sideways into a row about 22 m long within 1.4 s; the last
// centimetres of their overlaps were then pushed at the soft rows' rate,
// heavily damped for stacking, and 3 of these 40 piles were still deeper
// than 2 cm at 2 s (parted at 2.02 to 2.08 s). A contact created
// overlapping is pushed to the same rest twice as fast
// (kStartOverlapPushFactor, engine/src/deep_overlap.cpp): within 2 cm by 2 s.
// The bounds, no tolerance added. Seeds 30001 to 30040 still have
// two such piles parting at 2.05 and 2.07 s (docs/validation.md, "A created
// overlap's last centimetres").
TEST(OverlapPiles, TwentyCapsulesAtOnePointOnTheGroundPartWithinTwoSeconds) {
    for (unsigned seed = 1; seed <= 40; ++seed) {
        const PileFigures f = airPile(Kind::capsule, 20, 0.5f, seed);
        const std::string what = "20 capsules at one point on the ground, seed " + std::to_string(seed);
        expectNothingThrown(f, what);
        EXPECT_LE(f.deepestAt2s, 0.02f) << what;
        expectPartedInTime(f, what);
    }
}

// 50 capsules (1.5 m long, 0.5 m thick) created at one point on the ground
// (centres 0.5 m up, within 1 cm), seeds 1 to 20, spread along the ground,
// pushed sideways at up to the sideways limit. At 10c they parted after 1.83
// to 2.28 s, 10 of the 20 still deeper than 2 cm at 2 s; at 15c
// (kSidewaysPushFactor, deep_overlap.hpp) after 1.43 to 2.07 s, seed 8 the
// last (2.5 cm deep at 2 s). So the rise, speed and energy bounds
// hold for every pile, no tolerance added; its 2 s for all but one, a
// regression bound (docs/validation.md, "A wider sideways limit, once
// more").
TEST(OverlapPiles, FiftyCapsulesAtOnePointOnTheGroundPartWithinTwoSecondsButOne) {
    int late = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const PileFigures f = airPile(Kind::capsule, 50, 0.5f, seed);
        const std::string what = "50 capsules at one point on the ground, seed " + std::to_string(seed);
        expectNothingThrown(f, what);
        EXPECT_GE(f.separatedAt, 0.0f) << what;
        late += f.separatedAt > 2.0f || f.deepestAt2s > 0.02f;
    }
    EXPECT_LE(late, 1);
}

// 50 boxes created at one point 1 m up land at once as a lump and must spread
// along the ground in one layer 50 m long (the rise bound allows no
// second): its ends 25 m out, which at the sideways push limit of 3c took
// 25 m / (3 · 3 m/s) = 2.8 s, so the 2 s was out of reach
// (docs/validation.md, "Variants beyond the layouts"); at today's 5c
// it takes 1.7 s before any lag of the sweeps ("A wider sideways limit"). The edges do
// move out at the limit, but the pile parts later: the last overlaps are
// boxes left above the first layer, which the push may not lift above the
// highest they have been, and which wait for the layer below to open a gap.
// Before a deep overlap stayed deep to a quarter of its deep depth
// (kDeepExitFraction, engine/src/contact.hpp) the soft rows lifted such
// boxes instead: over seeds 1 to 20, 14 layouts had a box more than 0.5 m
// above where it was created (up to 0.70 m), apart after 5.6 to 6.7 s; now
// none (at most 0.14 m), apart after 5.8 to 6.9 s (with the pushes of the
// later change above, at most 0.29 m, 5.5 to 6.35 s; 5.67 to 6.38 s before
// the sideways limit became 5c, 5.25 to 5.83 s since). So the rise,
// speed and energy bounds hold, no tolerance added; the time bound is a
// regression bound, not a physical one: 6 s, the slowest of those 20
// layouts (5.83 s) rounded up (7 s, from 6.92 s, before; at 3c seeds 1, 3
// and 5 part after 6.15, 6.38 and 6.08 s; since the push's sweeps converge,
// kMaxPushSweeps, after 3.97, 4.08 and 3.80 s). Since a pushed body shoves
// the bodies beside it instead of driving into them (docs/validation.md,
// "Shoves between moving bodies"), seeds 1 to 20 part after 2.85 to 3.83 s
// (seeds 1, 3 and 5: 3.17, 3.83 and 3.23 s): the bound was 4 s, 3.83 s
// rounded up. With the sideways limit at 10c, the last of a created overlap
// relaxed again and level deep rows never stalled (docs/validation.md, "The
// sideways limit again"), 2.13 to 3.18 s (seeds 1, 3 and 5: 2.77, 2.63 and
// 2.82 s): 3.5 s, 3.18 s rounded up to the half second. (Before the push
// started each step from half of where the last one ended, deep_overlap.cpp,
// kPushCarry, a box wedged between two others was pushed one way in one
// step and back in the next, and these layouts parted after 9.05 to 9.33 s.)
TEST(OverlapPiles, FiftyBoxesAtOnePointOnTheGroundSpreadAtThePushLimit) {
    for (unsigned seed : {1u, 3u, 5u}) {
        const PileFigures f = airPile(Kind::box, 50, 1.0f, seed);
        const std::string what = "50 boxes at one point 1 m up, seed " + std::to_string(seed);
        expectNothingThrown(f, what);
        EXPECT_GE(f.separatedAt, 0.0f) << what;
        EXPECT_LE(f.separatedAt, 3.5f) << what;
    }
}

// The example on the ground: 50 unit boxes created at one point,
// their centres 0.5 m up (resting on it), seeds 1 to 20. They spread along the
// ground at the push's sideways limit (deep_overlap.hpp, kSidewaysPushFactor)
// into one layer 50 m long, and may not rise, be thrown or gain energy while
// they do: the bounds, no tolerance added. At 3c, seeds 1, 4 and 5
// rose to 1.038, 1.027 and 1.033 times their energy while their layer was
// still closing (10 of seeds 1 to 20 beyond 1.02); at 5c to at most 1.009
// here, 1.018 over seeds 1 to 20 (docs/validation.md, "A wider sideways
// limit"). With the push's sweeps run on until they converge but its guards
// holding one way, 19 of seeds 1 to 20 rose beyond 1.02 (up to 1.052), boxes
// tilted onto corners; with the two-point guards held both ways, at most
// 1.0045 here (docs/validation.md, "A push that converges"). The layer's ends
// are 24.5 m out, 1.6 s at 5c before any lag of the sweeps: they parted after
// 2.6 to 2.9 s, 2.0 to 2.4 s once a pushed body shoved the bodies beside it
// (docs/validation.md, "Shoves between moving bodies"; seeds 1 to 4 here
// 2.03 to 2.42 s, 2.2 to 3.3 cm deep at 2 s). At 10c (0.8 s), with the last
// of a created overlap relaxed again and level deep rows never stalled,
// seeds 1 to 20 part after 1.22 to 1.47 s, at most 1.2 cm deep at 2 s
// (docs/validation.md, "The sideways limit again"; with level deep rows
// stalling as others do, seeds 7 and 15 were still 2.3 and 2.5 cm deep at
// 2 s). The 2 s, no tolerance added.
TEST(OverlapPiles, FiftyBoxesAtOnePointOnTheGroundPartWithinTwoSecondsGainingNoEnergy) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const PileFigures f = airPile(Kind::box, 50, 0.5f, seed);
        const std::string what = "50 boxes at one point on the ground, seed " + std::to_string(seed);
        expectGentle(f, what);
        expectPartedInTime(f, what);
    }
}

// The deep push's limits per body (deep_overlap.cpp): across gravity at most
// ten times maxPushSpeed c (kSidewaysPushFactor, unit/test_deep_push.cpp), so
// in a step no body of a pile in the air moves sideways more than 10·c·Δt (the
// pseudo-velocity is the only sideways motion here: the pile is at rest and
// the push leaves no velocity), and the pushes through a pile of 20 boxes
// created at one point add up beyond 2·c; upwards at most c, less the fall,
// so no body rises more than c·Δt in a step.
constexpr float kSidewaysFactor = 10.0f;  // kSidewaysPushFactor (engine/src/deep_overlap.hpp, not public)
TEST(OverlapPiles, APushAcrossGravityInTheAirGoesBeyondTwiceTheCapUpToTheSidewaysLimit) {
    for (unsigned seed : {1u, 2u, 3u}) {
        World world({.enableSleep = false});
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> jitter(-0.01f, 0.01f);
        std::vector<BodyId> bodies;
        for (int i = 0; i < 20; ++i)
            bodies.push_back(makeBody(world, Kind::box, {jitter(rng), 10.0f + jitter(rng)}, 0.0f));
        const float cap = world.settings().maxPushSpeed;
        // Float rounding of a sum of four substeps' moves, far below the
        // c·Δt = 5 cm that separates the bounds.
        const float rounding = 1e-5f;
        float reached = 0.0f;
        for (int step = 0; step < 3; ++step) {
            std::vector<Vec2> before;
            for (BodyId b : bodies) before.push_back(world.position(b));
            world.step(kDt);
            float sideways = 0.0f, rise = -1.0f;
            for (std::size_t i = 0; i < bodies.size(); ++i) {
                const Vec2 p = world.position(bodies[i]);
                sideways = std::max(sideways, std::abs(p.x - before[i].x));
                rise = std::max(rise, p.y - before[i].y);
                EXPECT_EQ(world.linearVelocity(bodies[i]).x, 0.0f) << "seed " << seed << " step " << step;
            }
            reached = std::max(reached, sideways);
            EXPECT_LE(sideways, kSidewaysFactor * cap * kDt + rounding) << "seed " << seed << " step " << step;
            EXPECT_LE(rise, cap * kDt + rounding) << "seed " << seed << " step " << step;
        }
        EXPECT_GT(reached, 2.0f * cap * kDt) << "seed " << seed;
    }
}

// A body created 90 % inside the ground (boxes and circles 0.9 m deep,
// capsules lying 0.45 m deep) is pushed out, not launched.
TEST(OverlapPiles, DeepInsideTheGround) {
    for (Kind kind : {Kind::box, Kind::circle, Kind::capsule}) {
        World world({.enableSleep = false});
        test::makeGround(world);
        const float y = kind == Kind::capsule ? -0.2f : -0.4f;
        std::vector<BodyId> bodies{makeBody(world, kind, {0.0f, y}, 0.0f)};
        expectGentle(measure(world, bodies), std::string("one of the ") + kindName(kind) + " deep in the ground");
    }
}

// Piles of small bodies created on the ground: the piles of OnTheGround at a
// tenth and at a fifth of the size (boxes and circles 0.1 and 0.2 m across,
// capsules 0.15 and 0.3 m long; 8 within 0.3 m by 0.1 m or 0.6 m by 0.2 m,
// 20 within 0.5 m by 0.2 m or 1 m by 0.4 m), seeds 1 to 5. Their overlaps
// were all shallower than the 5 cm from which an overlap is pushed apart on
// pseudo-velocities (sideways where a lift would add height), so the soft
// rows lifted them: 15 of the 20 layouts of 0.1 m boxes and capsules broke
// the energy bound (up to 1.29 times the start, which is small). A contact
// then counted as deep from a fifth of its thinner shape's thickness when
// that is less than 5 cm, and those 20 met the bounds, but of these 60
// layouts the 8 circles of seed 3 still gained 6.3 % (0.1 m) and 11 % (0.2
// m), and of 600 other piles of 0.2 m bodies 29 broke the bound. Deep from a tenth
// (contact.hpp, kDeepFraction), all 60 meet the bounds, no tolerance
// added.
TEST(OverlapPiles, SmallBodiesOnTheGround) {
    for (float size : {0.1f, 0.2f})
        for (Kind kind : {Kind::box, Kind::circle, Kind::capsule})
            for (int count : {8, 20})
                for (unsigned seed = 1; seed <= 5; ++seed)
                    expectGentle(groundPile(kind, count, seed, size), std::to_string(count) + " " + kindName(kind) +
                                                                          " of " + (size < 0.15f ? "0.1" : "0.2") +
                                                                          " m scattered on the ground, seed " +
                                                                          std::to_string(seed));
}

// A small body created inside a big one on the ground: a box, a circle, a
// capsule or a hexagon about 1 m across, at a random place and angle inside a
// 2 m box resting on the ground (9 layouts of each). The sideways push was
// refused when either body's share of the move, split by their masses, was
// longer than its own width (the small body, with four fifths of the move,
// would have slid 1.2 m), so the pair was pushed along its normal and the big
// box ended on the small one: 16 of these 36 broke a bound (rises up to
// 1.0 m, energy up to 1.84 times the start). The small body now moves its
// own width and the big one the rest (deep_overlap.cpp,
// prepareDeepOverlaps): rise at most 3.5 cm, energy at most 1.011. The
// issue's bounds, no tolerance added.
TEST(OverlapPiles, ASmallBodyInsideABigOneSlidesOut) {
    for (int kind = 0; kind < 4; ++kind)
        for (unsigned seed = 1; seed <= 9; ++seed) {
            World world({.enableSleep = false});
            test::makeGround(world, 200.0f);
            std::mt19937 rng(seed);
            std::uniform_real_distribution<float> inside(-0.5f, 0.5f), angle(-3.14159f, 3.14159f);
            const ShapeDef def{.density = 1.0f, .friction = 0.6f};
            BodyId big = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 1.0f}});
            world.createPolygonShape(big, def, makeBox(1.0f, 1.0f));
            const Vec2 p{inside(rng), 1.0f + inside(rng)};
            BodyId small = world.createBody({.type = BodyType::dynamic_body, .position = p, .angle = angle(rng)});
            const char* name = "box";
            if (kind == 0) world.createPolygonShape(small, def, makeBox(0.5f, 0.5f));
            if (kind == 1) {
                name = "circle";
                world.createCircleShape(small, def, Circle{{0.0f, 0.0f}, 0.5f});
            }
            if (kind == 2) {
                name = "capsule";
                world.createCapsuleShape(small, def, Capsule{{-0.25f, 0.0f}, {0.25f, 0.0f}, 0.25f});
            }
            if (kind == 3) {
                name = "hexagon";
                Vec2 corners[6];
                for (int i = 0; i < 6; ++i)
                    corners[i] = {0.5f * std::cos(1.0471976f * i), 0.5f * std::sin(1.0471976f * i)};
                world.createPolygonShape(small, def, *makePolygon(computeHull(corners)));
            }
            const std::vector<BodyId> bodies{big, small};
            expectGentle(measure(world, bodies),
                         std::string("a ") + name + " inside a 2 m box on the ground, seed " + std::to_string(seed));
        }
}

// A box that gravity does not pull (gravity scale 0) created 0.3 m deep in
// the top of a box resting on the ground, 5 cm off its centre. Sliding it
// aside, as a falling body is to keep from adding height (deep_overlap.cpp),
// would move it 0.95 m (its width less the offset) where lifting it, at no
// cost in energy, moves it 0.3 m: it is pushed out along the normal. The
// world's gravity, which it does not feel, slid it 0.55 m aside in the first
// second. The bounds: apart (B a box's height above A, less the slop), and
// moved sideways less than the depth, which the long way could not do.
TEST(OverlapPiles, AWeightlessBodyIsPushedOutTheShorterWay) {
    World world({.enableSleep = false});
    test::makeGround(world, 200.0f);
    const ShapeDef def{.density = 1.0f, .friction = 0.6f};
    BodyId below = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 0.5f}});
    world.createPolygonShape(below, def, makeBox(0.5f, 0.5f));
    const Vec2 created{0.05f, 1.2f};
    BodyId weightless = world.createBody({.type = BodyType::dynamic_body, .position = created, .gravityScale = 0.0f});
    world.createPolygonShape(weightless, def, makeBox(0.5f, 0.5f));
    for (int step = 0; step < 60; ++step) world.step(kDt);
    const Vec2 p = world.position(weightless);
    std::printf("[figure] weightless box after 1 s: %.3f m sideways, %.3f m above the box below\n",
                std::abs(p.x - created.x), p.y - world.position(below).y);
    EXPECT_GE(p.y - world.position(below).y, 1.0f - world.settings().penetrationSlop);
    EXPECT_LT(std::abs(p.x - created.x), 0.3f);
}

// Two L-shaped bodies (two boxes each, 1 m across) created overlapping on
// the ground, side by side at the same angle: each pair of their shapes is a
// contact with its own normal, and the pushes of two of them oppose. A push
// row split unlike the masses (ASmallBodyInsideABigOneSlidesOut's rule) moves
// the pair's centre of mass; held by the pair's other rows it drove both L's
// along the ground at twice the cap, 50 m in 20 s, still 0.37 m deep at 2 s.
// Now they part within the bounds, and neither ends further from
// where it was created than the 1 m an L is wide: no clearing of the two
// needs more relative motion than that, and the push shares it between them.
TEST(OverlapPiles, TwoLShapedBodiesPartWithoutDriving) {
    const float offsets[][2] = {{0.05f, 0.0f}, {0.1f, 0.0f}, {0.2f, 0.0f}, {0.0f, 0.1f}};  // x (m), angle (rad)
    for (const auto& [dx, angle] : offsets) {
        World world({.enableSleep = false});
        test::makeGround(world, 200.0f);
        const ShapeDef def{.density = 1.0f, .friction = 0.6f};
        std::vector<BodyId> bodies;
        for (int i = 0; i < 2; ++i) {
            const BodyId b = world.createBody({.type = BodyType::dynamic_body,
                                               .position = {static_cast<float>(i) * dx, 0.6f},
                                               .angle = static_cast<float>(i) * angle});
            world.createPolygonShape(b, def, makeOffsetBox(0.5f, 0.125f, {0.0f, -0.375f}, 0.0f));
            world.createPolygonShape(b, def, makeOffsetBox(0.125f, 0.5f, {-0.375f, 0.0f}, 0.0f));
            bodies.push_back(b);
        }
        const std::string what = "two L's " + std::to_string(dx) + " m and " + std::to_string(angle) + " rad apart";
        expectGentle(measure(world, bodies), what);
        for (int i = 0; i < 2; ++i)
            EXPECT_LE(std::abs(world.position(bodies[static_cast<std::size_t>(i)]).x - static_cast<float>(i) * dx),
                      1.0f)
                << what << ", body " << i;
    }
}

// A body created with its centroid exactly on a thin static segment (a
// platform at the height a body was spawned at) is half inside it on either
// side. Continuous collision read its centroid's path as entering the
// segment at the path's start and stopped it there every step: it hung 0.5 m
// deep for good. It now leaves on the side its contact pushes it to (here
// the first of the two equal normals, downwards), within the 2 cm at
// 2 s, and falls free.
TEST(OverlapPiles, CentredOnAThinSegment) {
    for (Kind kind : {Kind::box, Kind::circle, Kind::capsule}) {
        World world({.enableSleep = false});
        BodyId platform = world.createBody({});
        world.createSegmentShape(platform, {}, Segment{{-3.0f, 2.0f}, {3.0f, 2.0f}});
        BodyId body = makeBody(world, kind, {0.0f, 2.0f}, 0.0f);
        for (int step = 0; step < 2 * 60; ++step) world.step(kDt);
        const std::string what = std::string("one of the ") + kindName(kind) + " centred on a segment";
        EXPECT_LE(deepest(world), 0.02f) << what;
        EXPECT_NE(world.position(body).y, 2.0f) << what;
    }
}

// A row of 20 unit boxes created on the ground, each half inside the next
// (centres 0.5 m apart), friction 0.6 and 1. The push solved each manifold's
// two points one after the other and turned every box the same way (0.061
// rad in the first step), and the row ended leaning on itself, propped on
// corners: 1.028 times its energy with friction 0.6, 1.017 at rest. With the
// two points solved together (deep_overlap.cpp, pushPointPair): 1.006 and
// 1.005, every box within 0.0031 rad of flat. The bounds, no
// tolerance added.
TEST(OverlapPiles, ARowCreatedHalfOverlappingOnTheGroundStaysFlat) {
    for (const float friction : {0.6f, 1.0f}) {
        World world({.enableSleep = false});
        const std::vector<BodyId> boxes = rowHalfOverlapping(world, 20, 0.5f, -4.75f, friction);
        const PileFigures f = measure(world, boxes);
        float tilt = 0.0f;
        for (const BodyId b : boxes) tilt = std::max(tilt, std::abs(world.angle(b)));
        const std::string what = "row of 20 boxes half overlapping on the ground, friction " +
                                 std::to_string(friction).substr(0, 3);
        expectGentle(f, what);
        std::printf("[figure] %s: largest tilt at 20 s %.4f rad\n", what.c_str(), tilt);
        expectPartedInTime(f, what);
    }
}

// Rows of 40 boxes 0.6 m wide created on the ground, each half inside the
// next (centres 0.3 m apart), without friction and with 0.6. The push of
// the middle's deep contacts squeezed the ends' contacts, already out of the
// deep regime, back to just under the deep depth (5 cm), and their soft rows
// pushed that out through the velocities, which the relax pass could not
// take back: the rows slid apart with 1.042 and 1.046 times their energy
// (the start plus the lift out of the ground, as measured here). A contact
// created overlapping is now pushed on pseudo-velocities down to
// kStartOverlapDeep (contact.hpp), and twice as fast
// (kStartOverlapPushFactor, deep_overlap.cpp): 1.011 and 1.006. The row
// has 11.7 m of overlap to undo, 5.85 m at each end. Its push's sweeps,
// stopped at sixteen, left it 1.7 and 3.0 cm deep at 2 s (2.3 and 5.2 cm
// before the two changes above; 1.4 and 2.8 cm with the sideways limit at
// 5c); run on until they converge (kMaxPushSweeps, deep_overlap.cpp), it is
// within 2 cm after 0.87 and 1.03 s, at 1.018 and 1.007 times its energy
// (since the shoves below, 0.53 s, at 1.008 and 1.005). Rows of 80 (23.7 m
// of overlap) were still 3.3 and 3.0 cm deep at 2 s, at 1.022 times their
// energy without friction: the push drove the boxes it moved into the boxes
// beside them, and the soft rows parted those overlaps through the
// velocities. Now a pushed body shoves the bodies beside it
// (deep_overlap.cpp, shoveTouching; docs/validation.md, "Shoves between
// moving bodies"): within 2 cm after 1.45 and 1.42 s, at 1.018 and 1.009.
// The bounds, all of them, no tolerance added.
TEST(OverlapPiles, ALongRowCreatedHalfOverlappingOnTheGroundPartsGently) {
    for (const int count : {40, 80})
        for (const float friction : {0.0f, 0.6f}) {
            World world({.enableSleep = false});
            const float firstX = -0.15f * static_cast<float>(count - 1);  // centred
            const std::vector<BodyId> boxes = rowHalfOverlapping(world, count, 0.3f, firstX, friction);
            const PileFigures f = measure(world, boxes);
            const std::string what = "row of " + std::to_string(count) +
                                     " boxes of 0.6 m half overlapping on the ground, friction " +
                                     std::to_string(friction).substr(0, 3);
            expectGentle(f, what);
            expectPartedInTime(f, what);
        }
}

// A body pushed out of an overlap shoves a body leaning on it (deep_overlap.cpp,
// kShoveSteepest). Two unit boxes created 0.3 m into each other on the
// ground, and a capsule (1.8 m long, radius 0.1) leaning on the far top
// corner of one of them, its foot on the ground, its side resting on the
// corner: the contact's normal is as far from level as the capsule is from
// upright. The push slides the box out of its neighbour, towards the
// capsule. Before steeper rows shoved along their level part, the box was
// driven into the capsule, 2.4 to 3.7 cm deep at leans of 0.3 to 0.8 rad
// (17° to 46°), which the soft row then pushed out through the velocities;
// in a pile of capsules fallen against each other that went back and forth
// for a second (docs/validation.md, "Shoves across leaning rows"). Shoved,
// the capsule slides along and the contact stays within the penetration
// slop (5 mm), the depth a soft row rests at: what is left is its sag under
// the capsule's weight, a tenth of a millimetre at the contacts' stiffness
// (g/ω², ω = 2π·50 Hz), and 0.8 mm at most was measured. The boxes part too.
TEST(OverlapPiles, ABodyPushedOutOfAnOverlapShovesABodyLeaningOnIt) {
    for (const float lean : {0.3f, 0.45f, 0.6f, 0.8f}) {
        World world({.enableSleep = false});
        BodyId ground = world.createBody({.type = BodyType::static_body});
        world.createPolygonShape(ground, ShapeDef{.friction = 0.6f}, makeOffsetBox(50.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
        const float overlap = 0.3f;
        const BodyId left = makeBody(world, Kind::box, {-0.5f + 0.5f * overlap, 0.5f}, 0.0f);
        const BodyId pushed = makeBody(world, Kind::box, {0.5f - 0.5f * overlap, 0.5f}, 0.0f);
        // The capsule's axis u leans towards the boxes; its side touches the
        // corner C along n, and its foot's centre lies one radius up.
        const float half = 0.8f, radius = 0.1f;
        const Vec2 corner{1.0f - 0.5f * overlap, 1.0f};
        const Vec2 u{-std::sin(lean), std::cos(lean)}, n{std::cos(lean), std::sin(lean)};
        const float along = (corner.y + radius * n.y - radius) / u.y;  // foot to corner, along u
        const Vec2 foot = corner - along * u + radius * n;
        ASSERT_LT(along, 2.0f * half);
        const BodyId leaning = world.createBody(
            {.type = BodyType::dynamic_body, .position = foot + half * u, .angle = lean});
        world.createCapsuleShape(leaning, ShapeDef{.density = 1.0f, .friction = 0.6f},
                                 Capsule{{0.0f, -half}, {0.0f, half}, radius});
        auto depth = [&](BodyId a, BodyId b) {
            float d = 0.0f;
            for (const ContactData& c : world.contacts()) {
                const BodyId x = world.shapeBody(c.shapeA), y = world.shapeBody(c.shapeB);
                if (!((x == a && y == b) || (x == b && y == a))) continue;
                for (int j = 0; j < c.manifold.pointCount; ++j) d = std::min(d, c.manifold.points[j].separation);
            }
            return -d;
        };
        float deepestOnCapsule = 0.0f;
        for (int step = 0; step < 180; ++step) {
            world.step(kDt);
            deepestOnCapsule = std::max(deepestOnCapsule, depth(pushed, leaning));
        }
        const std::string what = "capsule leaning " + std::to_string(lean).substr(0, 4) + " rad";
        std::printf("[figure] %s: deepest on the capsule %.4f m, boxes %.4f m deep at 3 s\n", what.c_str(),
                    deepestOnCapsule, depth(left, pushed));
        EXPECT_LE(deepestOnCapsule, world.settings().penetrationSlop) << what;
        EXPECT_LE(depth(left, pushed), 0.02f) << what;  // the 2 cm, well before 3 s
    }
}

// A pair pushed apart sideways does not slide back into itself (deep_overlap.cpp,
// prepareDeepOverlaps). A circle of radius 0.24 m created 12 cm deep in the top
// of a flat box (0.7 × 0.27 m) on a frictionless ground, 0.15 m off its centre,
// so that the push slides it out towards that side (it may not lift it above
// where it was created), while the two slide the other way relative to each
// other at 2.3 m/s (the box at 1.7 m/s one way, the circle at 0.6 m/s the
// other). Before, the push moved the circle back as fast as the velocities
// slid it on, and nothing on a frictionless ground takes velocities out: the
// pair drifted along together, 12 cm deep, for as long as it ran (a pile of
// the outside probe did so for 18 s, 0.25 m deep; docs/validation.md,
// "Shoves across leaning rows"). Now the velocity against the push is
// exchanged between the two (momentum kept, kinetic energy lost): the pair
// parts within the 2 s and 2 cm. No horizontal force acts from
// outside (the ground's normal is vertical, frictionless), so the total
// momentum along x is the start's up to float rounding (1e-4 of it, far
// above a few hundred steps' rounding, far below the 0.4 kg·m/s a one-sided
// change would make); and a passive system gains no energy (the 1 %).
TEST(OverlapPiles, APairPushedApartSidewaysDoesNotSlideBackIntoItself) {
    World world({.enableSleep = false});
    BodyId ground = world.createBody({.type = BodyType::static_body});
    world.createPolygonShape(ground, ShapeDef{.friction = 0.0f}, makeOffsetBox(200.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
    const BodyId box = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 0.135f}});
    world.createPolygonShape(box, ShapeDef{.density = 1.0f, .friction = 0.0f}, makeBox(0.35f, 0.135f));
    const BodyId circle = world.createBody(
        {.type = BodyType::dynamic_body, .position = {0.15f, 0.27f + 0.24f - 0.12f}});
    world.createCircleShape(circle, ShapeDef{.density = 1.0f, .friction = 0.0f}, Circle{{0.0f, 0.0f}, 0.24f});
    world.setLinearVelocity(box, {1.7f, 0.0f});
    world.setLinearVelocity(circle, {-0.6f, 0.0f});
    const std::vector<BodyId> pair{box, circle};
    auto momentumX = [&] {
        float p = 0.0f;
        for (const BodyId b : pair) p += world.mass(b) * world.linearVelocity(b).x;
        return p;
    };
    auto energy = [&] {
        float e = 0.0f;
        for (const BodyId b : pair) {
            const Vec2 v = world.linearVelocity(b);
            const float w = world.angularVelocity(b);
            e += 0.5f * world.mass(b) * dot(v, v) + 0.5f * world.rotationalInertia(b) * w * w +
                 world.mass(b) * kG * world.worldCenterOfMass(b).y;
        }
        return e;
    };
    const float p0 = momentumX(), e0 = energy();
    float peak = e0;
    for (int step = 1; step <= 120; ++step) {
        world.step(kDt);
        peak = std::max(peak, energy());
        EXPECT_NEAR(momentumX(), p0, 1e-4f * std::abs(p0)) << "step " << step;
    }
    std::printf("[figure] circle deep in a sliding box: %.4f m deep at 2 s, energy peak %.4f of the start\n",
                deepest(world), peak / e0);
    EXPECT_LE(deepest(world), 0.02f);
    EXPECT_LE(peak, 1.01f * e0);
}

// Rows of 10 and 20 boxes of 0.6 m created half overlapping on a ground
// without friction, which keeps whatever velocity the push leaves. A created
// overlap is pushed on pseudo-velocities until it is within kStartOverlapDeep
// (1 cm, engine/src/contact.hpp), and its soft rows then push the rest out
// through the velocities, each asking its pair to part at up to
// biasRate·(1 cm − slop): 6.12/s · 5 mm = 3.1 cm/s at the defaults (50 Hz,
// ζ = 25, substeps of 1/240 s: ω/(2ζ + hω)). Along a row those asks add
// up: left in the velocities, box i of n moves out at |i − (n − 1)/2| times
// that, ½·m·Σv² = 0.014 J for 10 boxes and 0.11 J for 20. The relax pass
// takes a soft row's push back, whole once it converges, but one relax sweep
// a substep converges along a row only in part: the rows kept 0.022 and
// 0.10 J after 3 s (0.022 and 0.072 J with the sideways limit at 5c). The
// blocks holding such rows are now relaxed again until they settle
// (kWideFromStart, engine/src/contact_solver.cpp): 0.0030 and 0.035 J. The
// bound is half the unrelaxed estimate: that much of the push taken back.
TEST(OverlapPiles, ARowPushedOutOfItsCreatedOverlapsKeepsLittleOfThePushInItsVelocities) {
    const WorldSettings defaults;
    const float h = (1.0f / 60.0f) / static_cast<float>(defaults.substeps);
    const float omega = 2.0f * 3.14159265f * defaults.contactHertz;
    const float biasRate = omega / (2.0f * defaults.contactDampingRatio + h * omega);
    const float ask = biasRate * (0.01f - defaults.penetrationSlop);  // m/s, one row at the handover
    for (const int count : {10, 20}) {
        World world({.enableSleep = false});
        const float firstX = -0.15f * static_cast<float>(count - 1);  // centred
        const std::vector<BodyId> boxes = rowHalfOverlapping(world, count, 0.3f, firstX, 0.0f);
        for (int step = 0; step < 180; ++step) world.step(kDt);
        double kinetic = 0.0, unrelaxed = 0.0;
        for (int i = 0; i < count; ++i) {
            const BodyId b = boxes[static_cast<std::size_t>(i)];
            kinetic += 0.5 * world.mass(b) * lengthSquared(world.linearVelocity(b)) +
                       0.5 * world.rotationalInertia(b) * world.angularVelocity(b) * world.angularVelocity(b);
            const double v = std::abs(i - 0.5 * (count - 1)) * ask;
            unrelaxed += 0.5 * world.mass(b) * v * v;
        }
        std::printf("[figure] row of %d frictionless boxes created half overlapping: kinetic energy after 3 s "
                    "%.4f J, unrelaxed estimate %.4f J\n",
                    count, kinetic, unrelaxed);
        EXPECT_LE(kinetic, 0.5 * unrelaxed) << count << " boxes";
    }
}

// 50 unit boxes created at one point on the ground, seeds 1 to 5. The push
// turned bodies without limit: one box of seed 1 turned by 0.26 rad in a step
// and back by 0.6 rad in the next (a corner at 25 m/s), which drove a corner
// 16 cm into the ground; the ground's deep row then lifted the box (a body
// may leave something immovable above the highest it has been) and left it
// standing on the corner. Now no point of a pushed body turns faster than
// the turn limit 3c (kTurnPushFactor, deep_overlap.cpp): a unit box (reach
// √2/2 m) turns at most 3c·Δt/reach = 0.212 rad a step on its pseudo-spin. Measured from the
// positions, a step's turn also holds what the spin turned it by, credited
// here at the larger of the step's first and last spins; within the step the
// soft rows' push may spin a box further, at most c at a point, which the
// relax pass takes back before the step ends. So the bound is
// 4c·Δt/reach = 0.283 rad; the largest turns were 0.49 to 0.97 rad before
// (seeds 1, 3, 4, 5) and 0.214 with the limit (0.212 since the sideways limit
// became 5c).
TEST(OverlapPiles, FiftyBoxesAtOnePointOnTheGroundAreNotTurnedFasterThanThePushAllows) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
        World world({.enableSleep = false});
        test::makeGround(world, 200.0f);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> jitter(-0.01f, 0.01f);
        std::vector<BodyId> boxes;
        for (int i = 0; i < 50; ++i)
            boxes.push_back(makeBody(world, Kind::box, {jitter(rng), 0.5f + jitter(rng)}, 0.0f));
        const float reach = std::sqrt(0.5f);
        const float bound = 4.0f * world.settings().maxPushSpeed * kDt / reach;
        std::vector<float> angle, spin;
        for (BodyId b : boxes) {
            angle.push_back(world.angle(b));
            spin.push_back(world.angularVelocity(b));
        }
        float largest = 0.0f;
        for (int step = 0; step < 6 * 60; ++step) {
            world.step(kDt);
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                const float a = world.angle(boxes[i]), w = world.angularVelocity(boxes[i]);
                const float turned = std::abs(std::remainder(a - angle[i], 2.0f * 3.14159265f));
                largest = std::max(largest, turned - std::max(std::abs(w), std::abs(spin[i])) * kDt);
                angle[i] = a;
                spin[i] = w;
            }
        }
        std::printf(
            "[figure] 50 boxes at one point on the ground, seed %u: largest turn in a step beyond the spin's %.3f rad\n",
            seed, largest);
        EXPECT_LE(largest, bound) << "seed " << seed;
    }
}

// 20 boxes created at one point on the ground, seeds 40001 to 40020 (not used
// in developing what follows). The push turned boxes resting on the ground
// about their centres, which drove a corner of each into the ground; the
// ground's soft row then lifted the box out through the velocities, a lift
// the push itself may never give (no body is pushed above the highest it has
// been), and boxes ended propped on each other's corners: 3 of these 20
// piles rose to 1.027 to 1.030 times their energy. The push may no longer
// drive a body into something that does not move and holds it up
// (deep_overlap.cpp, guardAgainstImmovable): at most 1.006. Nothing thrown, by the issue's
// bounds, no tolerance added (one of these piles is 2.2 cm deep at 2 s; the
// parting time is held by TwentyAtOnePointOnTheGroundPartWithinTwoSeconds).
TEST(OverlapPiles, TwentyBoxesAtOnePointOnTheGroundAreNotProppedUp) {
    float worst = 0.0f;
    for (unsigned seed = 40001; seed <= 40020; ++seed) {
        const PileFigures f = airPile(Kind::box, 20, 0.5f, seed);
        worst = std::max(worst, f.energyRatio);
        expectNothingThrown(f, "20 boxes at one point on the ground, seed " + std::to_string(seed));
    }
    std::printf("[figure] 20 boxes at one point on the ground, seeds 40001 to 40020: energy at most %.4f x start\n",
                worst);
}

// A box of 0.25 m resting on the ground with a box of 0.9 m created above it,
// 0.11 and 0.2 m deep in it. Lifting the big box would take it above the
// highest it has been, so the pair is pushed sideways; split by the masses
// the small box would slide beyond its own width, and it slid its width while
// the big one took the rest only where that rest was no more than the lift it
// replaced. Beyond that the pair was pushed along its normal, which only the
// ground's soft row carried out (the push drove the small box into the
// ground, the row lifted the pair): once the push could no longer drive a
// body into what holds it up (guardAgainstImmovable) the pair stalled, 4.3
// and 7.6 cm deep at 2 s, the big box raised 0.11 and 0.20 m by the soft
// rows (1.18 and 1.39 times the energy).
// Now the sideways split is taken whatever the rest (deep_overlap.cpp,
// prepareDeepOverlaps): apart within a second, the big box not raised. The
// issue's bounds, no tolerance added.
TEST(OverlapPiles, ASmallBoxUnderABigOneSlidesOutFromUnderIt) {
    for (const float depth : {0.11f, 0.2f}) {
        World world({.enableSleep = false});
        test::makeGround(world, 200.0f);
        const std::vector<BodyId> bodies = {test::makeBox(world, {0.0f, 0.125f}, 0.125f),
                                            test::makeBox(world, {0.0f, 0.25f - depth + 0.45f}, 0.45f)};
        const PileFigures f = measure(world, bodies);
        const std::string what = "0.25 m box on the ground under a 0.9 m box " + std::to_string(depth).substr(0, 4) +
                                 " m deep in it";
        expectGentle(f, what);
        expectPartedInTime(f, what);
    }
}

// A box of 0.5 m created 0.2 m deep in a plank 0.3 m thick lying on the
// ground, 6 m long with the box at its middle, or 10 m long with the box 2 m
// from it. The pair is pushed sideways (lifting the box would take it above
// the highest it has been); the box slides its own width and the plank gives
// way by the rest, which may be more than the lift it replaces. Before, such
// a pair was pushed along its normal, the plank into the ground, whose soft
// row lifted the box out: after 6 s from the 6 m plank, 9 cm deep at 2 s,
// and from the 10 m plank not within 10 s (0.14 m deep at 2 s). With the push
// kept from driving the plank into the ground (guardAgainstImmovable) and
// before the split was taken whatever the rest, neither parted at all. Now
// the plank moves 1.9 m and they part in 1.43 s.
// The bounds, no tolerance added.
TEST(OverlapPiles, ABoxInsideALongPlankOnTheGroundParts) {
    for (const auto& [length, offset] : {std::pair{6.0f, 0.0f}, std::pair{10.0f, 2.0f}}) {
        World world({.enableSleep = false});
        test::makeGround(world, 200.0f);
        const BodyId plank = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 0.15f}});
        world.createPolygonShape(plank, {.density = 1.0f, .friction = 0.6f}, makeBox(0.5f * length, 0.15f));
        const BodyId box = test::makeBox(world, {offset, 0.3f - 0.2f + 0.25f}, 0.25f);
        const PileFigures f = measure(world, {plank, box});
        const std::string what = "box 0.2 m deep in a plank " + std::to_string(static_cast<int>(length)) + " m long";
        expectGentle(f, what);
        expectPartedInTime(f, what);
    }
}

}  // namespace
}  // namespace i2d
