// The step: the order of the stages, and the solver's per-step arrays.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "body.hpp"
#include "contact_solver.hpp"
#include "contact_tilt.hpp"
#include "deep_overlap.hpp"
#include "joint.hpp"
#include "joint_tree.hpp"
#include "scratch_array.hpp"
#include "wide_contact.hpp"
#include "wide_revolute.hpp"

namespace i2d::detail {

struct WorldState;

/// The solver passes of a step: `substeps` under soft_step, one otherwise.
/// The solve, the impact stage's timing and the warm starts' scaling
/// (warm_start.hpp) each divide the step by it.
inline int solverSubsteps(const WorldSettings& s) {
    return s.positionCorrection == PositionCorrection::soft_step ? s.substeps : 1;
}

/// The joints' soft-row stiffness (Hz) over substeps of h: jointHertz, capped
/// at a quarter of the substep rate (solver.cpp; joint_tree.cpp's jointOmega).
inline float jointHertzOver(const WorldSettings& s, float h) { return std::min(s.jointHertz, 0.25f * (1.0f / h)); }

inline constexpr std::uint8_t kBodyMoves = 1, kBodyTurns = 2;  ///< SolverArrays::bodyMoves

/// What the greedy colouring needs of one active contact (solver.cpp,
/// colourContacts): its bodies, and flags.
struct ColourKey {
    int a, b;  ///< body slots
    std::uint8_t flags;
};

/// What preparing a contact's row reads of one of its bodies (the arms and the
/// inverse masses), kept per body slot for this step's states
/// (SolverArrays::rowBodies): 32 bytes read in place of a 224-byte body,
/// which in a large scene was a cache miss a contact.
struct RowBody {
    Vec2 center{};       ///< centre of mass, world, at the step's start
    Vec2 localCenter{};  ///< centre of mass, body frame
    float invMass = 0.0f, invInertia = 0.0f;
    int state = kNullIndex;  ///< the body's state this step; kNullIndex: none (read the body)
    int unused = 0;
};
static_assert(sizeof(RowBody) == 32, "one per body slot, read per contact: keep it at 32 bytes");
/// The record of `body`, whose state this step is `state` (kNullIndex: none).
inline RowBody rowBodyOf(const Body& body, int state) {
    return {body.center, body.localCenter, body.invMass, body.invInertia, state, 0};
}

/// Arrays rebuilt by every step. Each is sized for this step's awake bodies,
/// contacts or joints.
struct SolverArrays {
    // Written whole for every awake body as the step gathers them: made
    // again when a world frees its step arrays (releaseLargeStepArrays),
    // zero-filled first as vectors are, they were half of what rain1000's
    // step spent zeroing (callgrind: 8.8 to 4.0 million instructions of
    // memset over 600 steps).
    ScratchArray<BodyState> states;             ///< awake bodies, then one zero state for immovable sides
    ScratchArray<BodyIntegration> integration;  ///< per awake body
    std::vector<int> stateBodies;               ///< body slot of each state (awake bodies only)
    /// How many states have their forces split around the drift this step
    /// (BodyIntegration::split; split_kick.hpp), and the joint plan's groups
    /// of jointed states.
    int splitKickCount = 0;
    int movingStates = 0;                       ///< states moved by forces (dynamic) this step
    std::vector<int> splitKickGroup;            ///< per state: its joint group's root, −1 without joints
    std::vector<std::uint8_t> splitKickDrives;  ///< per root: the group has a joint that does more than hold
    std::vector<std::uint8_t> splitKickHeld;    ///< per root, this step: that, or a contact row
    std::vector<Vec2> biasV;                    ///< split mode pseudo-velocities (zero entry last)
    std::vector<float> biasW;
    ScratchArray<ContactConstraint> constraints;  ///< in colour order (solver.cpp)
    std::vector<std::uint8_t> contactColours;     ///< per active contact: its row's group (solver.cpp), or kNoRow
    std::vector<int> colourOffsets;  ///< per row group: its first row (advanced as prepareContacts places rows)
    std::vector<std::uint32_t> contactColourMasks;  ///< per body slot: the colours of its contact rows (solver.cpp)
    /// Per body slot, for a body of this step's states: kBodyMoves when it
    /// moves under an impulse (a non-zero inverse mass or inertia), kBodyTurns
    /// when it turns further than kTurningRowAngle in the step (its contacts
    /// may need turning rows), what the colouring reads instead of the bodies
    /// themselves.
    std::vector<std::uint8_t> bodyMoves;
    /// Per body slot: for a body of this step's states, what preparing the
    /// rows reads of it (state kNullIndex for the others).
    std::vector<RowBody> rowBodies;
    int rowCount = 0;                     ///< contact rows this step
    std::vector<JointSlot> jointSlots;    ///< every joint with an awake body, in the world's order
    std::vector<JointConstraint> joints;  ///< rows of the slots not solved wide, in slot order (joint_solver.cpp)
    std::vector<int> jointScratch;        ///< the row of each slot while the order is built
    /// The joint plan (slots, tree choice, colouring, order, the wide blocks'
    /// lanes) is kept from step to step while the awake bodies are the same
    /// in the same order (jointPlanBodies) and nothing it was made from
    /// changed: whatever changes a joint (but a motor's speed or a mouse
    /// joint's target, which the rows read every step), its bodies' masses,
    /// types or enabled flags, or the settings sets jointPlanStale
    /// (joint_solver.cpp).
    bool jointPlanStale = true;
    float jointPlanOmega = 0.0f;        ///< jointOmega when the plan was made (joint_tree.hpp)
    std::vector<int> jointPlanBodies;   ///< stateBodies when the plan was made (empty without joints)
    std::vector<int> jointOrder;        ///< by colour: rows, then each colour's wide slots
    JointTrees trees;                   ///< joints solved exactly (joint_tree.cpp)
    std::vector<int> jointColourStart;  ///< per joint colour: its first place in jointOrder; then the row count
    std::vector<int> jointWideStart;    ///< per joint colour: its first place of the wide path
    std::vector<WideRevoluteBlock> wideRevolutes;  ///< the wide rows, kHingeLanes to a block (wide_revolute.cpp)
    std::vector<WideRevoluteFrame> wideFrames;     ///< per block: where its lanes' anchors come from
    int positionUpdates = 0;                       ///< position updates so far in this step (solver.cpp)
    int wideFrameAt = -1;                          ///< the positionUpdates the blocks' kept anchors and K were made at
    std::vector<int> wideBlockStart;               ///< per joint colour: its first block; then the block count
    std::vector<std::uint8_t> jointColours;
    std::vector<std::uint32_t> bodyColours;  ///< per state: the joint colours its rows took (joint_solver.cpp)
    std::vector<int> deepContactCount;       ///< per state: contacts overlapping deeper than kDeepOverlap
    bool anyDeepJoint = false;               ///< some joint row is a deep joint this step (isDeepJoint)
    bool pushTrees = false;                  ///< an exact tree is pushed this step (TreeNode::pushed)
    /// Per wide block: a hinge of it became a deep joint (refreshWideRevolutes).
    std::vector<std::uint8_t> wideDeep;
    bool anyDeepOverlap = false;  ///< some row overlaps deeper than kDeepOverlap this step
    bool anyRollingRow = false;   ///< some row gets a rolling-resistance row this step
    bool anyTurningRow = false;   ///< some row is a turning row this step (contact_solver.cpp)
    /// Per state, in a step with a turning row: its angular velocity when the
    /// step began, which the turning rows' bend is predicted with (turningBend).
    std::vector<float> startSpin;
    std::vector<int> deepRows;            ///< the rows that do, ascending (contact_solver.cpp)
    std::vector<SidePush> sidePushes;     ///< deep rows pushed sideways, in row order (deep_overlap.cpp)
    std::vector<DeepCarry> deepCarry;     ///< per deep row, in deepRows' order (contact_solver.cpp)
    std::vector<std::uint8_t> supported;  ///< per state: rests on something immovable (deep_overlap.cpp)
    /// Per state: how far a deep row pushing it out of something immovable
    /// may lift it above the highest it has been (m; deep_overlap.cpp).
    std::vector<float> pushOffFixedLift;
    /// The shallow rows of the bodies a deep row pushes against something
    /// immovable that holds them up, and each point's guard impulse (two per
    /// row): the push may not drive such a body into what it rests on
    /// (deep_overlap.cpp).
    std::vector<int> pushGuards;
    std::vector<float> pushGuardImpulses;
    std::vector<float> pushGuardScales;  ///< per guard: pairScale of its row (fixed within a step)
    /// The shallow rows between two moving bodies, one of them pushed, and
    /// each row's shove impulse: a pushed body shoves the body it touches
    /// (deep_overlap.cpp, shoveTouching).
    std::vector<int> pushShoves;
    std::vector<float> pushShoveImpulses;
    /// Per shove: the level direction it shoves along (unit, across gravity)
    /// when its row is steeper than level (deep_overlap.cpp, kShoveLevel), or
    /// zero for a level row, which shoves along its normal.
    std::vector<Vec2> pushShoveAxes;
    /// Per state: in a deep row whose two bodies moved less than kStallMove
    /// relative to each other over the last step (deep_overlap.cpp).
    std::vector<std::uint8_t> pushStalled;
    std::vector<std::uint8_t> pushWalled;  ///< per state: touches something immovable that does not hold it up
    /// Per deep row, in deepRows' order: K11, K22 and K12 of its two points
    /// (pairMatrix), for the push's pair solve (deep_overlap.cpp, each substep).
    std::vector<float> pushPairs;
    /// The deep pushes' impulses of this step's deep rows (in deepRows' order)
    /// and the last step's (deep_overlap.cpp), and the step that filled them in.
    std::vector<PushCarry> pushCarry, pushCarryLast;
    std::uint32_t pushCarryStamp = 0;
    std::vector<std::uint8_t> sweeps;  ///< per state: 1 when continuous collision sweeps it (needsSweep)
    std::vector<int> supportStart, supportAbove, supportQueue;  ///< deep_overlap.cpp's lists of what rests on what
    std::vector<RollingConstraint> rolling;         ///< contacts with rolling resistance (contact_solver.cpp)
    ScratchArray<WideContactBlock> wideContacts;    ///< the coloured contact rows four at a time (wide_contact.cpp)
    ScratchArray<WideContactCold> wideContactCold;  ///< what the sweeps do not read, block by block
    bool wideContactsActive = false;                ///< this step solves them so
    bool wideContactsOnly = false;                  ///< ... prepared without scalar rows (solver.cpp)
    ScratchArray<int> rowContacts;  ///< per active contact: its place in its row group (colourContacts), −1 for none
    std::vector<int> wideContactColourStart;  ///< per row group: its first block; then the block count
    std::vector<int> wideBlockRows;           ///< per block: its first row and its group's end
    /// The blocks with a lane at rest and without a warm start (kWideCold),
    /// ascending, and where each row group's begin in that list (as
    /// wideContactColourStart's groups; then the list's size): empty when
    /// no lane is cold (settleColdContacts, contact_solver.cpp).
    std::vector<int> coldBlocks, coldBlockStart;
    /// The same for the blocks with a lane of a deep overlap (kWideDeep) or
    /// of a contact whose load was taken away lately (kWideUnloaded): empty
    /// in a step without either, or whose rows are not in wide blocks
    /// (relaxDeepContacts, contact_solver.cpp; listRelaxedAgainBlocks, solver.cpp).
    std::vector<int> deepBlocks, deepBlockStart;
    std::vector<std::uint8_t> tiltCandidate;  ///< per active contact: a tilt row's candidate (contact_tilt.cpp)
    TiltChains tilt;                          ///< the columns' tilt rows, solved exactly (contact_tilt.cpp)
    std::vector<float> listedImpulses;        ///< a listed lane's normal impulses after a sweep (contact_solver.cpp)
    int contactOverflowStart = 0;             ///< the first row of the scalar rest (the overflow group)
    /// This step sweeps the contact rows last to first (colour by colour,
    /// the overflow group's rows in reverse too): every other step, so the
    /// order of a Gauss-Seidel sweep leans no stack the same way each step
    /// (set in solver.cpp, read by solveContacts).
    bool sweepBackward = false;
};

/// limitSpeed for a velocity faster than maxSpeed (or not finite).
Vec2 limitFastSpeed(Vec2 v, float maxSpeed);

/// v limited to maxSpeed, its direction kept (also for a velocity whose
/// square overflows single precision). Inline: every body's velocity passes
/// through it twice per substep, and nearly all are below the limit.
inline Vec2 limitSpeed(Vec2 v, float maxSpeed) {
    if (!(lengthSquared(v) > maxSpeed * maxSpeed)) return v;
    return limitFastSpeed(v, maxSpeed);
}

/// Advances the world by dt: pairs → narrowphase → impacts → solve →
/// continuous collision → proxies → sleep.
void stepWorld(WorldState& w, float dt);

}  // namespace i2d::detail
