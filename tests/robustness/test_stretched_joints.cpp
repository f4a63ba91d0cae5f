// Joints the game leaves open (Joint::stretched, docs/joints.md "Stretched
// joints"): created with their anchors apart, or pulled apart by moving a
// body. Their error is closed on pseudo-velocities, which move bodies without
// leaving them a velocity, so closing it gains no energy. Sleeping off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <impulse2d/impulse2d.hpp>

namespace i2d {
namespace {

constexpr float kDt = 1.0f / 60.0f;
constexpr float kGravity = 10.0f;

/// Kinetic plus potential energy of `bodies`, the potential measured from `floor`.
double energy(const World& world, const std::vector<BodyId>& bodies, float floor) {
    double e = 0.0;
    for (BodyId b : bodies) {
        const float w = world.angularVelocity(b);
        e += 0.5 * world.mass(b) * lengthSquared(world.linearVelocity(b)) + 0.5 * world.rotationalInertia(b) * w * w +
             world.mass(b) * kGravity * (world.worldCenterOfMass(b).y - floor);
    }
    return e;
}

/// A plank 1 m × 0.2 m at (x, 10) (0.2 kg at density 1).
BodyId plank(World& world, float x, float density) {
    BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {x, 10}});
    world.createPolygonShape(b, {.density = density}, makeBox(0.5f, 0.1f));
    return b;
}

/// How far a revolute joint's anchors are apart (m).
float opening(const World& world, JointId j) {
    const RevoluteJointDef d = world.revoluteJointDef(j);
    return length(transformPoint(world.transform(world.jointBodyB(j)), d.localAnchorB) -
                  transformPoint(world.transform(world.jointBodyA(j)), d.localAnchorA));
}

// Solver2D's Stretched Chain (the reference's hard cases): 40 discs of radius
// 0.2 m that do not collide, on revolute joints with 1 m links but created 2 m
// apart, so every joint starts 1 m open (the first 1.5 m), hung from a static
// anchor; the bar: back to its length within 1 s, no energy gained. Before
// stretched joints the soft rows closed every joint at biasRate·1 m = 68 m/s
// and flung the discs at 246 m/s; the energy peaked at 36,000 J over the start.
TEST(StretchedJoints, AChainCreatedStretchedClosesWithinASecondWithoutGainingEnergy) {
    for (int substeps : {4, 1}) {
        WorldSettings settings;
        settings.enableSleep = false;
        settings.substeps = substeps;
        World world(settings);
        const float top = 20.0f;
        BodyId previous = world.createBody({});
        std::vector<BodyId> discs;
        std::vector<JointId> joints;
        for (int i = 0; i < 40; ++i) {
            BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {2.0f * (i + 1), top}});
            world.createCircleShape(b, {.density = 1.0f, .filter = {.groupIndex = -1}}, Circle{{0, 0}, 0.2f});
            joints.push_back(world.createRevoluteJoint({.bodyA = previous,
                                                        .bodyB = b,
                                                        .localAnchorA = i == 0 ? Vec2{0, top} : Vec2{0.5f, 0},
                                                        .localAnchorB = {-0.5f, 0}}));
            discs.push_back(b);
            previous = b;
        }
        auto totalOpening = [&] {
            float sum = 0.0f;
            for (JointId j : joints) sum += opening(world, j);
            return sum;
        };
        ASSERT_GT(totalOpening(), 40.0f);
        // The scale of this chain's energy: what it releases hanging straight
        // down from the anchor, disc i 0.5 + i m below it (1,005 J). The energy
        // audit's bar (tests/testbed/test_energy_audit.cpp) is 1 % of the energy
        // a system can give.
        double scale = 0.0;
        for (int i = 0; i < 40; ++i) scale += world.mass(discs[static_cast<std::size_t>(i)]) * kGravity * (0.5 + i);
        const double start = energy(world, discs, top);
        double peak = start;
        float closedAtOneSecond = 0.0f;
        for (int step = 1; step <= 600; ++step) {
            world.step(kDt);
            peak = std::max(peak, energy(world, discs, top));
            if (step == 60) closedAtOneSecond = totalOpening();
        }
        std::printf(
            "[figure] stretched chain, %d substeps: open %.3f m at 1 s (of 41.5), energy at most %+.3f J (scale %.0f J)\n",
            substeps, static_cast<double>(closedAtOneSecond), peak - start, scale);
        EXPECT_LE(peak - start, 0.01 * scale) << substeps << " substeps";
        // Back to its length: the joints' summed opening within 1 % of the
        // chain's 40 m at 1 s (measured 0.08 m). At one substep a 40-link chain
        // swept by Gauss-Seidel opens up again as it swings, as one created
        // closed does (docs/joints.md), so only the default is held to it.
        if (substeps == 4) {
            EXPECT_LE(closedAtOneSecond, 0.4f);
        }
    }
}

// A body the game moves 2.2 m away from the body it is hinged to, in mid-air
// while the pair tumbles: the hinge closes within a few steps and the pair
// gains no energy (the push's equal and opposite pseudo-impulses move neither
// the pair's centre of mass nor leave a velocity). Before stretched joints the
// soft rows closed it at 68 m/s a metre and the pair gained 450 J.
TEST(StretchedJoints, ABodyMovedAwayFromItsHingeIsPulledBackWithoutGainingEnergy) {
    World world({.enableSleep = false});
    BodyId a = plank(world, 0.0f, 1.0f);
    BodyId b = plank(world, 1.0f, 3.0f);
    JointId hinge = world.createRevoluteJoint(
        {.bodyA = a, .bodyB = b, .localAnchorA = {0.5f, 0}, .localAnchorB = {-0.5f, 0}});
    world.setAngularVelocity(a, 2.0f);
    for (int i = 0; i < 30; ++i) world.step(kDt);
    world.setTransform(b, world.position(b) + Vec2{2.0f, 1.0f}, world.angle(b) + 1.0f);
    ASSERT_GT(opening(world, hinge), 2.0f);
    const std::vector<BodyId> pair{a, b};
    const double start = energy(world, pair, 0.0f);
    // Kinetic energy when moved (tumbling and falling for 0.5 s): 1 % of it
    // is allowed for the rows' rounding (measured: the energy only falls).
    double kinetic = start;
    for (BodyId x : pair) kinetic -= world.mass(x) * kGravity * world.worldCenterOfMass(x).y;
    double peak = start;
    int closedAt = -1;
    for (int step = 1; step <= 120; ++step) {
        world.step(kDt);
        peak = std::max(peak, energy(world, pair, 0.0f));
        if (closedAt < 0 && opening(world, hinge) < 0.01f) closedAt = step;
    }
    std::printf("[figure] hinge moved 2.2 m open: closed within 1 cm after %d steps, energy at most %+.4f J\n",
                closedAt, peak - start);
    EXPECT_LE(peak - start, 0.01 * kinetic);
    // The push closes β = biasRate·h ≈ 0.28 of the gap a substep (0.73 a
    // step): 2.2 m to 1 cm takes about 4 steps (measured 5); 10 allows the
    // joint's leaving the exact tree and its rows' first substeps.
    EXPECT_GE(closedAt, 1);
    EXPECT_LE(closedAt, 10);
}

// A tree of unlike joints moved apart: a rigid weld and a hinge, their bodies
// moved 1.5 m apart. The points close without energy; the weld's angle,
// which a push that only translates cannot turn, is closed by its soft rows
// once the points are.
TEST(StretchedJoints, AWeldAndAHingeMovedApartCloseTheirPointsAndTheWeldItsAngle) {
    World world({.enableSleep = false});
    BodyId a = plank(world, 0.0f, 1.0f);
    BodyId b = plank(world, 1.0f, 1.0f);
    BodyId c = plank(world, 2.0f, 1.0f);
    JointId hinge = world.createRevoluteJoint(
        {.bodyA = a, .bodyB = b, .localAnchorA = {0.5f, 0}, .localAnchorB = {-0.5f, 0}});
    JointId weld = world.createWeldJoint(
        {.bodyA = b, .bodyB = c, .localAnchorA = {0.5f, 0}, .localAnchorB = {-0.5f, 0}});
    world.setTransform(c, {3.0f, 11.0f}, 0.6f);
    world.setTransform(a, {-1.0f, 9.5f}, 0.0f);
    const std::vector<BodyId> bodies{a, b, c};
    const double start = energy(world, bodies, 0.0f);
    double peak = start;
    for (int step = 1; step <= 120; ++step) {
        world.step(kDt);
        peak = std::max(peak, energy(world, bodies, 0.0f));
    }
    const WeldJointDef wd = world.weldJointDef(weld);
    const float weldGap = length(transformPoint(world.transform(c), wd.localAnchorB) -
                                 transformPoint(world.transform(b), wd.localAnchorA));
    const float weldAngle = std::fabs(world.angle(c) - world.angle(b) - wd.referenceAngle);
    std::printf(
        "[figure] weld and hinge moved apart: after 2 s hinge %.4f m, weld %.4f m and %.4f rad, energy at most %+.4f J\n",
        static_cast<double>(opening(world, hinge)), static_cast<double>(weldGap), static_cast<double>(weldAngle),
        peak - start);
    // Closed to the soft rows' own scale (the slop, 5 mm; 0.01 rad).
    EXPECT_LE(opening(world, hinge), 0.005f);
    EXPECT_LE(weldGap, 0.005f);
    EXPECT_LE(weldAngle, 0.01f);
    // The energy the three bodies (0.2 kg each) can give is their fall to the
    // floor of the measure, 10 m (60 J); 1 % of it (the audit's bar).
    double fall = 0.0;
    for (BodyId x : bodies) fall += world.mass(x) * kGravity * 10.0;
    EXPECT_LE(peak - start, 0.01 * fall);
}

// A weld turned by the game about its own anchor, its first body hinged to a
// static pin: the point stays closed and only the angle is off (1.5 rad).
// The push turns the bodies back by the weld's angle row alone, with no
// velocity: the pair gains 1.6 J once, the first body lifted by its share of
// the turn (the pair ends straight, pointing up from the pin, and swings from
// there without gaining more). Before, the soft rows closed the angle at
// biasRate·1.5 rad, about 100 rad/s: the pair's energy peaked 15.5 J over
// the start in the snap (and had lost all but 0.7 J of it by 0.5 s).
TEST(StretchedJoints, AWeldTurnedAboutItsAnchorTurnsBackWithoutGainingEnergy) {
    World world({.enableSleep = false});
    BodyId pin = world.createBody({});
    BodyId a = plank(world, 0.0f, 1.0f);
    BodyId b = plank(world, 1.0f, 1.0f);
    world.createRevoluteJoint({.bodyA = pin, .bodyB = a, .localAnchorA = {-0.5f, 10}, .localAnchorB = {-0.5f, 0}});
    JointId weld = world.createWeldJoint(
        {.bodyA = a, .bodyB = b, .localAnchorA = {0.5f, 0}, .localAnchorB = {-0.5f, 0}});
    // B turned 1.5 rad about the shared anchor (0.5, 10): its centre, 0.5 m
    // from the anchor, goes round with it.
    const float turn = 1.5f;
    world.setTransform(b, Vec2{0.5f, 10.0f} + Vec2{0.5f * std::cos(turn), 0.5f * std::sin(turn)}, turn);
    const WeldJointDef wd = world.weldJointDef(weld);
    auto gap = [&] {
        return length(transformPoint(world.transform(b), wd.localAnchorB) -
                      transformPoint(world.transform(a), wd.localAnchorA));
    };
    ASSERT_LT(gap(), 1.0e-4f);
    const std::vector<BodyId> pair{a, b};
    const double start = energy(world, pair, 0.0f);
    double closing = start, closed = start, peak = start;
    for (int step = 1; step <= 120; ++step) {
        world.step(kDt);
        const double e = energy(world, pair, 0.0f);
        if (step <= 30) closing = std::max(closing, e);  // the turn is undone within 8 steps
        if (step == 30) closed = e;
        if (step >= 30) peak = std::max(peak, e);
    }
    const float angle = std::fabs(world.angle(b) - world.angle(a) - wd.referenceAngle);
    std::printf(
        "[figure] weld turned 1.5 rad: after 2 s %.4f rad and %.4f m off; energy at most %+.4f J while closing, "
        "%+.4f J once closed, at most %+.4f J more after\n",
        static_cast<double>(angle), static_cast<double>(gap()), closing - start, closed - start, peak - closed);
    EXPECT_LE(angle, 0.01f);
    EXPECT_LE(gap(), 0.005f);
    const double mass = world.mass(a) + world.mass(b);
    // Closing: the push moves no point of the pair further than the arc the
    // turn spans at B's far end (1.5 rad × 1 m), so the potential it adds is
    // at most m·g·1.5 m (6 J for the 0.4 kg pair), and it leaves no velocity;
    // the soft rows' snap peaked at 15.5 J.
    EXPECT_LE(closing - start, mass * kGravity * 1.5);
    // Once closed, the pair swings as a passive system: within 1 % of the
    // energy its fall to the floor of the measure gives (the audit's bar).
    EXPECT_LE(peak - closed, 0.01 * mass * kGravity * 10.0);
}

// A slider created with its cart 1 m off the rail's axis and turned 0.5 rad,
// a bob hinged below the cart 1.5 m from its anchor: the slider's rows (off
// the axis, the angle) and the hinge's point close together on the push, the
// axis's row moving the cart, the angle's turning it. Before, the soft rows
// closed them at biasRate·C and the bob swung at 13 m/s, the pair 28.5 J over
// its start.
TEST(StretchedJoints, ASliderCreatedOffItsAxisSettlesOntoItWithoutGainingEnergy) {
    World world({.enableSleep = false});
    BodyId rail = world.createBody({.position = {0, 10}});
    BodyId cart = world.createBody({.type = BodyType::dynamic_body, .position = {1, 11}, .angle = 0.5f});
    world.createPolygonShape(cart, {.density = 1.0f}, makeBox(0.4f, 0.2f));
    BodyId bob = world.createBody({.type = BodyType::dynamic_body, .position = {2.5f, 10}});
    world.createCircleShape(bob, {.density = 1.0f}, Circle{{0, 0}, 0.25f});
    world.createPrismaticJoint({.bodyA = rail, .bodyB = cart, .localAxisA = {1, 0}});
    JointId hinge = world.createRevoluteJoint({.bodyA = cart, .bodyB = bob, .localAnchorB = {0, 1.0f}});
    const std::vector<BodyId> bodies{cart, bob};
    const double start = energy(world, bodies, 0.0f);
    double peak = start;
    for (int step = 1; step <= 300; ++step) {
        world.step(kDt);
        peak = std::max(peak, energy(world, bodies, 0.0f));
        if (step == 60) {
            // On the axis and level within the slop (5 mm, 0.01 rad) at 1 s.
            EXPECT_NEAR(world.position(cart).y, 10.0f, 0.005f);
            EXPECT_NEAR(world.angle(cart), 0.0f, 0.01f);
            EXPECT_LE(opening(world, hinge), 0.005f);
        }
    }
    std::printf("[figure] slider created 1 m off its axis: energy at most %+.4f J over %.1f J\n", peak - start, start);
    // The energy the pair can give, its fall to the floor of the measure
    // (about 52 J): 1 % of it (the audit's bar).
    double fall = 0.0;
    for (BodyId b : bodies) fall += world.mass(b) * kGravity * 10.0;
    EXPECT_LE(peak - start, 0.01 * fall);
}

// The exact trees share one factorization, but only a tree holding a
// stretched joint is solved rigid and pushed: a heavy-ended chain (ten 1 kg
// links and a 100 kg ball, an exact tree by its mass ratio) steps bit for bit
// the same beside a chain of discs created with its joints 1 m open as alone.
TEST(StretchedJoints, AChainCreatedOpenLeavesAnotherTreeAsItWas) {
    auto swing = [](bool besideStretched) {
        World world({.enableSleep = false});
        BodyId anchor = world.createBody({});
        BodyId previous = anchor;
        for (int i = 0; i < 10; ++i) {
            BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {0.5f * i + 0.25f, 20}});
            world.createPolygonShape(b, {.density = 16.0f, .filter = {.groupIndex = -1}}, makeBox(0.25f, 0.0625f));
            world.createRevoluteJoint({.bodyA = previous,
                                       .bodyB = b,
                                       .localAnchorA = i == 0 ? Vec2{0, 20} : Vec2{0.25f, 0},
                                       .localAnchorB = {-0.25f, 0}});
            previous = b;
        }
        BodyId ball = world.createBody({.type = BodyType::dynamic_body, .position = {5.5f, 20}});
        world.createCircleShape(ball, {.density = 127.0f, .filter = {.groupIndex = -1}}, Circle{{0, 0}, 0.5f});
        world.createRevoluteJoint(
            {.bodyA = previous, .bodyB = ball, .localAnchorA = {0.25f, 0}, .localAnchorB = {-0.5f, 0}});
        if (besideStretched) {
            BodyId p = anchor;
            for (int i = 0; i < 10; ++i) {
                BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = {100 + 2.0f * (i + 1), 20}});
                world.createCircleShape(b, {.density = 1.0f, .filter = {.groupIndex = -1}}, Circle{{0, 0}, 0.2f});
                world.createRevoluteJoint({.bodyA = p,
                                           .bodyB = b,
                                           .localAnchorA = i == 0 ? Vec2{100, 20} : Vec2{0.5f, 0},
                                           .localAnchorB = {-0.5f, 0}});
                p = b;
            }
        }
        for (int i = 0; i < 120; ++i) world.step(kDt);
        return std::vector<float>{world.position(ball).x, world.position(ball).y, world.linearVelocity(ball).x,
                                  world.linearVelocity(ball).y, world.angularVelocity(ball)};
    };
    EXPECT_EQ(swing(false), swing(true));
}

}  // namespace
}  // namespace i2d
