// Revolute point rows solved four or eight at a time (wide_revolute.cpp) against the
// scalar row (revolute_joint.cpp) on the same random rows: the same
// operations in the same order, so the velocities and impulses must agree
// bit for bit, in every pass, on SSE2 and on the portable path (the
// sanitizer build compiles the engine with I2D_SCALAR_FLOAT4).
#include <algorithm>
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "joint_rows.hpp"
#include "solver.hpp"
#include "wide_contact.hpp"
#include "wide_revolute.hpp"

namespace {

using namespace i2d;
using namespace i2d::detail;

struct Case {
    SolverArrays wide, scalar;
    std::vector<JointConstraint> rows;
};

/// n independent hinges (row i joins bodies 2i and 2i+1; every fifth row has
/// an immovable side A, the zero state), random states and rows.
Case makeCase(unsigned seed, int n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f), m(0.05f, 3.0f), angle(-3.0f, 3.0f);
    Case c;
    std::vector<BodyState> states(static_cast<std::size_t>(2 * n) + 1);
    for (std::size_t i = 0; i + 1 < states.size(); ++i) {
        BodyState& s = states[i];
        s.v = {u(rng), u(rng)};
        s.w = u(rng);
        s.dp = {0.01f * u(rng), 0.01f * u(rng)};
        const float a = 0.05f * angle(rng);
        s.dq = {std::cos(a), std::sin(a)};
    }
    const int zero = 2 * n;
    for (int i = 0; i < n; ++i) {
        JointConstraint jc;
        jc.type = JointType::revolute;
        jc.singlePrecision = true;
        const bool immovableA = i % 5 == 0;
        jc.a = immovableA ? kNullIndex : 2 * i;
        jc.b = 2 * i + 1;
        jc.invMassA = immovableA ? 0.0f : m(rng);
        jc.invIA = immovableA ? 0.0f : m(rng);
        jc.invMassB = m(rng);
        jc.invIB = m(rng);
        jc.rA = {u(rng), u(rng)};
        jc.rB = {u(rng), u(rng)};
        jc.deltaCenter = {u(rng), u(rng)};
        jc.impulses.linear = {u(rng), u(rng)};
        jc.row.revolute = RevoluteRow{};
        c.rows.push_back(jc);
    }
    for (SolverArrays* s : {&c.wide, &c.scalar}) {
        s->states.resizeForOverwrite(states.size());
        std::copy(states.begin(), states.end(), s->states.begin());
    }
    // The blocks, as packWideRevolutes fills them (empty lanes on the zero state).
    for (int start = 0; start < n; start += kHingeLanes) {
        WideRevoluteBlock& k = c.wide.wideRevolutes.emplace_back();
        for (int lane = 0; lane < kHingeLanes; ++lane) {
            const int r = start + lane;
            const JointConstraint* jc = r < n ? &c.rows[static_cast<std::size_t>(r)] : nullptr;
            k.a[lane] = jc && jc->a >= 0 ? jc->a : zero;
            k.b[lane] = jc ? jc->b : zero;
            k.joint[lane] = jc ? r : -1;
            k.rAx[lane] = jc ? jc->rA.x : 0.0f, k.rAy[lane] = jc ? jc->rA.y : 0.0f;
            k.rBx[lane] = jc ? jc->rB.x : 0.0f, k.rBy[lane] = jc ? jc->rB.y : 0.0f;
            k.dcx[lane] = jc ? jc->deltaCenter.x : 0.0f, k.dcy[lane] = jc ? jc->deltaCenter.y : 0.0f;
            k.mA[lane] = jc ? jc->invMassA : 0.0f, k.iA[lane] = jc ? jc->invIA : 0.0f;
            k.mB[lane] = jc ? jc->invMassB : 0.0f, k.iB[lane] = jc ? jc->invIB : 0.0f;
            k.px[lane] = jc ? jc->impulses.linear.x : 0.0f, k.py[lane] = jc ? jc->impulses.linear.y : 0.0f;
            k.moves[lane] = moveFlags(k.mA[lane], k.iA[lane], k.mB[lane], k.iB[lane]);
        }
    }
    return c;
}

BodyState& stateOf(SolverArrays& s, int index) {
    return index >= 0 ? s.states[static_cast<std::size_t>(index)] : s.states.back();
}

void expectSame(Case& c, const char* what) {
    const int n = static_cast<int>(c.rows.size());
    for (std::size_t i = 0; i + 1 < c.wide.states.size(); ++i) {
        const BodyState &a = c.wide.states[i], &b = c.scalar.states[i];
        ASSERT_EQ(a.v.x, b.v.x) << what << " body " << i;
        ASSERT_EQ(a.v.y, b.v.y) << what << " body " << i;
        ASSERT_EQ(a.w, b.w) << what << " body " << i;
    }
    for (int r = 0; r < n; ++r) {
        const WideRevoluteBlock& k = c.wide.wideRevolutes[static_cast<std::size_t>(r / kHingeLanes)];
        ASSERT_EQ(k.px[r % kHingeLanes], c.rows[static_cast<std::size_t>(r)].impulses.linear.x) << what << " row " << r;
        ASSERT_EQ(k.py[r % kHingeLanes], c.rows[static_cast<std::size_t>(r)].impulses.linear.y) << what << " row " << r;
    }
}

/// Restores the widest lanes the CPU offers when a test ends.
struct LaneLimit {
    explicit LaneLimit(int lanes) { limitWideLanes(lanes); }
    ~LaneLimit() { limitWideLanes(8); }
};

void expectAgreement(int lanes) {
    const LaneLimit limit(lanes);
    for (unsigned seed = 1; seed <= 20; ++seed) {
        Case c = makeCase(seed, 37);  // not a multiple of four or eight: the last block has empty lanes
        const int blocks = static_cast<int>(c.wide.wideRevolutes.size());
        warmStartWideRevolutes(c.wide, 0, blocks, false);
        for (JointConstraint& jc : c.rows) warmStartRevoluteJoint(jc, stateOf(c.scalar, jc.a), stateOf(c.scalar, jc.b));
        c.scalar.states.back() = c.wide.states.back() = BodyState{};
        expectSame(c, "warm start");
        JointContext ctx;
        ctx.h = 1.0f / 240.0f;
        ctx.invH = 240.0f;
        ctx.jointSoft = makeSoft(60.0f, 2.0f, ctx.h);
        ctx.pushFactor = 0.2f;
        for (SolvePass pass : {SolvePass::soft_bias, SolvePass::soft_relax, SolvePass::baumgarte}) {
            ctx.pass = pass;
            solveWideRevolutes(c.wide, ctx, 0, blocks, true);  // the states do not move here
            for (JointConstraint& jc : c.rows)
                solveRevoluteJoint(jc, ctx, stateOf(c.scalar, jc.a), stateOf(c.scalar, jc.b));
            c.scalar.states.back() = c.wide.states.back() = BodyState{};
            expectSame(c, "solve");
        }
    }
}

TEST(WideRevolute, AgreesBitForBitWithTheScalarRowInFourLanes) { expectAgreement(4); }

// A block in one register's eight lanes where the CPU has AVX2 (37 rows are
// five blocks, the last with three empty lanes: the sweep takes two pairs of
// blocks in sixteen lanes, then the last alone); the four-lane path solves
// each block as two halves.
TEST(WideRevolute, AgreesBitForBitWithTheScalarRowInEightLanes) {
    limitWideLanes(8);
    if (wideLanes() != 8) GTEST_SKIP() << "no AVX2 on this CPU (or a portable build)";
    expectAgreement(8);
}

}  // namespace
