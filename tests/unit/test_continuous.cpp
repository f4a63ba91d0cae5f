// Continuous collision: fast bodies against thin static walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "world_fixtures.hpp"

namespace {

using namespace i2d;

struct Shot {
    float finalX = 0.0f;
    float maxX = -1.0e30f;  ///< furthest the bullet's centre got
};

// A circle of radius r shot along +x at `speed` (no gravity) at a static wall
// 0.1 m thick whose left face is at x = 10.
Shot shootAtWall(float speed, float radius, bool continuous, float dt = 1.0f / 60.0f) {
    WorldSettings s;
    s.gravity = {0.0f, 0.0f};
    s.enableContinuous = continuous;
    s.enableSleep = false;
    World world(s);
    BodyId wall = world.createBody({.position = {10.05f, 0.0f}});
    world.createPolygonShape(wall, {}, makeBox(0.05f, 5.0f));
    BodyId bullet = world.createBody(
        {.type = BodyType::dynamic_body, .position = {0.0f, 0.3f}, .linearVelocity = {speed, 0.0f}});
    world.createCircleShape(bullet, {.density = 4.0f}, {{0.0f, 0.0f}, radius});
    Shot shot;
    for (int i = 0; i < 120; ++i) {
        world.step(dt);
        shot.maxX = std::max(shot.maxX, world.position(bullet).x);
    }
    shot.finalX = world.position(bullet).x;
    return shot;
}

// Speeds from 10 to 2000 m/s: 0.17 m to 33 m per step at 60 Hz, against a
// 0.1 m wall and a 0.05 m bullet. With continuous collision the bullet's
// centre never gets past the wall's left face (x = 10) by more than its own
// radius plus the 0.005 m target gap of the sweep. Without it these straight
// shots are now stopped too, by speculative contacts whose margin follows the
// approach (the second test); the shots that still pass without the sweep,
// spinning ones, are in test_continuous_property.cpp.
TEST(Continuous, BulletsDoNotPassAThinWall) {
    for (float speed : {10.0f, 50.0f, 200.0f, 500.0f, 2000.0f}) {
        Shot shot = shootAtWall(speed, 0.05f, true);
        EXPECT_LT(shot.maxX, 10.0f) << speed << " m/s";
        EXPECT_LT(shot.finalX, 10.0f) << speed << " m/s";
    }
}

// A contact's speculative margin grows with how far its bodies can close in
// the step (contact.cpp), so a shot that does not turn is stopped at the
// wall's face even without the sweep: with the fixed 0.02 m margin alone the
// shots at 200, 500 and 2000 m/s passed through.
TEST(Continuous, WithoutItStraightShotsStopAtSpeculativeContacts) {
    for (float speed : {200.0f, 500.0f, 2000.0f}) {
        const Shot shot = shootAtWall(speed, 0.05f, false);
        EXPECT_LT(shot.maxX, 10.0f) << speed << " m/s";
        EXPECT_LT(shot.finalX, 10.0f) << speed << " m/s";
    }
}

// The speculative margin is measured along the manifold's normal, which
// between two corners points from one to the other: a box falling 0.1 m to
// the side of a ledge, its lower corner above the ledge's upper one, closes
// along that diagonal at 0.7 times its speed though its side never meets the
// ledge. Struck there as an impact, it was thrown sideways. The ledge's side
// keeps them 0.1 m apart whatever the fall, so no point may be kept
// (contact.cpp, apartAlongASide): the box falls past untouched, with no
// sideways speed and no spin.
TEST(Continuous, ABoxFallingPastACornerIsNotTouched) {
    WorldSettings s;
    s.enableSleep = false;
    World world(s);
    BodyId ledge = world.createBody({});
    world.createPolygonShape(ledge, {}, makeBox(0.5f, 0.5f));
    // Lower-left corner at (0.6, 0.6): 0.1 m right of the ledge's side, 0.1 m above its top.
    BodyId box = world.createBody(
        {.type = BodyType::dynamic_body, .position = {1.1f, 1.1f}, .linearVelocity = {0.0f, -14.0f}});
    world.createPolygonShape(box, {}, makeBox(0.5f, 0.5f));
    for (int i = 0; i < 20; ++i) {
        world.step(1.0f / 60.0f);
        // Gravity acts along y alone: anything else came from a contact.
        EXPECT_EQ(world.linearVelocity(box).x, 0.0f) << "step " << i;
        EXPECT_EQ(world.angularVelocity(box), 0.0f) << "step " << i;
    }
    EXPECT_LT(world.position(box).y, -3.0f);  // it fell past (4.7 m in 20 steps)
}

// A box sliding fast along the ground (gap under the speculative distance)
// must not be stopped by the sweep against the ground it rests on: in 0.5 s
// at 30 m/s with friction 0 it travels 15 m.
TEST(Continuous, FastSlidingIsNotStalled) {
    WorldSettings s;
    s.enableSleep = false;
    World world(s);
    test::makeGround(world, 100.0f, 0.0f);
    BodyId box = world.createBody(
        {.type = BodyType::dynamic_body, .position = {-50.0f, 0.1f}, .linearVelocity = {30.0f, 0.0f}});
    world.createPolygonShape(box, {.friction = 0.0f}, makeBox(0.1f, 0.1f));
    for (int i = 0; i < 30; ++i) world.step(1.0f / 60.0f);
    // Frictionless, horizontal: the exact travel is 30 · 0.5 = 15 m; allow 1%.
    EXPECT_NEAR(world.position(box).x, -35.0f, 0.15f);
    EXPECT_NEAR(world.linearVelocity(box).x, 30.0f, 0.3f);
}

// A kinematic wall 2 cm thick moving at 20 m/s (0.33 m a step) sweeps ten
// balls of radius 5 cm resting 0.5 m apart along the ground; struck, they
// run ahead of it, strike one another and hop a few millimetres over the
// ground. A ball rolling at 20 m/s that closed a 6 mm hop over the ground in
// a step (its contact, made at the step's start, let it) was taken for a hit
// by continuous collision and put back to the start of its step, 33 cm
// behind, where the wall, which is not swept, passed over it: 2 of the 10
// ended behind the wall while still on the ground (Box2D 2.4.1: none). The
// approach a sweep lets pass as a graze now includes the gap the shape had
// when the step began. Bound: no ball's centre is ever behind the wall's
// front face while the ball is on the ground.
TEST(Continuous, BallsRunningAheadOfAFastKinematicWallStayAhead) {
    World world({.enableSleep = false});
    const BodyId ground = world.createBody({.position = {0.0f, -0.5f}});
    world.createPolygonShape(ground, {}, makeBox(80.0f, 0.5f));
    const BodyId wall = world.createBody(
        {.type = BodyType::kinematic_body, .position = {-1.0f, 1.0f}, .linearVelocity = {20.0f, 0.0f}});
    world.createPolygonShape(wall, {}, makeBox(0.01f, 1.0f));
    std::vector<BodyId> balls;
    for (int i = 0; i < 10; ++i) {
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = {1.0f + 0.5f * static_cast<float>(i), 0.05f}});
        world.createCircleShape(b, {}, {{0.0f, 0.0f}, 0.05f});
        balls.push_back(b);
    }
    int behind = 0;
    for (int step = 0; step < 300; ++step) {
        world.step(1.0f / 60.0f);
        const float front = world.position(wall).x + 0.01f;
        for (const BodyId b : balls) {
            const Vec2 p = world.position(b);
            if (p.y > -0.5f && std::abs(p.x) < 80.0f && p.x < front) ++behind;  // on the ground, behind the wall
        }
    }
    EXPECT_EQ(behind, 0);
}

// A thin rod spinning at 60 rad/s thrown at 20 m/s against a wall as thin as
// the rod: its ends sweep about 1.3 m per step (rotation dominates), yet no
// part of it may end up beyond the wall. Gravity off so only the sweep matters.
float spinningRodFurthestX(bool continuous) {
    WorldSettings s;
    s.gravity = {0.0f, 0.0f};
    s.enableContinuous = continuous;
    World world(s);
    BodyId wall = world.createBody({.position = {5.02f, 0.0f}});
    world.createPolygonShape(wall, {}, makeBox(0.02f, 20.0f));
    BodyId rod = world.createBody({.type = BodyType::dynamic_body,
                                   .position = {0.0f, 0.0f},
                                   .linearVelocity = {20.0f, 0.0f},
                                   .angularVelocity = 60.0f});
    const Polygon shape = makeBox(1.0f, 0.02f);
    world.createPolygonShape(rod, {}, shape);
    float furthest = -1.0e30f;
    for (int i = 0; i < 120; ++i) {
        world.step(1.0f / 60.0f);
        Transform xf{world.position(rod), makeRot(world.angle(rod))};
        for (int k = 0; k < shape.count; ++k) furthest = std::max(furthest, transformPoint(xf, shape.vertices[k]).x);
    }
    return furthest;
}

TEST(Continuous, SpinningRodDoesNotPassAThinWall) {
    // The wall's far face is at x = 5.04; a rod corner may sink into the wall
    // by the contact's allowed penetration, far less than the 0.04 m thickness.
    EXPECT_LT(spinningRodFurthestX(true), 5.04f);
}

// A ball fired at a free 0.1 m plank (dynamic, no gravity), at its middle
// so that the plank does not spin out of the way: as a bullet it is swept
// against the plank and cannot pass it. Without the flag (dynamic-versus-
// dynamic pairs are not swept) it passed through with the fixed 0.02 m
// speculative margin; the margin now follows the approach, and the contact
// stops it at the plank's face as well. Returns the
// largest x of the ball's centre in the plank's frame over the run (the
// plank's near face is at x = −0.05 in its frame).
float ballIntoPlank(bool bullet, float speed) {
    WorldSettings s;
    s.gravity = {0.0f, 0.0f};
    s.enableSleep = false;
    World world(s);
    BodyId plank = world.createBody({.type = BodyType::dynamic_body, .position = {5.0f, 0.0f}});
    world.createPolygonShape(plank, {.density = 1.0f}, makeBox(0.05f, 1.0f));
    BodyId ball = world.createBody({.type = BodyType::dynamic_body,
                                    .position = {0.0f, 0.0f},
                                    .linearVelocity = {speed, 0.0f},
                                    .isBullet = bullet});
    world.createCircleShape(ball, {.density = 4.0f}, {{0.0f, 0.0f}, 0.05f});
    float worst = -1.0e30f;
    for (int i = 0; i < 60; ++i) {
        world.step(1.0f / 60.0f);
        const Transform plankXf{world.position(plank), world.rotation(plank)};
        worst = std::max(worst, invTransformPoint(plankXf, world.position(ball)).x);
    }
    return worst;
}

TEST(Continuous, BulletDoesNotPassADynamicPlank) {
    for (float speed : {50.0f, 200.0f, 400.0f}) {
        // The ball's centre never gets past the plank's near face: its
        // surface may sink into the plank by at most its own radius.
        EXPECT_LT(ballIntoPlank(true, speed), -0.05f) << speed << " m/s";
    }
    EXPECT_LT(ballIntoPlank(false, 200.0f), -0.05f);  // not a bullet: stopped by its speculative contact
}

// A bullet meets a dynamic plank where the plank ended the step, found
// through the plank's box in the broadphase tree, which must then hold that
// end pose. A thin plank 1 m long, 1.2 m above the bullet's line, is driven
// down by a force that moves it about a metre in one step, across the line:
// its box from the step's start (nothing foreseen its move) lies wholly
// above the line. The bullet, 2.5 m from the plank at 300 m/s (5 m a step),
// must stop at the plank's face rather than pass to 2.5 m beyond it.
TEST(Continuous, ABulletMeetsAPlankDrivenAcrossItsPathWithinTheStep) {
    World world({.gravity = {0.0f, 0.0f}, .enableSleep = false});
    const BodyId plank = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 1.2f}});
    world.createPolygonShape(plank, {.density = 1.0f}, makeBox(0.05f, 0.5f));
    const BodyId bullet = world.createBody({.type = BodyType::dynamic_body,
                                            .position = {-2.5f, 0.0f},
                                            .linearVelocity = {300.0f, 0.0f},
                                            .isBullet = true});
    world.createCircleShape(bullet, {.density = 1.0f}, {{0.0f, 0.0f}, 0.05f});
    // The force for about 1 m in the step: 4 substeps of semi-implicit Euler
    // move a body a·Δt²·5/8 from rest.
    const float mass = world.mass(plank), dt = 1.0f / 60.0f;
    world.applyForceToCenter(plank, {0.0f, -mass * 1.0f / (dt * dt * 0.625f)});
    world.step(dt);
    const float plankBottom = world.position(plank).y - 0.5f, plankTop = world.position(plank).y + 0.5f;
    ASSERT_LT(plankBottom, -0.05f);  // the plank did end the step across the bullet's line
    ASSERT_GT(plankTop, 0.05f);
    EXPECT_LT(world.position(bullet).x, world.position(plank).x - 0.05f);
}

// A body whose centroid begins a step nearer a static surface than its own
// extent (partly through a thin floor) keeps the step's motion along the
// surface and its turn; only its centroid's approach is taken out. Put back
// to the step's start instead, a 2 m × 5 cm plank thrown spinning at 20
// rad/s at a chain floor of 0.5 m segments stayed where it was from its
// tenth step on, reporting 9 m/s and 20 rad/s it never flew. Bound: over 20
// steps it moves at least half the way its reported speed along the floor
// takes it, and turns at least half its reported spin (before: not at all).
TEST(Continuous, ABodyPartlyThroughAFloorIsNotFrozen) {
    WorldSettings s;
    s.enableSleep = false;
    World world(s);
    std::vector<Vec2> points;
    for (int i = 100; i >= -100; --i) points.push_back({0.5f * static_cast<float>(i), 0.0f});
    world.createChain(world.createBody({}), {.points = points});
    BodyId plank = world.createBody({.type = BodyType::dynamic_body,
                                     .position = {0.0f, 0.3f},
                                     .angle = 3.182f,
                                     .linearVelocity = {-8.99f, -20.0f},
                                     .angularVelocity = 20.0f});
    world.createPolygonShape(plank, {}, makeBox(1.0f, 0.025f));
    const float dt = 1.0f / 60.0f;
    for (int i = 0; i < 20; ++i) world.step(dt);
    const Vec2 p0 = world.position(plank);
    float turned = 0.0f, reportedTurn = 0.0f, reportedMove = 0.0f, lastAngle = world.angle(plank);
    for (int i = 0; i < 20; ++i) {
        reportedMove += std::abs(world.linearVelocity(plank).x) * dt;
        world.step(dt);
        reportedTurn += std::abs(world.angularVelocity(plank)) * dt;
        float d = world.angle(plank) - lastAngle;
        d = std::remainder(d, 2.0f * 3.14159265f);
        turned += std::abs(d);
        lastAngle = world.angle(plank);
    }
    EXPECT_GT(std::abs(world.position(plank).x - p0.x), 0.5f * reportedMove);
    EXPECT_GT(turned, 0.5f * reportedTurn);
}

// A box landing under a push towards the ground far beyond its weight (a
// force the game applies for one step) ends that step held by its contact
// some centimetres into the ground (its soft rows yield under 100 times its
// weight), and continuous collision puts it back on the surface. The
// velocity it is given there took the step's acceleration back as if the box
// had flown free since it reached the surface: 6.5 m/s up under 1,000 N,
// and the 400 m/s speed limit under 100 kN, from a landing with no
// restitution. Whatever the contacts do, nothing in a landing without
// restitution throws the box up faster than the push that moves overlaps
// apart (WorldSettings::maxPushSpeed), so it never rises higher than that
// speed carries it against gravity, v²/2g (0.46 m at the defaults).
TEST(Continuous, ABoxLandingUnderALargePushIsNotThrownUp) {
    for (float force : {300.0f, 1.0e3f, 1.0e5f}) {
        World world;
        BodyId ground = world.createBody({});
        world.createPolygonShape(ground, {}, makeBox(10.0f, 0.5f));
        // 5 cm above the ground (its surface at y = 0.5), falling at 10 m/s.
        BodyId box = world.createBody(
            {.type = BodyType::dynamic_body, .position = {0.0f, 1.05f}, .linearVelocity = {0.0f, -10.0f}});
        world.createPolygonShape(box, {.density = 1.0f}, makeBox(0.5f, 0.5f));
        const WorldSettings& s = world.settings();
        const float g = -s.gravity.y;
        const float rest = 1.0f;  // the box's centre resting on the ground
        float highest = 0.0f, fastestUp = 0.0f;
        for (int i = 0; i < 60; ++i) {
            if (i == 0) world.applyForceToCenter(box, {0.0f, -force});
            world.step(1.0f / 60.0f);
            highest = std::max(highest, world.position(box).y - rest);
            fastestUp = std::max(fastestUp, world.linearVelocity(box).y);
        }
        EXPECT_LE(fastestUp, s.maxPushSpeed) << "force " << force;
        EXPECT_LE(highest, s.maxPushSpeed * s.maxPushSpeed / (2.0f * g)) << "force " << force;
    }
}

// A circle shot at the vertex two static segments share (a wall from
// (0, 50) to (0, −50) in two pieces, or a chain through the same points),
// aimed at it exactly, is stopped as by one segment: its centre never gets
// past the wall (x = 0). The ray cast of the centroid's chord could miss a
// chord through the very end of each segment, and the sweep then took the
// shot for a graze: 23 to 25 of 4,785 such aims (speeds 20 to 300 m/s,
// −80 to 80°) passed two segments untouched, 6 a chain's vertex.
TEST(Continuous, ShotsAtASharedVertexDoNotPass) {
    int through = 0, shots = 0;
    for (const bool chain : {false, true})
        for (float speed = 30.0f; speed <= 300.0f; speed += 30.0f)
            for (float degrees = -75.0f; degrees <= 75.0f; degrees += 5.0f) {
                WorldSettings s;
                s.enableSleep = false;
                World world(s);
                BodyId wall = world.createBody({});
                if (chain) {
                    const Vec2 points[] = {{0.0f, 50.0f}, {0.0f, 2.0f}, {0.0f, 0.0f}, {0.0f, -2.0f}, {0.0f, -50.0f}};
                    world.createChain(wall, {.points = points});
                } else {
                    world.createSegmentShape(wall, {}, {{0.0f, 50.0f}, {0.0f, 0.0f}});
                    world.createSegmentShape(wall, {}, {{0.0f, 0.0f}, {0.0f, -50.0f}});
                }
                const float a = degrees * 3.14159265f / 180.0f;
                BodyId ball = world.createBody({.type = BodyType::dynamic_body,
                                                .position = {-1.0f, -std::tan(a)},
                                                .linearVelocity = {speed * std::cos(a), speed * std::sin(a)},
                                                .gravityScale = 0.0f});
                world.createCircleShape(ball, {}, {{0.0f, 0.0f}, 0.1f});
                for (int i = 0; i < 6; ++i) world.step(1.0f / 60.0f);
                ++shots;
                if (world.position(ball).x > 0.0f) ++through;
            }
    EXPECT_EQ(through, 0) << "of " << shots << " shots";
}

// A flat box (0.42 × 0.15 m, 63 g) pressed into a thin ground by a box 100
// to 10,000 times as dense on it (50 to 5,000 kg) sinks a little each step,
// never further than the speculative distance, so continuous collision did
// not sweep it. On a two-sided segment it went in until its centre crossed
// the line (1,000 and 10,000 times), and the segment pushed it out below; on
// a chain it tilted 5° and, 7 cm deep over the chain's vertex, both segments
// dropped their manifolds as ghosts (100 times): it fell through either way,
// more than 400 m. Now a body with a contact deeper than the deep-overlap
// depth against a static or kinematic body is swept too (continuous.cpp,
// markPressedBodies), so its centre's probe keeps it from crossing, and a
// chain segment takes a manifold deeper than the speculative distance
// against its face alone instead of dropping it as a ghost (seams.cpp). The
// bound: the flat box's centre never crosses the ground's line (its half
// thickness, 7.5 cm, below where it rests), which the one-sided chain and
// the two-sided segment each take for the other side. Measured: its centre
// at least 3.5 cm (chain) and 0.3 cm (segment) above the line.
TEST(Continuous, AThinBodyUnderAHeavyLoadStaysOnAThinGround) {
    for (const bool chain : {true, false})
        for (const float density : {100.0f, 1000.0f, 10000.0f}) {
            World world({.enableSleep = false});
            BodyId ground = world.createBody({});
            if (chain) {
                std::vector<Vec2> points;
                for (int i = 0; i <= 20; ++i) points.push_back({10.0f - static_cast<float>(i), 0.0f});  // solid above
                world.createChain(ground, {.points = points});
            } else {
                world.createSegmentShape(ground, {}, Segment{{-10.0f, 0.0f}, {10.0f, 0.0f}});
            }
            BodyId flat = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 0.075f}});
            world.createPolygonShape(flat, {}, makeBox(0.21f, 0.075f));
            BodyId heavy = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 0.4f}});
            world.createPolygonShape(heavy, {.density = density}, makeBox(0.5f, 0.25f));
            float lowest = 1.0f;
            for (int i = 0; i < 600; ++i) {
                world.step(1.0f / 60.0f);
                lowest = std::min(lowest, world.position(flat).y);
            }
            std::printf("[figure] flat box under a box %.0f times as dense on a %s: its centre at least %.4f m above "
                        "the line\n",
                        density, chain ? "chain" : "segment", lowest);
            EXPECT_GT(lowest, 0.0f) << (chain ? "chain" : "segment") << ", density " << density;
        }
}

TEST(Continuous, BulletFlagIsKept) {
    World world;
    BodyId b = world.createBody({.type = BodyType::dynamic_body, .isBullet = true});
    EXPECT_TRUE(world.isBullet(b));
    world.setBullet(b, false);
    EXPECT_FALSE(world.isBullet(b));
}

}  // namespace
