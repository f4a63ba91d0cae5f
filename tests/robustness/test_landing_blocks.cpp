// Blocks of boxes landing as one: a 7 × 7 grid of unit boxes dropped from
// 10 m, its lowest row striking the ground at 14 m/s and every row above it
// striking the row below within the same step or the next. Restitution is
// zero and nothing drives the boxes, so the landing can only take energy
// away. Box2D 2.4.1 lands the grids with 5 and 10 cm gaps standing (its top
// row within 7 mm of its columns); Impulse2D threw boxes sideways along the
// grid's diagonals at 11 m/s and its top row up at 5 to 10 m/s, and the
// grid of touching boxes moved up to 1 cm sideways threw its top row up at
// 16 m/s (docs/impacts.md, "Landing blocks"). Default settings, sleeping
// off.
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
constexpr float kG = 10.0f;  // test::makeGround's worlds use the default gravity, 10 m/s²
constexpr int kSide = 7;

struct Landing {
    float fastestUp = 0.0f;    ///< m/s: the largest upward speed of any box over the run
    float speedExcess = 0.0f;  ///< m/s: the largest speed beyond a free fall from its highest point + the cap
    float sideways = 0.0f;     ///< m: the largest distance of a box of the top row from its column at the end
    float energyRatio = 0.0f;  ///< the largest total energy over the start's
};

/// Drops a grid of kSide × kSide unit boxes, `gap` apart, its bottom 10 m
/// above the ground, each box moved sideways by up to ±`jitter` (seeded).
Landing dropGrid(float gap, float jitter, unsigned seed) {
    World world(WorldSettings{.enableSleep = false});
    test::makeGround(world, 200.0f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> offset(-jitter, jitter);
    std::vector<BodyId> boxes;
    std::vector<float> column;
    for (int row = 0; row < kSide; ++row)
        for (int col = 0; col < kSide; ++col) {
            const float x = static_cast<float>(col) * (1.0f + gap) + (jitter > 0.0f ? offset(rng) : 0.0f);
            boxes.push_back(test::makeBox(world, {x, 10.5f + static_cast<float>(row) * (1.0f + gap)}));
            column.push_back(x);
        }
    const float cap = world.settings().maxPushSpeed;
    auto energy = [&] {
        double e = 0.0;
        for (BodyId b : boxes) {
            const float w = world.angularVelocity(b);
            e += 0.5 * world.mass(b) * lengthSquared(world.linearVelocity(b)) +
                 0.5 * world.rotationalInertia(b) * w * w + world.mass(b) * kG * world.position(b).y;
        }
        return e;
    };
    std::vector<float> highest;
    for (BodyId b : boxes) highest.push_back(world.position(b).y);
    const double start = energy();
    double most = start;
    Landing r;
    for (int step = 0; step < 5 * 60; ++step) {  // lands after 1.4 s; 5 s sees it settle
        world.step(kDt);
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            const Vec2 v = world.linearVelocity(boxes[i]);
            const float y = world.position(boxes[i]).y;
            highest[i] = std::max(highest[i], y);
            r.fastestUp = std::max(r.fastestUp, v.y);
            r.speedExcess = std::max(r.speedExcess, length(v) - (std::sqrt(2.0f * kG * (highest[i] - y)) + cap));
        }
        most = std::max(most, energy());
    }
    for (std::size_t i = boxes.size() - kSide; i < boxes.size(); ++i)
        r.sideways = std::max(r.sideways, std::abs(world.position(boxes[i]).x - column[i]));
    r.energyRatio = static_cast<float>(most / start);
    return r;
}

void print(const Landing& r, const char* what) {
    std::printf("[figure] %s: fastest up %.2f m/s, speed beyond free fall + cap %+.2f m/s, top row %.3f m from its "
                "columns, energy %.6f x start\n",
                what, r.fastestUp, r.speedExcess, r.sideways, r.energyRatio);
}

// Issue #13's bound for piles: no body faster than a free fall from the
// highest point it reached plus the push cap; and passive, never above the
// start: the landing can only take energy away, and 10⁻⁴ covers the rounding
// of positions and velocities held in floats (about 10⁻⁷ of each term).
void expectNotThrown(const Landing& r, const char* what) {
    EXPECT_LE(r.speedExcess, 0.0f) << what;
    EXPECT_LE(r.energyRatio, 1.0001f) << what;
}

// With gaps, the corners of diagonal neighbours are 0.14 m apart and fall
// past each other; the landing must not strike them (contact.cpp,
// computeManifold).
TEST(LandingBlocks, AGridWithGapsLandsStanding) {
    for (float gap : {0.05f, 0.1f, 0.2f}) {
        char what[64];
        std::snprintf(what, sizeof what, "7 x 7 boxes %.2f m apart", static_cast<double>(gap));
        const Landing r = dropGrid(gap, 0.0f, 1u);
        print(r, what);
        expectNotThrown(r, what);
        // A box may rise only as the soft push lifts it out of an overlap
        // the landing pressed in: at most the push cap (maxPushSpeed,
        // 3 m/s). Measured 0.39 to 0.40 m/s.
        EXPECT_LT(r.fastestUp, 3.0f) << what;
        // The top row stays over its columns: half a box, beyond which a
        // box would have slid off the one below it (measured 0).
        EXPECT_LT(r.sideways, 0.5f) << what;
    }
}

// Touching, each box up to 1 cm to the side: a box lands on the one below
// it and on a corner of the next one at once, and the impact stage strikes
// the two one after the other; the shock pass then held each row still
// while it carried the rows above up with the speed the corner strikes had
// given it (impact_stage.cpp). Not yet met: the grid does not land standing
// (rows slide apart; docs/impacts.md, "Landing blocks").
TEST(LandingBlocks, AGridOfTouchingBoxesIsNotThrown) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        char what[64];
        std::snprintf(what, sizeof what, "7 x 7 touching boxes, 1 cm jitter, seed %u", seed);
        const Landing r = dropGrid(0.0f, 0.01f, seed);
        print(r, what);
        expectNotThrown(r, what);
    }
}

}  // namespace
}  // namespace i2d
