// Contact rows solved four manifolds at a time (wide_contact.cpp) against the
// scalar rows (contact_solver.cpp) on the same random rows: every regime a
// row can be in — one or two points, points together or one after the other,
// speculative, pushed at the cap, deep (rigid in the push pass, its impulses
// carried to the next substep by carryDeepLoads, in its block or its row),
// left to the impact law in the last relax,
// round sides, a side that does not move — must give the same velocities and
// impulses bit for bit, in every soft_step pass (the sanitizer build runs the
// portable path; on CPUs with AVX2 the eight-lane path is checked as well).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "contact_solver.hpp"
#include "wide_contact.hpp"
#include "world_state.hpp"

namespace {

using namespace i2d;
using namespace i2d::detail;

/// n independent rows (row i joins bodies 2i and 2i+1; every sixth row's A
/// side is the zero state), random states and rows.
void fill(WorldState& w, unsigned seed, int n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), m(0.05f, 3.0f), unit(0.0f, 1.0f);
    SolverArrays& s = w.solver;
    s.states.assign(static_cast<std::size_t>(2 * n) + 1, BodyState{});
    for (std::size_t i = 0; i + 1 < s.states.size(); ++i) {
        BodyState& b = s.states[i];
        b.v = {3.0f * u(rng), 3.0f * u(rng)};
        b.w = 3.0f * u(rng);
        b.dp = {0.02f * u(rng), 0.02f * u(rng)};
        const float a = 0.1f * u(rng);
        b.dq = {std::cos(a), std::sin(a)};
    }
    const int zero = 2 * n;
    // Every soft_step row has the step's softness (the stiffer one where a side
    // cannot move) and the world's push cap, which the wide sweeps take from
    // the step rather than from each row; a low cap, so that a share of the
    // pushes (biasRate times overlaps to 5 cm: up to 0.45 m/s, 0.9 against an
    // immovable side) reach it.
    w.settings.maxPushSpeed = 0.3f;
    const RowContext x = makeRowContext(w, 1.0f / 240.0f, true);
    s.constraints.resizeForOverwrite(static_cast<std::size_t>(n));
    s.rowCount = n;
    for (int i = 0; i < n; ++i) {
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(i)];
        const bool immovableA = i % 6 == 0;
        cc.contact = i;
        cc.a = immovableA ? zero : 2 * i;
        cc.b = 2 * i + 1;
        const float angle = 6.2831853f * unit(rng);
        cc.normal = {std::cos(angle), std::sin(angle)};
        cc.friction = unit(rng);
        cc.restitution = 0.0f;
        cc.invMassA = immovableA ? 0.0f : m(rng);
        cc.invIA = immovableA ? 0.0f : m(rng);
        cc.invMassB = m(rng);
        cc.invIB = m(rng);
        const Softness& soft = immovableA ? x.staticSoft : x.dynamicSoft;
        cc.biasRate = soft.biasRate;
        cc.massScale = soft.massScale;
        cc.impulseScale = soft.impulseScale;
        cc.maxPush = w.settings.maxPushSpeed;
        cc.tangentSpeed = unit(rng) < 0.2f ? u(rng) : 0.0f;
        cc.deepOverlap = unit(rng) < 0.15f;  // rigid in the push pass (deep_overlap.cpp pushes it)
        cc.pointCount = static_cast<std::uint8_t>(unit(rng) < 0.3f ? 1 : 2);
        cc.pointsTogether = cc.pointCount == 2 && unit(rng) < 0.7f;
        cc.roundA = unit(rng) < 0.3f;
        cc.roundB = unit(rng) < 0.3f;
        cc.turnA = cc.turnB = false;  // (turning rows are the scalar path's alone)
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            cp.rA = {u(rng), u(rng)};
            cp.rB = {u(rng), u(rng)};
            // Overlaps to 5 cm, and gaps (speculative points).
            cp.adjustedSeparation = 0.05f * u(rng) - dot(cp.rB - cp.rA, cc.normal);
            cp.normalMass = m(rng);
            cp.tangentMass = m(rng);
            cp.normalImpulse = unit(rng) < 0.5f ? 2.0f * unit(rng) : 0.0f;
            cp.tangentImpulse = 0.5f * u(rng);
            cp.maxNormalImpulse = 0.0f;
            cp.relativeVelocity = 0.0f;
            cp.restitutionBias = 0.0f;
            cp.biasImpulse = 0.0f;
        }
        // K12 for a coupling ρ = K12/√(K11·K22) in (−0.9, 0.9): the block
        // solve's determinant 1 − ρ² stays above kLeastBlockDeterminant.
        const float rho = 1.8f * unit(rng) - 0.9f;
        cc.pairCoupling = cc.pointsTogether ? rho / std::sqrt(cc.points[0].normalMass * cc.points[1].normalMass) : 0.0f;
    }
}

/// Reorders the rows (independent of each other, so the order changes no
/// result) so that those of one point come last; returns how many have two.
int onePointRowsLast(SolverArrays& s) {
    ContactConstraint* rows = &s.constraints[0];
    ContactConstraint* end = rows + s.rowCount;
    return static_cast<int>(
        std::stable_partition(rows, end, [](const ContactConstraint& cc) { return cc.pointCount == 2; }) - rows);
}

/// Restores the widest lanes the CPU offers when a test ends.
struct LaneLimit {
    explicit LaneLimit(int lanes) { limitWideLanes(lanes); }
    ~LaneLimit() { limitWideLanes(8); }
};

void expectAgreement(int lanes) {
    const LaneLimit limit(lanes);
    // Deep points whose rising impulse the carry cut (pushed apart) and kept
    // (a sag its load explains): both must occur for the test to cover them.
    int cut = 0, keptRising = 0;
    // Groups of blocks the eight-lane sweep takes four at a time (sixteen
    // lanes), with a pair left over (eight lanes), with an odd block left
    // over (four lanes): each path must be run.
    int fours = 0, pairsLeft = 0, oddsLeft = 0;
    for (unsigned seed = 1; seed <= 30; ++seed) {
        const int n = 41;  // not a multiple of four: the last block has empty lanes
        WorldState scalar({}, 1), wide({}, 2);
        fill(scalar, seed, n);
        fill(wide, seed, n);
        SolverArrays& s = wide.solver;
        // One colour in its two row groups, as solver.cpp lays them out: the
        // rows of two points, then those of one (each group's last block
        // partly empty), the second group swept by the one-point kernel.
        const int twoPoints = onePointRowsLast(scalar.solver);
        onePointRowsLast(s);
        const int twoBlocks = (twoPoints + 3) / 4, oneBlocks = (n - twoPoints + 3) / 4;
        for (const int blocks : {twoBlocks, oneBlocks}) {
            fours += blocks >= 4;
            pairsLeft += blocks % 4 >= 2;
            oddsLeft += blocks % 2;
        }
        s.wideContacts.resizeForOverwrite(static_cast<std::size_t>(twoBlocks + oneBlocks));
        s.wideContactCold.resizeForOverwrite(static_cast<std::size_t>(twoBlocks + oneBlocks));
        for (int block = 0; block < twoBlocks; ++block) packWideContactBlock(s, block, 4 * block, twoPoints);
        for (int block = 0; block < oneBlocks; ++block)
            packWideContactBlock(s, twoBlocks + block, twoPoints + 4 * block, n);
        s.wideContactsActive = true;
        s.wideContactColourStart = {0, twoBlocks, twoBlocks + oneBlocks};
        static_assert(kWideGroupsPerColour == 2);
        s.contactOverflowStart = n;
        // Each block's first row and its group's end, as solver.cpp lists
        // them: the deep rows' carry finds their lanes from these.
        s.wideBlockRows.clear();
        for (int block = 0; block < twoBlocks; ++block)
            s.wideBlockRows.insert(s.wideBlockRows.end(), {4 * block, twoPoints});
        for (int block = 0; block < oneBlocks; ++block)
            s.wideBlockRows.insert(s.wideBlockRows.end(), {twoPoints + 4 * block, n});
        for (WorldState* w : {&scalar, &wide}) {
            w->solver.deepRows.clear();
            for (int r = 0; r < n; ++r)
                if (w->solver.constraints[static_cast<std::size_t>(r)].deepOverlap) w->solver.deepRows.push_back(r);
            beginDeepCarry(w->solver);
        }
        // Impact speed 0.5 m/s: a fair share of the random speculative points
        // approach faster and are left to the impact law in the last relax.
        scalar.settings.impactThreshold = wide.settings.impactThreshold = 0.5f;
        // Two substeps' sweeps, the deep rows' impulses carried between them
        // (carryDeepLoads) from the blocks in one world, the rows in the other.
        for (int substep = 0; substep < 2; ++substep) {
            if (substep > 0) {
                const SolverArrays& r = scalar.solver;
                std::vector<float> before, previous;
                for (std::size_t d = 0; d < r.deepRows.size(); ++d)
                    for (int j = 0; j < r.constraints[static_cast<std::size_t>(r.deepRows[d])].pointCount; ++j) {
                        before.push_back(
                            r.constraints[static_cast<std::size_t>(r.deepRows[d])].points[j].normalImpulse);
                        previous.push_back(r.deepCarry[d].previous[j]);
                    }
                carryDeepLoads(scalar.solver);
                carryDeepLoads(s);
                std::size_t k = 0;
                for (int row : r.deepRows)
                    for (int j = 0; j < r.constraints[static_cast<std::size_t>(row)].pointCount; ++j, ++k) {
                        const float after = r.constraints[static_cast<std::size_t>(row)].points[j].normalImpulse;
                        cut += after < before[k];
                        keptRising += after == before[k] && before[k] > previous[k];
                    }
            }
            warmStartContacts(scalar);
            warmStartContacts(wide);
            for (SolvePass pass : {SolvePass::soft_bias, SolvePass::soft_relax, SolvePass::soft_relax_last}) {
                solveContacts(scalar, 1.0f / 240.0f, pass);
                solveContacts(wide, 1.0f / 240.0f, pass);
            }
        }
        writeBackWideContacts(s, 0, static_cast<int>(s.wideContacts.size()));
        for (std::size_t i = 0; i + 1 < s.states.size(); ++i) {
            ASSERT_EQ(s.states[i].v.x, scalar.solver.states[i].v.x) << "seed " << seed << " body " << i;
            ASSERT_EQ(s.states[i].v.y, scalar.solver.states[i].v.y) << "seed " << seed << " body " << i;
            ASSERT_EQ(s.states[i].w, scalar.solver.states[i].w) << "seed " << seed << " body " << i;
        }
        for (int r = 0; r < n; ++r) {
            const ContactConstraint& a = s.constraints[static_cast<std::size_t>(r)];
            const ContactConstraint& b = scalar.solver.constraints[static_cast<std::size_t>(r)];
            for (int j = 0; j < a.pointCount; ++j) {
                ASSERT_EQ(a.points[j].normalImpulse, b.points[j].normalImpulse) << "seed " << seed << " row " << r;
                ASSERT_EQ(a.points[j].tangentImpulse, b.points[j].tangentImpulse) << "seed " << seed << " row " << r;
                ASSERT_EQ(a.points[j].maxNormalImpulse, b.points[j].maxNormalImpulse)
                    << "seed " << seed << " row " << r;
            }
        }
    }
    EXPECT_GT(cut, 0);
    EXPECT_GT(keptRising, 0);
    EXPECT_GT(fours, 0);
    EXPECT_GT(pairsLeft, 0);
    EXPECT_GT(oddsLeft, 0);
}

TEST(WideContact, AgreesBitForBitWithTheScalarRowsInFourLanes) { expectAgreement(4); }

// Where the CPU has AVX2: each group's blocks four at a time in sixteen lanes
// (two AVX registers a value, wide_avx2.cpp), then a pair in eight, the odd
// one left to the four lanes.
TEST(WideContact, AgreesBitForBitWithTheScalarRowsInEightLanes) {
    limitWideLanes(8);
    if (wideLanes() != 8) GTEST_SKIP() << "no AVX2 on this CPU (or a portable build)";
    expectAgreement(8);
}

// The soft step with closed-form impacts prepares each lane straight from its
// contact, four at a time (prepareWideContactLanes), without a scalar row:
// every lane must hold the same bits as the row prepareContacts writes, packed.
TEST(WideContact, LanesPreparedFromContactsMatchThePackedRows) {
    for (unsigned seed = 1; seed <= 20; ++seed) {
        WorldState w({}, 1);
        // Every other seed, the impact stage has moved some bodies' starts
        // this step (impactShift), so the rows' separations carry shifts.
        const bool shifted = seed % 2 == 0;
        w.stepStamp = 7;
        if (shifted) w.startsShiftedAt = w.stepStamp;
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f), m(0.05f, 3.0f), unit(0.0f, 1.0f);
        const int bodyCount = 16;
        int awake = 0;
        w.impactStarts.resize(static_cast<std::size_t>(bodyCount));
        for (int i = 0; i < bodyCount; ++i) {
            Body& b = w.bodies[w.bodies.allocate()];
            const bool moves = i % 5 != 0;  // every fifth is static: the zero state
            b.type = moves ? BodyType::dynamic_body : BodyType::static_body;
            b.invMass = moves ? m(rng) : 0.0f;
            b.invInertia = moves ? m(rng) : 0.0f;
            b.center = {5.0f * u(rng), 5.0f * u(rng)};
            b.localCenter = {0.1f * u(rng), 0.1f * u(rng)};
            b.v = {3.0f * u(rng), 3.0f * u(rng)};
            b.w = 3.0f * u(rng);
            b.solverIndex = moves ? awake++ : kNullIndex;
            if (shifted && moves && i % 3 == 0) {
                StepStart& start = w.impactStarts[static_cast<std::size_t>(i)];
                start.stamp = w.stepStamp;
                start.center = b.center + Vec2{0.05f * u(rng), 0.05f * u(rng)};
                const float turn = 0.1f * u(rng);
                start.q = {std::cos(turn), std::sin(turn)};
                b.xf.q = {std::cos(2.0f * turn), std::sin(2.0f * turn)};
            }
        }
        SolverArrays& s = w.solver;
        s.states.assign(static_cast<std::size_t>(awake) + 1, BodyState{});
        // What the lanes read of the bodies with a state (gatherBodies); the
        // scalar rows read the bodies themselves.
        s.rowBodies.resize(static_cast<std::size_t>(bodyCount));
        for (int i = 0; i < bodyCount; ++i)
            if (w.bodies[i].solverIndex != kNullIndex)
                s.rowBodies[static_cast<std::size_t>(i)] = rowBodyOf(w.bodies[i], w.bodies[i].solverIndex);
        const int n = 37;  // not a multiple of four: the last block has empty lanes
        for (int k = 0; k < n; ++k) {
            const int c = w.contacts.allocate();
            Contact& ct = w.contacts[c];
            ct.bodyA = 1 + (k % (bodyCount - 1));  // never two static sides
            ct.bodyB = (ct.bodyA + 1 + k % 3) % bodyCount;
            if (ct.bodyB % 5 == 0 && ct.bodyA % 5 == 0) ct.bodyB = 1;
            ct.touching = true;
            const float angle = 6.2831853f * unit(rng);
            ct.manifold.normal = {std::cos(angle), std::sin(angle)};
            ct.manifold.pointCount = unit(rng) < 0.3f ? 1 : 2;
            for (int j = 0; j < ct.manifold.pointCount; ++j) {
                ct.manifold.points[j].point = {5.0f * u(rng), 5.0f * u(rng)};
                ct.manifold.points[j].separation = 0.03f * u(rng);
                ct.normalImpulse[j] = unit(rng);
                ct.tangentImpulse[j] = 0.5f * u(rng);
            }
            ct.friction = unit(rng);
            ct.restitution = unit(rng) < 0.5f ? unit(rng) : 0.0f;
            ct.roundA = unit(rng) < 0.3f;
            ct.roundB = unit(rng) < 0.3f;
            ct.framed = unit(rng) < 0.5f;  // a kept manifold's arms come from its frame
            if (ct.framed) {
                const float a = u(rng), r = u(rng);
                ct.frame.rotationA = {std::cos(a), std::sin(a)};
                ct.frame.relative = {{u(rng), u(rng)}, {std::cos(r), std::sin(r)}};
                ct.frame.anchorA[0] = {u(rng), u(rng)};
                ct.frame.anchorA[1] = {u(rng), u(rng)};
            }
            w.activeContacts.push_back(c);
            w.activeLooks.push_back(
                {ct.bodyA, ct.bodyB, true, kLookRow});  // (beside each active contact, as collide keeps them)
            if (shifted) {  // some contacts struck by the impact stage (a rebound time), some not
                w.impactTime.resize(static_cast<std::size_t>(c) + 1, -1.0f);
                w.impactTime[static_cast<std::size_t>(c)] = unit(rng) < 0.5f ? 0.01f * unit(rng) : -1.0f;
            }
        }
        // One colour holding every row, in contact order.
        s.rowCount = n;
        s.contactColours.assign(static_cast<std::size_t>(n), 0);
        s.colourOffsets.assign(25, n);
        s.colourOffsets[0] = 0;
        const float h = 1.0f / 240.0f;
        prepareContacts(w, h, true);
        const int blocks = (n + 3) / 4;
        s.wideContacts.resizeForOverwrite(static_cast<std::size_t>(blocks));
        s.wideContactCold.resizeForOverwrite(static_cast<std::size_t>(blocks));
        const RowContext x = makeRowContext(w, h, true);
        for (int block = 0; block < blocks; ++block) {
            packWideContactBlock(s, block, 4 * block, n);
            // The lanes in reverse order, in calls of 1 to 4 contacts, so each
            // lane's result must not depend on its neighbours.
            WideContactBlock grouped;
            WideContactCold groupedCold;
            const int chunk = 1 + block % 4;
            WideLaneTarget targets[4];
            int pending = 0;
            for (int lane = 3; lane >= 0; --lane) {
                const int r = 4 * block + lane;
                if (r >= n) {
                    packEmptyWideContactLane(grouped, groupedCold, lane, x.zeroState);
                    continue;
                }
                targets[pending++] = {w.activeContacts[static_cast<std::size_t>(r)], &grouped, &groupedCold, lane};
                if (pending == chunk) {
                    prepareWideContactLanes(w, x, targets, pending);
                    pending = 0;
                }
            }
            if (pending > 0) prepareWideContactLanes(w, x, targets, pending);
            const WideContactBlock& packed = s.wideContacts[static_cast<std::size_t>(block)];
            WideContactCold packedCold = s.wideContactCold[static_cast<std::size_t>(block)];
            for (int lane = 0; lane < 4; ++lane)
                packedCold.row[lane] = groupedCold.row[lane] = 0;  // a row only when packed
            ASSERT_EQ(std::memcmp(&packed, &grouped, sizeof(WideContactBlock)), 0)
                << "seed " << seed << " block " << block;
            ASSERT_EQ(std::memcmp(&packedCold, &groupedCold, sizeof(WideContactCold)), 0)
                << "seed " << seed << " block " << block;
        }
    }
}

}  // namespace
