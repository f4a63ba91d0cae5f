// The warm start of deep rows (contact_solver.cpp, carryDeepLoads): a deep
// point being pushed apart carries the smaller of its last two substeps'
// impulses, so an impact is never re-applied while a steady load is; a point
// whose depth its load explains (a sag) carries its impulse in full.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_solver.hpp"
#include "world_state.hpp"

namespace {

using namespace i2d;
using namespace i2d::detail;

/// One deep row: a body (state 0) on something immovable (the zero state,
/// 1), normal up, one point under the centre `depth` m deep, its accumulated
/// normal impulse `impulse` when the step began.
void oneDeepRow(WorldState& w, float depth, float impulse) {
    SolverArrays& s = w.solver;
    s.states.assign(2, BodyState{});
    s.constraints.resizeForOverwrite(1);
    s.rowCount = 1;
    ContactConstraint& cc = s.constraints[0];
    cc.contact = 0;
    cc.a = 1;
    cc.b = 0;
    cc.normal = {0.0f, 1.0f};
    cc.friction = 0.6f;
    cc.restitution = 0.0f;
    cc.invMassA = cc.invIA = 0.0f;
    cc.invMassB = cc.invIB = 1.0f;
    const Softness soft = makeSoft(30.0f, 10.0f, 1.0f / 240.0f);
    cc.biasRate = soft.biasRate;
    cc.massScale = soft.massScale;
    cc.impulseScale = soft.impulseScale;
    cc.maxPush = 3.0f;
    cc.tangentSpeed = 0.0f;
    cc.deepOverlap = true;
    cc.pointsTogether = false;
    cc.roundA = cc.roundB = false;
    cc.turnA = cc.turnB = false;
    cc.pointCount = 1;
    cc.pairCoupling = 0.0f;
    ContactPointConstraint& cp = cc.points[0];
    cp.rA = cp.rB = {0.0f, 0.0f};
    cp.adjustedSeparation = -depth;
    cp.normalMass = cp.tangentMass = 1.0f;
    cp.normalImpulse = impulse;
    cp.tangentImpulse = 0.6f * impulse;  // at the friction cone's edge
    cp.maxNormalImpulse = cp.relativeVelocity = cp.restitutionBias = cp.biasImpulse = 0.0f;
    s.wideContactsActive = false;
    s.deepRows = {0};
    beginDeepCarry(s);
}

/// The impulse the next substep is warm-started with, after this substep's
/// sweeps ended with `impulse`.
float carry(WorldState& w, float impulse) {
    ContactPointConstraint& cp = w.solver.constraints[0].points[0];
    cp.normalImpulse = impulse;
    carryDeepLoads(w.solver);
    return cp.normalImpulse;
}

// 10 cm deep, a load of 0.5 N·s per substep (the weight of 12 kg at 240 substeps a second):
// the push asks for biasRate·d beyond what that load explains, so the point
// is being pushed apart. The substep it is struck, its impulse jumps to
// 50 N·s; that is never re-applied, then the impulse after the strike is
// carried as it is, and a steady one in full.
TEST(DeepCarry, AStrikeIsNotCarriedASteadyLoadIs) {
    WorldState w({}, 1);
    oneDeepRow(w, 0.1f, 0.5f);
    const ContactConstraint& cc = w.solver.constraints[0];
    ASSERT_GT(cc.biasRate * 0.1f, loadPush(cc, cc.points[0], 0.5f)) << "the point must be pushed apart";
    EXPECT_EQ(carry(w, 0.5f), 0.5f);   // steady
    EXPECT_EQ(carry(w, 50.0f), 0.5f);  // the strike: the load before it
    // Its friction stays within the cone of the impulse carried.
    EXPECT_LE(std::abs(cc.points[0].tangentImpulse), 0.6f * 0.5f);
    EXPECT_EQ(carry(w, 0.7f), 0.7f);  // after it: smaller than the strike
    EXPECT_EQ(carry(w, 0.7f), 0.7f);  // steady again
    EXPECT_EQ(carry(w, 0.8f), 0.7f);  // a rise: carried a substep late
    EXPECT_EQ(carry(w, 0.6f), 0.6f);  // a fall: at once
}

// 7 cm deep under a load whose push explains more than that depth (the sag
// under a heavy top, deep_overlap.cpp): not an overlap. Its impulse rising
// by 10 % per substep is carried in full every substep; cut to the smaller of
// two, the 5-box stack under a 200 times heavier top fell
// (HeavyTop.FiveBoxStackUnderATopUpTo300TimesHeavierStands).
TEST(DeepCarry, TheSagOfAHeavyLoadCarriesItsRisingImpulseInFull) {
    WorldState w({}, 1);
    const float depth = 0.07f;
    oneDeepRow(w, depth, 1.0f);
    const ContactConstraint& cc = w.solver.constraints[0];
    // The impulse whose load push equals biasRate·depth, and twice that.
    const float explains = cc.biasRate * depth / loadPush(cc, cc.points[0], 1.0f);
    oneDeepRow(w, depth, 2.0f * explains);
    float impulse = 2.0f * explains;
    for (int substep = 0; substep < 5; ++substep) {
        impulse *= 1.1f;
        EXPECT_EQ(carry(w, impulse), impulse) << substep;
    }
}

}  // namespace
