// The joint rows of a step: preparation of every joint with an awake body
// (common part here, each type's part in its own file), colouring, and the
// dispatch of the warm start, the solver passes, split mode's push and the
// store to each type.
//
// Order: the rows are greedily coloured by their movable bodies, as the
// contact rows are (solver.cpp), and solved colour by colour, so a chain or
// grid built in one direction is not swept in that direction.
#include <algorithm>
#include <cmath>

#include "distance_joint.hpp"
#include "joint_solver.hpp"
#include "joint_tree.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

constexpr int kJointColours = 16;  ///< colours tried before the overflow group

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

void colourJoints(SolverArrays& s) {
    std::vector<JointConstraint>& rows = s.joints;
    const std::size_t bodyCount = s.stateBodies.size();
    const std::size_t words = (bodyCount + 63) / 64;
    s.colourBits.assign(words * kJointColours, 0u);
    std::vector<std::uint8_t>& colours = s.jointColours;
    colours.resize(rows.size());
    int counts[kJointColours + 1] = {};
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const JointConstraint& jc = rows[i];
        struct Side {
            int index;
            bool moves;
        } sides[4] = {{jc.a, jc.invMassA != 0.0f || jc.invIA != 0.0f},
                      {jc.b, jc.invMassB != 0.0f || jc.invIB != 0.0f},
                      {jc.c, jc.invMassC != 0.0f || jc.invIC != 0.0f},
                      {jc.d, jc.invMassD != 0.0f || jc.invID != 0.0f}};
        int colour = kJointColours;
        for (int c = 0; c < kJointColours && colour == kJointColours; ++c) {
            std::uint64_t* bits = s.colourBits.data() + static_cast<std::size_t>(c) * words;
            bool free = true;
            for (const Side& side : sides)
                if (side.moves && side.index >= 0 &&
                    (bits[static_cast<std::size_t>(side.index) / 64] >> (side.index % 64) & 1u))
                    free = false;
            if (!free) continue;
            for (const Side& side : sides)
                if (side.moves && side.index >= 0)
                    bits[static_cast<std::size_t>(side.index) / 64] |= std::uint64_t{1} << (side.index % 64);
            colour = c;
        }
        colours[i] = static_cast<std::uint8_t>(colour);
        ++counts[colour];
    }
    // Stable counting sort by colour.
    int offset = 0;
    for (int& n : counts) {
        const int c = n;
        n = offset;
        offset += c;
    }
    s.jointScratch.resize(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        s.jointScratch[static_cast<std::size_t>(counts[colours[i]]++)] = rows[i];
    rows.swap(s.jointScratch);
}

void fillBody(const WorldState& w, int body, int& index, float& invMass, float& invI) {
    const Body& b = w.bodies[body];
    // Awake bodies have a solver state; a static or sleeping body does not move.
    index = b.awake ? b.solverIndex : kNullIndex;
    invMass = index >= 0 ? b.invMass : 0.0f;
    invI = index >= 0 ? b.invInertia : 0.0f;
}

}  // namespace

void prepareJoints(WorldState& w, float dt) {
    SolverArrays& s = w.solver;
    std::vector<JointConstraint>& rows = s.joints;
    rows.clear();
    rows.reserve(static_cast<std::size_t>(w.joints.count));  // one allocation (the array may have been freed)
    const bool warm = w.settings.enableWarmStarting;
    for (int j = 0; j < w.joints.capacity(); ++j) {
        const Joint& joint = w.joints[j];
        if (!joint.alive) continue;
        const Body& bA = w.bodies[joint.bodyA];
        const Body& bB = w.bodies[joint.bodyB];
        if (!bA.awake && !bB.awake) continue;
        if (!bA.enabled || !bB.enabled) continue;  // a joint on a disabled body acts on nothing
        JointConstraint& jc = rows.emplace_back();
        jc.joint = j;
        jc.type = joint.type;
        fillBody(w, joint.bodyA, jc.a, jc.invMassA, jc.invIA);
        fillBody(w, joint.bodyB, jc.b, jc.invMassB, jc.invIB);
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
        // (the anchors turn, their lengths stay); its products stay in single
        // precision below 1e18 each.
        const double bound = double(jc.invMassA) + jc.invMassB + double(jc.invIA) * lengthSquared(jc.rA) +
                             double(jc.invIB) * lengthSquared(jc.rB);
        jc.singlePrecision = bound < 1.0e18;
    }
    colourJoints(s);
    buildJointTrees(w);
}

void warmStartJoints(WorldState& w) {
    SolverArrays& s = w.solver;
    for (JointConstraint& jc : s.joints) {
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
    }
    clearZeroState(s);
}

void solveJoints(WorldState& w, const JointContext& ctx) {
    SolverArrays& s = w.solver;
    for (JointConstraint& jc : s.joints) {
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
    }
    clearZeroState(s);
    solveJointTrees(w, ctx, ctx.positionUpdates);
    clearZeroState(s);
}

void pushJoints(WorldState& w, const JointContext& ctx) {
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
    for (const JointConstraint& jc : s.joints) {
        BodyState pA = pseudo(jc.a), pB = pseudo(jc.b);
        if (jc.type == JointType::distance) {
            pushDistanceJoint(jc, ctx, stateOf(s, jc.a), stateOf(s, jc.b), pA, pB);
        } else {
            // The position error of the rigid rows alone, from zero: springs,
            // motors and drives are velocity effects and do not push.
            JointConstraint row = jc;
            row.impulses = JointImpulses{};
            row.inTree = false;  // the push sweeps every row
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
    }
}

void storeJoints(WorldState& w, float h) {
    SolverArrays& s = w.solver;
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
                force = invDt * acc.linear;
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
