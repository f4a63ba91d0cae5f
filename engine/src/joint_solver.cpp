// The joint rows of a step: preparation of every joint with an awake body
// (common part here, each type's part in its own file), colouring, and the
// dispatch of the warm start, the solver passes, split mode's push and the
// store to each type.
//
// Order: the rows are greedily coloured by their movable bodies, as the
// contact rows are (solver.cpp), and solved colour by colour, so a chain or
// grid built in one direction is not swept in that direction.
#include <algorithm>
#include <bit>
#include <cmath>

#include "distance_joint.hpp"
#include "joint_solver.hpp"
#include "joint_tree.hpp"
#include "split_kick.hpp"
#include "wide_revolute.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

constexpr int kJointColours = 16;  ///< colours tried before the overflow group
/// Wide blocks per chunk a worker claims (a colour's blocks are shared among
/// the workers: they touch no movable body twice); 256 hinges.
constexpr int kWideGrain = 32;

/// The solver state of a body index, or a zero stand-in that is thrown away.
BodyState& stateOf(SolverArrays& s, int index) {
    // A body that does not move this step uses the zero state kept after the
    // awake bodies, as contacts do; rows leave it at zero (their inverse
    // masses for it are zero) and each sweep resets it (clearZeroState).
    // Zeroing a stand-in on the stack for every row instead doubled the time
    // of small joint scenes (pendulum_wave: 0.029 against 0.014 ms per step),
    // through the store each row then read back.
    return index >= 0 ? s.states[static_cast<std::size_t>(index)] : s.states.back();
}

/// Resets the zero state after a sweep: what a row with zero inverse masses
/// wrote there is ±0, or NaN from degenerate input (see stopNonFiniteBodies
/// in solver.cpp), and must not reach the next sweep.
void clearZeroState(SolverArrays& s) { s.states.back() = BodyState{}; }

/// Colours the slots (greedy, in slot order) and orders them by (colour,
/// wide): s.jointOrder lists slot indices, colour c's from jointColourStart[c],
/// its wide ones from jointWideStart[c]. The overflow colour (rows that share
/// bodies) is never wide.
void colourJoints(SolverArrays& s) {
    std::vector<JointSlot>& slots = s.jointSlots;
    // Per body, the colours its rows took so far (bit c: colour c); a row
    // takes the lowest colour none of its movable bodies has.
    std::vector<std::uint32_t>& used = s.bodyColours;
    used.assign(slots.empty() ? 0 : s.stateBodies.size(), 0u);
    std::vector<std::uint8_t>& colours = s.jointColours;
    colours.resize(slots.size());
    int counts[2 * (kJointColours + 1)] = {};
    for (std::size_t i = 0; i < slots.size(); ++i) {
        JointSlot& jc = slots[i];
        const int sides[4] = {jc.invMassA != 0.0f || jc.invIA != 0.0f ? jc.a : kNullIndex,
                              jc.invMassB != 0.0f || jc.invIB != 0.0f ? jc.b : kNullIndex,
                              jc.movesC ? jc.c : kNullIndex, jc.movesD ? jc.d : kNullIndex};
        std::uint32_t taken = 0u;
        for (int side : sides)
            if (side >= 0) taken |= used[static_cast<std::size_t>(side)];
        const std::uint32_t free = ~taken & ((std::uint32_t{1} << kJointColours) - 1u);
        const int colour = free != 0u ? std::countr_zero(free) : kJointColours;
        if (colour < kJointColours)
            for (int side : sides)
                if (side >= 0) used[static_cast<std::size_t>(side)] |= std::uint32_t{1} << colour;
        jc.wide = jc.wide && !jc.inTree && colour < kJointColours;
        colours[i] = static_cast<std::uint8_t>(2 * colour + (jc.wide ? 1 : 0));
        ++counts[colours[i]];
    }
    // Stable counting sort by (colour, wide).
    int offset = 0;
    for (int& n : counts) {
        const int c = n;
        n = offset;
        offset += c;
    }
    // counts[k] is now the first place of group k: colour c's slots start at
    // group 2c, its wide ones at group 2c + 1.
    s.jointColourStart.resize(kJointColours + 2);
    s.jointWideStart.resize(kJointColours + 1);
    for (int c = 0; c <= kJointColours; ++c) {
        s.jointColourStart[static_cast<std::size_t>(c)] = counts[2 * c];
        s.jointWideStart[static_cast<std::size_t>(c)] = counts[2 * c + 1];
    }
    s.jointColourStart[kJointColours + 1] = static_cast<int>(slots.size());
    s.jointOrder.resize(slots.size());
    for (std::size_t i = 0; i < slots.size(); ++i)
        s.jointOrder[static_cast<std::size_t>(counts[colours[i]]++)] = static_cast<int>(i);
}

/// The wide blocks of each colour's wide slots, and where each colour's begin.
void packWideRows(const WorldState& w, SolverArrays& s) {
    s.wideRevolutes.clear();
    s.wideFrames.clear();
    s.wideBlockStart.resize(kJointColours + 2);
    for (int c = 0; c <= kJointColours; ++c) {
        s.wideBlockStart[static_cast<std::size_t>(c)] = static_cast<int>(s.wideRevolutes.size());
        packWideRevolutes(w, s, s.jointWideStart[static_cast<std::size_t>(c)],
                          s.jointColourStart[static_cast<std::size_t>(c) + 1]);
    }
    s.wideBlockStart[kJointColours + 1] = static_cast<int>(s.wideRevolutes.size());
}

void fillBody(const WorldState& w, int body, int& index, float& invMass, float& invI) {
    const Body& b = w.bodies[body];
    // Awake bodies have a solver state; a static or sleeping body does not move.
    index = b.awake ? b.solverIndex : kNullIndex;
    invMass = index >= 0 ? b.invMass : 0.0f;
    invI = index >= 0 ? b.invInertia : 0.0f;
}

/// 1/m + |r|²/I at the joint's anchor on `body` (JointSlot::anchorInvMassA):
/// a body driven at an anchor far outside itself gives there as a much
/// lighter one would (a 0.05 kg disc of radius 0.12 m hinged 0.5 m from its
/// centre: as 1.4 g). A joint without anchors (motor, gear, mouse) takes
/// the inverse mass.
float anchorMobility(const Joint& joint, const Body& body, float invMass, float invI, bool sideA) {
    const Vec2 anchor = std::visit(
        [&](const auto& def) -> Vec2 {
            if constexpr (requires {
                              def.localAnchorA;
                              def.localAnchorB;
                          })
                return sideA ? def.localAnchorA : def.localAnchorB;
            else
                return body.localCenter;
        },
        joint.def);
    return invMass + invI * lengthSquared(anchor - body.localCenter);
}

/// A revolute joint with its point rows only, in a step that may solve it
/// eight at a time (not split mode, whose push sweeps every row), with a point
/// matrix that fits single precision (see solvePointRows).
bool wideCandidate(const WorldState& w, const Joint& joint, const Body& bA, const Body& bB, const JointSlot& slot) {
    if (joint.type != JointType::revolute || w.settings.positionCorrection == PositionCorrection::split) return false;
    const RevoluteJointDef& def = std::get<RevoluteJointDef>(joint.def);
    if (def.enableLimit || def.enableMotor || def.enableSpring) return false;
    const double bound = double(slot.invMassA) + slot.invMassB +
                         double(slot.invIA) * lengthSquared(def.localAnchorA - bA.localCenter) +
                         double(slot.invIB) * lengthSquared(def.localAnchorB - bB.localCenter);
    return bound < kSinglePrecisionBound;
}

/// The joint plan: a slot for every joint with an awake body, the joints
/// solved exactly, the colouring and order, and the wide blocks' lanes
/// (their anchors are the step's: refreshWideRevolutes). The order's scalar
/// places name rows, which prepareJoints makes in slot order.
void planJoints(WorldState& w, float h) {
    SolverArrays& s = w.solver;
    std::vector<JointSlot>& slots = s.jointSlots;
    slots.clear();
    for (int j = 0; j < w.joints.capacity(); ++j) {
        const Joint& joint = w.joints[j];
        if (!joint.alive) continue;
        const Body& bA = w.bodies[joint.bodyA];
        const Body& bB = w.bodies[joint.bodyB];
        if (!bA.awake && !bB.awake) continue;
        if (!bA.enabled || !bB.enabled) continue;  // a joint on a disabled body acts on nothing
        JointSlot& slot = slots.emplace_back();
        slot.joint = j;
        fillBody(w, joint.bodyA, slot.a, slot.invMassA, slot.invIA);
        fillBody(w, joint.bodyB, slot.b, slot.invMassB, slot.invIB);
        slot.anchorInvMassA = anchorMobility(joint, bA, slot.invMassA, slot.invIA, true);
        slot.anchorInvMassB = anchorMobility(joint, bB, slot.invMassB, slot.invIB, false);
        if (joint.type == JointType::gear) {
            float m, i;
            fillBody(w, w.joints[joint.joint1].bodyA, slot.c, m, i);
            slot.movesC = m != 0.0f || i != 0.0f;
            fillBody(w, w.joints[joint.joint2].bodyA, slot.d, m, i);
            slot.movesD = m != 0.0f || i != 0.0f;
        }
        slot.equalityRows = static_cast<std::uint8_t>(equalityRowCount(joint));
        slot.rowsOnlyAtLimit = rowsOnlyAtLimit(joint);
        slot.stretched = joint.stretched;
        slot.pointLoad = holdsLoadAtPoint(joint);
        slot.spring = hasSpringRow(joint);
        slot.onlyHolds = jointOnlyHolds(joint);
        slot.wide = wideCandidate(w, joint, bA, bB, slot) && !joint.stretched;
        if (slot.wide && joint.deepHinge) slot.wide = false, slot.deepHinge = true;
    }
    selectTreeJoints(w, slots, h);
    colourJoints(s);
    // The scalar places of the order name rows: the slots the wide path does
    // not take, counted in slot order.
    std::vector<int>& rowOfSlot = s.jointScratch;
    rowOfSlot.assign(slots.size(), kNullIndex);
    int rowCount = 0;
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (!slots[i].wide) rowOfSlot[i] = rowCount++;
    for (std::size_t c = 0; c + 1 < s.jointColourStart.size(); ++c)
        for (int r = s.jointColourStart[c]; r < s.jointWideStart[c]; ++r) {
            int& place = s.jointOrder[static_cast<std::size_t>(r)];
            place = rowOfSlot[static_cast<std::size_t>(place)];
        }
    packWideRows(w, s);
    groupJointedStates(s);
}

}  // namespace

void prepareJoints(WorldState& w, float dt, float h) {
    SolverArrays& s = w.solver;
    // The plan is what a joint's bodies being awake, their masses and the
    // joint itself decide; in a jointed scene at rest or swinging, none of
    // that changes from step to step, and making it was a quarter of a
    // 1,742-joint grid's step. A world without joints keeps no plan (and no
    // copy of the awake list).
    const bool jointed = w.joints.count > 0;
    // The exact trees depend on the joints' stiffness over the substep
    // (selectTreeJoints): a plan is kept while it is within a quarter of what
    // it was planned for, so that a step length that jitters does not make
    // it again every step.
    const float omega = jointOmega(w.settings, h);
    const bool sameStiffness = omega <= 1.25f * s.jointPlanOmega && s.jointPlanOmega <= 1.25f * omega;
    if (!jointed || s.jointPlanStale || !sameStiffness || s.jointPlanBodies != s.stateBodies) {
        planJoints(w, h);
        if (jointed) {
            s.jointPlanBodies = s.stateBodies;
            s.jointPlanStale = false;
            s.jointPlanOmega = omega;
        } else {
            std::vector<int>().swap(s.jointPlanBodies);
        }
    }

    // The rows of the slots the wide path does not take, in slot order.
    const std::vector<JointSlot>& slots = s.jointSlots;
    std::vector<JointConstraint>& rows = s.joints;
    rows.clear();
    s.anyDeepJoint = false;
    s.pushTrees = false;
    const bool warm = w.settings.enableWarmStarting;
    for (const JointSlot& slot : slots) {
        if (slot.wide) continue;
        const Joint& joint = w.joints[slot.joint];
        const Body& bA = w.bodies[joint.bodyA];
        const Body& bB = w.bodies[joint.bodyB];
        JointConstraint& jc = rows.emplace_back();
        jc.joint = slot.joint;
        jc.type = joint.type;
        jc.inTree = slot.inTree;
        jc.treePushed = slot.treePushed;
        jc.treeLoop = slot.treeLoop;
        jc.treeSpring = slot.treeSpring;
        jc.a = slot.a, jc.b = slot.b;
        jc.invMassA = slot.invMassA, jc.invIA = slot.invIA, jc.invMassB = slot.invMassB, jc.invIB = slot.invIB;
        jc.deltaCenter = bB.center - bA.center;
        jc.qA = bA.xf.q;
        jc.qB = bB.xf.q;
        jc.impulses = warm ? joint.impulses : JointImpulses{};
        switch (joint.type) {
            case JointType::distance: prepareDistanceJoint(w, joint, jc); break;
            case JointType::revolute: prepareRevoluteJoint(w, joint, jc); break;
            case JointType::prismatic: preparePrismaticJoint(w, joint, jc); break;
            case JointType::weld: prepareWeldJoint(w, joint, jc); break;
            case JointType::wheel: prepareWheelJoint(w, joint, jc); break;
            case JointType::motor: prepareMotorJoint(w, joint, jc, dt); break;
            case JointType::mouse: prepareMouseJoint(w, joint, jc); break;
            case JointType::pulley: preparePulleyJoint(w, joint, jc); break;
            case JointType::gear:
                fillBody(w, w.joints[joint.joint1].bodyA, jc.c, jc.invMassC, jc.invIC);
                fillBody(w, w.joints[joint.joint2].bodyA, jc.d, jc.invMassD, jc.invID);
                prepareGearJoint(w, joint, jc);
                break;
        }
        // Every entry of the point matrix is at most m_A⁻¹ + m_B⁻¹ + I_A⁻¹|r_A|² + I_B⁻¹|r_B|²
        // (the anchors turn, their lengths stay).
        const double bound = double(jc.invMassA) + jc.invMassB + double(jc.invIA) * lengthSquared(jc.rA) +
                             double(jc.invIB) * lengthSquared(jc.rB);
        jc.singlePrecision = bound < kSinglePrecisionBound;
        jc.deep = !jc.inTree && holdsPoint(joint) && isDeepJoint(w, joint, jc.deltaCenter + jc.rB - jc.rA);
        if (joint.stretched && !isStretched(true, jointStretch(w, joint))) {  // back to the soft rows next step
            w.joints[slot.joint].stretched = false;
            s.jointPlanStale = true;
        }
        s.anyDeepJoint = s.anyDeepJoint || jc.deep;
        if (slot.deepHinge && !jc.deep) {  // back on the wide path from the next step
            w.joints[slot.joint].deepHinge = false;
            s.jointPlanStale = true;
        }
    }
    buildJointTrees(w, h);
    s.wideDeep.assign(s.wideRevolutes.size(), 0);
    auto refresh = [&](int b, int e) { refreshWideRevolutes(w, s, b, e); };
    w.runner.run(static_cast<int>(s.wideRevolutes.size()), kWideGrain, refresh);
    // A hinge that became a deep joint leaves the wide path with the next
    // step's plan (a step late: it is solved as before in this one).
    for (std::size_t k = 0; k < s.wideDeep.size(); ++k) {
        if (!s.wideDeep[k]) continue;
        const WideRevoluteBlock& block = s.wideRevolutes[k];
        for (int lane = 0; lane < kHingeLanes; ++lane) {
            if (block.joint[lane] < 0) continue;
            const Vec2 separation{block.dcx[lane] + block.rBx[lane] - block.rAx[lane],
                                  block.dcy[lane] + block.rBy[lane] - block.rAy[lane]};
            Joint& joint = w.joints[block.joint[lane]];
            if (!isDeepJoint(w, joint, separation)) continue;
            joint.deepHinge = true;
            s.jointPlanStale = true;
        }
    }
    s.wideFrameAt = -1;  // the blocks' kept anchors are made by the first pass
}

/// Colour by colour: the scalar rows, then the wide blocks.
template <class ScalarRow, class WideBlocks>
void sweepColours(SolverArrays& s, ScalarRow&& scalarRow, WideBlocks&& wideBlocks) {
    for (std::size_t c = 0; c + 1 < s.jointColourStart.size(); ++c) {
        for (int r = s.jointColourStart[c]; r < s.jointWideStart[c]; ++r)
            scalarRow(s.joints[static_cast<std::size_t>(s.jointOrder[static_cast<std::size_t>(r)])]);
        if (s.wideBlockStart[c] < s.wideBlockStart[c + 1]) wideBlocks(s.wideBlockStart[c], s.wideBlockStart[c + 1]);
    }
}

void warmStartJoints(WorldState& w) {
    SolverArrays& s = w.solver;
    const bool kept = s.wideFrameAt == s.positionUpdates;
    sweepColours(
        s,
        [&](JointConstraint& jc) {
            BodyState& sA = stateOf(s, jc.a);
            BodyState& sB = stateOf(s, jc.b);
            switch (jc.type) {
                case JointType::distance: warmStartDistanceJoint(jc, sA, sB); break;
                case JointType::revolute: warmStartRevoluteJoint(jc, sA, sB); break;
                case JointType::prismatic: warmStartPrismaticJoint(jc, sA, sB); break;
                case JointType::weld: warmStartWeldJoint(jc, sA, sB); break;
                case JointType::wheel: warmStartWheelJoint(jc, sA, sB); break;
                case JointType::motor: warmStartMotorJoint(jc, sA, sB); break;
                case JointType::mouse: warmStartMouseJoint(jc, sA, sB); break;
                case JointType::pulley: warmStartPulleyJoint(jc, sA, sB); break;
                case JointType::gear: warmStartGearJoint(jc, {sA, sB, stateOf(s, jc.c), stateOf(s, jc.d)}); break;
            }
        },
        [&](int first, int last) {
            auto range = [&](int b, int e) { warmStartWideRevolutes(s, first + b, first + e, kept); };
            w.runner.run(last - first, kWideGrain, range);
        });
    s.wideFrameAt = s.positionUpdates;
    clearZeroState(s);
}

void solveJoints(WorldState& w, const JointContext& pass) {
    SolverArrays& s = w.solver;
    const bool kept = s.wideFrameAt == s.positionUpdates;
    // A deep joint's rows are rigid and without push in the biased pass
    // (isDeepJoint); pushJoints closes its error on pseudo-velocities.
    JointContext rigid = pass;
    rigid.pass = SolvePass::no_push;
    holdTreeLimits(w, s.positionUpdates);
    sweepColours(
        s,
        [&](JointConstraint& jc) {
            const JointContext& ctx = jc.deep && pass.pass == SolvePass::soft_bias ? rigid : pass;
            BodyState& sA = stateOf(s, jc.a);
            BodyState& sB = stateOf(s, jc.b);
            switch (jc.type) {
                case JointType::distance: solveDistanceJoint(jc, ctx, sA, sB); break;
                case JointType::revolute: solveRevoluteJoint(jc, ctx, sA, sB); break;
                case JointType::prismatic: solvePrismaticJoint(jc, ctx, sA, sB); break;
                case JointType::weld: solveWeldJoint(jc, ctx, sA, sB); break;
                case JointType::wheel: solveWheelJoint(jc, ctx, sA, sB); break;
                case JointType::motor: solveMotorJoint(jc, ctx, sA, sB); break;
                case JointType::mouse: solveMouseJoint(jc, ctx, sA, sB); break;
                case JointType::pulley: solvePulleyJoint(jc, ctx, sA, sB); break;
                case JointType::gear: solveGearJoint(jc, ctx, {sA, sB, stateOf(s, jc.c), stateOf(s, jc.d)}); break;
            }
        },
        [&](int first, int last) {
            auto range = [&](int b, int e) { solveWideRevolutes(s, pass, first + b, first + e, kept); };
            w.runner.run(last - first, kWideGrain, range);
        });
    s.wideFrameAt = s.positionUpdates;
    clearZeroState(s);
    solveJointTrees(w, pass, s.positionUpdates);
    clearZeroState(s);
}

void pushJoints(WorldState& w, const JointContext& ctx, bool deepOnly) {
    SolverArrays& s = w.solver;
    // A pseudo-velocity state: the motion since the step began from the real
    // state, the velocity from the push arrays.
    auto pseudo = [&](int index) {
        BodyState p{};
        if (index < 0) return p;
        p = s.states[static_cast<std::size_t>(index)];
        p.v = s.biasV[static_cast<std::size_t>(index)];
        p.w = s.biasW[static_cast<std::size_t>(index)];
        return p;
    };
    auto writeBack = [&](int index, const BodyState& p) {
        if (index < 0) return;
        s.biasV[static_cast<std::size_t>(index)] = p.v;
        s.biasW[static_cast<std::size_t>(index)] = p.w;
    };
    JointContext push = ctx;
    push.pass = SolvePass::baumgarte;
    // Colour by colour, as the velocity sweeps (split mode has no wide blocks).
    sweepColours(
        s,
        [&](const JointConstraint& jc) {
            if (deepOnly && !jc.deep) return;
            BodyState pA = pseudo(jc.a), pB = pseudo(jc.b);
            if (jc.type == JointType::distance) {
                pushDistanceJoint(jc, ctx, stateOf(s, jc.a), stateOf(s, jc.b), pA, pB);
            } else {
                // The position error of the rigid rows alone, from zero: springs,
                // motors and drives are velocity effects and do not push.
                JointConstraint row = jc;
                row.impulses = JointImpulses{};
                row.inTree = false;  // the push sweeps every row,
                row.treeLimit = 0;   // limits too
                switch (jc.type) {
                    case JointType::revolute:
                        row.row.revolute.enableMotor = row.row.revolute.enableSpring = false;
                        solveRevoluteJoint(row, push, pA, pB);
                        break;
                    case JointType::prismatic:
                        row.row.prismatic.enableMotor = row.row.prismatic.enableSpring = false;
                        solvePrismaticJoint(row, push, pA, pB);
                        break;
                    case JointType::wheel:
                        row.row.wheel.enableMotor = row.row.wheel.enableSpring = false;
                        solveWheelJoint(row, push, pA, pB);
                        break;
                    case JointType::weld:
                        if (row.row.weld.linearHertz == 0.0f && row.row.weld.angularHertz == 0.0f)
                            solveWeldJoint(row, push, pA, pB);
                        break;
                    case JointType::pulley: solvePulleyJoint(row, push, pA, pB); break;
                    case JointType::gear: {
                        BodyState pC = pseudo(jc.c), pD = pseudo(jc.d);
                        solveGearJoint(row, push, {pA, pB, pC, pD});
                        writeBack(jc.c, pC);
                        writeBack(jc.d, pD);
                        break;
                    }
                    default: break;  // motor, mouse: drives, not constraints
                }
            }
            writeBack(jc.a, pA);
            writeBack(jc.b, pB);
        },
        [](int, int) {});
}

void storeJoints(WorldState& w, float h) {
    SolverArrays& s = w.solver;
    storeWideRevolutes(w, h);
    const float invDt = 1.0f / h;
    for (const JointConstraint& jc : s.joints) {
        Joint& joint = w.joints[jc.joint];
        const JointImpulses& acc = jc.impulses;
        joint.impulses = acc;
        const BodyState& sA = stateOf(s, jc.a);
        const BodyState& sB = stateOf(s, jc.b);
        Vec2 force{};
        float torque = 0.0f, effort = 0.0f;
        switch (jc.type) {
            case JointType::distance: {
                const Vec2 rA = rotate(sA.dq, jc.rA), rB = rotate(sB.dq, jc.rB);
                const Vec2 axis = normalize((sB.dp - sA.dp) + jc.deltaCenter + rB - rA);
                const float axial = acc.axial + acc.lower - acc.upper;
                force = (axial * invDt) * axis;
                joint.lastForce = std::abs(axial) * invDt;
                break;
            }
            case JointType::revolute:
                force = invDt * (acc.linear + revoluteLimitPointImpulse(jc, sA, sB));
                torque = (acc.spring + acc.motor + acc.lower - acc.upper) * invDt;
                effort = acc.motor * invDt;
                break;
            case JointType::prismatic: {
                const SliderFrame f = sliderFrame(jc, jc.row.prismatic.axisA, sA, sB);
                force = invDt * ((acc.spring + acc.motor + acc.lower - acc.upper) * f.axis + acc.axial * f.perp);
                torque = acc.angular * invDt;
                effort = acc.motor * invDt;
                break;
            }
            case JointType::wheel: {
                const SliderFrame f = sliderFrame(jc, jc.row.wheel.axisA, sA, sB);
                force = invDt * ((acc.spring + acc.lower - acc.upper) * f.axis + acc.axial * f.perp);
                torque = acc.motor * invDt;
                effort = acc.motor * invDt;
                break;
            }
            case JointType::weld:
            case JointType::motor:
                force = invDt * acc.linear;
                torque = acc.angular * invDt;
                break;
            case JointType::mouse: force = invDt * acc.linear; break;
            case JointType::pulley: {
                const Vec2 rB = rotate(sB.dq, jc.rB);
                const Vec2 uB = normalize(sB.dp + rB - jc.row.pulley.groundFromCenterB);
                force = (jc.row.pulley.ratio * acc.axial * invDt) * uB;
                break;
            }
            case JointType::gear: {
                GearStates gs{const_cast<BodyState&>(sA), const_cast<BodyState&>(sB), stateOf(s, jc.c),
                              stateOf(s, jc.d)};
                joint.gearError = gearCoordinateError(jc, gs);
                torque = jc.row.gear.ratio * acc.axial * invDt;
                break;
            }
        }
        joint.reactionForce = force;
        joint.reactionTorque = torque;
        joint.motorEffort = effort;
        if (jc.type != JointType::distance) joint.lastForce = length(force);
    }
}

}  // namespace i2d::detail
