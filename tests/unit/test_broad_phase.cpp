// The broadphase keeps every moving shape's speculative box inside its fat
// box. A body whose shapes cannot have moved further than the room they had
// when last measured is not measured again (Body::boxSlack, broad_phase.cpp
// leftFatBox). These tests hold each part of that bound: a box creeping a
// millimetre a step, a plank turning about its own origin (no translation at
// all), a box turning about a centre of mass set far from it, must each meet
// a wall rather than pass it (a fat box left behind finds no pair with the
// wall); a box at rest must touch a wall within a speculative distance
// raised past the room it had; and in a random world of spinning discs
// off their bodies' centres, teleported, re-massed and under a changing
// speculative distance, every pair of discs within the speculative
// distance at a step's start has its contact in that step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

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

TEST(BroadPhase, EveryPairWithinTheSpeculativeDistanceHasItsContact) {
    // Thirty discs up to 2.8 m from their bodies' origins, on bodies whose
    // centres of mass are moved up to 2.8 m off it (setMassData), drifting
    // (at most 0.3 m/s) and turning (at most 1 rad/s) inside a walled 20 m
    // square without gravity, so that most of a disc's motion is the turn;
    // every 25 steps one body is teleported, one re-massed, and the
    // speculative distance switched between 0.02 and 0.2 m. A contact's
    // manifold is computed at its step's start with a margin of at least
    // the speculative distance, so two discs nearer than that at the end of
    // one step (0.9 of it, for rounding) must touch in the next: a pair the
    // broadphase missed (a fat box left behind) has no contact at all.
    // Without the turn in the bound on a body's motion 8 such pairs have none.
    std::mt19937 rng(20261203);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    World world({.gravity = {0.0f, 0.0f}, .enableSleep = false});
    BodyId walls = world.createBody({});
    for (const Vec2 c : {Vec2{0.0f, -10.5f}, Vec2{0.0f, 10.5f}, Vec2{-10.5f, 0.0f}, Vec2{10.5f, 0.0f}})
        world.createPolygonShape(walls, {.restitution = 1.0f},
                                 makeOffsetBox(c.x == 0.0f ? 11.0f : 0.5f, c.x == 0.0f ? 0.5f : 11.0f, c, 0.0f));
    struct Disc {
        BodyId body;
        ShapeId shape;
        float radius;
    };
    std::vector<Disc> discs;
    auto remass = [&](BodyId b) {
        world.setMassData(b, {.mass = 0.5f + u(rng),
                              .center = {4.0f * u(rng) - 2.0f, 4.0f * u(rng) - 2.0f},
                              .rotationalInertia = 0.05f + 0.5f * u(rng)});
    };
    for (int i = 0; i < 30; ++i) {
        const BodyId b = world.createBody({.type = BodyType::dynamic_body,
                                           .position = {16.0f * u(rng) - 8.0f, 16.0f * u(rng) - 8.0f},
                                           .angle = 6.0f * u(rng) - 3.0f,
                                           .linearVelocity = {0.4f * u(rng) - 0.2f, 0.4f * u(rng) - 0.2f},
                                           .angularVelocity = 2.0f * u(rng) - 1.0f});
        const float r = 0.1f + 0.3f * u(rng);
        const ShapeId s = world.createCircleShape(b, {.density = 1.0f, .friction = 0.3f, .restitution = 0.5f},
                                                  Circle{{4.0f * u(rng) - 2.0f, 4.0f * u(rng) - 2.0f}, r});
        remass(b);
        discs.push_back({b, s, r});
    }
    auto centre = [&](const Disc& d) {
        const AABB box = world.shapeAABB(d.shape);
        return 0.5f * (box.lower + box.upper);
    };
    int checked = 0, missed = 0;
    for (int step = 1; step <= 1200; ++step) {
        if (step % 25 == 0) {
            const Disc& t = discs[static_cast<std::size_t>(step / 25) % discs.size()];
            world.setTransform(t.body, {16.0f * u(rng) - 8.0f, 16.0f * u(rng) - 8.0f}, 6.0f * u(rng) - 3.0f);
            remass(discs[static_cast<std::size_t>(step / 25 + 7) % discs.size()].body);
            WorldSettings s = world.settings();
            s.speculativeDistance = s.speculativeDistance < 0.1f ? 0.2f : 0.02f;
            world.setSettings(s);
        }
        // The pairs within the speculative distance at this step's start.
        const float spec = world.settings().speculativeDistance;
        std::vector<std::pair<std::size_t, std::size_t>> near;
        for (std::size_t i = 0; i < discs.size(); ++i)
            for (std::size_t j = i + 1; j < discs.size(); ++j)
                if (length(centre(discs[j]) - centre(discs[i])) - discs[i].radius - discs[j].radius < 0.9f * spec)
                    near.emplace_back(i, j);
        world.step(kDt);
        for (const auto& [i, j] : near) {
            ++checked;
            bool found = false;
            for (const ContactData& c : world.bodyContacts(discs[i].body))
                found = found || (c.shapeA == discs[j].shape || c.shapeB == discs[j].shape);
            if (!found) ++missed;
        }
    }
    std::printf("[figure] pairs within the speculative distance %d, without their contact %d\n", checked, missed);
    EXPECT_GT(checked, 100);  // the world does bring discs near each other
    EXPECT_EQ(missed, 0);
}

}  // namespace
}  // namespace i2d
