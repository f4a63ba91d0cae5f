// The character mover: a capsule walked through a level by moveCharacter
// (collide, solve planes, cast, repeat) must climb slopes and steps, stop at
// walls, never pass through anything and not jitter when it rests.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "world_fixtures.hpp"

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;
// A capsule 1.6 m tall and 0.6 m wide, in its own frame: the position is the
// centre of its lower circle, so it stands on y = 0 at position.y = 0.3.
const Capsule kCapsule{{0.0f, 0.0f}, {0.0f, 1.0f}, 0.3f};
constexpr float kStand = 0.3f;

struct Walker {
    Vec2 position;
    Vec2 velocity{};
    bool grounded = false;
    float deepest = 0.0f;  ///< the largest overlap any plane reported (m)
};

// One frame of a simple game controller: walk at `speed`, fall under
// gravity, move, keep the clipped velocity.
void walk(const World& w, Walker& m, float speed) {
    m.velocity.x = speed;
    m.velocity.y -= 10.0f * kDt;
    MoverResult r = moveCharacter(w, kCapsule, m.position, kDt * m.velocity, m.velocity, {});
    m.position = r.position;
    m.velocity = r.velocity;
    m.grounded = std::any_of(r.planes.begin(), r.planes.end(),
                             [](const CollisionPlane& p) { return p.normal.y > 0.7f; });
    for (const CollisionPlane& p : r.planes) m.deepest = std::max(m.deepest, p.offset);
}

// The mover rests in its planes by at most the slop the plane solver allows
// (kLinearSlop) plus the cast's stopping band (0.1·kLinearSlop).
constexpr float kMaxOverlap = 1.1f * kLinearSlop;

TEST(Mover, WalksOnFlatGroundWithoutJitter) {
    World w;
    test::makeGround(w, 100.0f);
    Walker m{{0.0f, kStand}};
    float lowest = 1.0f, highest = -1.0f;
    for (int i = 0; i < 120; ++i) {
        walk(w, m, 3.0f);
        if (i >= 10) {
            lowest = std::min(lowest, m.position.y);
            highest = std::max(highest, m.position.y);
        }
    }
    EXPECT_TRUE(m.grounded);
    // 2 s at 3 m/s.
    EXPECT_NEAR(m.position.x, 6.0f, 0.01f);
    // Height steady to 0.1 mm over the last 110 frames: no jitter.
    EXPECT_LT(highest - lowest, 1.0e-4f);
    EXPECT_NEAR(m.position.y, kStand, kMaxOverlap);
    EXPECT_LE(m.deepest, kMaxOverlap);
}

TEST(Mover, StandsStillOnTheGround) {
    World w;
    test::makeGround(w);
    Walker m{{0.0f, kStand + 0.5f}};
    for (int i = 0; i < 60; ++i) walk(w, m, 0.0f);  // falls and lands
    const Vec2 rest = m.position;
    for (int i = 0; i < 120; ++i) {
        walk(w, m, 0.0f);
        EXPECT_LT(distance(m.position, rest), 1.0e-4f) << "frame " << i;
    }
    EXPECT_TRUE(m.grounded);
    EXPECT_NEAR(m.velocity.y, 0.0f, 1.0e-3f);  // gravity clipped away each frame, not accumulated
}

// A 30° ramp from x = 2 rising 2.5 m, then a platform: the mover walks up it
// and along the top, always on the surface.
TEST(Mover, WalksUpASlope) {
    World w;
    test::makeGround(w, 100.0f);
    BodyId ramp = w.createBody({});
    const float run = 2.5f / std::tan(0.5235988f);  // 4.33 m
    w.createSegmentShape(ramp, {}, {{2.0f, 0.0f}, {2.0f + run, 2.5f}});
    w.createSegmentShape(ramp, {}, {{2.0f + run, 2.5f}, {30.0f, 2.5f}});
    Walker m{{0.0f, kStand}};
    for (int i = 0; i < 240; ++i) {
        walk(w, m, 3.0f);
        // Never below the surface under it (segment or ground), less the slop.
        const float x = m.position.x;
        float surface = 0.0f;
        if (x > 2.0f) surface = std::min(2.5f, (x - 2.0f) * std::tan(0.5235988f));
        // On the ramp the lower circle's centre is r/cos 30° above the line.
        const float clearance = (x > 2.0f && x < 2.0f + run) ? kStand / std::cos(0.5235988f) : kStand;
        EXPECT_GE(m.position.y, surface + clearance - kMaxOverlap - 0.02f) << "frame " << i << " x " << x;
    }
    EXPECT_GT(m.position.x, 2.0f + run + 1.0f);
    EXPECT_NEAR(m.position.y, 2.5f + kStand, kMaxOverlap);
    EXPECT_TRUE(m.grounded);
    EXPECT_LE(m.deepest, kMaxOverlap);
}

// A wall at x = 5: the mover stops against it and its velocity is clipped.
TEST(Mover, StopsAgainstAWallAndSlidesNoFurther) {
    World w;
    test::makeGround(w, 100.0f);
    BodyId wall = w.createBody({});
    w.createPolygonShape(wall, {}, makeOffsetBox(0.5f, 3.0f, {5.5f, 3.0f}, 0.0f));
    Walker m{{0.0f, kStand}};
    for (int i = 0; i < 180; ++i) walk(w, m, 4.0f);
    EXPECT_NEAR(m.position.x + kCapsule.radius, 5.0f, kMaxOverlap);
    EXPECT_LE(m.position.x + kCapsule.radius, 5.0f + kMaxOverlap);
    EXPECT_NEAR(m.position.y, kStand, kMaxOverlap);  // not pushed up the wall
    EXPECT_NEAR(m.velocity.x, 0.0f, 1.0e-4f);
    EXPECT_LE(m.deepest, kMaxOverlap);
}

// Pushing diagonally into a wall (no gravity): the mover slides along it at
// the speed of the motion's component along the wall, steadily.
TEST(Mover, SlidesAlongAWall) {
    World w({.gravity = {0, 0}});
    BodyId wall = w.createBody({});
    w.createSegmentShape(wall, {}, {{5.0f, -20.0f}, {5.0f, 20.0f}});
    Vec2 p{0.0f, 0.0f};
    float xLow = 100.0f, xHigh = -100.0f;
    for (int i = 0; i < 180; ++i) {
        MoverResult r = moveCharacter(w, kCapsule, p, kDt * Vec2{4.0f, 2.0f}, {4.0f, 2.0f}, {});
        p = r.position;
        if (i >= 120) {  // long after reaching the wall (1.2 s at 4 m/s)
            xLow = std::min(xLow, p.x);
            xHigh = std::max(xHigh, p.x);
        }
    }
    // 3 s at 2 m/s up the wall, never slowed by it.
    EXPECT_NEAR(p.y, 6.0f, 1e-3f);
    EXPECT_LE(p.x + kCapsule.radius, 5.0f + kMaxOverlap);
    EXPECT_LT(xHigh - xLow, 1e-4f);  // no jitter against the wall
}

// Stairs of 0.1 m risers and 0.4 m treads: the capsule's round bottom meets
// each nose on a slanted plane and slides up over it.
TEST(Mover, ClimbsSteps) {
    World w;
    test::makeGround(w, 100.0f);
    BodyId stairs = w.createBody({});
    for (int k = 1; k <= 8; ++k) {
        const float x0 = 2.0f + 0.4f * static_cast<float>(k - 1);
        const float h = 0.1f * static_cast<float>(k);
        w.createPolygonShape(stairs, {}, makeOffsetBox(0.2f, h * 0.5f, {x0 + 0.2f, h * 0.5f}, 0.0f));
    }
    w.createPolygonShape(stairs, {}, makeOffsetBox(5.0f, 0.4f, {10.2f, 0.4f}, 0.0f));  // landing at 0.8 m
    Walker m{{0.0f, kStand}};
    for (int i = 0; i < 300; ++i) walk(w, m, 2.0f);
    EXPECT_GT(m.position.x, 7.0f);                          // past the stairs
    EXPECT_NEAR(m.position.y, 0.8f + kStand, kMaxOverlap);  // on the landing
    EXPECT_LE(m.deepest, kMaxOverlap);
}

// One huge move at a thin wall (a segment): the cast stops it, no tunnelling.
TEST(Mover, DoesNotTunnelThroughAThinWall) {
    World w({.gravity = {0, 0}});
    BodyId wall = w.createBody({});
    w.createSegmentShape(wall, {}, {{3.0f, -5.0f}, {3.0f, 5.0f}});
    MoverResult r = moveCharacter(w, kCapsule, {0.0f, 0.0f}, {50.0f, 0.0f}, {3000.0f, 0.0f}, {});
    EXPECT_LE(r.position.x + kCapsule.radius, 3.0f + kMaxOverlap);
    EXPECT_GT(r.position.x + kCapsule.radius, 3.0f - 0.01f);
    EXPECT_NEAR(r.velocity.x, 0.0f, 1.0e-3f);
}

TEST(Mover, SolvePlanesStopsMotionIntoACorner) {
    CollisionPlane planes[2] = {{.normal = {0.0f, 1.0f}, .offset = 0.0f}, {.normal = {-1.0f, 0.0f}, .offset = 0.0f}};
    PlaneSolution s = solvePlanes({1.0f, -1.0f}, planes);
    // Neither plane lets it in by more than the slop.
    EXPECT_GE(s.delta.y, -kLinearSlop - 1e-6f);
    EXPECT_LE(s.delta.x, kLinearSlop + 1e-6f);
    EXPECT_GT(planes[0].push, 0.0f);
    EXPECT_GT(planes[1].push, 0.0f);
    // Along one plane it slides freely.
    CollisionPlane floor[1] = {{.normal = {0.0f, 1.0f}, .offset = 0.0f}};
    s = solvePlanes({1.0f, -1.0f}, floor);
    EXPECT_NEAR(s.delta.x, 1.0f, 1e-6f);
    EXPECT_NEAR(s.delta.y, -kLinearSlop, 1e-6f);
    const Vec2 v = clipVector({2.0f, -3.0f}, floor);
    EXPECT_NEAR(v.x, 2.0f, 1e-6f);
    EXPECT_NEAR(v.y, 0.0f, 1e-6f);
}

TEST(Mover, BadInputIsRefused) {
    World w;
    const float nan = std::nanf("");
    EXPECT_THROW((void)w.castMover(kCapsule, {nan, 0.0f}), Error);
    EXPECT_THROW((void)w.collideMover({{0, 0}, {0, 1}, -0.1f}), Error);
    EXPECT_THROW((void)moveCharacter(w, kCapsule, {nan, 0.0f}, {1, 0}, {}, {}), Error);
}

// A filter's accept function that throws (the game's own exception, or the
// i2d::Error of a change the locked world refuses) leaves the world unlocked
// afterwards: the mover's queries held the lock by hand and kept it for good.
TEST(Mover, AnAcceptFunctionThatThrowsLeavesTheWorldUsable) {
    World w;
    BodyId ground = test::makeGround(w);
    const ShapeId floor = w.bodyShapes(ground).front();
    const QueryFilter throwing{.accept = [](ShapeId) -> bool { throw std::runtime_error("game"); }};
    const QueryFilter destroying{.accept = [&](ShapeId s) {
        w.destroyShape(s);  // refused: the world is locked
        return true;
    }};
    for (const QueryFilter& filter : {throwing, destroying}) {
        EXPECT_ANY_THROW((void)w.collideMover(kCapsule, filter));
        EXPECT_ANY_THROW((void)w.castMover(kCapsule, {1.0f, 0.0f}, filter));
        EXPECT_ANY_THROW((void)moveCharacter(w, kCapsule, {0.0f, kStand}, {kDt, 0.0f}, {1.0f, 0.0f}, filter));
        w.step(kDt);  // threw "cannot be changed while it is stepping" before
        EXPECT_NO_THROW((void)test::makeBox(w, {3.0f, 0.5f}));
    }
    EXPECT_TRUE(w.isValid(floor));
}

}  // namespace
}  // namespace i2d
