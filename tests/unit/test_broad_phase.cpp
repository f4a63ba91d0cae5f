// The broadphase keeps every moving shape's speculative box inside its fat
// box. A body whose shapes cannot have moved further than the room they had
// when last measured is not measured again (Body::boxSlack, broad_phase.cpp
// leftFatBox). These tests hold each part of that bound: a box creeping a
// millimetre a step, a plank turning about its own origin (no translation at
// all), a box turning about a centre of mass set far from it, must each meet
// a wall rather than pass it (a fat box left behind finds no pair with the
// wall); and a box at rest must touch a wall within a speculative distance
// raised past the room it had.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include <impulse2d/impulse2d.hpp>

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;

struct Creep {
    Vec2 velocity{0.06f, 0.0f};                       ///< 1 mm a step
    float spin = 0.0f;                                ///< rad/s
    std::optional<Vec2> centerOfMass = std::nullopt;  ///< local, set by setMassData; else the shape's own centre
    bool plank = false;                 ///< a 4 m plank standing on end at the origin, instead of a unit box
    Vec2 boxCenter{};                   ///< where the unit box lies in the body (local)
    float wallFace = 2.0f;              ///< x of the wall's left face (m)
    float wallY = 0.0f;                 ///< the wall's centre, 10 m tall
    float speculativeDistance = 0.02f;  ///< the world's (m)
    int steps = 3500;
};

struct CreepResult {
    float past = -1.0f;  ///< how far the body's shape got past the wall's face (m)
    bool touched = false;
    /// Steps that ended with the body's box nearer the wall's face than 0.9
    /// of the speculative distance and no contact between them: a contact's
    /// manifold has a point within the speculative distance, so its pair was
    /// missing (only for a wall taller than the body's reach: there the box's
    /// gap is the shape's).
    int missedPairs = 0;
};

/// The body creeping into the wall.
CreepResult creepIntoWall(const Creep& c) {
    WorldSettings settings{.gravity = {0.0f, 0.0f}, .enableSleep = false};
    settings.speculativeDistance = c.speculativeDistance;
    World world(settings);
    BodyId wall = world.createBody({});
    world.createPolygonShape(wall, {}, makeOffsetBox(0.5f, 5.0f, {c.wallFace + 0.5f, c.wallY}, 0.0f));
    BodyId body = world.createBody({.type = BodyType::dynamic_body, .position = {0.0f, 0.0f}});
    const Polygon shape = c.plank ? makeOffsetBox(0.05f, 1.95f, {0.0f, 0.0f}, 0.0f)
                                  : makeOffsetBox(0.5f, 0.5f, c.boxCenter, 0.0f);
    world.createPolygonShape(body, {.density = 1.0f, .friction = 0.0f}, shape);
    if (c.centerOfMass) world.setMassData(body, {.mass = 1.0f, .center = *c.centerOfMass, .rotationalInertia = 0.2f});
    world.setLinearVelocity(body, c.velocity);
    world.setAngularVelocity(body, c.spin);
    CreepResult r;
    for (int i = 0; i < c.steps; ++i) {
        world.step(kDt);
        float right = -1.0e9f;
        for (const ShapeId s : world.bodyShapes(body)) right = std::max(right, world.shapeAABB(s).upper.x);
        const bool contact = !world.bodyContacts(body).empty();
        r.past = std::max(r.past, right - c.wallFace);
        r.touched = r.touched || contact;
        if (!contact && c.wallFace - right < 0.9f * c.speculativeDistance) ++r.missedPairs;
    }
    std::printf("[figure] past the wall %.5f m, touched %d, steps without the pair %d\n", r.past, r.touched ? 1 : 0,
                r.missedPairs);
    return r;
}

// Each body is stopped at the wall's face within 5 mm: its approach, 1 to 2
// mm a step, is met by a contact whose margin covers a step's travel (the
// measured overlaps are within a tenth of a millimetre). Passing through,
// the box's side would end 1.5 m past the face and the plank's end 5 cm.

TEST(BroadPhase, ABoxCreepingTowardsAWallMeetsIt) {
    const auto [past, touched, missed] = creepIntoWall({});
    EXPECT_TRUE(touched);
    EXPECT_EQ(missed, 0);
    EXPECT_LT(past, 0.005f);
}

TEST(BroadPhase, APlankTurningAboutItsOriginMeetsTheWall) {
    // Standing on end at the origin, turning clockwise at 0.03 rad/s (its end
    // 1 mm a step): its origin never moves, so only the turn in the bound
    // can tell that its box left the fat box. Its upper end meets the wall
    // 77° on.
    const auto [past, touched,
                missed] = creepIntoWall({.velocity = {0.0f, 0.0f}, .spin = -0.03f, .plank = true, .wallFace = 1.9f});
    EXPECT_TRUE(touched);
    EXPECT_EQ(missed, 0);
    EXPECT_LT(past, 0.005f);
}

TEST(BroadPhase, ABoxTurningAboutAFarCentreOfMassMeetsTheWall) {
    // The centre of mass 1.5 m from the box (setMassData): the box orbits it.
    const auto [past, touched, missed] = creepIntoWall({.spin = 0.2f, .centerOfMass = Vec2{0.0f, 1.5f}});
    EXPECT_TRUE(touched);
    EXPECT_EQ(missed, 0);
    EXPECT_LT(past, 0.005f);
}

TEST(BroadPhase, ABoxOrbitingItsBodysOriginMeetsTheWall) {
    // The box lies 8 m above its body's origin, and setMassData puts the
    // centre of mass at the origin: the body turns in place (0.01 rad/s, the
    // box 1.3 mm a step, to the right at first) and the box meets the wall
    // after 1 m. The bound needs the box's distance from the centre of mass
    // as it is now: measured from the box's own centre, where the centre of
    // mass was before setMassData, it is 0.7 m instead of 8.7, and the box
    // would be measured again only after 1.1 m, its fat box left behind:
    // so measured, it went 0.5 m into the wall, 373 steps without the pair.
    const auto [past, touched, missed] = creepIntoWall({.velocity = {0.0f, 0.0f},
                                                        .spin = -0.01f,
                                                        .centerOfMass = Vec2{0.0f, 0.0f},
                                                        .boxCenter = {0.0f, 8.0f},
                                                        .wallFace = 1.5f,
                                                        .wallY = 8.0f,
                                                        .steps = 1500});
    EXPECT_TRUE(touched);
    EXPECT_EQ(missed, 0);
    EXPECT_LT(past, 0.005f);
}

TEST(BroadPhase, ABoxAtRestTouchesAWallWithinARaisedSpeculativeDistance) {
    // A box at rest 0.3 m from the wall: beyond the 0.02 m speculative
    // distance and the 0.1 m margin of its fat box, so no pair and no
    // contact. With the speculative distance raised to 0.5 m the wall is
    // within it, and the next step must find the pair and a contact with a
    // point (a touching contact: its manifold has points within the
    // speculative distance), as a box created there would.
    World world({.gravity = {0.0f, 0.0f}, .enableSleep = false});
    BodyId wall = world.createBody({});
    world.createPolygonShape(wall, {}, makeOffsetBox(0.5f, 5.0f, {2.5f, 0.0f}, 0.0f));  // face at x = 2
    BodyId box = world.createBody({.type = BodyType::dynamic_body, .position = {1.2f, 0.0f}});
    world.createPolygonShape(box, {.density = 1.0f}, makeBox(0.5f, 0.5f));
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_TRUE(world.bodyContacts(box).empty());
    WorldSettings s = world.settings();
    s.speculativeDistance = 0.5f;
    world.setSettings(s);
    world.step(kDt);
    world.step(kDt);  // the pair found in a step's broadphase has its manifold in the next
    EXPECT_FALSE(world.bodyContacts(box).empty());
}

}  // namespace
}  // namespace i2d
