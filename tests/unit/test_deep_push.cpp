// The push of deep overlaps (deep_overlap.cpp, pushDeepOverlaps): each
// body's pseudo-velocity across gravity is held to three times maxPushSpeed
// c, whether the body is supported (rests, through upward normals, on
// something immovable) or rests on nothing; without gravity to three times c
// in every direction. A manifold's two points are pushed together.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "contact_solver.hpp"
#include "deep_overlap.hpp"
#include "world_fixtures.hpp"
#include "world_state.hpp"

namespace {

using namespace i2d;
using namespace i2d::detail;

constexpr int kBodies = 5;

/// `count` (five unless said) unit-mass bodies in a horizontal row, each 0.5 m deep in the next
/// and the first 0.5 m deep in something immovable on its left (the zero
/// state): one deep row per pair, normal +x, one point at the centres. Each
/// row asks its pair to part at c, so, unlimited, the k-th body would be
/// pushed right at (k + 1)·c.
void deepRow(WorldState& w, Vec2 gravity, bool supported, int count = kBodies) {
    w.settings.gravity = gravity;
    SolverArrays& s = w.solver;
    s.states.assign(count + 1, BodyState{});
    s.integration.assign(count, BodyIntegration{});
    s.stateBodies.clear();
    for (int i = 0; i < count; ++i) {
        const int slot = w.bodies.allocate();
        Body& b = w.bodies[slot];
        b.type = BodyType::dynamic_body;
        b.invMass = b.invInertia = 1.0f;
        b.solverIndex = i;
        s.stateBodies.push_back(slot);
        s.integration[static_cast<std::size_t>(i)].linearAcceleration = gravity;
    }
    s.supported.assign(count + 1, supported ? 1 : 0);
    // As prepareDeepOverlaps marks it: the first body's row, against the zero
    // state, is level, so it may lift that body by nothing.
    s.pushOffFixedLift.assign(count + 1, 0.0f);
    s.constraints.resizeForOverwrite(count);
    s.rowCount = count;
    s.deepRows.clear();
    s.sidePushes.clear();
    const Softness soft = makeSoft(30.0f, 10.0f, 1.0f / 240.0f);
    for (int r = 0; r < count; ++r) {
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(r)];
        cc = ContactConstraint{};
        cc.a = r == 0 ? count : r - 1;  // the zero state, then the body on the left
        cc.b = r;
        cc.normal = {1.0f, 0.0f};
        cc.invMassA = cc.invIA = r == 0 ? 0.0f : 1.0f;
        cc.invMassB = cc.invIB = 1.0f;
        cc.biasRate = soft.biasRate;
        cc.massScale = soft.massScale;
        cc.impulseScale = soft.impulseScale;
        cc.deepOverlap = true;
        cc.roundA = cc.roundB = false;
        cc.turnA = cc.turnB = false;
        cc.pointCount = 1;
        ContactPointConstraint& cp = cc.points[0];
        cp.rA = cp.rB = {0.0f, 0.0f};
        cp.adjustedSeparation = -0.5f;
        cp.normalMass = 1.0f / (cc.invMassA + cc.invMassB);
        cp.normalImpulse = cp.biasImpulse = 0.0f;
        s.deepRows.push_back(r);
    }
}

/// The fastest pseudo-speed after the push of a step's fourth substep, each
/// substep's sweeps starting from the last one's impulses (each body's
/// pseudo-velocity is along +x: the rows are).
float fastestPush(Vec2 gravity, bool supported, int count) {
    WorldState w({}, 1);
    deepRow(w, gravity, supported, count);
    for (int substep = 0; substep < 4; ++substep) pushDeepOverlaps(w, 1.0f / 240.0f);
    float fastest = 0.0f;
    for (int i = 0; i < count; ++i) {
        const Vec2 v = w.solver.biasV[static_cast<std::size_t>(i)];
        EXPECT_EQ(v.y, 0.0f) << "body " << i;
        fastest = std::max(fastest, v.x);
    }
    return fastest;
}

// A row long enough to ask for more than the sideways limit: its last body,
// unlimited, would be pushed at kLongRow·c, three times the cap beyond the
// limit. With sixteen sweeps a substep, which do not converge along it, one
// substep's push left the last body of a row of 8 at 13.4 m/s of a limit of
// 15, so a step's four substeps are taken; with the sweeps run on until they
// converge (kMaxPushSweeps, deep_overlap.cpp) one substep reaches the limit
// as well.
constexpr int kLongRow = static_cast<int>(kSidewaysPushFactor) + 3;

// Float rounding of limitTo's rescaling (a few ulps of the limit, 30 m/s).
constexpr float kRounding = 1e-5f;

TEST(DeepPush, AcrossGravityTheSidewaysLimitForEveryBody) {
    const float c = WorldSettings{}.maxPushSpeed;
    {
        WorldState w({}, 1);
        deepRow(w, {0.0f, -10.0f}, true);
        const ContactConstraint& cc = w.solver.constraints[0];
        ASSERT_GT(cc.biasRate * 0.5f, c) << "each row must ask for the cap";
    }
    // Reaching kSidewaysPushFactor·c shows the pile asks for more than each
    // point's c; a supported body is held to the same limit as one resting
    // on nothing.
    EXPECT_NEAR(fastestPush({0.0f, -10.0f}, true, kLongRow), kSidewaysPushFactor * c, kRounding);
    EXPECT_NEAR(fastestPush({0.0f, -10.0f}, false, kLongRow), kSidewaysPushFactor * c, kRounding);
}

// Without gravity nothing is supported and every direction is across.
TEST(DeepPush, WithoutGravityTheSidewaysLimitInEveryDirection) {
    const float c = WorldSettings{}.maxPushSpeed;
    EXPECT_NEAR(fastestPush({0.0f, 0.0f}, false, kLongRow), kSidewaysPushFactor * c, kRounding);
}

// The same row stood on end: the first body 0.5 m deep in something
// immovable below it, each of the others 0.5 m deep in the one below, all
// at rest. No body is lifted above the highest it has been
// (deep_overlap.cpp): at its highest a body is not lifted at all, however
// hard the rows below push, whether it rests on something or not, and 1 m
// below it the cap applies. The first body, pushed out of what cannot move,
// is lifted either way (by at most its depth there: the next test).
TEST(DeepPush, ABodyIsLiftedBackToItsHighestAtMost) {
    const float c = WorldSettings{}.maxPushSpeed;
    const float h = 1.0f / 240.0f;
    for (bool supported : {true, false})
        for (float below : {0.0f, 1.0f}) {
            WorldState w({}, 1);
            deepRow(w, {0.0f, -10.0f}, supported);
            for (int r = 0; r < kBodies; ++r) {
                w.solver.constraints[static_cast<std::size_t>(r)].normal = {0.0f, 1.0f};
                w.bodies[w.solver.stateBodies[static_cast<std::size_t>(r)]].highest = below;  // centres at 0
            }
            w.solver.pushOffFixedLift[0] = 0.5f;  // its depth in what is below, as prepareDeepOverlaps marks it
            pushDeepOverlaps(w, h);
            const std::vector<Vec2>& v = w.solver.biasV;
            // Lifted, within the cap (the rows above it push back on it: 2.05 m/s).
            EXPECT_GT(v[0].y, 0.5f * c) << below << " m below its highest";
            EXPECT_LE(v[0].y, c + kRounding) << below << " m below its highest";
            for (std::size_t i = 1; i < kBodies; ++i) {
                EXPECT_EQ(v[i].x, 0.0f);
                if (below == 0.0f)
                    EXPECT_EQ(v[i].y, 0.0f) << "body " << i << " at its highest, supported " << supported;
                else
                    EXPECT_NEAR(v[i].y, c, kRounding) << "body " << i << ", 1 m below its highest";
            }
        }
}

// A body pushed out of what cannot move may rise above the highest it has
// been by that row's depth along up at the step's start, and no further
// (prepareDeepOverlaps): a body the push itself drove into the ground is
// lifted out of it, not above where it was. One body at its highest, 0.5 m
// deep in what is below it, allowed a lift of 0.2 m (as if the row had been
// 0.2 m deep when the step began): already lifted 0.2 m in the step's
// earlier substeps, it is not lifted again though its row asks for the cap;
// 1 mm short, the substep lifts it by the 1 mm, 0.24 m/s at h = 1/240 s.
TEST(DeepPush, ABodyPushedOutOfWhatCannotMoveRisesByItsDepthAtMost) {
    const float h = 1.0f / 240.0f;
    for (float lifted : {0.2f, 0.199f}) {
        WorldState w({}, 1);
        deepRow(w, {0.0f, -10.0f}, true, 1);
        w.solver.constraints[0].normal = {0.0f, 1.0f};
        w.bodies[w.solver.stateBodies[0]].highest = 0.0f;  // its centre is at 0
        w.solver.pushOffFixedLift[0] = 0.2f;
        w.solver.states[0].dp = {0.0f, lifted};
        pushDeepOverlaps(w, h);
        // (0.2 − lifted)/h in float: lifted is 0.199 to within 1e-8 m, so
        // the limit to within 1e-8/h ≈ 2.4e-6 m/s; 1e-5 allows rounding.
        EXPECT_NEAR(w.solver.biasV[0].y, (0.2f - lifted) / h, 1e-5f) << "lifted " << lifted << " m so far";
        // Not lifted yet in this step, it is lifted at the cap.
        w.solver.states[0].dp = {};
        pushDeepOverlaps(w, h);
        EXPECT_NEAR(w.solver.biasV[0].y, WorldSettings{}.maxPushSpeed, kRounding);
    }
}

// Twenty unit boxes created in a row, each half inside the next, without
// gravity or a ground: every manifold's two points (the bottom and top of
// the overlap) are alike, so the push has nothing to turn. Solved one point
// after the other, the first point's push turned each box before the second
// was solved, and the sweeps left the turn in them, all the same way: up to
// 0.063 rad in the first step, and on the ground such a row ended leaning on
// itself, 2.8 % over its energy (docs/validation.md, "Rows turned by the
// push"). Now the two points are solved together (pushPointPair). Bound:
// with equal targets and mirrored arms the exact solve gives the two points
// equal impulses, so any turn left is float rounding; 1e-6 rad is 60,000
// times below the 0.063 rad the order gave (measured 0).
TEST(DeepPush, ARowOfBoxesPushedApartIsNotTurned) {
    WorldSettings settings;
    settings.gravity = {0.0f, 0.0f};
    settings.enableSleep = false;
    World world(settings);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 20; ++i) boxes.push_back(test::makeBox(world, {0.5f * static_cast<float>(i), 0.0f}));
    world.step(1.0f / 60.0f);
    float turned = 0.0f, spread = 0.0f;
    for (const BodyId b : boxes) turned = std::max(turned, std::abs(world.angle(b)));
    spread = world.position(boxes.back()).x - world.position(boxes.front()).x;
    std::printf("[figure] row of 20 boxes half inside each other, first step: largest turn %.2e rad, spread "
                "%.3f m (created 9.5 m)\n",
                turned, spread);
    EXPECT_GT(spread, 9.5f);  // the push acted
    EXPECT_LE(turned, 1e-6f);
}

}  // namespace
