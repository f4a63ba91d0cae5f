// Integration of the solver's bodies (integration.cpp) and the stop of a body
// a sweep left with a non-finite velocity. In the soft step the integrations
// are where a non-finite velocity is found (no scan of its own after each
// sweep): a body found so must be left as it is, the others integrated as
// ever, and stopNonFiniteBodies must then stop it and drop its rows'
// impulses, so that every body stays finite.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "integration.hpp"
#include "world_state.hpp"

namespace {

using namespace i2d;
using namespace i2d::detail;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr int kBodies = 8;  // two groups of four: the four-wide paths and their scalar fallback
constexpr float kH = 1.0f / 240.0f;
constexpr float kMaxSpeed = 400.0f;

/// kBodies bodies moving right at 1 m/s, unturned, moved by gravity; the
/// zero state after them.
SolverArrays movingBodies() {
    SolverArrays s;
    s.states.assign(kBodies + 1, BodyState{});
    s.integration.assign(kBodies, BodyIntegration{});
    s.stateBodies.clear();
    for (int i = 0; i < kBodies; ++i) {
        BodyState& st = s.states[static_cast<std::size_t>(i)];
        st.v = {1.0f, 0.0f};
        st.dq = Rot{1.0f, 0.0f};
        BodyIntegration& in = s.integration[static_cast<std::size_t>(i)];
        in.linearAcceleration = {0.0f, -10.0f};
        in.movedByForces = true;
        s.stateBodies.push_back(i);
    }
    return s;
}

TEST(Integration, PositionsLeaveANonFiniteBodyWhereItIsAndSaySo) {
    SolverArrays s = movingBodies();
    s.states[5].v.x = kNan;  // in the second group of four
    std::atomic<bool> nonFinite{false};
    integratePositions(s, kH, kMaxSpeed, 0, kBodies, nonFinite);
    EXPECT_TRUE(nonFinite.load());
    EXPECT_EQ(s.states[5].dp.x, 0.0f);
    EXPECT_EQ(s.states[5].dp.y, 0.0f);
    // Every other body moved by h·v, in either group (the second one on the
    // scalar path, which a non-finite lane sends it to).
    for (int i : {0, 3, 4, 6, 7}) EXPECT_FLOAT_EQ(s.states[static_cast<std::size_t>(i)].dp.x, kH) << i;
}

TEST(Integration, PositionsOfFiniteBodiesSayNothing) {
    SolverArrays s = movingBodies();
    std::atomic<bool> nonFinite{false};
    integratePositions(s, kH, kMaxSpeed, 0, kBodies, nonFinite);
    EXPECT_FALSE(nonFinite.load());
    for (int i = 0; i < kBodies; ++i) EXPECT_FLOAT_EQ(s.states[static_cast<std::size_t>(i)].dp.x, kH) << i;
}

TEST(Integration, VelocitiesLeaveANonFiniteBodyAsItIsAndSaySo) {
    SolverArrays s = movingBodies();
    s.states[2].w = kInf;  // in the first group of four
    // A body not moved by forces (kinematic) is looked at too: a row's NaN
    // impulse times its zero inverse mass is NaN.
    s.integration[6].movedByForces = false;
    s.states[6].v.y = kNan;
    std::atomic<bool> nonFinite{false};
    integrateVelocities(s, kH, kMaxSpeed, 0, kBodies, false, Vec2{0.0f, 1.0f}, nonFinite);
    EXPECT_TRUE(nonFinite.load());
    EXPECT_EQ(s.states[2].v.y, 0.0f);  // no gravity added
    EXPECT_TRUE(std::isinf(s.states[2].w));
    for (int i : {0, 1, 3, 4, 5, 7}) EXPECT_FLOAT_EQ(s.states[static_cast<std::size_t>(i)].v.y, -10.0f * kH) << i;

    // Only bodies 0 to 3 asked: body 6 is not seen.
    SolverArrays t = movingBodies();
    t.states[6].v.y = kNan;
    std::atomic<bool> firstGroup{false};
    integrateVelocities(t, kH, kMaxSpeed, 0, 4, false, Vec2{0.0f, 1.0f}, firstGroup);
    EXPECT_FALSE(firstGroup.load());
}

TEST(Integration, StopNonFiniteBodiesStopsThemAndDropsTheirRowsImpulses) {
    SolverArrays s = movingBodies();
    s.states[5].v.x = kNan;
    s.constraints.resizeForOverwrite(2);
    for (int r = 0; r < 2; ++r) {
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(r)];
        cc = ContactConstraint{};
        cc.pointCount = 1;
        cc.points[0] = ContactPointConstraint{};
        cc.points[0].normalImpulse = 3.0f;
        cc.points[0].tangentImpulse = 1.0f;
    }
    s.constraints[0].a = 5, s.constraints[0].b = 6;        // on the non-finite body
    s.constraints[1].a = 1, s.constraints[1].b = kBodies;  // on body 1 and the zero state
    stopNonFiniteBodies(s);
    EXPECT_EQ(s.states[5].v.x, 0.0f);
    EXPECT_EQ(s.states[5].v.y, 0.0f);
    EXPECT_EQ(s.states[5].w, 0.0f);
    EXPECT_EQ(s.constraints[0].points[0].normalImpulse, 0.0f);
    EXPECT_EQ(s.constraints[0].points[0].tangentImpulse, 0.0f);
    EXPECT_EQ(s.constraints[1].points[0].normalImpulse, 3.0f);  // untouched
    for (int i = 0; i < kBodies; ++i) {
        const BodyState& st = s.states[static_cast<std::size_t>(i)];
        EXPECT_TRUE(std::isfinite(st.v.x) && std::isfinite(st.v.y) && std::isfinite(st.w)) << i;
        if (i != 5) {
            EXPECT_EQ(st.v.x, 1.0f) << i;
        }
    }
}

/// Random bodies for the agreement test below: a few kinematic (not moved by
/// forces) and a few faster than the limits, so that the wide groups that
/// hold one fall back to the scalar loop; most groups hold none.
SolverArrays randomBodies(unsigned seed, int n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), damp(0.9f, 1.0f);
    SolverArrays s;
    s.states.assign(static_cast<std::size_t>(n) + 1, BodyState{});
    s.integration.assign(static_cast<std::size_t>(n), BodyIntegration{});
    for (int i = 0; i < n; ++i) {
        BodyState& st = s.states[static_cast<std::size_t>(i)];
        const float speed = i == 35 ? 600.0f : 5.0f;  // above kMaxSpeed
        st.v = {speed * u(rng), speed * u(rng)};
        st.w = (i == 60 ? 4000.0f : 20.0f) * u(rng);  // above the turn limit
        st.upBeforeRelax = u(rng);
        st.dp = {0.1f * u(rng), 0.1f * u(rng)};
        const float a = 3.0f * u(rng);
        st.dq = {std::cos(a), std::sin(a)};
        BodyIntegration& in = s.integration[static_cast<std::size_t>(i)];
        in.linearAcceleration = {10.0f * u(rng), 10.0f * u(rng)};
        in.torque = 5.0f * u(rng);
        in.invInertia = 2.0f + u(rng);
        in.linearDampingFactor = damp(rng);
        in.angularDampingFactor = damp(rng);
        in.movedByForces = i != 20 && i != 50;
        s.stateBodies.push_back(i);
    }
    return s;
}

// The wide integrations (four bodies at a time, and eight on CPUs with AVX2)
// must give the scalar loop's bits: each body integrated on its own (a range
// of one, which only the scalar loop takes) against all at once.
TEST(Integration, WideGroupsAgreeBitForBitWithTheScalarLoop) {
    constexpr int n = 77;  // groups of eight, of four and a tail
    for (unsigned seed = 1; seed <= 20; ++seed) {
        SolverArrays wide = randomBodies(seed, n), scalar = randomBodies(seed, n);
        std::atomic<bool> flag{false};
        integrateVelocities(wide, kH, kMaxSpeed, 0, n, false, Vec2{0.0f, 1.0f}, flag);
        for (int i = 0; i < n; ++i) integrateVelocities(scalar, kH, kMaxSpeed, i, i + 1, false, Vec2{0.0f, 1.0f}, flag);
        integratePositions(wide, kH, kMaxSpeed, 0, n, flag);
        for (int i = 0; i < n; ++i) integratePositions(scalar, kH, kMaxSpeed, i, i + 1, flag);
        EXPECT_FALSE(flag.load());
        for (int i = 0; i < n; ++i)
            EXPECT_EQ(std::memcmp(&wide.states[static_cast<std::size_t>(i)],
                                  &scalar.states[static_cast<std::size_t>(i)], sizeof(BodyState)),
                      0)
                << "seed " << seed << ", body " << i;
    }
}

}  // namespace
