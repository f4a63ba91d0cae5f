// Revolute joints without limit, motor or spring (a hinge's point rows only,
// the bulk of chains, bridges and grids), solved eight at a time: the rows of
// one colour touch no movable body twice, so eight of them are independent
// and their arithmetic runs in the lanes of an AVX register (where the CPU
// has AVX2) or, half a block at a time, of Float4 (SSE2 on x86-64, portable
// elsewhere). The maths is the revolute joint's point block
// (revolute_joint.cpp) lane by lane.
#pragma once

#include <cstdint>
#include <vector>

#include "joint.hpp"

namespace i2d::detail {

struct SolverArrays;
struct WorldState;

/// Lanes of a block of hinges: eight, so that on CPUs with AVX2 each field
/// is one register's load; the four-lane path solves a block as two halves.
inline constexpr int kHingeLanes = 8;

/// Eight hinges' rows, structure of arrays. An empty lane names the zero
/// state on both sides with zero inverse masses, so it changes nothing.
struct WideRevoluteBlock {
    int a[kHingeLanes], b[kHingeLanes];  ///< solver state indices (the zero state for a body that does not move)
    int joint[kHingeLanes];              ///< the world's joint slot, −1 for an empty lane
    float rAx[kHingeLanes], rAy[kHingeLanes], rBx[kHingeLanes], rBy[kHingeLanes];  ///< anchors from the centres
                                                                                   ///< of mass at the step's start
    float dcx[kHingeLanes], dcy[kHingeLanes];  ///< centre B − centre A at the step's start
    float mA[kHingeLanes], iA[kHingeLanes], mB[kHingeLanes], iB[kHingeLanes];  ///< inverse masses and inertias
    float px[kHingeLanes], py[kHingeLanes];                                    ///< accumulated impulse (N·s)
    /// Which sides move (kWideMovesA, kWideMovesB as a contact lane's flags:
    /// a nonzero inverse mass or inertia), what the eight-lane write-back
    /// tests instead of the four inverse masses.
    std::uint32_t moves[kHingeLanes];
    /// The anchors turned to the substep's positions and the point matrix
    /// K = [k11 k12; k12 k22] with 1/det K, kept by the warm start for the
    /// passes before the positions move (solveWideRevolutes).
    float turnedAx[kHingeLanes], turnedAy[kHingeLanes], turnedBx[kHingeLanes], turnedBy[kHingeLanes];
    float k11[kHingeLanes], k12[kHingeLanes], k22[kHingeLanes], invDet[kHingeLanes];
};
using HingeField = float (WideRevoluteBlock::*)[kHingeLanes];

/// What a block's lanes are made from each step while the joint plan is kept
/// (SolverArrays::jointPlanStale): the world's body slots and the anchors from
/// the centres of mass in the bodies' frames (they change only with the
/// masses or the joint, which make a new plan).
struct WideRevoluteFrame {
    int bodyA[kHingeLanes], bodyB[kHingeLanes];
    float armAx[kHingeLanes], armAy[kHingeLanes], armBx[kHingeLanes], armBy[kHingeLanes];
};

/// Packs the slots at places [first, last) of s.jointOrder (all wide
/// revolutes of one colour) into blocks appended to s.wideRevolutes (and
/// their frames to s.wideFrames): the lanes' bodies, masses and impulses;
/// refreshWideRevolutes writes the anchors.
void packWideRevolutes(const WorldState& w, SolverArrays& s, int first, int last);
/// The step's anchors and centre offsets of blocks [firstBlock, lastBlock)
/// from their bodies' poses (as prepareJoints writes rows: setAnchors in
/// joint_rows.hpp), and their impulses zeroed when warm starting is off. A
/// lane keeps its impulse from the last step's store otherwise: it is the
/// joint's (storeWideRevolutes wrote it, and nothing else writes a wide
/// joint's impulse).
void refreshWideRevolutes(const WorldState& w, SolverArrays& s, int firstBlock, int lastBlock);

/// The warm start and one sweep in ctx's pass of blocks [firstBlock,
/// lastBlock). A block's anchors turned to the current positions and its
/// point matrix are made by the first pass after the positions move and kept
/// for the passes until they move again (`kept`: they are current;
/// SolverArrays::wideFrameAt): a substep's relax makes them, and the next
/// substep's warm start and push pass reuse them.
void warmStartWideRevolutes(SolverArrays& s, int firstBlock, int lastBlock, bool kept);
void solveWideRevolutes(SolverArrays& s, const JointContext& ctx, int firstBlock, int lastBlock, bool kept);
/// The blocks' impulses back into their joints for the next warm start, with
/// the reaction force (as storeJoints does for rows); h as there.
void storeWideRevolutes(WorldState& w, float h);
/// Drops the accumulated impulse of every lane on a body marked bad.
void dropWideImpulses(SolverArrays& s, const std::vector<char>& bad);

}  // namespace i2d::detail
