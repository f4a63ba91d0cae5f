// Contact rows solved four manifolds at a time (wide_contact.cpp): the rows
// of one colour touch no movable body twice, so four are independent and
// their arithmetic runs in the lanes of Float4. Each lane does what the
// scalar row does (contact_solver.cpp) with the same operations in the same
// order, its branches turned into selects, so the results are bit-identical
// (tests/unit/test_wide_contact.cpp). Used in soft_step for the rows of the
// coloured groups; the overflow group (rows that share bodies), split and
// baumgarte modes, and steps with rolling resistance keep the scalar rows. A
// row overlapping deeper than kDeepOverlap is rigid in its block's push pass,
// as in the scalar row; the push that moves it apart (deep_overlap.cpp) reads
// its load from the block (readWideNormalImpulses), and what its warm start
// carries is set in the block (carryDeepLoads, contact_solver.cpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "contact_solver.hpp"
#include "scratch_array.hpp"

namespace i2d::detail {

struct SolverArrays;
struct WorldState;

/// The blocks of a colour come in two groups (solver.cpp): manifolds of two
/// points, then manifolds of one, whose sweeps skip the second point.
inline constexpr int kWideGroupsPerColour = 2;

/// One of the two points of four manifolds (whether a lane has it: the
/// block's kWidePoint0/kWidePoint1 flags).
struct WideContactPoint {
    float rAx[4], rAy[4], rBx[4], rBy[4];
    float adjustedSeparation[4], normalMass[4], tangentMass[4];
    float normalImpulse[4], tangentImpulse[4];
};

/// A lane's flags (WideContactBlock::flags), the row's booleans.
enum WideContactFlag : std::uint32_t {
    kWideTogether = 1u << 0,       ///< the manifold's two points are solved together (solvePointPair)
    kWideRoundA = 1u << 1,         ///< A's shape is a circle: its contact point does not turn with it
    kWideRoundB = 1u << 2,         ///< the same for B
    kWideDeep = 1u << 3,           ///< overlaps deeper than kDeepOverlap (rigid in the soft_bias pass)
    kWideImmovableSide = 1u << 4,  ///< a side cannot move: the rows' stiffer softness (RowContext::staticSoft)
    kWidePoint0 = 1u << 5,         ///< the manifold has its first point
    kWidePoint1 = 1u << 6,         ///< and its second
    kWideMovesA = 1u << 7,         ///< A can move (a nonzero inverse mass or inertia): the sweeps write its velocity
    kWideMovesB = 1u << 8,         ///< the same for B
    kWideCold = 1u << 9,           ///< a contact at rest without a warm start: settled (settleColdContacts)
    kWideUnloaded = 1u << 10,      ///< a contact whose load was taken away lately: relaxed again (relaxDeepContacts)
    /// A contact created overlapping (Contact::overlapFromStart) and no longer
    /// deep: its soft rows push the last of the overlap out, relaxed again (relaxDeepContacts)
    kWideFromStart = 1u << 11,
};
/// The flags a preparation reports when some lane has them (packWideContactBlock, prepareWideContactLanes).
constexpr std::uint32_t kWideFound = kWideCold | kWideFromStart;

/// Whether the row of a contact whose manifold got points this step
/// (Contact::touchBegan, so it has no warm start: the manifold before had no
/// point to carry one) starts cold and at rest (kWideCold): no point
/// overlaps deeper than the penetration slop (`separation[j]`: an overlap is
/// pushed apart, not a load to find) or closes or opens faster than one step
/// of gravity (`speed[j]`, its normal speed; RowContext::restingSpeed).
inline bool coldAtRest(const RowContext& x, int points, const float* separation, const float* speed) {
    if (points == 0) return false;
    for (int j = 0; j < points; ++j)
        if (!(separation[j] >= -x.restingDepth) || !(std::abs(speed[j]) <= x.restingSpeed)) return false;
    return true;
}

/// kWideMovesA and kWideMovesB for a lane (a contact's or a hinge's) with
/// these inverse masses and inertias: a side moves (and the eight-lane
/// write-back writes it) when either is nonzero.
inline std::uint32_t moveFlags(float invMassA, float invIA, float invMassB, float invIB) {
    return (invMassA != 0.0f || invIA != 0.0f ? kWideMovesA : 0u) |
           (invMassB != 0.0f || invIB != 0.0f ? kWideMovesB : 0u);
}

/// Four manifolds, structure of arrays. An empty lane names the zero state on
/// both sides with zero masses and no points. The substeps' sweeps stream
/// through every block several times, so a block holds only what they read:
/// the rows' softness and push cap are the step's (RowContext: every soft_step
/// row has the same, by whether a side can move) and come with the sweep, and
/// the booleans share one word per lane; what else a lane needs is in its
/// WideContactCold, an array of its own beside the blocks. 480 bytes a block
/// instead of 704 made many_pyramids' step 10 % faster and pyramid100's 4 %,
/// bit-identical (docs/performance.md).
struct WideContactBlock {
    int a[4], b[4];  ///< solver state indices
    float nx[4], ny[4];
    float friction[4], tangentSpeed[4];
    float mA[4], iA[4], mB[4], iB[4];
    float pairCoupling[4];   ///< the rows' pairCoupling (K12 where positive, of two points solved together)
    std::uint32_t flags[4];  ///< WideContactFlag bits
    WideContactPoint points[2];
};
// The sweeps' time on large scenes follows the bytes they stream (a block 160
// bytes larger made many_pyramids' step 14 % slower): grow it only knowingly.
static_assert(sizeof(WideContactBlock) == 480, "a wide contact block is what the sweeps stream through");

/// What the sweeps do not stream through, block by block beside the blocks
/// (SolverArrays::wideContactCold): where each lane's row and contact are, for
/// the write-back and the store, and each point's largest normal impulse, which
/// only the velocity-bias restitution reads (SweepParams::trackMax).
struct WideContactCold {
    int row[4];      ///< the row in SolverArrays::constraints, −1 for an empty lane or one prepared without a row
    int contact[4];  ///< the contact slot, −1 for an empty lane
    float maxNormalImpulse[2][4];
};

/// Packs the rows [start, min(start + 4, last)) of SolverArrays::constraints
/// (of one colour, which ends at `last`) into block `block` of
/// s.wideContacts (sized by the caller), every field written. Returns the
/// kWideFound flags some lane has (kWideCold is looked for when the world
/// `w` and the rows' context `x` are given).
std::uint32_t packWideContactBlock(SolverArrays& s, int block, int start, int last, const WorldState* w = nullptr,
                                   const RowContext* x = nullptr);
/// Where one contact's lane goes (prepareWideContactLanes).
struct WideLaneTarget {
    int contact;  ///< contact slot
    WideContactBlock* block;
    WideContactCold* cold;
    int lane;
};
/// Prepares `count` (at most 4) lanes straight from their contacts, with no
/// scalar row (row −1), soft_step only: each lane holds what
/// packWideContactBlock makes of the row prepareContacts writes. The contacts
/// are read one by one, the arithmetic of prepareContactRow and
/// finishContactRow runs in the lanes of Float4 in the same order, so the
/// bits are the scalar row's. Writes those lanes only, so lanes may be
/// prepared on any worker. Returns the kWideFound flags some lane has.
std::uint32_t prepareWideContactLanes(const WorldState& w, const RowContext& x, const WideLaneTarget* targets,
                                      int count);
/// Lane `lane` of block k empty: the zero state on both sides, no points.
void packEmptyWideContactLane(WideContactBlock& k, WideContactCold& cold, int lane, int zeroState);
/// `points` (1 or 2) is the most points a lane of blocks [firstBlock,
/// lastBlock) has: with 1, the second point's arithmetic is skipped, which
/// changes nothing where it is absent.
void warmStartWideContacts(SolverArrays& s, int firstBlock, int lastBlock, int points = 2);
/// One sweep of blocks [firstBlock, lastBlock) in a soft_step pass: soft_bias,
/// soft_relax or soft_relax_last (`leaveImpacts`: the last relax with the
/// closed-form impact law, see contact_solver.cpp).
/// `trackMax` false leaves maxNormalImpulse alone: only the velocity-bias
/// restitution pass reads it, through the rows (writeBackWideContacts).
/// `x` and `maxPush` give the rows' softness and push cap (the step's, as
/// prepareContactRow sets them in soft_step).
void solveWideContacts(SolverArrays& s, const RowContext& x, float maxPush, SolvePass pass, float h, bool leaveImpacts,
                       float impactSpeed, int firstBlock, int lastBlock, bool trackMax = true, int points = 2);
/// The accumulated impulses of blocks [firstBlock, lastBlock) back into their
/// rows (for restitution and the store, which read the rows).
void writeBackWideContacts(SolverArrays& s, int firstBlock, int lastBlock);
/// How many lanes the wide contact and hinge sweeps and the integrations
/// use: 8 (two contact blocks, one hinge block or eight bodies at once) on an
/// x86-64 CPU with AVX2, else 4. Both give bit-identical results.
int wideLanes();
/// At most this many lanes (4 or 8) from now on: for tests comparing the two.
void limitWideLanes(int lanes);
/// The normal impulses accumulated so far of `rows` (ascending) from their
/// blocks into the rows, for the push of deep overlaps (deep_overlap.cpp).
void readWideNormalImpulses(SolverArrays& s, const std::vector<int>& rows);
/// Drops the accumulated impulses of every lane on a body marked bad.
void dropWideContactImpulses(SolverArrays& s, const std::vector<char>& bad);

}  // namespace i2d::detail
