// Integration of the solver's bodies (integration.cpp) and the stop of a body
// a sweep left with a non-finite velocity. In the soft step the integrations
// are where a non-finite velocity is found (no scan of its own after each
// sweep): a body found so must be left as it is, the others integrated as
// ever, and stopNonFiniteBodies must then stop it and drop its rows'
// impulses, so that every body stays finite.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>

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

}  // namespace
