// The exact solve of joint trees (joint_tree.cpp; Baraff (1996), Linear-Time
// Dynamics using Lagrange Multipliers): after one velocity pass the joints'
// velocity rows hold exactly, whatever the masses, where a Gauss-Seidel sweep
// leaves most of the error; a joint closing a loop through them is solved
// with them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "joint.hpp"
#include "joint_tree.hpp"
#include "world_fixtures.hpp"
#include "world_state.hpp"

namespace {

using namespace i2d;

struct Hinge {
    JointId id;
    BodyId a, b;
    Vec2 point;  ///< where the anchors coincide at the start (world)
};

/// A random tree of n discs of masses 1 to 1000 kg hinged to each other by
/// revolute joints (body i to a random earlier one), the first hinged to the
/// ground; random velocities; no gravity. With `loop`, one more hinge closes
/// a cycle.
struct RandomTree {
    World world;
    std::vector<BodyId> bodies;
    std::vector<Hinge> hinges;

    /// `springHertz` > 0 gives every hinge an angular spring of that
    /// frequency (damping ratio 0.5), at rest at the start.
    RandomTree(unsigned seed, int n, float exactRatio, bool loop, float springHertz = 0.0f)
        : world([&] {
              WorldSettings s;
              s.gravity = {};
              s.enableSleep = false;
              s.positionCorrection = PositionCorrection::baumgarte;
              s.velocityIterations = 1;
              s.exactJointMassRatio = exactRatio;
              return s;
          }()) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> pos(-5.0f, 5.0f), speed(-3.0f, 3.0f), logMass(0.0f, 3.0f);
        BodyId ground = world.createBody({});
        for (int i = 0; i < n; ++i) {
            BodyId b = world.createBody({.type = BodyType::dynamic_body,
                                         .position = {pos(rng), pos(rng)},
                                         .linearVelocity = {speed(rng), speed(rng)},
                                         .angularVelocity = speed(rng)});
            world.createCircleShape(b, {.density = 1.0f, .filter = {.groupIndex = -1}}, {{0.0f, 0.0f}, 0.2f});
            const float mass = std::pow(10.0f, logMass(rng));
            world.setMassData(b, {.mass = mass, .center = {}, .rotationalInertia = 0.02f * mass});
            bodies.push_back(b);
        }
        auto hinge = [&](BodyId a, BodyId b) {
            const Vec2 pa = world.position(a), pb = world.position(b);
            const Vec2 p = 0.5f * (pa + pb);
            hinges.push_back({world.createRevoluteJoint({.bodyA = a,
                                                         .bodyB = b,
                                                         .localAnchorA = p - pa,
                                                         .localAnchorB = p - pb,
                                                         .enableSpring = springHertz > 0.0f,
                                                         .hertz = springHertz,
                                                         .dampingRatio = 0.5f}),
                              a, b, p});
        };
        hinge(ground, bodies[0]);
        for (int i = 1; i < n; ++i) hinge(bodies[std::uniform_int_distribution<int>(0, i - 1)(rng)], bodies[i]);
        if (loop) hinge(bodies[static_cast<std::size_t>(n - 1)], bodies[0]);
    }

    /// Relative speed of each hinge's anchors, with the anchors where they
    /// were when the step began (the rows the step solved).
    float worstAnchorSpeed(const std::vector<Vec2>& centres) const {
        float worst = 0.0f;
        for (const Hinge& h : hinges) {
            auto pointVelocity = [&](BodyId b) {
                if (world.bodyType(b) != BodyType::dynamic_body) return Vec2{};
                const std::size_t k = static_cast<std::size_t>(std::find(bodies.begin(), bodies.end(), b) -
                                                               bodies.begin());
                return world.linearVelocity(b) + cross(world.angularVelocity(b), h.point - centres[k]);
            };
            worst = std::max(worst, length(pointVelocity(h.b) - pointVelocity(h.a)));
        }
        return worst;
    }
    std::vector<Vec2> centres() const {
        std::vector<Vec2> c;
        for (BodyId b : bodies) c.push_back(world.position(b));
        return c;
    }
};

// One baumgarte step with one velocity iteration from joints that hold
// exactly (C = 0, so the velocity target is J v = 0): solved exactly, the
// anchors' relative speed is float round-off of the 3 m/s speeds (1e-6
// relative per operation over a 40-node elimination, so 1e-3 m/s is ample);
// swept once, it stays of the order of the speeds themselves.
TEST(JointTree, OneExactPassHoldsEveryVelocityRow) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        RandomTree exact(seed, 20, 1.0f, false), swept(seed, 20, INFINITY, false);
        const std::vector<Vec2> centres = exact.centres();
        exact.world.step(1.0f / 60.0f);
        swept.world.step(1.0f / 60.0f);
        EXPECT_LT(exact.worstAnchorSpeed(centres), 1e-3f) << "seed " << seed;
        EXPECT_GT(swept.worstAnchorSpeed(centres), 0.1f) << "seed " << seed;
    }
}

// The same with a hinge closing a loop (the last body to the first): its rows
// are solved with the tree as auxiliary rows (joint_tree.cpp, Baraff (1996)
// §8), so after one pass it holds as exactly as the tree's own hinges (the
// same round-off bound). Swept beside the tree, it did not (a swept row moves
// its bodies by their own masses, and the tree then moves them back).
TEST(JointTree, OneExactPassHoldsAJointClosingALoopToo) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        RandomTree exact(seed, 20, 1.0f, true);
        const std::vector<Vec2> centres = exact.centres();
        exact.world.step(1.0f / 60.0f);
        EXPECT_LT(exact.worstAnchorSpeed(centres), 1e-3f) << "seed " << seed;
    }
}

// The same trees with an angular spring (5 Hz, damping ratio 0.5, at rest)
// on every hinge: each spring is an auxiliary row of the tree solve
// (joint_tree.cpp, springRow), so after one pass it holds its implicit
// equation exactly, ω_B − ω_A + Γ·λ = 0 (C = 0 at rest; λ the spring's
// impulse, here the hinge's torque times the step; Γ = (I_A⁻¹ + I_B⁻¹)/a₂ of
// makeSoft, a₂ = hω(2ζ + hω)), to the same round-off bound as the hinges
// (1e-3 rad/s against speeds of 3). Swept beside the tree, a spring moved its
// two bodies by their own inertias and the tree then moved them again: its
// equation was off by the order of the speeds.
TEST(JointTree, OneExactPassHoldsTheSpringsBetweenTheTreesBodiesToo) {
    constexpr float kHertz = 5.0f, kZeta = 0.5f, kStep = 1.0f / 60.0f;
    const float omega = 2.0f * 3.14159265f * kHertz;
    const float a2 = kStep * omega * (2.0f * kZeta + kStep * omega);
    for (unsigned seed = 1; seed <= 20; ++seed) {
        // As many hinges as a step solves springs with the trees (the rest are swept).
        const int n = detail::kMaxLoopRows;
        RandomTree exact(seed, n, 1.0f, false, kHertz), swept(seed, n, INFINITY, false, kHertz);
        const std::vector<Vec2> centres = exact.centres();
        exact.world.step(kStep);
        swept.world.step(kStep);
        EXPECT_LT(exact.worstAnchorSpeed(centres), 1e-3f) << "seed " << seed;
        auto worstSpringResidual = [&](const RandomTree& tree) {
            float worst = 0.0f;
            for (const Hinge& h : tree.hinges) {
                auto spinAndMobility = [&](BodyId b) {
                    if (tree.world.bodyType(b) != BodyType::dynamic_body) return std::pair{0.0f, 0.0f};
                    return std::pair{tree.world.angularVelocity(b), 1.0f / tree.world.rotationalInertia(b)};
                };
                const auto [wA, iA] = spinAndMobility(h.a);
                const auto [wB, iB] = spinAndMobility(h.b);
                const float lambda = tree.world.jointReactionTorque(h.id) * kStep;
                worst = std::max(worst, std::abs(wB - wA + (iA + iB) / a2 * lambda));
            }
            return worst;
        };
        EXPECT_LT(worstSpringResidual(exact), 1e-3f) << "seed " << seed;
        EXPECT_GT(worstSpringResidual(swept), 0.1f) << "seed " << seed;
    }
}

// The same trees left to the mass-ratio rule: masses from 1 to 1000 kg make
// every one of them qualify at the default ratio of 10.
TEST(JointTree, TreesOfUnlikeMassesAreSolvedExactlyByDefault) {
    RandomTree tree(7, 20, WorldSettings{}.exactJointMassRatio, false);
    const std::vector<Vec2> centres = tree.centres();
    tree.world.step(1.0f / 60.0f);
    EXPECT_LT(tree.worstAnchorSpeed(centres), 1e-3f);
}

/// Largest kinetic energy over 5 s of free motion (no gravity) relative to
/// that after the first step, in the default soft step; NaN if not finite.
float worstEnergyGain(RandomTree& tree) {
    WorldSettings s = tree.world.settings();
    s.positionCorrection = PositionCorrection::soft_step;
    tree.world.setSettings(s);
    auto kinetic = [&] {
        float e = 0.0f;
        for (BodyId b : tree.bodies) {
            const Vec2 v = tree.world.linearVelocity(b);
            const float w = tree.world.angularVelocity(b);
            e += 0.5f * tree.world.mass(b) * dot(v, v) + 0.5f * tree.world.rotationalInertia(b) * w * w;
        }
        return e;
    };
    tree.world.step(1.0f / 60.0f);  // the first step takes out the velocities the joints forbid
    const float e0 = kinetic();
    float worst = 0.0f;
    for (int i = 0; i < 300; ++i) {
        tree.world.step(1.0f / 60.0f);
        worst = std::max(worst, kinetic() / e0 - 1.0f);
    }
    return worst;
}

// Random trees of masses from 1 to 1000 kg on levers up to 7 m long, with and
// without a loop (which keeps one joint in the sweep), moving freely for 5 s
// in the default soft step: a passive system, so no energy may be gained. 1 %
// is far above the float sum of 20 bodies' energies (~1e-6); a gain from the
// solver grows without bound. Swept by Gauss-Seidel alone, most of these
// trees gain energy, some by a factor of 10⁴ (printed, for the record).
TEST(JointTree, RandomTreesOfUnlikeMassesNeverGainEnergy) {
    int sweptGains = 0;
    for (bool loop : {false, true}) {
        for (unsigned seed = 1; seed <= 10; ++seed) {
            RandomTree exact(seed, 20, 1.0f, loop), swept(seed, 20, INFINITY, loop);
            const float gain = worstEnergyGain(exact);
            ASSERT_TRUE(std::isfinite(gain)) << "seed " << seed;
            EXPECT_LE(gain, 0.01f) << "seed " << seed << (loop ? " with a loop" : "");
            const float sweptGain = worstEnergyGain(swept);
            sweptGains += !(sweptGain <= 0.01f);
        }
    }
    std::printf("[figure] random 1000:1 joint trees: %d of 20 gain energy when swept, 0 solved exactly\n", sweptGains);
}

/// Largest rise of the total energy of a free tree of hinged discs and boxes
/// (3 to 12 bodies 1 m apart, one of them 1000 times as dense as the rest)
/// dropped from 6 m onto the ground, over 5 s after its first step, as a
/// fraction of the energy its fall can release (its weight times its height
/// above the ground's top plus 1 m). With `loop`, one more hinge joins two
/// of its bodies, closing a loop.
double landingTreeGain(unsigned seed, int substeps, bool loop = false) {
    std::mt19937 rng(seed);
    auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {}, makeOffsetBox(50.0f, 0.5f, {0.0f, -0.5f}, 0.0f));
    const int n = 3 + static_cast<int>(rng() % 10);
    const int heavy = static_cast<int>(rng() % static_cast<unsigned>(n));
    std::vector<BodyId> bodies;
    std::vector<Vec2> at;
    const Filter apart{.groupIndex = -1};
    for (int i = 0; i < n; ++i) {
        const int parent = i == 0 ? -1 : static_cast<int>(rng() % static_cast<unsigned>(i));
        Vec2 p{0.0f, 6.0f};
        if (parent >= 0) {
            const float angle = uniform(0.0f, 6.2831853f);
            p = at[static_cast<std::size_t>(parent)] + Vec2{std::cos(angle), std::sin(angle)};
        }
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = p, .angle = uniform(-3.0f, 3.0f)});
        const ShapeDef def{.density = i == heavy ? 1000.0f : 1.0f, .filter = apart};
        if (rng() % 2)
            world.createCircleShape(b, def, Circle{{0.0f, 0.0f}, uniform(0.1f, 0.35f)});
        else
            world.createPolygonShape(b, def, makeBox(uniform(0.1f, 0.35f), uniform(0.1f, 0.35f)));
        if (parent >= 0) {
            const BodyId a = bodies[static_cast<std::size_t>(parent)];
            const Vec2 mid = 0.5f * (p + at[static_cast<std::size_t>(parent)]);
            world.createRevoluteJoint({.bodyA = a,
                                       .bodyB = b,
                                       .localAnchorA = invTransformPoint(world.transform(a), mid),
                                       .localAnchorB = invTransformPoint(world.transform(b), mid)});
        }
        bodies.push_back(b);
        at.push_back(p);
    }
    if (loop) {  // a hinge between two bodies of the tree, halfway between them
        const int i = static_cast<int>(rng() % static_cast<unsigned>(n));
        const int j = (i + 1 + static_cast<int>(rng() % static_cast<unsigned>(n - 1))) % n;
        const BodyId a = bodies[static_cast<std::size_t>(i)], b = bodies[static_cast<std::size_t>(j)];
        const Vec2 mid = 0.5f * (at[static_cast<std::size_t>(i)] + at[static_cast<std::size_t>(j)]);
        world.createRevoluteJoint({.bodyA = a,
                                   .bodyB = b,
                                   .localAnchorA = invTransformPoint(world.transform(a), mid),
                                   .localAnchorB = invTransformPoint(world.transform(b), mid)});
    }
    const double g = -world.settings().gravity.y;
    auto energy = [&] { return test::totalEnergy(world, bodies); };
    double scale = 0.0;
    for (BodyId b : bodies) scale += world.mass(b) * g * (world.worldCenterOfMass(b).y + 1.0);
    world.step(1.0f / 60.0f);  // the first step takes out the velocities the joints forbid
    const double start = energy();
    double peak = start;
    for (int i = 0; i < 300; ++i) {
        world.step(1.0f / 60.0f);
        peak = std::max(peak, energy());
    }
    return (peak - start) / scale;
}

/// The 1 % bound of the tests below for 100 landing trees (with a loop or not) at 4, 2 and 1 substeps.
void expectLandingTreesKeepTheirEnergy(bool loop) {
    for (int substeps : {4, 2, 1}) {
        double worst = 0.0;
        for (unsigned seed = 1; seed <= 100; ++seed) {
            const double gain = landingTreeGain(seed, substeps, loop);
            ASSERT_TRUE(std::isfinite(gain)) << "seed " << seed;
            EXPECT_LE(gain, 0.01) << "seed " << seed << ", " << substeps << " substeps";
            worst = std::max(worst, gain);
        }
        std::printf("[figure] 100 landing 1000:1 hinge trees%s, %d substeps: energy at most %.4f of the fall's over "
                    "the start\n",
                    loop ? " with a loop" : "", substeps, worst);
    }
}

// Hinge trees with a body 1000 times as dense as the rest, dropped on the
// ground: a passive system, so no energy may be gained (the 1 %,
// measured against what the fall can release). The heavy body stops on the
// ground while its light links are still moving; the tension's geometric
// stiffness is added to a tree's inertia only while none of its bodies
// touches anything (joint_tree.cpp): added there as well (the tree solved
// rigid beside its contacts, whose rows turn the same bodies with their own
// inertia), one of these trees gained 7.5 times what its fall releases at 4
// substeps (of 100 other such trees, 3 at 4 substeps, the worst 562 times,
// and 2 at 2 substeps).
TEST(JointTree, HingeTreesWithAHeavyBodyLandingNeverGainEnergy) { expectLandingTreesKeepTheirEnergy(false); }

// The same trees with one more hinge closing a loop, solved with the tree
// (joint_tree.cpp) beside the contacts of the landing. None gained more than
// 1 % with the loop swept either; this holds the exact loop rows to it.
TEST(JointTree, HingeTreesClosedByALoopLandingNeverGainEnergy) { expectLandingTreesKeepTheirEnergy(true); }

/// A ragdoll of capsules (torso `ratio` times as dense as the head and limbs,
/// eight hinges with limits, each with a motor of speed 0 and 2 N·m as joint
/// friction) dropped from 3 to 6 m in a random pose onto the ground, sleeping
/// off. Returns its kinetic energy after 10 s over the energy of a 1 mm fall
/// of its whole weight.
double ragdollRestingEnergy(unsigned seed, float ratio) {
    std::mt19937 rng(seed);
    auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    test::makeGround(world);
    const Vec2 origin{uniform(-1.0f, 1.0f), uniform(3.0f, 6.0f)};
    const Rot turn = makeRot(uniform(-3.0f, 3.0f));
    std::vector<BodyId> bodies;
    auto bone = [&](Vec2 a, Vec2 b, float radius, float density) {
        const Vec2 wa = origin + rotate(turn, a), wb = origin + rotate(turn, b), c = 0.5f * (wa + wb);
        const BodyId id = world.createBody(
            {.type = BodyType::dynamic_body, .position = c, .angularVelocity = uniform(-2.0f, 2.0f)});
        world.createCapsuleShape(id, {.density = density, .filter = {.groupIndex = -1}},
                                 Capsule{wa - c, wb - c, radius});
        bodies.push_back(id);
        return id;
    };
    auto hinge = [&](BodyId a, BodyId b, Vec2 at, float lower, float upper) {
        const Vec2 p = origin + rotate(turn, at);
        world.createRevoluteJoint({.bodyA = a,
                                   .bodyB = b,
                                   .localAnchorA = invTransformPoint(world.transform(a), p),
                                   .localAnchorB = invTransformPoint(world.transform(b), p),
                                   .enableLimit = true,
                                   .lowerAngle = lower,
                                   .upperAngle = upper,
                                   .enableMotor = true,
                                   .maxMotorTorque = 2.0f});
    };
    const BodyId torso = bone({0.0f, 0.0f}, {0.0f, 0.6f}, 0.15f, ratio);
    hinge(torso, bone({0.0f, 0.85f}, {0.0f, 0.95f}, 0.12f, 1.0f), {0.0f, 0.75f}, -0.5f, 0.5f);
    for (float side : {-1.0f, 1.0f}) {
        const BodyId upperArm = bone({0.2f * side, 0.6f}, {0.2f * side, 0.3f}, 0.06f, 1.0f);
        hinge(torso, upperArm, {0.2f * side, 0.6f}, -2.5f, 2.5f);
        hinge(upperArm, bone({0.2f * side, 0.25f}, {0.2f * side, -0.05f}, 0.05f, 1.0f), {0.2f * side, 0.27f}, -2.5f,
              0.1f);
        const BodyId thigh = bone({0.1f * side, -0.1f}, {0.1f * side, -0.5f}, 0.08f, 1.0f);
        hinge(torso, thigh, {0.1f * side, -0.05f}, -1.5f, 1.0f);
        hinge(thigh, bone({0.1f * side, -0.55f}, {0.1f * side, -0.95f}, 0.07f, 1.0f), {0.1f * side, -0.52f}, -0.1f,
              2.5f);
    }
    for (int i = 0; i < 600; ++i) world.step(1.0f / 60.0f);
    double kinetic = 0.0, weight = 0.0;
    for (BodyId b : bodies) {
        const Vec2 v = world.linearVelocity(b);
        const double w = world.angularVelocity(b);
        kinetic += 0.5 * world.mass(b) * (double(v.x) * v.x + double(v.y) * v.y) +
                   0.5 * world.rotationalInertia(b) * w * w;
        weight += world.mass(b) * -world.settings().gravity.y;
    }
    return kinetic / (weight * 0.001);
}

// Ragdolls whose torso is 10 and 50 times as dense as their limbs are exact
// trees; lying on the ground they must come to rest (Box2D v3's Ragdoll
// sample), here: after 10 s, less kinetic energy than a 1 mm fall of the
// whole ragdoll would give. A tree is solved rigid and pushed only while none
// of its bodies touches anything: solved so on the ground too, beside its
// contacts and held limits with nothing to damp them, the ragdolls with the
// 10 times torso kept jiggling, up to 4.4 times the bound (measured now:
// 0.0025 and 0.014 times it).
TEST(JointTree, RagdollsWithAHeavyTorsoComeToRestOnTheGround) {
    for (float ratio : {10.0f, 50.0f}) {
        double worst = 0.0;
        for (unsigned seed = 1; seed <= 10; ++seed) {
            const double resting = ragdollRestingEnergy(seed, ratio);
            EXPECT_LT(resting, 1.0) << "seed " << seed << ", torso " << ratio << " times as dense";
            worst = std::max(worst, resting);
        }
        std::printf("[figure] ragdolls with a torso %.0f times as dense, after 10 s: kinetic energy at most %.4f times "
                    "a 1 mm fall's\n",
                    ratio, worst);
    }
}

// A chain of thin links (0.1 m × 2.5 cm, 0.1 kg each) hinged end to end from
// a pivot, with a disc on its last hinge `ratio` times a link's mass,
// released level under gravity at the default settings (an exact tree: its
// mass ratio is above exactJointMassRatio), sleeping off: a passive system.
// Returns the largest total energy over `seconds`, relative to its start,
// the potential measured from the lowest the chain can reach (hanging
// straight down), so the start is the energy the chain has to give.
double swingingChainPeakEnergy(int links, float ratio, float seconds, int substeps = WorldSettings{}.substeps) {
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const float length = 0.1f, halfThickness = 0.0125f, linkMass = 0.1f, radius = 0.05f;
    const BodyId pivot = world.createBody({});
    std::vector<BodyId> bodies;
    BodyId previous = pivot;
    Vec2 previousAnchor{};
    const ShapeDef noCollision{.filter = {.groupIndex = -1}};
    for (int i = 0; i < links; ++i) {
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = {(static_cast<float>(i) + 0.5f) * length, 0.0f}});
        ShapeDef def = noCollision;
        def.density = linkMass / (2.0f * length * halfThickness);
        world.createPolygonShape(b, def, makeBox(0.5f * length, halfThickness));
        world.createRevoluteJoint(
            {.bodyA = previous, .bodyB = b, .localAnchorA = previousAnchor, .localAnchorB = {-0.5f * length, 0.0f}});
        previous = b;
        previousAnchor = {0.5f * length, 0.0f};
        bodies.push_back(b);
    }
    const BodyId end = world.createBody({.type = BodyType::dynamic_body, .position = {links * length, 0.0f}});
    ShapeDef def = noCollision;
    def.density = ratio * linkMass / (3.14159265f * radius * radius);
    world.createCircleShape(end, def, Circle{{0.0f, 0.0f}, radius});
    world.createRevoluteJoint({.bodyA = previous, .bodyB = end, .localAnchorA = previousAnchor});
    bodies.push_back(end);
    const double lowest = -(links * length + radius);
    auto energy = [&] { return test::totalEnergy(world, bodies, lowest); };
    const double start = energy();
    double peak = start;
    for (int i = 0; i < static_cast<int>(seconds * 60.0f); ++i) {
        world.step(1.0f / 60.0f);
        peak = std::max(peak, energy());
        if (!std::isfinite(peak)) break;
    }
    return peak / start;
}

// Swinging chains with a heavy end keep their energy up to a 1000:1 end at 4,
// 2 and 1 substeps. They did up to 200:1 at 4 substeps only while the trees'
// rows were soft relative to each link's own mass: from 300:1 (and from 100:1
// at one substep) the links under the end's pull turned faster than a substep
// resolves (the tension's geometric stiffness, joint_tree.cpp) and the chains
// gained up to 6,000 times their energy. 1 % is the hard-cases issue's bound
// for a passive system; 20 s covers 7 to 14 swings, long enough for a gain to
// show (the gains showed from 2 to 3 s on).
TEST(JointTree, SwingingChainsWithAHeavyEndKeepTheirEnergyUpTo1000To1) {
    for (int substeps : {4, 2, 1}) {
        for (int links : {5, 10, 20}) {
            for (float ratio : {100.0f, 300.0f, 1000.0f}) {
                const double peak = swingingChainPeakEnergy(links, ratio, 20.0f, substeps);
                std::printf("[figure] swinging chain of %d links, %.0f:1 end, %d substeps: energy at most %.4f times "
                            "its start\n",
                            links, ratio, substeps, peak);
                EXPECT_LE(peak, 1.01) << links << " links, " << ratio << ":1, " << substeps << " substeps";
            }
        }
    }
}

/// What a chain of `links` alike capsules (length `linkLength`, radius a tenth
/// of it, hinged end to end, kept apart) hung from a static pivot and released
/// level does over 20 s at `hz` and `substeps`: the largest rise of its
/// energy over the start, as a fraction of what its fall to hanging straight
/// releases, and the largest distance from the pivot to the chain's free end
/// over its built length.
struct LightChainRun {
    double rise, stretch;
};
LightChainRun lightChainRun(int links, float linkLength, int substeps, float hz) {
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const Vec2 pivot{0.0f, 20.0f};
    BodyId previous = world.createBody({.position = pivot});
    Vec2 previousAnchor{0.0f, 0.0f};
    std::vector<BodyId> bodies;
    const float half = 0.5f * linkLength;
    for (int i = 0; i < links; ++i) {
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = pivot + Vec2{(i + 0.5f) * linkLength, 0.0f}});
        world.createCapsuleShape(b, {.density = 1.0f, .filter = {.groupIndex = -1}},
                                 {.center1 = {-half, 0.0f}, .center2 = {half, 0.0f}, .radius = 0.1f * linkLength});
        world.createRevoluteJoint(
            {.bodyA = previous, .bodyB = b, .localAnchorA = previousAnchor, .localAnchorB = {-half, 0.0f}});
        previous = b;
        previousAnchor = {half, 0.0f};
        bodies.push_back(b);
    }
    const float built = links * linkLength;
    const double floor = pivot.y - built;  // below every centre the chain can reach
    double mass = 0.0;
    for (BodyId b : bodies) mass += world.mass(b);
    const double releasable = mass * -settings.gravity.y * 0.5 * built;  // level to hanging straight
    const double start = test::totalEnergy(world, bodies, floor);
    LightChainRun run{0.0, 0.0};
    for (int i = 0; i < static_cast<int>(20.0f * hz); ++i) {
        world.step(1.0f / hz);
        const double e = test::totalEnergy(world, bodies, floor);
        run.rise = std::max(run.rise, std::isfinite(e) ? (e - start) / releasable : INFINITY);
        const Vec2 end = transformPoint(world.transform(previous), previousAnchor);
        run.stretch = std::max(run.stretch, double(length(end - pivot)) / built);
    }
    return run;
}

// Chains of many light alike links, swept one pass a substep at long
// substeps, tore and gained energy without bound: 30 links of 0.1 m at one
// substep had their joints 0.24 m open after a second and 150 times their
// releasable energy after 20 s. Their soft rows stretch by L·g/ω² under the
// load L of the links below (joint_tree.cpp, kLoadStretch); such trees are
// now solved exactly. The layouts: one substep at 60 and 30 Hz, two
// substeps, and four at 60 Hz (100 links) and at 15 Hz. Swept, five of them
// gained 9 to 608 times their releasable energy and stretched to 2.7 to 33
// times their length; the 100 links at 4 substeps gained nothing but
// stretched to 1.42 times theirs. 1 % of the releasable energy is the
// hard-cases issue's bound for a passive system; the chain's end within a
// tenth of its length beyond it leaves room for the whip's momentary
// openings at its end (up to 7 cm at one joint of 0.1 m links and 22 cm of
// 0.25 m links at one substep, as the links turn most of a radian a
// substep; the ends reach 1.027 to 1.063 of the length).
TEST(JointTree, ChainsOfManyLightLinksNeverTearOrGainEnergy) {
    struct Layout {
        int links;
        float linkLength;
        int substeps;
        float hz;
    };
    for (const Layout& c : {Layout{30, 0.1f, 1, 60.0f}, Layout{30, 0.1f, 1, 30.0f}, Layout{40, 0.25f, 1, 60.0f},
                            Layout{60, 0.05f, 2, 60.0f}, Layout{100, 0.05f, 4, 60.0f}, Layout{30, 0.1f, 4, 15.0f}}) {
        const LightChainRun run = lightChainRun(c.links, c.linkLength, c.substeps, c.hz);
        std::printf("[figure] chain of %d links of %.2f m, %d substeps at %.0f Hz: energy at most %+.4f of its "
                    "releasable energy over its start, its end at most %.3f of its length from the pivot\n",
                    c.links, double(c.linkLength), c.substeps, double(c.hz), run.rise, run.stretch);
        EXPECT_LE(run.rise, 0.01) << c.links << " links of " << c.linkLength << " m, " << c.substeps << " substeps, "
                                  << c.hz << " Hz";
        EXPECT_LE(run.stretch, 1.1) << c.links << " links of " << c.linkLength << " m, " << c.substeps << " substeps, "
                                    << c.hz << " Hz";
    }
}

}  // namespace

namespace {

/// A body of a hung tree (a box or, with no second half extent, a disc) and
/// its joint to an earlier one (parent −1: the static pivot at (0, 12.5)).
struct TreePart {
    Vec2 at;
    float angle, halfX, halfY;
    int parent;
    bool weld;
    Vec2 anchorParent, anchorSelf;  ///< in the two bodies' frames
    float referenceAngle;
};

/// Largest total energy over 5 s, relative to its start, of a tree hung from
/// the pivot, its bodies alike in density and kept apart; the potential is
/// measured from the lowest point a body's centre can reach (the pivot less
/// the furthest centre's distance from it), so the energy is never negative.
double hungTreePeakEnergy(const std::vector<TreePart>& parts, int substeps) {
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const BodyId ground = world.createBody({});
    const Vec2 pivot{0.0f, 12.5f};
    const ShapeDef def{.density = 1.0f, .filter = {.groupIndex = -1}};
    std::vector<BodyId> bodies;
    float reach = 0.0f;
    for (const TreePart& part : parts) {
        const BodyId b = world.createBody({.type = BodyType::dynamic_body, .position = part.at, .angle = part.angle});
        if (part.halfY > 0.0f)
            world.createPolygonShape(b, def, makeBox(part.halfX, part.halfY));
        else
            world.createCircleShape(b, def, Circle{{0.0f, 0.0f}, part.halfX});
        const BodyId a = part.parent < 0 ? ground : bodies[static_cast<std::size_t>(part.parent)];
        if (part.weld)
            world.createWeldJoint({.bodyA = a,
                                   .bodyB = b,
                                   .localAnchorA = part.anchorParent,
                                   .localAnchorB = part.anchorSelf,
                                   .referenceAngle = part.referenceAngle});
        else
            world.createRevoluteJoint(
                {.bodyA = a, .bodyB = b, .localAnchorA = part.anchorParent, .localAnchorB = part.anchorSelf});
        bodies.push_back(b);
        reach = std::max(reach, length(part.at - pivot));
    }
    return test::peakEnergyOver5s(world, bodies, pivot.y - reach);
}

}  // namespace

// Two hung trees of bodies alike in density (0.05 to 0.34 kg, 0.1 to 0.35 m
// across) whose joints sit 0.5 m from their centres, drawn from random trees
// of hinges and welds that exploded in the soft step's sweep: a box with
// three bodies welded to it, and a disc of radius 0.12 m, 1.4 g at its
// anchors, hinged between bodies of 14 to 62 g there and welded to one.
// Swept, the star reached 402, 110 and 35 times the energy it started with
// at 4, 2 and 1 substeps, the lever tree 2,584 and 3,447 times at 2 and 1.
// Trees with a body welded to two others or more (the star), or whose
// masses at the anchors are exactJointMassRatio apart (the lever), are now
// solved exactly (joint_tree.cpp). A passive system: the hard-cases issue's
// bound, 1 % over 5 s at 4, 2 and 1 substeps.
TEST(JointTree, LeversAndWeldedStarsOfAlikeBodiesKeepTheirEnergy) {
    const std::vector<TreePart> star{
        {{0.0f, 12.0f}, -2.6599f, 0.2319f, 0.3195f, -1, false, {0.0f, 12.5f}, {-0.2316f, -0.4431f}, 0.0f},
        {{-0.9896f, 11.856f}, 0.2129f, 0.2875f, 0.0f, 0, true, {0.4718f, -0.1654f}, {0.4988f, -0.0342f}, 2.8728f},
        {{-0.9935f, 11.8859f}, 2.887f, 0.2457f, 0.0f, 0, true, {0.4666f, -0.1795f}, {-0.4664f, -0.1803f}, -0.7362f},
        {{-0.2185f, 11.0242f}, -1.4175f, 0.2234f, 0.2357f, 0, true, {0.3229f, 0.3818f}, {-0.4655f, 0.1825f}, 1.2424f}};
    const std::vector<TreePart> lever{
        {{0.0f, 12.0f}, 2.9287f, 0.2225f, 0.0f, -1, false, {0.0f, 12.5f}, {0.1057f, -0.4887f}, 0.0f},
        {{-0.8381f, 12.5455f}, -1.5789f, 0.1229f, 0.0f, 0, false, {0.4672f, -0.1781f}, {0.2694f, 0.4212f}, 0.0f},
        {{-1.1521f, 11.5961f}, -2.1825f, 0.2526f, 0.0f, 1, false, {0.476f, -0.1531f}, {-0.4788f, -0.1441f}, 0.0f},
        {{-1.5142f, 13.2824f}, -0.7963f, 0.3312f, 0.0f, 1, true, {-0.3657f, -0.341f}, {0.4997f, -0.016f}, 0.7826f},
        {{-1.8001f, 12.2726f}, -2.1793f, 0.3215f, 0.3005f, 1, false, {0.1404f, -0.4799f}, {-0.387f, 0.3166f}, 0.0f}};
    for (int substeps : {4, 2, 1}) {
        const double starPeak = hungTreePeakEnergy(star, substeps), leverPeak = hungTreePeakEnergy(lever, substeps);
        std::printf("[figure] %d substeps: welded star at most %.4f times its start, lever tree %.4f\n", substeps,
                    starPeak, leverPeak);
        EXPECT_LE(starPeak, 1.01) << substeps << " substeps";
        EXPECT_LE(leverPeak, 1.01) << substeps << " substeps";
    }
}

namespace {

/// Largest total energy over 5 s, relative to its start, of a random tree of
/// hinged discs and boxes (3 to 12 bodies, each 0.5 to 1.5 m from its parent,
/// the hinge halfway between them or at the child's centre) hung from a
/// static pivot, each body with one chance in four of being 10, 100 or 1,000
/// times as dense as the rest (the layout's ratio), with one or two more
/// hinges closing loops between bodies that are not parent and child (hinged
/// halfway between them). The bodies are kept
/// apart; the potential is measured from 20 m below the pivot, lower than any
/// body can reach, so the energy is never negative.
double loopedTreePeakEnergy(unsigned seed, int substeps) {
    std::mt19937 rng(seed);
    auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    auto pick = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const Vec2 pivot{0.0f, 20.0f};
    const BodyId ground = world.createBody({.position = pivot});
    const int n = pick(3, 12);
    const float ratio = std::pow(10.0f, static_cast<float>(pick(1, 3)));
    std::vector<BodyId> bodies;
    std::vector<int> parents;
    auto hinge = [&](BodyId a, BodyId b, Vec2 at) {
        world.createRevoluteJoint({.bodyA = a,
                                   .bodyB = b,
                                   .localAnchorA = invTransformPoint(world.transform(a), at),
                                   .localAnchorB = invTransformPoint(world.transform(b), at)});
    };
    for (int i = 0; i < n; ++i) {
        const int parent = i == 0 ? -1 : pick(0, i - 1);
        const Vec2 from = parent < 0 ? pivot : world.position(bodies[static_cast<std::size_t>(parent)]);
        const float heading = uniform(0.0f, 6.2832f), reach = uniform(0.5f, 1.5f);
        const Vec2 at = from + reach * Vec2{std::cos(heading), std::sin(heading)};
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = at, .angle = uniform(-3.14f, 3.14f)});
        const ShapeDef def{.density = pick(0, 3) == 0 ? ratio : 1.0f, .filter = {.groupIndex = -1}};
        if (pick(0, 1) == 0)
            world.createCircleShape(b, def, Circle{{0.0f, 0.0f}, uniform(0.1f, 0.4f)});
        else
            world.createPolygonShape(b, def, makeBox(uniform(0.1f, 0.4f), uniform(0.1f, 0.4f)));
        hinge(parent < 0 ? ground : bodies[static_cast<std::size_t>(parent)], b,
              pick(0, 1) == 0 ? at : 0.5f * (from + at));
        bodies.push_back(b);
        parents.push_back(parent);
    }
    const int loops = pick(1, 2);
    for (int k = 0; k < loops; ++k) {
        const int i = pick(0, n - 1), j = pick(0, n - 1);
        if (i == j || parents[static_cast<std::size_t>(i)] == j || parents[static_cast<std::size_t>(j)] == i) continue;
        const BodyId a = bodies[static_cast<std::size_t>(i)], b = bodies[static_cast<std::size_t>(j)];
        hinge(a, b, 0.5f * (world.position(a) + world.position(b)));
    }
    return test::peakEnergyOver5s(world, bodies, pivot.y - 20.0);
}

}  // namespace

namespace {

/// A chain of `links` capsules 1 m long hung from a pivot by a hinge and
/// joined end to end by welds whose point is rigid and whose angle is a
/// spring (2 Hz, damping ratio 0.1), the last link `ratio` times as dense,
/// released level; over 10 s, the largest total energy relative to its start
/// (the potential from below the lowest point the chain can reach) and the
/// widest any weld's anchors open (m).
std::pair<double, double> springWeldChain(int links, float ratio, int substeps) {
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const Vec2 pivot{0.0f, 20.0f};
    const BodyId ground = world.createBody({.position = pivot});
    std::vector<BodyId> bodies;
    BodyId previous = ground;
    Vec2 previousAnchor{};
    for (int i = 0; i < links; ++i) {
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = pivot + Vec2{static_cast<float>(i) + 0.5f, 0.0f}});
        world.createCapsuleShape(b, {.density = i == links - 1 ? ratio : 1.0f, .filter = {.groupIndex = -1}},
                                 Capsule{{-0.5f, 0.0f}, {0.5f, 0.0f}, 0.1f});
        if (i == 0)
            world.createRevoluteJoint({.bodyA = ground, .bodyB = b, .localAnchorB = {-0.5f, 0.0f}});
        else
            world.createWeldJoint({.bodyA = previous,
                                   .bodyB = b,
                                   .localAnchorA = previousAnchor,
                                   .localAnchorB = {-0.5f, 0.0f},
                                   .angularHertz = 2.0f,
                                   .angularDampingRatio = 0.1f});
        previous = b;
        previousAnchor = {0.5f, 0.0f};
        bodies.push_back(b);
    }
    auto energy = [&] { return test::totalEnergy(world, bodies, pivot.y - links - 1.0); };
    const double start = energy();
    double peak = start, open = 0.0;
    for (int i = 0; i < 600; ++i) {
        world.step(1.0f / 60.0f);
        peak = std::max(peak, energy());
        for (std::size_t k = 1; k < bodies.size(); ++k)
            open = std::max<double>(open, length(transformPoint(world.transform(bodies[k - 1]), {0.5f, 0.0f}) -
                                                 transformPoint(world.transform(bodies[k]), {-0.5f, 0.0f})));
        if (!std::isfinite(peak)) break;
    }
    return {peak / start, open};
}

}  // namespace

// A weld whose angle is a spring holds its point as a hinge does: its point
// rows are solved with its tree, which such a chain with a heavy end is
// (joint_tree.cpp), rigid and pushed while it touches nothing. Swept (a weld
// with any spring handed the tree nothing), a chain of 10 links with an end
// 1,000 times as dense opened 0.92, 6.2 and 34 m at 4, 2 and 1 substeps; now
// its welds stay within 2 mm (a 10:1 chain's within 1.6 cm). Bounds: a tenth
// of a link, the chain keeping its shape; 1 %, the hard-cases issue's bound
// for a passive system.
TEST(JointTree, WeldsWithAnAngularSpringHoldAHeavyEndAsHingesDo) {
    for (int substeps : {4, 2, 1})
        for (float ratio : {10.0f, 100.0f, 1000.0f}) {
            const auto [peak, open] = springWeldChain(10, ratio, substeps);
            std::printf("[figure] spring-weld chain, %.0f:1 end, %d substeps: energy at most %.4f times its start, "
                        "welds open at most %.4f m\n",
                        ratio, substeps, peak, open);
            EXPECT_LE(peak, 1.01) << ratio << ":1, " << substeps << " substeps";
            EXPECT_LE(open, 0.1) << ratio << ":1, " << substeps << " substeps";
        }
}

// Hinge trees holding a heavy body, with joints closing loops through them:
// the loops' joints were swept beside the exact trees, each moving its bodies
// by their own masses. Of these 40 layouts 3, 1 and 2 gained more than 1 % at
// 4, 2 and 1 substeps, the worst 6.3 times its energy (of 1,000: 38, 25 and
// 29, the worst 448 times). Their rows are now solved with the trees (Baraff
// (1996) §8's auxiliary rows): none of the 40 rises above its start. A
// passive system: the hard-cases issue's bound, 1 % over 5 s. Not all of the
// 1,000 meet it yet: 3, 2 and 1 (the worst 2.3 times at 4 substeps, as much
// as before; docs/validation.md, energy audit).
TEST(JointTree, LoopsClosedThroughHeavyHingeTreesKeepTheirEnergy) {
    for (int substeps : {4, 2, 1}) {
        double worst = 0.0;
        for (unsigned seed = 1; seed <= 40; ++seed) {
            const double peak = loopedTreePeakEnergy(seed, substeps);
            worst = std::max(worst, peak);
            EXPECT_LE(peak, 1.01) << "seed " << seed << ", " << substeps << " substeps";
        }
        std::printf("[figure] %d substeps: 40 hinge trees with loops, at most %.4f times their start\n", substeps,
                    worst);
    }
}

namespace {

/// Largest total energy over 5 s, relative to its start, of a random tree of
/// discs and boxes (3 to 12 bodies, each 0.5 to 1.5 m from its parent) hung
/// from a static pivot, each body with one chance in four of being 10, 100 or
/// 1,000 times as dense as the rest (the layout's ratio). Each body joins its
/// parent (at the child's centre or halfway) by a weld with an angular spring
/// (0.5 to 5 Hz, damping ratio 0 to 1) one time in four; else by a slider
/// along the line from its parent, with a translation limit and, half the
/// time, a spring, one time in three; else by a hinge, plain or with an
/// angular spring and, half the time, an angle limit. One or two distance
/// springs join random bodies (their limits, half the time, at 0.7 and 1.3
/// times their length). The springs start at rest, so leaving their energy
/// out can only hide a gain.
/// The bodies are kept apart; the potential is measured from 25 m below the
/// pivot, lower than any body can reach (12 reaches of 1.5 m and 12 slides
/// of 0.5 m).
double springTreePeakEnergy(unsigned seed, int substeps) {
    std::mt19937 rng(seed);
    auto uniform = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    auto pick = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
    WorldSettings settings;
    settings.enableSleep = false;
    settings.substeps = substeps;
    World world(settings);
    const Vec2 pivot{0.0f, 30.0f};
    const BodyId ground = world.createBody({.position = pivot});
    const int n = pick(3, 12);
    const float ratio = std::pow(10.0f, static_cast<float>(pick(1, 3)));
    std::vector<BodyId> bodies;
    for (int i = 0; i < n; ++i) {
        const int parent = i == 0 ? -1 : pick(0, i - 1);
        const BodyId a = parent < 0 ? ground : bodies[static_cast<std::size_t>(parent)];
        const Vec2 from = world.position(a);
        const float heading = uniform(0.0f, 6.2832f), reach = uniform(0.5f, 1.5f);
        const Vec2 dir{std::cos(heading), std::sin(heading)};
        const Vec2 at = from + reach * dir;
        const BodyId b = world.createBody(
            {.type = BodyType::dynamic_body, .position = at, .angle = uniform(-3.14f, 3.14f)});
        const ShapeDef def{.density = pick(0, 3) == 0 ? ratio : 1.0f, .filter = {.groupIndex = -1}};
        if (pick(0, 1) == 0)
            world.createCircleShape(b, def, Circle{{0.0f, 0.0f}, uniform(0.1f, 0.4f)});
        else
            world.createPolygonShape(b, def, makeBox(uniform(0.1f, 0.4f), uniform(0.1f, 0.4f)));
        const Vec2 anchor = pick(0, 1) == 0 ? at : 0.5f * (from + at);
        const Vec2 anchorA = invTransformPoint(world.transform(a), anchor);
        const Vec2 anchorB = invTransformPoint(world.transform(b), anchor);
        const float reference = std::remainder(world.angle(b) - world.angle(a), 6.2831853f);
        const float hertz = uniform(0.5f, 5.0f), damping = uniform(0.0f, 1.0f);
        const bool spring = pick(0, 1) == 0, limit = pick(0, 1) == 0;
        if (parent >= 0 && pick(0, 3) == 0) {
            world.createWeldJoint({.bodyA = a,
                                   .bodyB = b,
                                   .localAnchorA = anchorA,
                                   .localAnchorB = anchorB,
                                   .referenceAngle = reference,
                                   .angularHertz = hertz,
                                   .angularDampingRatio = damping});
        } else if (parent >= 0 && pick(0, 2) == 0) {
            world.createPrismaticJoint({.bodyA = a,
                                        .bodyB = b,
                                        .localAnchorA = anchorA,
                                        .localAnchorB = anchorB,
                                        .localAxisA = invRotate(world.transform(a).q, dir),
                                        .referenceAngle = reference,
                                        .enableLimit = true,
                                        .lowerTranslation = -uniform(0.1f, 0.5f),
                                        .upperTranslation = uniform(0.1f, 0.5f),
                                        .enableSpring = spring,
                                        .hertz = spring ? hertz : 0.0f,
                                        .dampingRatio = damping});
        } else {
            world.createRevoluteJoint({.bodyA = a,
                                       .bodyB = b,
                                       .localAnchorA = anchorA,
                                       .localAnchorB = anchorB,
                                       .referenceAngle = reference,
                                       .enableLimit = spring && limit,
                                       .lowerAngle = -uniform(0.1f, 0.8f),
                                       .upperAngle = uniform(0.1f, 0.8f),
                                       .enableSpring = spring,
                                       .hertz = spring ? hertz : 0.0f,
                                       .dampingRatio = damping});
        }
        bodies.push_back(b);
    }
    for (int k = pick(1, 2); k > 0; --k) {
        const int i = pick(0, n - 1), j = pick(0, n - 1);
        if (i == j) continue;
        const BodyId a = bodies[static_cast<std::size_t>(i)], b = bodies[static_cast<std::size_t>(j)];
        const float length = std::max(distance(world.position(a), world.position(b)), 0.1f);
        const bool limit = pick(0, 1) == 0;
        world.createDistanceJoint({.bodyA = a,
                                   .bodyB = b,
                                   .length = length,
                                   .enableSpring = true,
                                   .hertz = uniform(0.5f, 5.0f),
                                   .dampingRatio = uniform(0.0f, 1.0f),
                                   .enableLimit = limit,
                                   .minLength = 0.7f * length,
                                   .maxLength = 1.3f * length});
    }
    return test::peakEnergyOver5s(world, bodies, pivot.y - 25.0);
}

}  // namespace

// Trees of hinges, sliders and welds with springs and limits, and springs
// between their bodies, holding heavy bodies. A spring between the trees'
// bodies was swept beside them, moving its two bodies by their own masses; a
// limit the trees held kept its warm-started impulse when they let go of it,
// and was swept with its bodies' own masses before each solve decided to
// hold it. Of these 40 layouts 2, 3 and 3 gained more than 1 % at 4, 2 and 1
// substeps, the worst 2.3 times its energy (of 1,000: 38, 42 and 63, the
// worst 350 times). With the springs solved with the trees as auxiliary rows
// of their own compliance, a limit let go of taken off through the trees,
// and the held limits decided before the sweep (joint_tree.cpp), none of the
// 40 gains; of the 1,000, one at each substep count (the worst 8.1 % at 4
// substeps). A passive system (the springs at rest at the start, their
// energy left out, which can only hide a gain): the hard-cases issue's
// bound, 1 % over 5 s.
TEST(JointTree, TreesOfSpringsAndLimitsHoldingHeavyBodiesKeepTheirEnergy) {
    for (int substeps : {4, 2, 1}) {
        double worst = 0.0;
        for (unsigned seed = 1; seed <= 40; ++seed) {
            const double peak = springTreePeakEnergy(seed, substeps);
            worst = std::max(worst, peak);
            EXPECT_LE(peak, 1.01) << "seed " << seed << ", " << substeps << " substeps";
        }
        std::printf("[figure] %d substeps: 40 trees of springs and limits, at most %.4f times their start\n", substeps,
                    worst);
    }
}

// Trees hung from the same static bodies are judged by their own masses:
// two hinge chains of alike links (1 kg) and one of alike links with a
// 100 kg end, all three hung from the static node. Only the heavy-ended
// chain's joints are solved exactly; judged over everything joined through
// the static node, the alike chains were marked too, and so left the wide
// path for scalar rows.
TEST(JointTree, ChainsHungFromTheSameStaticBodyAreJudgedApart) {
    detail::WorldState w({}, 1);
    constexpr int kLinks = 4;
    const float endMass[3] = {1.0f, 100.0f, 1.0f};
    std::vector<detail::JointSlot> slots;
    for (int chain = 0; chain < 3; ++chain) {
        for (int link = 0; link < kLinks; ++link) {
            const int slot = w.bodies.allocate();
            detail::Body& b = w.bodies[slot];
            b.type = BodyType::dynamic_body;
            b.invMass = 1.0f / (link == kLinks - 1 ? endMass[chain] : 1.0f);
            b.invInertia = 10.0f * b.invMass;
            const int index = static_cast<int>(w.solver.stateBodies.size());
            w.solver.stateBodies.push_back(slot);
            detail::JointSlot& j = slots.emplace_back();
            j.a = link == 0 ? detail::kNullIndex : index - 1;  // the first link hangs from the static node
            j.b = index;
            j.invMassA = link == 0 ? 0.0f : w.bodies[w.solver.stateBodies[static_cast<std::size_t>(index - 1)]].invMass;
            j.invIA = 10.0f * j.invMassA;
            j.invMassB = b.invMass;
            j.invIB = b.invInertia;
            j.equalityRows = 2;
        }
    }
    detail::selectTreeJoints(w, slots, 1.0f / 240.0f);
    for (std::size_t i = 0; i < slots.size(); ++i)
        EXPECT_EQ(slots[i].inTree, i / kLinks == 1) << "joint " << i << " of chain " << i / kLinks;
}

namespace {

/// A 0.2 kg disc pinned to the world with an angle limit, carrying an 18 kg
/// box hinged 1.43 m from its centre: a tree of 90:1, solved exactly. The
/// limit's own row moves the disc by its inertia about the pivot alone, so
/// swept it barely slowed the box: the angle passed the limit by 0.52 rad,
/// and when it came back the hinges opened by 0.5 and 1.3 m and the pair
/// spun up to the rotation limit (energy from −26 J to 1.5 MJ). The tree now
/// holds a limit it reaches or nears (joint_tree.cpp).
struct LimitedPair {
    World world;
    BodyId disc, box;
    JointId pin;
    explicit LimitedPair(int substeps) : world(settings(substeps)) {
        const BodyId ground = world.createBody({});
        disc = world.createBody(
            {.type = BodyType::dynamic_body, .position = {0.0399254784f, 0.0111809783f}, .angle = 2.1700778f});
        world.createCircleShape(disc, {.density = 3.77567554f}, Circle{{0.0f, 0.0f}, 0.128754929f});
        box = world.createBody(
            {.type = BodyType::dynamic_body, .position = {-1.64351475f, -0.145014107f}, .angle = 2.71540165f});
        world.createPolygonShape(box, {.density = 26.2254562f}, makeBox(0.493358999f, 0.345605433f));
        pin = world.createRevoluteJoint({.bodyA = ground,
                                         .bodyB = disc,
                                         .localAnchorB = {0.0132873431f, 0.0392747298f},
                                         .referenceAngle = 2.1700778f,
                                         .enableLimit = true,
                                         .lowerAngle = -0.774666667f,
                                         .upperAngle = 0.39300853f});
        world.createRevoluteJoint({.bodyA = disc,
                                   .bodyB = box,
                                   .localAnchorA = {0.827022851f, 1.1661036f},
                                   .localAnchorB = {-0.156356469f, -0.270167857f},
                                   .referenceAngle = 0.545323849f});
    }
    static WorldSettings settings(int substeps) {
        WorldSettings s;
        s.enableSleep = false;  // sleep would hide a gain
        s.substeps = substeps;
        return s;
    }
    /// Kinetic plus potential energy, the potential from height y0 (J).
    double energy(double y0) const {
        double e = 0.0;
        for (BodyId b : {disc, box}) {
            const Vec2 v = world.linearVelocity(b);
            const double om = world.angularVelocity(b);
            e += 0.5 * world.mass(b) * dot(v, v) + 0.5 * world.rotationalInertia(b) * om * om +
                 world.mass(b) * 10.0 * (world.worldCenterOfMass(b).y - y0);
        }
        return e;
    }
};

}  // namespace

TEST(JointTree, ALimitHoldsAHeavyLoadThroughALightLink) {
    for (int substeps : {4, 2, 1}) {
        LimitedPair p(substeps);
        // The energy audit's convention: potential from the lowest origin, the
        // bound 1 % of the start, never less than 1 J.
        const double y0 = std::min(p.world.position(p.disc).y, p.world.position(p.box).y);
        const double start = p.energy(y0);
        double peak = start;
        float beyond = 0.0f;
        for (int i = 0; i < 600; ++i) {
            p.world.step(1.0f / 60.0f);
            peak = std::max(peak, p.energy(y0));
            beyond = std::max(beyond, p.world.revoluteJointAngle(p.pin) - 0.39300853f);
        }
        std::printf("[figure] limited 90:1 pair, %d substeps: energy at most %+.3f J over its start, the angle at "
                    "most %.4f rad past the limit\n",
                    substeps, peak - start, double(beyond));
        EXPECT_LE(peak - start, 0.01 * std::max(std::abs(start), 1.0)) << substeps << " substeps";
        // The tree holds the limit from 2° before it (joint_tree.cpp) and the
        // disc reaches it at about 3 rad/s: it can pass the limit only where
        // a substep carries it further than 2°, by 3·h − 2° = 0.015 rad at
        // one substep and not at all at 2 and 4 (measured: 0 at all three;
        // 0.004, 0.0095 and 0.042 rad when held only once reached). 2 mrad
        // more for the position the substep's first-order update leaves.
        const float h = 1.0f / (60.0f * substeps), slop = 2.0f / 180.0f * 3.14159265f;
        EXPECT_LE(beyond, std::max(3.0f * h - slop, 0.0f) + 0.002f) << substeps << " substeps";
    }
}

// A held limit lets go when the load turns the other way: the pair at rest
// against the limit, the box is thrown up, and the disc must leave the limit.
TEST(JointTree, AHeldLimitLetsGoWhenTheLoadTurns) {
    LimitedPair p(4);
    for (int i = 0; i < 120; ++i) p.world.step(1.0f / 60.0f);
    const float held = p.world.revoluteJointAngle(p.pin);
    ASSERT_GT(held, 0.38f) << "the pair rests against its upper limit";
    p.world.applyLinearImpulse(p.box, {0.0f, -400.0f}, p.world.worldCenterOfMass(p.box));
    float least = held;
    for (int i = 0; i < 60; ++i) {
        p.world.step(1.0f / 60.0f);
        least = std::min(least, p.world.revoluteJointAngle(p.pin));
    }
    std::printf("[figure] held at %.3f rad, then down to %.3f rad after the box was thrown\n", double(held),
                double(least));
    EXPECT_LT(least, held - 0.1f) << "the disc stayed at its limit";
}

// A limit the tree lets go of carries no torque: it held the pair's load
// (128 N·m) and was warm started with it, and when the thrown box turned the
// disc off the limit the tree let go of it but kept that impulse, which the
// limit's sweep row (the disc's own inertia) took back a few percent a pass:
// 128, 105 and 41 N·m over three steps while the disc left the limit. Now it
// is taken off through the tree when let go (joint_tree.cpp, releaseLimits).
TEST(JointTree, ALimitLetGoOfCarriesNoTorque) {
    LimitedPair p(4);
    for (int i = 0; i < 120; ++i) p.world.step(1.0f / 60.0f);
    const float load = std::abs(p.world.jointReactionTorque(p.pin));
    ASSERT_GT(load, 100.0f) << "the pair rests against its upper limit";
    p.world.applyLinearImpulse(p.box, {0.0f, -400.0f}, p.world.worldCenterOfMass(p.box));
    float previous = p.world.revoluteJointAngle(p.pin);
    int leaving = 0;
    for (int i = 0; i < 30; ++i) {
        p.world.step(1.0f / 60.0f);
        const float angle = p.world.revoluteJointAngle(p.pin);
        // Moving away from the upper limit (0.393 rad) and off it, not yet
        // within 2° (0.035 rad, where the tree may hold it) of the lower
        // (−0.775 rad): nothing but the limits acts along the angle (no
        // spring, no motor), so the torque is theirs, 0 but for rounding
        // (10⁻³ of the load).
        if (angle < previous && angle < 0.39f && angle > -0.74f) {
            ++leaving;
            EXPECT_LE(std::abs(p.world.jointReactionTorque(p.pin)), 1e-3f * load) << "step " << i;
        }
        previous = angle;
    }
    EXPECT_GT(leaving, 5) << "the disc left its limit";
}

namespace {

/// A light cart (a 0.1 m disc, 31 g) on a frictionless slider along x with
/// its travel limited to ±0.5 m, and a box `ratio` times its mass carried
/// 1.53 m away: hinged to the cart (`rope` false) or hung from it by a rope of
/// that length (a distance joint with only a maximum length), released level
/// with the slider. A prismatic joint's rows, a rope's length and a slider's
/// limit were left to the Gauss-Seidel sweep, where the cart's mass alone
/// resisted the box: the hinge opened 15 cm at 300:1 and the rope stretched
/// 15 cm (98 cm at one substep). The tree now takes the slider's rows, and
/// the limits and the rope's length while they hold (joint_tree.cpp).
struct CartAndLoad {
    World world;
    BodyId cart, load;
    static constexpr Vec2 kOffset{1.5f, 0.3f};  ///< the load's centre from the cart's at the start

    CartAndLoad(float ratio, bool rope, int substeps)
        : world([&] {
              WorldSettings s;
              s.enableSleep = false;  // sleep would hide drift
              s.substeps = substeps;
              return s;
          }()) {
        const BodyId ground = world.createBody({});
        cart = world.createBody({.type = BodyType::dynamic_body});
        world.createCircleShape(cart, {.density = 1.0f}, Circle{{0.0f, 0.0f}, 0.1f});
        load = world.createBody({.type = BodyType::dynamic_body, .position = kOffset});
        const float area = 0.4f * 0.2f;
        world.createPolygonShape(load, {.density = ratio * world.mass(cart) / area}, makeBox(0.2f, 0.1f));
        world.createPrismaticJoint({.bodyA = ground,
                                    .bodyB = cart,
                                    .localAxisA = {1.0f, 0.0f},
                                    .enableLimit = true,
                                    .lowerTranslation = -0.5f,
                                    .upperTranslation = 0.5f});
        if (rope)
            world.createDistanceJoint({.bodyA = cart,
                                       .bodyB = load,
                                       .length = length(kOffset),
                                       .enableSpring = true,
                                       .enableLimit = true,
                                       .minLength = 0.0f,
                                       .maxLength = length(kOffset)});
        else
            world.createRevoluteJoint({.bodyA = cart, .bodyB = load, .localAnchorB = -kOffset});
    }
    double energy() const {
        double e = 0.0;
        for (BodyId b : {cart, load}) {
            const Vec2 v = world.linearVelocity(b);
            const float om = world.angularVelocity(b);
            e += 0.5 * world.mass(b) * dot(v, v) + 0.5 * world.rotationalInertia(b) * om * om +
                 world.mass(b) * 10.0 * world.worldCenterOfMass(b).y;
        }
        return e;
    }
    /// The hinge's opening, or how far the rope is stretched past its length.
    float jointError(bool rope) const {
        const Vec2 loadAnchor = rope ? world.position(load) : transformPoint(world.transform(load), -kOffset);
        const float gap = distance(loadAnchor, world.position(cart));
        return rope ? gap - length(kOffset) : gap;
    }
    struct Outcome {
        double start, peak;  ///< energy (J)
        float worstError;    ///< jointError's largest
    };
    /// 10 s at 60 Hz.
    Outcome run(bool rope) {
        Outcome o{energy(), energy(), 0.0f};
        for (int i = 0; i < 600; ++i) {
            world.step(1.0f / 60.0f);
            o.peak = std::max(o.peak, energy());
            o.worstError = std::max(o.worstError, jointError(rope));
        }
        return o;
    }
};

}  // namespace

// The hinge of the cart carrying a 300-times heavier box, solved with the
// slider in one tree.
TEST(JointTree, ASliderCarryingAHeavyLoadHoldsItsHinge) {
    constexpr float kRatio = 300.0f;
    CartAndLoad s(kRatio, false, 4);
    const auto [start, peak, opening] = s.run(false);
    std::printf("[figure] slider carrying a %g:1 load: hinge opened at most %.4f m\n", double(kRatio), double(opening));
    // The tree's rows are soft with the joints' frequency ω = 2π·60 Hz against
    // the row's own mass, the cart's: a load F sags them by F/(m_cart·ω²). The
    // hinge carries at most the tension of a pendulum released level with
    // its pivot and 0.3/1.53 of its length above it, (3 + 2·0.3/1.53)·m·g at
    // the bottom: 3.4·300·g/ω² = 7.2 cm. (Measured 2.2 cm; 15 cm swept.)
    const float omega = 2.0f * 3.14159265f * 60.0f;
    EXPECT_LT(opening, 3.4f * kRatio * 10.0f / (omega * omega));
    EXPECT_LE(peak - start, 0.01 * std::abs(start));  // the hard-cases issue's 1 %
}

// The rope of the cart carrying a 300-times heavier box: held rigid by the
// tree once taut.
TEST(JointTree, ARopeFromALightSliderHoldsAHeavyLoad) {
    for (int substeps : {4, 1}) {
        CartAndLoad s(300.0f, true, substeps);
        const auto [start, peak, stretch] = s.run(true);
        std::printf("[figure] rope from a light slider, %d substeps: stretched at most %.4f m\n", substeps,
                    double(stretch));
        // A limit is held from the substep in which it is reached or nears
        // (5 mm): the load can pass it by one substep's travel at most, at
        // the speed of a fall from its start to the lowest the rope lets it
        // reach (0.3 + 1.53 m), √(2·g·1.83) = 6.05 m/s. (Measured 0.1 cm at 4
        // substeps and 1.4 cm at one, the tree holding the rope from 5 mm
        // before it is taut; 15 and 98 cm swept.)
        const float h = 1.0f / (60.0f * substeps);
        EXPECT_LT(stretch, std::sqrt(2.0f * 10.0f * 1.83f) * h) << substeps << " substeps";
        EXPECT_LE(peak - start, 0.01 * std::abs(start)) << substeps << " substeps";
    }
}

// A rigid weld from the world to a light body that does not turn, carrying a
// box 255 times its mass on a hinge: a tree. The weld's angle row acts on
// nothing (neither side turns); its zero pivot made the weld's whole block
// singular, which the elimination drops, so the weld held nothing and the
// light body fell with the box (125 m in 5 s). A row no body can act on is
// now moot, as in the joint's own sweep (joint_tree.cpp).
TEST(JointTree, ARowNoBodyCanActOnLeavesTheOthersHeld) {
    WorldSettings s;
    s.enableSleep = false;
    World w(s);
    const BodyId ground = w.createBody({});
    const BodyId light = w.createBody({.type = BodyType::dynamic_body, .fixedRotation = true});
    w.createCircleShape(light, {.density = 1.0f}, Circle{{0.0f, 0.0f}, 0.1f});
    const BodyId box = w.createBody({.type = BodyType::dynamic_body, .position = {1.0f, 0.0f}});
    w.createPolygonShape(box, {.density = 100.0f}, makeBox(0.2f, 0.1f));
    w.createWeldJoint({.bodyA = ground, .bodyB = light});
    w.createRevoluteJoint({.bodyA = light, .bodyB = box, .localAnchorB = {-1.0f, 0.0f}});
    float drift = 0.0f;
    for (int i = 0; i < 300; ++i) {
        w.step(1.0f / 60.0f);
        drift = std::max(drift, length(w.position(light)));
    }
    std::printf("[figure] welded light body under a %.0f:1 load: moved at most %.4f m\n",
                double(w.mass(box) / w.mass(light)), double(drift));
    // The weld's soft point row (ω = 2π·60 Hz against the light body's mass)
    // sags under the hinge's pull, at most a pendulum released level's 3·m·g:
    // 3·m_box·g/(m_light·ω²) = 5.4 cm. (Measured 1.5 cm.)
    const float omega = 2.0f * 3.14159265f * 60.0f;
    EXPECT_LT(drift, 3.0f * w.mass(box) * 10.0f / (w.mass(light) * omega * omega));
}
