// Validation suite — every case of cases.cpp asserted: Impulse2D always,
// Box2D 2.4.1 where the case holds it to a figure (free fall to rounding;
// pendulum, incline, rolling and bounce within their stated tolerance;
// stacks and pyramids stand; the joint cases of joint_cases.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "cases.hpp"

namespace {

const std::vector<val::Case>& cases() {
    static const std::vector<val::Case> all = val::allCases(VAL_ASSETS_DIR);
    return all;
}

std::vector<std::size_t> caseIndices() {
    std::vector<std::size_t> v(cases().size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = i;
    return v;
}

void expectWithin(const val::Case& c, tb::EngineKind kind) {
    const val::Check& check = c.check(kind);
    const double figure = c.measure(kind);
    const double reference = c.reference(kind);
    ASSERT_TRUE(std::isfinite(figure)) << c.id << " (" << tb::engineName(kind) << "): no figure";
    if (!check.knownIssue.empty()) {
        // A documented shortfall (docs/validation.md, "Known issues"): held to
        // the bound its cause allows; the report shows it against the real one.
        ::testing::Test::RecordProperty("known_issue", check.knownIssue);
        EXPECT_LE(std::abs(figure - reference), check.issueTolerance)
            << c.id << " (" << tb::engineName(kind) << "): " << c.quantity << " = " << figure << ", known issue ("
            << check.knownIssue << ") now beyond its bound " << check.issueTolerance;
        return;
    }
    EXPECT_LE(std::abs(figure - reference), check.tolerance)
        << c.id << " (" << tb::engineName(kind) << "): " << c.quantity << " = " << figure << ", held against "
        << reference << " ± " << check.tolerance << " (" << check.why << ")";
}

class Validation : public ::testing::TestWithParam<std::size_t> {};

TEST_P(Validation, Impulse2D) {
    const val::Case& c = cases()[GetParam()];
    if (!c.impulse2d.asserted) GTEST_SKIP() << "reported only: " << c.impulse2d.why;
    expectWithin(c, tb::EngineKind::impulse2d);
}

TEST_P(Validation, Box2D) {
    const val::Case& c = cases()[GetParam()];
    if (!tb::box2dAvailable()) GTEST_SKIP() << "testbed built without Box2D 2.4.1";
    if (!c.box2d.asserted) GTEST_SKIP() << "reported only: " << c.box2d.why;
    expectWithin(c, tb::EngineKind::box2d);
}

INSTANTIATE_TEST_SUITE_P(Cases, Validation, ::testing::ValuesIn(caseIndices()),
                         [](const ::testing::TestParamInfo<std::size_t>& info) { return cases()[info.param].id; });

// Box2D 2.4.1 integrates by semi-implicit Euler (v += h g, then x += h v):
// its free fall runs ahead of g t²/2 by g h t/2. Impulse2D gives a body that
// touches nothing its gravity in two halves around the drift (velocity
// Verlet, split_kick.hpp), which falls on g t²/2 itself. With one substep
// each, Box2D's drop leads by exactly g h t/2 but for float rounding: a few
// ulp of |y| ≤ 5 m per step in each engine, 60 steps × 2 ulp(8 m) = 1.1e-4 m.
TEST(FreeFall, BoxTwoDsDropLeadsByHalfAStepOfGravity) {
    if (!tb::box2dAvailable()) GTEST_SKIP() << "testbed built without Box2D 2.4.1";
    EXPECT_LE(val::oneSubstepFreeFallLead(), 60 * 2 * 8 * 1.1920928955078125e-07);
}

TEST(Analytic, EllipticIntegralMatchesTabulatedPeriods) {
    // HARD_CASES 5.2: T/T0 = 2K(sin(θ0/2))/π = 1.000476 (5°), 1.180341 (90°), 1.762204 (150°).
    const double pi = 3.14159265358979323846;
    EXPECT_NEAR(2.0 * val::ellipticK(std::sin(5.0 * pi / 360.0)) / pi, 1.000476, 1e-6);
    EXPECT_NEAR(2.0 * val::ellipticK(std::sin(90.0 * pi / 360.0)) / pi, 1.180341, 1e-6);
    EXPECT_NEAR(2.0 * val::ellipticK(std::sin(150.0 * pi / 360.0)) / pi, 1.762204, 1e-6);
}

}  // namespace
