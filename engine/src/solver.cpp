// The step: the order of its stages, and the solve stage itself —
// velocity integration, the constraint passes in the order of the position
// correction mode, position integration, and the colouring that orders the
// contact rows.
//
// Stages of a step (stepWorld):
//   broadphase pairs (contact.cpp) → narrowphase: manifolds, events
//   (contact.cpp) → impacts: the closed-form law (impact_stage.cpp) → solve
//   (this file; rows in contact_solver.cpp and distance_joint.cpp) →
//   continuous collision of fast bodies against static shapes
//   (continuous.cpp) → proxies refreshed (broad_phase.cpp) → sleep (island.cpp)
//
// Position error is corrected by one of three schemes (WorldSettings):
//  baumgarte  one step; the push velocity β·d/Δt (Tamis and Maggiore (2015),
//             Constraint based physics solver, eq. 5.2.3, 5.3.1) is part of the
//             velocity target, so it stays in the bodies afterwards;
//  split      one step; the single-frame push factor of Tamis and Maggiore
//             (2015) §8.1: the velocity system is solved without the push
//             (f_c0), the push is solved on a separate pseudo-velocity
//             (f_cv − f_c0) that moves positions for this step only and is then
//             dropped: correction adds no kinetic energy;
//  soft_step  `substeps` substeps, each: integrate velocities, warm start, solve
//             with soft (spring-damped) push, integrate positions, relax (solve
//             again without push). Then restitution, then store impulses
//             (Catto, Solver2D, and Box2D v3's soft step). Overlaps deeper than
//             kDeepOverlap are pushed on pseudo-velocities instead, added to
//             the motion of the substep and dropped (deep_overlap.cpp).
//
// Loops (per step): bodies 2 + 2·substeps; constraints (1 + 2·substeps) for
// soft_step, (1 + velocityIterations + positionIterations) otherwise. The
// substep loops read BodyState, BodyIntegration and the constraint rows: all
// contiguous arrays.
#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>

#include "contact_row.hpp"
#include "continuous.hpp"
#include "deep_overlap.hpp"
#include "float4.hpp"
#include "impact_stage.hpp"
#include "integration.hpp"
#include "joint_solver.hpp"
#include "split_kick.hpp"
#include "warm_start.hpp"
#include "world_state.hpp"

namespace i2d::detail {

// v limited to maxSpeed (solver.hpp). A velocity whose square overflows (a
// body of tiny mass pushed by a force: F/m beyond single precision) keeps its
// direction and is limited too, where scaling by maxSpeed/∞ would give
// ∞·0 = NaN (found by fuzz_world).
Vec2 limitFastSpeed(Vec2 v, float maxSpeed) {
    float speed2 = lengthSquared(v);
    if (!isFinite(speed2)) {
        const float largest = std::max(std::abs(v.x), std::abs(v.y));
        if (largest == INFINITY)
            v = {std::isinf(v.x) ? std::copysign(1.0f, v.x) : 0.0f, std::isinf(v.y) ? std::copysign(1.0f, v.y) : 0.0f};
        else
            v *= 1.0f / largest;
        speed2 = lengthSquared(v);
    }
    v *= maxSpeed / std::sqrt(speed2);
    return v;
}

namespace {

// ---------------------------------------------------------------------------
// Colouring
//
// The contact rows are graph-coloured each step (greedy, in slot order) and
// solved colour by colour, as Box2D v3 does (its constraint graph). No two
// rows of a colour share a movable body, so a colour's updates do not depend
// on each other and a Gauss-Seidel sweep over colours has no spatial
// direction. Sweeping in creation order instead (left to right, bottom to top
// in a pyramid) carries every sweep's friction error the same way:
// pyramid100's top box then swayed 0.64 m during the initial settling against
// 0.09 m coloured (docs/performance.md).

constexpr int kColourCount = 24;  ///< colours tried before the overflow group
/// Each colour's rows in two groups, its manifolds of two points (group 2c)
/// and then those of one (group 2c + 1), so that the wide sweeps solve a
/// block of circles' or capsules' single points without the arithmetic of an
/// absent second point (wide_contact_kernel.hpp). A colour's rows share no
/// movable body, so their order within it changes no result.
constexpr int kRowGroupCount = kWideGroupsPerColour * kColourCount;  ///< the overflow group's index
constexpr std::uint32_t kAllColours = (std::uint32_t{1} << kColourCount) - 1u;
/// Set in a body's colour mask when it has a row in the overflow group (not a
/// colour): the tilt chains count a body's rows by its mask's bits.
constexpr std::uint32_t kOverflowRowBit = std::uint32_t{1} << 31;
static_assert(kColourCount < 32, "a body's colours are the bits of a 32-bit mask");

/// The bodies per chunk of an integration stage, and the contact blocks per
/// chunk when they are packed, prepared or written back: large, so that few
/// cache lines are written by two workers (kParallelWork, stage_runner.hpp,
/// decides whether a step's solve is shared at all).
constexpr int kBodyGrain = 512;
constexpr int kPackGrain = 32;
constexpr int kPrepareGrain = 128;  ///< contacts per chunk when rows are prepared

constexpr std::uint8_t kKeyRow = 1, kKeyMoveA = 2, kKeyMoveB = 4, kKeyOnePoint = 8, kKeyDeep = 16, kKeyRolling = 32,
                       kKeyTurnA = 64, kKeyTurnB = 128;
constexpr std::uint8_t kKeyTurning = kKeyTurnA | kKeyTurnB;

ColourKey colourKey(const WorldState& w, std::size_t active, int zeroState) {
    // Whether the contact has a row: contactRowBodies's test, from the
    // narrowphase's look at the contact (ContactLook) and
    // SolverArrays::bodyMoves. Neither the contact nor its bodies are read
    // (but for a body turning fast, below): in a large scene each was a
    // cache miss (many_pyramids' colouring took 0.86 to 0.90 ms reading
    // both, 0.54 to 0.59 reading the contacts).
    const ContactLook& look = w.activeLooks[active];
    if (!(look.rowFlags & kLookRow)) return {0, 0, 0};
    const std::vector<std::uint8_t>& moves = w.solver.bodyMoves;
    const std::uint8_t markA = moves[static_cast<std::size_t>(look.bodyA)];
    const std::uint8_t markB = moves[static_cast<std::size_t>(look.bodyB)];
    const bool moveA = (markA & kBodyMoves) != 0, moveB = (markB & kBodyMoves) != 0;
    if (!moveA && !moveB) return {0, 0, 0};
    std::uint8_t flags = kKeyRow;
    if (moveA) flags |= kKeyMoveA;
    if (moveB) flags |= kKeyMoveB;
    // What decides the rows' path before any is prepared: the same tests as
    // prepareContacts' and prepareRollingResistance's.
    if (look.rowFlags & kLookDeep) flags |= kKeyDeep;
    // A body turning fast (gatherBodies marks it): a turning row if the
    // normal is its face (turningLook reads the contact and its shapes,
    // for these contacts only).
    if ((markA | markB) & kBodyTurns) {
        const std::uint8_t turn = turningLook(w, w.contacts[w.activeContacts[active]], w.stepDt);
        if (turn & kLookTurnA) flags |= kKeyTurnA;
        if (turn & kLookTurnB) flags |= kKeyTurnB;
    }
    if (look.rowFlags & kLookRollingSurface) {
        const int contact = w.activeContacts[active];
        const Contact& ct = w.contacts[contact];
        RowBodies rb;
        contactRowBodies(ct, w.bodies[ct.bodyA], w.bodies[ct.bodyB], zeroState, rb);
        if (!(rb.invIA + rb.invIB <= 0.0f)) flags |= kKeyRolling;
    }
    if (look.rowFlags & kLookOnePoint) flags |= kKeyOnePoint;
    return {look.bodyA, look.bodyB, flags};
}

/// Colours the rows of this step's active contacts (greedy, in activeContacts
/// order, overflow group last) and leaves in colourOffsets the first row of
/// each row group (kRowGroupCount) and in rowContacts each contact's place in
/// its group: a stable counting sort, so within a group the rows keep the
/// contacts' order. prepareContacts then writes each row at its place. The
/// pass depends on the order, so it runs on the stepping thread, finding
/// each contact's key as it goes: the keys found first on every worker into
/// an array cost more than they saved (many_pyramids on two workers: 0.42
/// against 0.36 ms for the colouring, the array written and read again).
void colourContacts(WorldState& w) {
    SolverArrays& s = w.solver;
    const std::size_t count = w.activeContacts.size();
    const int zeroState = static_cast<int>(s.states.size()) - 1;
    // Per body slot: bit c set once the body has a row of colour c (all
    // zero here: gatherBodies).
    std::vector<std::uint32_t>& masks = s.contactColourMasks;
    s.colourOffsets.assign(kRowGroupCount + 1, 0);
    s.contactColours.resize(count);
    s.rowContacts.resizeForOverwrite(count);
    int rows = 0;
    std::uint8_t any = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const ColourKey key = colourKey(w, i, zeroState);
        if (!(key.flags & kKeyRow)) {
            s.contactColours[i] = kNoRow;
            s.rowContacts[i] = -1;
            continue;
        }
        ++rows;
        any |= key.flags;
        // The turning side, for preparing the row (setTurning). The look
        // has none (collide wrote it this step), and is written only for a
        // turning row: written for every row, each look's line would move to
        // the stepping thread's core and back to the worker that prepares
        // the row (docs/performance.md, why two workers gain less).
        if (key.flags & kKeyTurning)
            w.activeLooks[i].rowFlags |= static_cast<std::uint8_t>(((key.flags & kKeyTurnA) ? kLookTurnA : 0) |
                                                                   ((key.flags & kKeyTurnB) ? kLookTurnB : 0));
        // The first colour neither movable body has a row in yet: the lowest
        // bit clear in both bodies' colour masks.
        const bool moveA = key.flags & kKeyMoveA, moveB = key.flags & kKeyMoveB;
        std::uint32_t* maskA = moveA ? &masks[static_cast<std::size_t>(key.a)] : nullptr;
        std::uint32_t* maskB = moveB ? &masks[static_cast<std::size_t>(key.b)] : nullptr;
        const std::uint32_t taken = (maskA ? *maskA : 0u) | (maskB ? *maskB : 0u) | ~kAllColours;
        int group = kRowGroupCount;
        // A turning row is scalar (contact_solver.cpp): the overflow group's.
        if (taken != ~std::uint32_t{0} && !(key.flags & kKeyTurning)) {
            const int c = std::countr_one(taken);
            const std::uint32_t bit = std::uint32_t{1} << c;
            if (maskA) *maskA |= bit;
            if (maskB) *maskB |= bit;
            group = kWideGroupsPerColour * c + ((key.flags & kKeyOnePoint) ? 1 : 0);
        }
        if (group == kRowGroupCount) {
            // A row in the overflow group: marked above the colours, so that
            // the tilt chains see every row of a body (kOverflowRowBit).
            if (maskA) *maskA |= kOverflowRowBit;
            if (maskB) *maskB |= kOverflowRowBit;
        }
        s.contactColours[i] = static_cast<std::uint8_t>(group);
        s.rowContacts[i] = s.colourOffsets[static_cast<std::size_t>(group)]++;  // its place in its group
    }
    // Counts to first rows.
    int offset = 0;
    for (int& n : s.colourOffsets) {
        const int c = n;
        n = offset;
        offset += c;
    }
    s.rowCount = rows;
    s.anyDeepOverlap = any & kKeyDeep;
    s.anyRollingRow = any & kKeyRolling;
    s.anyTurningRow = any & kKeyTurning;
}

/// The wide blocks of the coloured rows, row group c's rows ending at
/// ends[c]: each block's first row and its group's end in wideBlockRows, each
/// group's first block; returns the block count.
int layoutWideBlocks(SolverArrays& s, const int* ends) {
    std::vector<int>& blockRows = s.wideBlockRows;
    blockRows.clear();
    // (Released after a large step: one allocation, not one per doubling.)
    blockRows.reserve(2 * (static_cast<std::size_t>(s.rowCount) / 4 + kRowGroupCount));
    s.wideContactColourStart.resize(kRowGroupCount + 1);
    int start = 0;
    for (int c = 0; c < kRowGroupCount; ++c) {
        s.wideContactColourStart[static_cast<std::size_t>(c)] = static_cast<int>(blockRows.size() / 2);
        const int end = ends[c];
        for (int row = start; row < end; row += 4) {
            blockRows.push_back(row);
            blockRows.push_back(end);
        }
        start = end;
    }
    const int blocks = static_cast<int>(blockRows.size() / 2);
    s.wideContactColourStart[kRowGroupCount] = blocks;
    s.contactOverflowStart = start;
    // One allocation, sized first: growing block by block made a fresh
    // allocation, page faults and a copy per doubling, every step.
    s.wideContacts.resizeForOverwrite(static_cast<std::size_t>(blocks));
    s.wideContactCold.resizeForOverwrite(static_cast<std::size_t>(blocks));
    return blocks;
}

/// The blocks with a lane flagged `flag`, ascending, and where each row
/// group's begin in that list (SolverArrays::coldBlocks, deepBlocks).
void listBlocks(const SolverArrays& s, std::uint32_t flag, std::vector<int>& list, std::vector<int>& begin) {
    const std::vector<int>& start = s.wideContactColourStart;
    list.clear();
    begin.assign(start.size(), 0);
    for (std::size_t g = 0; g + 1 < start.size(); ++g) {
        begin[g] = static_cast<int>(list.size());
        for (int b = start[g]; b < start[g + 1]; ++b) {
            const std::uint32_t* f = s.wideContacts[static_cast<std::size_t>(b)].flags;
            if (((f[0] | f[1] | f[2] | f[3]) & flag) != 0) list.push_back(b);
        }
    }
    begin.back() = static_cast<int>(list.size());
}

/// How long a contact whose load a destroyed contact or joint took away
/// (WorldState::unloadedAt) is relaxed again: three time constants of its
/// soft rows (1/biasRate), by which they have pushed out all but e⁻³ (5 %)
/// of the sag the load had pressed in.
constexpr float kUnloadedTimeConstants = 3.0f;

/// The blocks relaxed again after each substep's relax sweep
/// (relaxDeepContacts): those with a lane of a deep overlap (kWideDeep), and
/// those with a lane of a contact whose load was taken away lately
/// (kWideUnloaded). Such a contact's soft rows push its bodies out of the
/// sag the load had pressed in, and one relax sweep in colour order leaves
/// part of that push in them: three circles stacked on the ground, the top
/// one 100 times as dense and then destroyed, left the other two rising at
/// 0.054 and 0.059 m/s (docs/validation.md, "Warm Start Energy").
void listRelaxedAgainBlocks(WorldState& w, const RowContext& x, bool fromStart) {
    SolverArrays& s = w.solver;
    std::uint32_t flags = (s.anyDeepOverlap ? kWideDeep : 0u) | (fromStart ? kWideFromStart : 0u);
    if (w.lastUnloadedAt != 0) {
        const float steps = kUnloadedTimeConstants / std::max(x.dynamicSoft.biasRate * x.fullDt, 1e-6f);
        // (1 + the stamp of the step before the release: this step is w.stepStamp.)
        auto recent = [&](std::uint32_t at) { return at != 0 && static_cast<float>(w.stepStamp + 1 - at) <= steps; };
        if (!recent(w.lastUnloadedAt)) {
            w.lastUnloadedAt = 0;
        } else {
            const std::vector<std::uint32_t>& at = w.unloadedAt;
            for (std::size_t b = 0; b < s.wideContacts.size(); ++b)
                for (int lane = 0; lane < 4; ++lane) {
                    const int c = s.wideContactCold[b].contact[lane];
                    if (c < 0 || static_cast<std::size_t>(c) >= at.size() || !recent(at[static_cast<std::size_t>(c)]))
                        continue;
                    s.wideContacts[b].flags[lane] |= kWideUnloaded;
                    flags |= kWideUnloaded;
                }
        }
    }
    if (flags != 0) listBlocks(s, flags, s.deepBlocks, s.deepBlockStart);
}

/// The blocks swept again in this step, from the kWideFound flags some lane
/// has (`found`): the cold ones (settleColdContacts) and those relaxed again.
void listSweptAgainBlocks(WorldState& w, const RowContext& x, std::uint32_t found) {
    if (found & kWideCold) listBlocks(w.solver, kWideCold, w.solver.coldBlocks, w.solver.coldBlockStart);
    listRelaxedAgainBlocks(w, x, (found & kWideFromStart) != 0);
}

/// Where the row at place `inGroup` of coloured row group `group` lies
/// among the wide blocks (prepareContactRows writes it there,
/// storeWideImpulses reads it back).
struct WideLane {
    std::size_t block;
    int lane;
};
WideLane wideLaneOf(const SolverArrays& s, std::size_t group, int inGroup) {
    return {static_cast<std::size_t>(s.wideContactColourStart[group] + inGroup / 4), inGroup % 4};
}

/// The accumulated impulses of the wide rows of active contacts [first,
/// last) into their contacts, for the next step's warm start (the store of
/// blocks prepared without rows; the overflow group's scalar rows are stored
/// with the others, storeContactImpulses). Active contact by active contact,
/// as the narrowphase and prepareContactRows read them, not block by block:
/// on several workers each contact is then written by the worker that reads
/// it in those stages, whose shares are the same parts of that order, and
/// its cache lines stay in that worker's core. Stored block by block, in
/// colour order, half of them were written on the other core and went back
/// and forth every step (pyramid100 on two workers, medians of 10
/// interleaved runs: 2.47 ms per step against 2.19, the rows' preparation
/// 0.54 against 0.45 ms; one worker the same, 2.75 against 2.70).
void storeWideImpulses(WorldState& w, int first, int last, float invH) {
    SolverArrays& s = w.solver;
    for (int k = first; k < last; ++k) {
        const int inGroup = s.rowContacts[static_cast<std::size_t>(k)];
        const std::size_t group = s.contactColours[static_cast<std::size_t>(k)];
        if (inGroup < 0 || group == kRowGroupCount) continue;
        const WideLane at = wideLaneOf(s, group, inGroup);
        const WideContactBlock& block = s.wideContacts[at.block];
        Contact& ct = w.contacts[w.activeContacts[static_cast<std::size_t>(k)]];
        for (int j = 0; j < ct.manifold.pointCount; ++j) {
            ct.normalImpulse[j] = block.points[j].normalImpulse[at.lane];
            ct.tangentImpulse[j] = block.points[j].tangentImpulse[at.lane];
        }
        if (ct.restLoad[0] | ct.restLoad[1]) holdRestLoads(ct, invH);
    }
}

/// Whether mask m has at most two bits set: std::popcount(m) <= 2 without
/// the library call std::popcount becomes on x86-64's baseline (no popcnt
/// instruction), which tiltCandidate made twice for every contact.
constexpr bool atMostTwoBits(std::uint32_t m) {
    m &= m - 1u;  // the lowest bit cleared
    m &= m - 1u;  // and the next
    return m == 0u;
}
static_assert(atMostTwoBits(0u) && atMostTwoBits(0x80000001u) && !atMostTwoBits(0x7u) && !atMostTwoBits(~0u));

/// Whether a contact's row may be a tilt row of a column (contact_tilt.cpp):
/// two points that both carried load when the step began, not an overlap
/// since its bodies were created or moved (pushed apart, not resting), and
/// no body of it with more than two rows (a box inside a pyramid, which
/// most such rows are, has four or more; kOverflowRowBit counts as many).
inline bool tiltCandidate(const SolverArrays& s, const Contact& ct) {
    if (ct.manifold.pointCount != 2 || !(ct.normalImpulse[0] > 0.0f) || !(ct.normalImpulse[1] > 0.0f) ||
        ct.overlapFromStart)
        return false;
    const std::uint32_t* masks = s.contactColourMasks.data();
    return atMostTwoBits(masks[ct.bodyA]) && atMostTwoBits(masks[ct.bodyB]);
}

/// The contact rows of this step (after colourContacts). soft_step without
/// rolling resistance solves the coloured rows four at a time: with
/// closed-form impacts and no deep overlap each row is prepared straight
/// into its lane on every worker, and only the overflow group gets scalar
/// rows; with velocity-bias impacts (whose restitution pass reads the rows)
/// or a deep overlap (whose push reads them) the rows are prepared and then
/// packed. Otherwise every row stays scalar.
void prepareContactRows(WorldState& w, float h, bool soft) {
    SolverArrays& s = w.solver;
    s.wideContactsActive = soft && !s.anyRollingRow && s.rowCount > 0;
    // The push of deep overlaps (deep_overlap.cpp) reads their rows: a step
    // with any prepares rows and packs them.
    s.wideContactsOnly = s.wideContactsActive && !s.anyDeepOverlap &&
                         w.settings.impactModel == ImpactModel::closed_form;
    s.contactOverflowStart = 0;
    s.tilt.rows.clear();
    s.tilt.chainStart.clear();
    s.tilt.candidate.clear();
    s.coldBlocks.clear();
    s.deepBlocks.clear();
    // The kWideFound flags some lane has, set by the workers that find one.
    std::atomic<std::uint32_t> found{0};
    if (!s.wideContactsOnly) {
        prepareContacts(w, h, soft);  // leaves each colour's end in colourOffsets
        if (!s.wideContactsActive) {
            s.wideContacts.resizeForOverwrite(0);
            s.wideContactCold.resizeForOverwrite(0);
            return;
        }
        const int blocks = layoutWideBlocks(s, s.colourOffsets.data());
        const std::vector<int>& blockRows = s.wideBlockRows;
        const RowContext x = makeRowContext(w, h, soft);
        auto pack = [&](int b, int e) {
            std::uint32_t lanes = 0;
            for (int k = b; k < e; ++k)
                lanes |= packWideContactBlock(s, k, blockRows[static_cast<std::size_t>(2 * k)],
                                              blockRows[static_cast<std::size_t>(2 * k + 1)], &w, &x);
            if (lanes) found.fetch_or(lanes, std::memory_order_relaxed);
        };
        w.runner.run(blocks, kPackGrain, pack);
        listSweptAgainBlocks(w, x, found.load(std::memory_order_relaxed));
        // The tilt rows' candidates (contact_tilt.cpp), from their lanes.
        for (int k = 0; k < (w.settings.exactColumnTilt ? blocks : 0); ++k) {
            const WideContactBlock& blk = s.wideContacts[static_cast<std::size_t>(k)];
            for (int lane = 0; lane < 4; ++lane)
                if ((blk.flags[lane] & kWidePoint1) != 0 && blk.points[0].normalImpulse[lane] > 0.0f &&
                    blk.points[1].normalImpulse[lane] > 0.0f &&
                    tiltCandidate(s, w.contacts[s.wideContactCold[static_cast<std::size_t>(k)].contact[lane]]))
                    s.tilt.candidate.push_back(4 * k + lane);
        }
        buildTiltChains(w);
        return;
    }
    // colourOffsets holds each colour's first row, so the next colour's is its end.
    layoutWideBlocks(s, s.colourOffsets.data() + 1);
    const int overflow = s.contactOverflowStart;
    s.contactOverflowStart = 0;  // the scalar rows are the overflow group's alone
    s.rolling.clear();
    // Each active contact's row is its group's first row (colourOffsets,
    // which this path leaves as it is) plus its place in the group
    // (rowContacts), as prepareContacts places them (a stable counting sort
    // by colour).
    const std::size_t activeCount = w.activeContacts.size();
    s.constraints.resizeForOverwrite(static_cast<std::size_t>(s.rowCount - overflow));
    const bool tilt = w.settings.exactColumnTilt;
    s.tiltCandidate.assign(tilt ? activeCount : 0, 0);
    // Contact by contact in slot order, which reads the contacts and bodies
    // in the order they lie in memory; each row goes to its lane (or the
    // overflow group's scalar row), so the contacts may be shared among the
    // workers. Preparing block by block instead (each block's four contacts
    // gathered, the block written whole, four lanes a store) ran 20 % fewer
    // instructions but read each colour's contacts strided through the slots:
    // many_pyramids' step took 1.3 times as long, pyramid100's 1.08.
    const RowContext x = makeRowContext(w, h, soft);
    const float slop = w.settings.penetrationSlop;
    // Four lanes' arithmetic at once (prepareWideContactLanes), the contacts
    // still read one by one: the preparation of 58,000 rows was mostly
    // arithmetic (many_pyramids: preparing each row twice added 14 % to the step).
    auto prepare = [&](int first, int last) {
        WideLaneTarget targets[4];
        int pending = 0;
        std::uint32_t lanes = 0;
        for (int k = first; k < last; ++k) {
            const int inGroup = s.rowContacts[static_cast<std::size_t>(k)];
            if (inGroup < 0) continue;
            const int contact = w.activeContacts[static_cast<std::size_t>(k)];
            const std::size_t group = s.contactColours[static_cast<std::size_t>(k)];
            if (group == kRowGroupCount) {  // the overflow group's rows are scalar
                ContactConstraint& cc = s.constraints[static_cast<std::size_t>(inGroup)];
                prepareContactRow(w, x, contact, cc);
                setTurning(cc, w.activeLooks[k].rowFlags);
                finishContactRow(x, slop, cc);
                continue;
            }
            const WideLane at = wideLaneOf(s, group, inGroup);
            targets[pending++] = {contact, &s.wideContacts[at.block], &s.wideContactCold[at.block], at.lane};
            if (tilt) s.tiltCandidate[static_cast<std::size_t>(k)] = tiltCandidate(s, w.contacts[contact]);
            if (pending == 4) {
                lanes |= prepareWideContactLanes(w, x, targets, pending);
                pending = 0;
            }
        }
        if (pending > 0) lanes |= prepareWideContactLanes(w, x, targets, pending);
        if (lanes) found.fetch_or(lanes, std::memory_order_relaxed);
    };
    w.runner.run(static_cast<int>(activeCount), kPrepareGrain, prepare);
    // The lanes past each group's last row stay empty.
    for (int c = 0; c < kRowGroupCount; ++c) {
        const int count = s.colourOffsets[static_cast<std::size_t>(c) + 1] -
                          s.colourOffsets[static_cast<std::size_t>(c)];
        if (count % 4 == 0) continue;
        const std::size_t k = static_cast<std::size_t>(s.wideContactColourStart[static_cast<std::size_t>(c) + 1] - 1);
        for (int lane = count % 4; lane < 4; ++lane)
            packEmptyWideContactLane(s.wideContacts[k], s.wideContactCold[k], lane, x.zeroState);
    }
    listSweptAgainBlocks(w, x, found.load(std::memory_order_relaxed));
    // The candidates of the columns' tilt rows (contact_tilt.cpp), marked
    // by the workers that prepared them, in the order of the active contacts.
    for (std::size_t k = 0; k < (tilt ? activeCount : 0); ++k) {
        if (!s.tiltCandidate[k]) continue;
        const WideLane at = wideLaneOf(s, s.contactColours[k], s.rowContacts[k]);
        s.tilt.candidate.push_back(static_cast<int>(at.block) * 4 + at.lane);
    }
    buildTiltChains(w);
}

/// Joint sweeps in each substep's solve stage (soft_step). A chain carrying a
/// heavy body (heavy_chain: 100 kg on 1 kg links) is a stiff, badly
/// conditioned system that one Gauss-Seidel sweep per substep left stretched
/// (3.1 m in total after 5 s; two sweeps: 1.0 m). Such trees of unlike masses
/// are now solved exactly (joint_tree.cpp: 0.35 m, the rows' compliance), so
/// one sweep suffices, as in Box2D v3; it saves a seventh of joint_grid's step.
constexpr int kJointSolvePasses = 1;

// ---------------------------------------------------------------------------
// The solve stage

/// Bodies [first, last) of the awake list into the solver arrays.
void gatherBodyRange(WorldState& w, float h, Vec2 g, int first, int last) {
    SolverArrays& s = w.solver;
    const std::vector<int>& awake = w.islands.awakeBodies;
    for (std::size_t i = static_cast<std::size_t>(first); i < static_cast<std::size_t>(last); ++i) {
        const int b = awake[i];
        Body& body = w.bodies[b];
        body.solverIndex = static_cast<int>(i);
        s.bodyMoves[static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(
            (body.invMass != 0.0f || body.invInertia != 0.0f ? kBodyMoves : 0) |
            (std::abs(body.w) * w.stepDt > kTurningRowAngle ? kBodyTurns : 0));
        s.rowBodies[static_cast<std::size_t>(b)] = rowBodyOf(body, static_cast<int>(i));
        s.stateBodies[i] = b;
        BodyState& st = s.states[i];
        st.v = body.v;
        st.w = body.w;
        st.upBeforeRelax = 0.0f;
        st.dp = {};
        st.dq = {};
        BodyIntegration& in = s.integration[i];
        in.movedByForces = body.type == BodyType::dynamic_body;
        in.splitBefore = body.splitChosen ? static_cast<std::uint8_t>(body.splitKick) : kSplitNotChosen;
        in.jointed = body.jointCount > 0;
        in.split = false;
        in.linearAcceleration = body.gravityScale * g + body.invMass * body.force;
        in.torque = body.torque;
        in.invInertia = body.invInertia;
        in.linearDampingFactor = 1.0f / (1.0f + h * body.linearDamping);
        in.angularDampingFactor = 1.0f / (1.0f + h * body.angularDamping);
    }
}

/// The solver arrays of this step's awake bodies; h is the (sub)step. Each
/// body on its own: shared among the workers.
void gatherBodies(WorldState& w, float h) {
    SolverArrays& s = w.solver;
    const std::vector<int>& awake = w.islands.awakeBodies;
    const std::size_t n = awake.size();
    const Vec2 g = w.settings.gravity;
    s.states.resizeForOverwrite(n + 1);
    s.states[n] = BodyState{};  // the zero state for immovable sides of contacts
    // The per-slot arrays are zero but at the last step's states (their only
    // writers); cleared there, not over every slot, so that sleeping and
    // static bodies cost nothing.
    for (const int b : s.stateBodies) {
        s.bodyMoves[static_cast<std::size_t>(b)] = 0;
        s.contactColourMasks[static_cast<std::size_t>(b)] = 0;
        s.rowBodies[static_cast<std::size_t>(b)].state = kNullIndex;
    }
    s.bodyMoves.resize(w.bodies.items.size(), 0);
    s.contactColourMasks.resize(w.bodies.items.size(), 0u);
    s.rowBodies.resize(w.bodies.items.size());
    s.integration.resizeForOverwrite(n);
    s.stateBodies.resize(n);
    auto range = [&](int first, int last) { gatherBodyRange(w, h, g, first, last); };
    w.runner.run(static_cast<int>(n), kBodyGrain, range);
}

using Clock = std::chrono::steady_clock;
float msSince(Clock::time_point t0) { return std::chrono::duration<float, std::milli>(Clock::now() - t0).count(); }

void solve(WorldState& w, float dt) {
    const WorldSettings& set = w.settings;
    SolverArrays& s = w.solver;
    const bool soft = set.positionCorrection == PositionCorrection::soft_step;
    const int substeps = solverSubsteps(set);
    const float h = dt / static_cast<float>(substeps);
    const float maxSpeed = set.maxLinearSpeed;

    const Clock::time_point prepareStart = Clock::now();
    // Shared when the step will be (the rows are not counted yet).
    w.runner.share(static_cast<int>(w.activeContacts.size()) + w.joints.count +
                       static_cast<int>(w.islands.awakeBodies.size()) >=
                   kParallelWork);
    gatherBodies(w, h);
    const std::size_t n = s.stateBodies.size();
    colourContacts(w);
    // Which bodies take their forces in two halves around the drift (they
    // touch nothing: split_kick.hpp), from the colouring's marks; the
    // jointed ones once the joint plan is made.
    splitFreeBodies(w, h, soft);
    // The solve is shared with the task system's workers when it is large
    // enough to gain from it (kParallelWork); the result is the same.
    w.runner.share(s.rowCount + w.joints.count + static_cast<int>(n) >= kParallelWork);
    s.positionUpdates = 0;
    prepareContactRows(w, h, soft);
    if (soft && !s.coldBlocks.empty()) estimateRestLoads(w, h);
    // Every other step the contact sweep runs backward. One direction alone
    // favours, in every stack, the rows it meets first (they take the larger
    // share of a change in load), the same way each step: pyramid100 leaned
    // and rocked 9 cm, tall_stack50 48 cm; alternating, 0.5 and 8 cm
    // (docs/validation.md, "The pyramid's compliance"). Not in a step with an
    // overlap being pushed apart: alternating there too took 4 of 160 piles
    // of small boxes created overlapping 2 to 9 % above their starting energy,
    // and none in one direction (tests/robustness, OverlapPiles).
    s.sweepBackward = (w.stepStamp & 1u) != 0 && !(soft && s.anyDeepOverlap);
    if (soft && s.anyDeepOverlap) {
        prepareDeepOverlaps(w);
        beginDeepCarry(s);
    }
    prepareJoints(w, dt, h);
    splitJointedBodies(w, h, soft);
    w.profile.prepare = msSince(prepareStart);
    // Joint stiffness capped at 1/4 of the substep rate, so jointHertz 60 holds
    // at 4 substeps as in Box2D v3 (twice its contact hertz). Swept by one
    // Gauss-Seidel pass, a 100:1 chain of distance joints diverged at this
    // stiffness; the exact solve of such trees (joint_tree.cpp) holds it.
    JointContext jointCtx;
    jointCtx.h = h;
    jointCtx.invH = 1.0f / h;
    jointCtx.jointSoft = makeSoft(jointHertzOver(set, h), set.jointDampingRatio, h);
    jointCtx.pushFactor = set.pushFactor;
    jointCtx.maxLinearSpeed = maxSpeed;
    // Where a sweep left a velocity non-finite (stopNonFiniteBodies). The
    // soft step finds it where the next integration reads every velocity
    // anyway (integrateVelocities, integratePositions: a body found so is
    // left as it is, and the bodies are stopped before anything else reads
    // them), and once after its last sweep. A scan of its own after each of
    // a substep's three sweeps was 3 % of a 1,000-circle scene's step, and
    // serial; the other modes keep it.
    std::atomic<bool> nonFinite{false};
    auto stopIfNonFinite = [&] {
        if (!nonFinite.load(std::memory_order_relaxed) && !nonFiniteVelocity(s.states[n])) return;
        stopNonFiniteBodies(s);
        nonFinite.store(false, std::memory_order_relaxed);
    };
    // A world without joints pays nothing for them, the check included.
    auto joints = [&](SolvePass pass) {
        if (s.joints.empty() && s.wideRevolutes.empty()) return;
        jointCtx.pass = pass;
        solveJoints(w, jointCtx);
        if (!soft) stopNonFiniteBodies(s);
    };
    auto contacts = [&](SolvePass pass, float step) {
        if (s.rowCount == 0) return;  // a world without contacts pays nothing for them
        solveContacts(w, step, pass);
        if (!soft) stopNonFiniteBodies(s);
    };
    auto warmStart = [&] {
        warmStartContacts(w);
        warmStartJoints(w);
        if (!soft) stopNonFiniteBodies(s);
    };

    // Integration body by body, on every worker when the step is large
    // enough to gain from it (kParallelWork; the result is the same either way).
    // soft_step pays each substep's push lift in the next integration (or
    // the write-back) (payPushLift).
    const float gravityLength = length(set.gravity);
    const Vec2 up = gravityLength > 0.0f ? (-1.0f / gravityLength) * set.gravity : Vec2{0.0f, 1.0f};
    auto velocities = [&](float step, bool payLift) {
        auto range = [&](int b, int e) {
            integrateVelocities(s, step, maxSpeed, static_cast<std::size_t>(b), static_cast<std::size_t>(e), payLift,
                                up, nonFinite);
        };
        w.runner.run(static_cast<int>(n), kBodyGrain, range);
        stopIfNonFinite();
    };
    auto positions = [&](float step) {
        auto range = [&](int b, int e) {
            integratePositions(s, step, maxSpeed, static_cast<std::size_t>(b), static_cast<std::size_t>(e), nonFinite);
        };
        w.runner.run(static_cast<int>(n), kBodyGrain, range);
        stopIfNonFinite();
    };
    if (s.anyTurningRow) {  // (before the first substep changes them)
        s.startSpin.resize(s.states.size());
        for (std::size_t i = 0; i < s.states.size(); ++i) s.startSpin[i] = s.states[i].w;
    }
    if (soft) {
        for (int i = 0; i < substeps; ++i) {
            velocities(h, i > 0 && s.anyDeepOverlap);
            if (i > 0 && s.anyDeepOverlap) carryDeepLoads(s);
            warmStart();
            for (int pass = 0; pass < kJointSolvePasses; ++pass) joints(SolvePass::soft_bias);
            contacts(SolvePass::soft_bias, h);
            if (!s.coldBlocks.empty()) settleColdContacts(w, h);
            solveTiltChains(w, h);
            if (s.anyDeepOverlap || s.anyDeepJoint || s.pushTrees || !s.tilt.rows.empty()) {
                stopNonFiniteBodies(s);  // (integratePositionsPushed does not look)
                if (s.anyDeepOverlap) {
                    // The push reads the load its rows carry (deep_overlap.cpp).
                    if (s.wideContactsActive) readWideNormalImpulses(s, s.deepRows);
                    pushDeepOverlaps(w, h);
                } else {
                    s.biasV.assign(s.states.size(), Vec2{});
                    s.biasW.assign(s.states.size(), 0.0f);
                }
                // The columns' tilt, closed on the same pseudo-velocities (contact_tilt.cpp).
                pushTiltChains(w, h);
                // The deep joints' error (isDeepJoint, world_state.hpp), one
                // sweep at the soft rows' own rate: biasRate·C = β·C/h.
                if (s.anyDeepJoint) {
                    JointContext push = jointCtx;
                    push.pushFactor = jointCtx.jointSoft.biasRate * h;
                    pushJoints(w, push, true);
                }
                // The pushed trees' error (rigid trees, stretched joints), at the same rate (joint_tree.cpp).
                if (s.pushTrees) {
                    JointContext push = jointCtx;
                    push.pushFactor = jointCtx.jointSoft.biasRate * h;
                    pushJointTrees(w, push);
                }
                dropNonFinitePush(s);
                integratePositionsPushed(s, h, maxSpeed, up);
            } else {
                positions(h);
            }
            ++s.positionUpdates;  // the joint trees and wide hinges keep what they made until then
            // The second half kick of the bodies whose forces are split
            // (split_kick.hpp): the integration's own pass (four or eight
            // bodies at a time) when every moving body is split, as in a
            // jointed scene in the air.
            if (s.splitKickCount > 0 && s.splitKickCount == s.movingStates)
                velocities(h, false);
            else if (s.splitKickCount > 0)
                kickAfterDrift(s, h, maxSpeed);
            joints(SolvePass::soft_relax);
            const SolvePass relax = i + 1 == substeps ? SolvePass::soft_relax_last : SolvePass::soft_relax;
            contacts(relax, h);
            if (!s.deepBlocks.empty()) relaxDeepContacts(w, h, relax);
            solveTiltChains(w, h);
        }
        stopNonFiniteBodies(s);    // the last sweep's, before the impulses are stored
        if (s.wideContactsOnly) {  // blocks without rows store into their contacts
            auto store = [&](int first, int last) { storeWideImpulses(w, first, last, 1.0f / h); };
            w.runner.run(static_cast<int>(w.activeContacts.size()), kPrepareGrain, store);
        } else if (s.wideContactsActive) {  // restitution and the store read the rows
            auto back = [&](int b, int e) { writeBackWideContacts(s, b, e); };
            w.runner.run(static_cast<int>(s.wideContacts.size()), kPackGrain, back);
        }
        if (set.impactModel == ImpactModel::velocity_bias) {
            applyRestitution(w);
            stopNonFiniteBodies(s);
        }
        if (s.anyDeepOverlap) carryDeepLoads(s, true);  // what the next step's first substep starts with
    } else {
        const bool baumgarte = set.positionCorrection == PositionCorrection::baumgarte;
        const SolvePass pass = baumgarte ? SolvePass::baumgarte : SolvePass::no_push;
        velocities(dt, false);
        warmStart();
        for (int it = 0; it < set.velocityIterations; ++it) {
            joints(pass);
            contacts(pass, dt);
        }
        if (!baumgarte) {
            s.biasV.assign(n + 1, Vec2{});
            s.biasW.assign(n + 1, 0.0f);
            for (int it = 0; it < set.positionIterations; ++it) {
                pushJoints(w, jointCtx);
                solveContactPush(w, dt);
                dropNonFinitePush(s);
            }
            // Move by v + v_push for this step only; v_push is then dropped.
            integratePositionsPushed(s, dt, maxSpeed, up);
        } else {
            positions(dt);
        }
    }
    storeContactImpulses(w);
    storeJoints(w, soft ? h : dt);
    // Write back: centre of mass, rotation, origin, velocities; clear forces.
    // The relax and restitution passes act after the last position update, so
    // the limits are applied once more to the velocities the body keeps.
    const float maxAngular = kMaxRotationPerStep / (dt / static_cast<float>(substeps));
    // Whether each body's shapes left their fat boxes, found here where the
    // body is in the cache and on every worker (refreshProxies moves those).
    std::vector<std::uint8_t>& leaves = w.broadPhase.proxyLeaves;
    leaves.resize(n);
    // And whether continuous collision must sweep it: asked here for the same
    // reason, the stage then visits the fast bodies only (it read every awake
    // body again on the stepping thread: 0.2 ms a step for many_pyramids'
    // 22,000 boxes on a quiet machine).
    const bool continuous = set.enableContinuous;
    std::vector<std::uint8_t>& sweeps = s.sweeps;
    sweeps.resize(n);
    auto writeBack = [&](int first, int last) {
        // In runs of kRun bodies, each still in the first-level cache when
        // its fat boxes are checked: the check's bound for a whole run goes
        // through a loop of its own (leftFatBoxes says why).
        constexpr int kRun = 32;
        for (int run = first; run < last; run += kRun) {
            const int end = std::min(run + kRun, last);
            for (std::size_t i = static_cast<std::size_t>(run); i < static_cast<std::size_t>(end); ++i) {
                Body& body = w.bodies[s.stateBodies[i]];
                BodyState& st = s.states[i];
                if (soft && s.anyDeepOverlap && s.integration[i].movedByForces)  // the last substep's push lift
                    payPushLift(s, i, st, s.integration[i].linearAcceleration, up, h);
                clampVelocity(st, maxSpeed, maxAngular);
                body.v = st.v;
                body.w = st.w;
                body.center += st.dp;
                Rot q = mulRot(st.dq, body.xf.q);
                float mag = std::sqrt(q.c * q.c + q.s * q.s);
                q = {q.c / mag, q.s / mag};
                body.xf.q = q;
                body.xf.p = body.center - rotate(q, body.localCenter);
                body.highest = std::max(body.highest, dot(body.center, up));
                body.force = {};
                body.torque = 0.0f;
                body.solverIndex = kNullIndex;
            }
            leftFatBoxes(w, s.stateBodies.data() + run, static_cast<std::size_t>(end - run), leaves.data() + run);
            for (std::size_t i = static_cast<std::size_t>(run); i < static_cast<std::size_t>(end); ++i)
                sweeps[i] = continuous && needsSweep(w, w.bodies[s.stateBodies[i]], s.states[i]) ? 1 : 0;
        }
    };
    w.runner.run(static_cast<int>(n), kBodyGrain, writeBack);
}

/// A world keeps its per-step arrays between steps while they hold at most
/// this much in all, so that a small world steps without allocating; beyond
/// it they are all freed when the step ends (Box2D 2.4.1 likewise keeps a
/// 100 kB stack and allocates its solver arrays beyond it in every step).
/// Kept one by one below 64 kB each, they added up: a world of 1,000 boxes
/// in columns held 170 bytes a body and 80 a contact of scratch between
/// steps. Freeing them costs a 1,000-body world a little of its step: rain1000
/// 1.7 % against keeping every array (engine alone, 10 interleaved rounds),
/// before states and integration were made again without zero-filling;
/// since, its median step is 1.009 of what it was with the arrays kept one by
/// one (docs/performance.md, "Memory at every world size").
constexpr std::size_t kKeptScratchBytes = 64 * 1024;

template <class T>
std::size_t bytesOf(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}
template <class T>
std::size_t bytesOf(const ScratchArray<T>& a) {
    return a.capacity() * sizeof(T);
}
template <class T>
void release(std::vector<T>& v) {
    std::vector<T>().swap(v);
}
template <class T>
void release(ScratchArray<T>& a) {
    a.release();
}

/// Calls f on every array a step fills anew before it reads it. Not among
/// them: what is carried from step to step (the deep rows' and pushes'
/// carries, the joint plan), the per-slot records cleared where written
/// (rowBodies, the impact stage's arrays: refilled in every step they would
/// charge idle bodies to the awake ones), and the stateBodies group
/// (releaseLargeStepArrays).
template <class F>
void forEachStepArray(WorldState& w, F&& f) {
    SolverArrays& s = w.solver;
    f(s.states);
    f(s.integration);
    f(s.biasV);
    f(s.biasW);
    f(s.constraints);
    f(s.wideContacts);
    f(s.wideContactCold);
    f(s.rowContacts);
    f(s.contactColours);
    f(s.deepContactCount);
    f(s.sweeps);
    f(s.wideBlockRows);
    f(s.listedImpulses);
    f(s.coldBlocks);
    f(s.deepBlocks);
    f(s.deepRows);
    f(s.sidePushes);
    f(s.supported);
    f(s.pushOffFixedLift);
    f(s.pushShoves);
    f(s.pushShoveImpulses);
    f(s.pushShoveAxes);
    f(s.pushStalled);
    f(s.pushWalled);
    f(s.supportStart);
    f(s.supportAbove);
    f(s.supportQueue);
    f(s.tiltCandidate);
    f(s.tilt.rows);
    f(s.tilt.chainStart);
    f(s.tilt.candidate);
    f(s.tilt.found);
    f(s.tilt.degree);
    f(s.tilt.link);
    f(s.tilt.visited);
    f(s.tilt.rhs);
    f(s.tilt.x);
    for (ChainFactors* c : {&s.tilt.velocity, &s.tilt.push}) {
        f(c->diag);
        f(c->upper);
        f(c->lower);
        f(c->active);
    }
    f(w.activeContacts);
    f(w.gatherScratch);
    f(w.gatherMarks);
    f(w.collideUpdates);
    f(w.collideLooks);
    f(w.activeLooks);
    f(w.broadPhase.proxyLeaves);
    f(w.islands.unionParent);
}

void releaseLargeStepArrays(WorldState& w) {
    SolverArrays& s = w.solver;
    // bodyMoves and contactColourMasks are per body slot and cleared at the
    // slots of stateBodies (gatherBodies): released with it when one of them
    // is large on its own, not with the rest (made again, they are zeroed
    // over every slot, which would charge idle bodies to the awake ones).
    // rowBodies is kept (32 bytes a body slot: released and filled again,
    // every step would pay for the idle bodies' slots), its states cleared here.
    if (bytesOf(s.stateBodies) > kKeptScratchBytes || bytesOf(s.contactColourMasks) > kKeptScratchBytes) {
        for (const int b : s.stateBodies) s.rowBodies[static_cast<std::size_t>(b)].state = kNullIndex;
        release(s.stateBodies);
        release(s.bodyMoves);
        release(s.contactColourMasks);
    }
    std::size_t held = 0;
    forEachStepArray(w, [&](const auto& a) { held += bytesOf(a); });
    if (held > kKeptScratchBytes) forEachStepArray(w, [](auto& a) { release(a); });
}

}  // namespace

void stepWorld(WorldState& w, float dt) {
    w.locked = true;
    w.stepping = true;
    struct Unlock {
        bool& flag;
        bool& stepping;
        ~Unlock() { flag = stepping = false; }
    } unlock{w.locked, w.stepping};

    // The last step's events go; end events caused since arrive (events.hpp).
    w.events.beginStep();

    w.stepDt = dt;
    Profile& profile = w.profile;
    auto t0 = Clock::now();
    auto t = t0;
    // Before the contacts carry their impulses to this step's manifolds.
    carryWarmStarts(w, dt);
    coverSetMotions(w, dt);
    updatePairs(w);
    profile.pairs = msSince(t);

    // The helpers of a large step start before the narrowphase and stay
    // until the proxies are refreshed: one hand-over per step. Started for the solve
    // alone, they woke too late to share a narrowphase of half a millisecond.
    // Only when some stage will be shared: the narrowphase is with enough
    // contacts, the solve with enough rows, joints and bodies (the last
    // step's rows stand for this step's, not counted yet). Helpers started
    // for a step that then shares nothing spun through it beside the stepping
    // thread and slowed it (circle_pile1000: 0.49 -> 0.58 ms per step).
    const int solveWork = w.solver.rowCount + w.joints.count + static_cast<int>(w.islands.awakeBodies.size());
    const bool parallel = w.tasks != nullptr && w.tasks->workerCount() > 1 &&
                          (w.contacts.count >= kParallelWork || solveWork >= kParallelWork);
    w.runner.begin(parallel ? w.tasks : nullptr);
    struct EndStages {
        StageRunner& runner;
        void end() { runner.end(); }
        ~EndStages() { runner.end(); }
    } stages{w.runner};

    t = Clock::now();
    collide(w);
    profile.collide = msSince(t);

    t = Clock::now();
    resolveImpacts(w, dt);
    profile.impacts = msSince(t);

    t = Clock::now();
    solve(w, dt);
    profile.solve = msSince(t);

    t = Clock::now();
    if (w.settings.enableContinuous) solveContinuous(w, dt);
    profile.sweeps = msSince(t);
    refreshProxies(w, dt);
    stages.end();
    profile.continuous = msSince(t);

    t = Clock::now();
    updateSleep(w, dt);
    releaseLargeStepArrays(w);
    profile.sleep = msSince(t);
    profile.step = msSince(t0);
}

}  // namespace i2d::detail
