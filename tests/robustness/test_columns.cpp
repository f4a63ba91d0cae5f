// Columns of touching boxes with sleeping off (docs/validation.md, "Columns").
// A column of soft contacts is a column of springs, which buckles under its
// own weight when every manifold is recomputed from the geometry each step;
// persistent manifolds (contact_persistence.hpp) keep it standing. Each test
// prints its figures and asserts the bound argued next to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "unit/world_fixtures.hpp"

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;

struct ColumnResult {
    float maxSway = 0.0f;  ///< largest |x| of the top box over the run (m)
    float drop = 0.0f;     ///< how far the top box sank (m)
    float maxEnergyRatio = 0.0f;
};

float energy(const World& world, const std::vector<BodyId>& boxes) {
    float e = 0.0f;
    for (BodyId b : boxes) {
        const float m = world.mass(b);
        e += 0.5f * m * lengthSquared(world.linearVelocity(b)) +
             0.5f * world.rotationalInertia(b) * world.angularVelocity(b) * world.angularVelocity(b) +
             m * 10.0f * world.position(b).y;
    }
    return e;
}

// `count` boxes of half-extent `half` (unit boxes by default) touching one
// above the other (friction 0.6) on a wide static ground, defaults except
// sleeping off, stepped for `seconds`. `lean` shifts box i sideways by lean·i
// (m), a column built leaning; `gap` (m) is left below each box.
ColumnResult standColumn(int count, float seconds, float reuseDistance, float lean = 0.0f, float half = 0.5f,
                         bool exactTilt = true, float gap = 0.0f) {
    WorldSettings settings;
    settings.enableSleep = false;
    settings.manifoldReuseDistance = reuseDistance;
    settings.exactColumnTilt = exactTilt;
    World world(settings);
    test::makeGround(world, 100.0f);
    std::vector<BodyId> boxes;
    for (int i = 0; i < count; ++i)
        boxes.push_back(test::makeBox(world,
                                      {lean * static_cast<float>(i),
                                       half * (1.0f + 2.0f * static_cast<float>(i)) + gap * static_cast<float>(i + 1)},
                                      half));
    const BodyId top = boxes.back();
    const float x0 = world.position(top).x;
    const float y0 = world.position(top).y;
    const float e0 = energy(world, boxes);
    ColumnResult r;
    const int steps = static_cast<int>(seconds / kDt);
    for (int s = 0; s < steps; ++s) {
        world.step(kDt);
        r.maxSway = std::max(r.maxSway, std::abs(world.position(top).x - x0));
        r.maxEnergyRatio = std::max(r.maxEnergyRatio, energy(world, boxes) / e0);
    }
    r.drop = y0 - world.position(top).y;
    std::printf("column of %d boxes of %.2f m leaning %.4f m per box, %.0f s, reuse %.3f m, tilt %s: top sway %.4f m, "
                "drop %.3f m, max energy %.5f of start\n",
                count, 2.0f * half, lean, seconds, reuseDistance, exactTilt ? "exact" : "soft", r.maxSway, r.drop,
                r.maxEnergyRatio);
    return r;
}

// Bounds (the hard-cases issue): a column of 20 stands 60 s with its top
// within 1 cm sideways and a drop under 0.25 m; 50 within 5 cm and under
// 1 m. The drop is the contacts' compliance: load / (m_eff·ω²) summed over
// the contacts, Σ i·10 N / (2·19,700 N/m) = 0.053 m for 20 boxes at the
// default 50 Hz (0.32 m for 50; 0.148 m and 0.87 m at 30 Hz, the bounds' own
// origin), which is why the bounds sit above those sums.
TEST(Columns, TwentyTouchingBoxesStandForAMinuteWithoutSleeping) {
    const ColumnResult r = standColumn(20, 60.0f, WorldSettings{}.manifoldReuseDistance);
    EXPECT_LT(r.maxSway, 0.01f);
    EXPECT_LT(r.drop, 0.25f);
    // Passive system: never above its start (1 % allowance of the audit).
    EXPECT_LT(r.maxEnergyRatio, 1.01f);
}

TEST(Columns, FiftyTouchingBoxesStandForAMinuteWithoutSleeping) {
    const ColumnResult r = standColumn(50, 60.0f, WorldSettings{}.manifoldReuseDistance);
    EXPECT_LT(r.maxSway, 0.05f);
    EXPECT_LT(r.drop, 1.0f);
    EXPECT_LT(r.maxEnergyRatio, 1.01f);
}

// The same bounds for boxes half and twice the unit size. A contact's sag is
// its load over m_eff·ω², and both scale with the boxes' mass, so the drop in
// metres is the same whatever their size (0.053 m for 20 and 0.32 m for 50
// at 50 Hz, above): a column of smaller boxes is the more slender one, of
// larger boxes the heavier. (Columns of 0.1 m boxes do not all stand:
// docs/validation.md, "Hard cases not yet met".)
TEST(Columns, TouchingColumnsOfHalfAndTwiceTheSizeStand) {
    for (float half : {0.25f, 1.0f}) {
        const ColumnResult r20 = standColumn(20, 60.0f, WorldSettings{}.manifoldReuseDistance, 0.0f, half);
        EXPECT_LT(r20.maxSway, 0.01f) << "boxes of " << 2.0f * half << " m";
        EXPECT_LT(r20.drop, 0.25f) << "boxes of " << 2.0f * half << " m";
        EXPECT_LT(r20.maxEnergyRatio, 1.01f) << "boxes of " << 2.0f * half << " m";
        const ColumnResult r50 = standColumn(50, 60.0f, WorldSettings{}.manifoldReuseDistance, 0.0f, half);
        EXPECT_LT(r50.maxSway, 0.05f) << "boxes of " << 2.0f * half << " m";
        EXPECT_LT(r50.drop, 1.0f) << "boxes of " << 2.0f * half << " m";
        EXPECT_LT(r50.maxEnergyRatio, 1.01f) << "boxes of " << 2.0f * half << " m";
    }
}

// The mechanism, pinned on a column built leaning (0.5 mm per box, its top
// 12 mm off) with the contacts' tilt left to their soft rows
// (exactColumnTilt off): a symmetric column has nothing to grow from. With
// persistent manifolds the lean's own gravity moment, captured when the
// manifolds were computed, bends the column once (its top moves about 4 cm)
// and the bending does not feed back: the top stays within 0.1 m for a
// minute, three orders of magnitude from the buckled case. With every
// manifold recomputed each step the same column buckles (its top ends tens of
// metres away), as Box2D 2.4.1's does; if that ever stands, the explanation
// in contact_persistence.hpp is wrong. The column has 25 boxes: a column of
// springs buckles under its own weight beyond a length that grows as the cube
// root of its bending stiffness (Greenhill's self-weight column), here the
// contacts' ω². At 30 Hz a column of 20 recomputed every step buckled; at the
// default 50 Hz (ω² 2.8 times, the length 1.4 times) it sways 0.35 m and
// stays, and one of 25 falls. The boxes are built 5 mm apart and land on
// each other: built touching, the rows would hold the loads the column was
// built with, its lean's moment included, without sagging under them
// (engine/src/rest_load.hpp), and the lean would have nothing to bend the
// column with (recomputed every step, such a column sways 0.78 m in 20 s and
// stands; 50 m with the gaps).
constexpr int kLeaningColumn = 25;
constexpr float kLeaningColumnGap = 0.005f;

TEST(Columns, ALeaningColumnWithSoftTiltStandsWithPersistentManifolds) {
    const ColumnResult r = standColumn(kLeaningColumn, 60.0f, WorldSettings{}.manifoldReuseDistance, 0.0005f, 0.5f,
                                       false, kLeaningColumnGap);
    EXPECT_LT(r.maxSway, 0.1f);
}

TEST(Columns, ALeaningColumnWithSoftTiltBucklesWhenManifoldsAreRecomputedEveryStep) {
    const ColumnResult r = standColumn(kLeaningColumn, 20.0f, 0.0f, 0.0005f, 0.5f, false, kLeaningColumnGap);
    EXPECT_GT(r.maxSway, 1.0f);
}

// With the tilt solved exactly along the column (the default, contact_tilt.cpp)
// nothing bends: the same column stands unmoved even with every manifold
// recomputed each step. The bound is the for a column of 20, 1 cm
// (measured: under 0.1 mm).
TEST(Columns, ALeaningColumnWithExactTiltStandsEvenWhenManifoldsAreRecomputed) {
    const ColumnResult r = standColumn(kLeaningColumn, 20.0f, 0.0f, 0.0005f);
    EXPECT_LT(r.maxSway, 0.01f);
}

// Columns built leaning one way (box i placed lean·i sideways), held to the
// issue's bounds for straight columns: top within 1 cm (20 boxes) and 5 cm
// (50) for a minute, drops under 0.25 m and 1 m. With soft tilts the lean's
// load bent every contact the same way, each bend adding to the load's
// offset (buckling under the P-delta moment): 50 boxes at 0.1 mm a box swung
// 14.9 cm, 20 at 0.5 mm 1.6 cm, and 50 at 1 mm fell (docs/validation.md,
// "Columns solved as one"). The drops are the contacts' sag, as for straight
// columns (0.049 and 0.312 m); the energy is never above its start
// (a passive system; the audit's 1 %).
TEST(Columns, ColumnsBuiltLeaningStandWithExactTilt) {
    struct Lean {
        int count;
        float lean, sway, drop;
    };
    for (const Lean c :
         {Lean{20, 0.0005f, 0.01f, 0.25f}, Lean{50, 0.0001f, 0.05f, 1.0f}, Lean{50, 0.001f, 0.05f, 1.0f}}) {
        const ColumnResult r = standColumn(c.count, 60.0f, WorldSettings{}.manifoldReuseDistance, c.lean);
        EXPECT_LT(r.maxSway, c.sway) << c.count << " boxes leaning " << c.lean << " m a box";
        EXPECT_LT(r.drop, c.drop) << c.count << " boxes leaning " << c.lean << " m a box";
        EXPECT_LT(r.maxEnergyRatio, 1.01f) << c.count << " boxes leaning " << c.lean << " m a box";
    }
}

// Columns of 0.1 m boxes: a contact's sag in metres is the same whatever
// the boxes' size, so a column of small boxes is the slender one: 45 and 50
// such boxes fell with the tilt left to the soft rows (50 by 3 s; 40 swayed
// 1.6 cm). With the tilt exact they stand, held to the bounds for a
// column of 50 (within 5 cm, a drop under 1 m; measured below 1 mm and
// 0.26 m at the end), and the energy never above its start.
TEST(Columns, AColumnOfFiftyTenCentimetreBoxesStandsWithExactTilt) {
    const ColumnResult r = standColumn(50, 60.0f, WorldSettings{}.manifoldReuseDistance, 0.0f, 0.05f);
    EXPECT_LT(r.maxSway, 0.05f);
    EXPECT_LT(r.drop, 1.0f);
    EXPECT_LT(r.maxEnergyRatio, 1.01f);
}

// A kept manifold must not hold a box up past an edge: a unit box slid
// frictionless off a ledge at 0.2 m/s tips (turns by 0.01 rad) where it
// does with every manifold recomputed, within 2 cm. The box's turn counts
// towards the reuse distance (its reach 0.71 m times sin 0.01 is 7 mm), so
// its manifold is recomputed within about a centimetre of travel.
float tippingCentre(float reuseDistance) {
    WorldSettings settings;
    settings.enableSleep = false;
    settings.manifoldReuseDistance = reuseDistance;
    World world(settings);
    const BodyId ledge = world.createBody({});
    world.createPolygonShape(ledge, {.friction = 0.0f}, makeOffsetBox(5.0f, 0.5f, {-5.0f, -0.5f}, 0.0f));
    const BodyId box = world.createBody(
        {.type = BodyType::dynamic_body, .position = {-0.3f, 0.5f}, .linearVelocity = {0.2f, 0.0f}});
    world.createPolygonShape(box, {.friction = 0.0f}, makeBox(0.5f, 0.5f));
    for (int s = 0; s < 600; ++s) {
        world.step(kDt);
        if (world.angle(box) < -0.01f) return world.position(box).x;
    }
    return 1e9f;
}

TEST(Columns, AKeptManifoldDoesNotHoldABoxPastAnEdge) {
    const float recomputed = tippingCentre(0.0f);
    const float kept = tippingCentre(WorldSettings{}.manifoldReuseDistance);
    std::printf("box slid off a ledge tips with its centre %.4f m past the edge (every manifold recomputed: %.4f m)\n",
                kept, recomputed);
    ASSERT_LT(recomputed, 0.1f);
    EXPECT_LT(kept - recomputed, 0.02f);
}

// A kept manifold must not hide a corner that comes down into the ground: a
// unit box stood on one bottom corner, tilted by `tilt`, falls flat about
// that corner. The corner it pivots on is the static ground's origin, so the
// ground's origin barely moves in the box's frame; only the turn moves the
// ground's surface under the far corner. A static body had no reach (it was
// set only for dynamic bodies), so the turn did not count towards the reuse
// distance: the manifold holding the pivot alone was kept until the box had
// turned 11 degrees, and the far corner went through the ground unseen, 3.6
// cm at a tilt of 0.4 rad, 8.7 cm at 0.8, 10.5 cm at 0.1 (where the whole
// fall is within the 11 degrees). Every body's reach is now set, and the far
// corner stays within the speculative contact it gets: the deepest it goes
// below the ground beyond what the contact reports is bounded by the
// penetration slop (5 mm; measured 0.1 to 0.4 mm).
TEST(Columns, AKeptManifoldDoesNotHideACornerComingDown) {
    for (float tilt : {0.1f, 0.2f, 0.4f, 0.8f}) {
        World world({.enableSleep = false});
        const BodyId ground = world.createBody({});  // its origin on its top face
        world.createPolygonShape(ground, {}, makeOffsetBox(50.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
        const Vec2 centre{0.5f * std::cos(tilt) - 0.5f * std::sin(tilt), 0.5f * std::sin(tilt) + 0.5f * std::cos(tilt)};
        const BodyId box = world.createBody({.type = BodyType::dynamic_body, .position = centre, .angle = tilt});
        world.createPolygonShape(box, {.density = 1.0f, .friction = 0.6f}, makeBox(0.5f, 0.5f));
        float hidden = 0.0f;
        for (int step = 0; step < 180; ++step) {
            world.step(kDt);
            const Vec2 p = world.position(box);
            const float a = world.angle(box);
            float lowest = 1e9f;
            for (float x : {-0.5f, 0.5f})
                for (float y : {-0.5f, 0.5f}) lowest = std::min(lowest, p.y + std::sin(a) * x + std::cos(a) * y);
            float reported = 0.0f;
            for (const ContactData& c : world.contacts())
                for (int j = 0; j < c.manifold.pointCount; ++j)
                    reported = std::min(reported, c.manifold.points[j].separation);
            hidden = std::max(hidden, -lowest + reported);
        }
        std::printf("box falling flat about a corner from %.1f rad: its corners go %.4f m below the ground beyond "
                    "what its contact reports\n",
                    tilt, hidden);
        EXPECT_LT(hidden, world.settings().penetrationSlop) << "tilt " << tilt;
    }
}

// Posts four times as tall as wide (0.25 × 1 m, density 1, friction 0.6),
// each set off its neighbour below by a random 0.5 mm at most (a third of a
// percent of its half width: for rigid bodies, wholly stable). Their two
// contact points are coupled (ρ = K12/√(K11·K22) = 0.7: pushing at one
// corner pushes the other too), and solved side by side the rocking of a
// post, the points' difference, converged by 18 % a pass: two posts rocked
// corner to corner for good and walked 3 cm in a minute, and a column of 20
// fell within 42 s (contact_solver.cpp, solvePointPair). Bounds: the
// columns' own (the hard-cases issue), a top within 1 cm sideways and a drop
// under 0.25 m over a minute, for 2 and 20 posts; a passive column never
// gains more than the audit's 1 %.
ColumnResult standPosts(int count, unsigned seed) {
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    test::makeGround(world, 100.0f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> offset(-0.0005f, 0.0005f);
    std::vector<BodyId> posts;
    for (int i = 0; i < count; ++i) {
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = {offset(rng), 0.5f + static_cast<float>(i)}});
        world.createPolygonShape(b, {.density = 1.0f, .friction = 0.6f}, makeBox(0.125f, 0.5f));
        posts.push_back(b);
    }
    const BodyId top = posts.back();
    const Vec2 start = world.position(top);
    const float e0 = energy(world, posts);
    ColumnResult r;
    for (int s = 0; s < static_cast<int>(60.0f / kDt); ++s) {
        world.step(kDt);
        r.maxSway = std::max(r.maxSway, std::abs(world.position(top).x - start.x));
        r.maxEnergyRatio = std::max(r.maxEnergyRatio, energy(world, posts) / e0);
    }
    r.drop = start.y - world.position(top).y;
    std::printf(
        "column of %d posts 0.25 x 1 m, seed %u, 60 s: top sway %.4f m, drop %.4f m, max energy %.5f of start\n", count,
        seed, r.maxSway, r.drop, r.maxEnergyRatio);
    return r;
}

TEST(Columns, NarrowPostsStandWithoutRocking) {
    for (const int count : {2, 20})
        for (const unsigned seed : {1u, 2u, 3u}) {
            const ColumnResult r = standPosts(count, seed);
            EXPECT_LT(r.maxSway, 0.01f) << count << " posts, seed " << seed;
            EXPECT_LT(r.drop, 0.25f) << count << " posts, seed " << seed;
            EXPECT_LT(r.maxEnergyRatio, 1.01f) << count << " posts, seed " << seed;
        }
}

}  // namespace
}  // namespace i2d
