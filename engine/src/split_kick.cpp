// Forces split around the drift (split_kick.hpp says why and where).
#include "split_kick.hpp"

#include <cmath>
#include <variant>
#include <vector>

#include "integration.hpp"
#include "joint.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// State i's choice this step (split or not) against its last: when it
/// changed, the body's velocity is moved from one meaning to the other (the
/// true one leads the lagging one by half a substep of its free
/// acceleration, exact for a free body; for a jointed one the joints' pull
/// is left out, which the joint rows take back along the directions they
/// hold, and taken as it was, a bob whose joint swung it past a floor
/// within the speculative margin gained m·g·h·|v_y| at each entry and exit,
/// 166 % of its swing in 20 s). A body's first choice takes its velocity as
/// it is; the other modes never split and take a velocity as they find it,
/// as they always have.
void recordChoice(WorldState& w, std::size_t i, bool split, float h, bool soft) {
    SolverArrays& s = w.solver;
    const BodyIntegration& in = s.integration[i];
    if (in.splitBefore == static_cast<std::uint8_t>(split)) return;
    Body& body = w.bodies[s.stateBodies[i]];
    body.splitKick = split;
    body.splitChosen = true;
    if (in.splitBefore == kSplitNotChosen || !soft || !in.movedByForces) return;
    BodyState& st = s.states[i];
    const float toward = split ? 0.5f * h : -0.5f * h;
    st.v = st.v + toward * in.linearAcceleration;
    st.w += toward * in.invInertia * in.torque;
}

/// State i split this step: its acceleration and damping for half kicks.
void halveKick(WorldState& w, int i, float h) {
    SolverArrays& s = w.solver;
    BodyIntegration& in = s.integration[static_cast<std::size_t>(i)];
    in.linearAcceleration = 0.5f * in.linearAcceleration;
    in.torque *= 0.5f;
    if (in.linearDampingFactor != 1.0f || in.angularDampingFactor != 1.0f) {
        const Body& body = w.bodies[s.stateBodies[static_cast<std::size_t>(i)]];
        in.linearDampingFactor = 1.0f / (1.0f + 0.5f * h * body.linearDamping);
        in.angularDampingFactor = 1.0f / (1.0f + 0.5f * h * body.angularDamping);
    }
    in.split = true;
    ++s.splitKickCount;
}

}  // namespace

bool jointOnlyHolds(const Joint& j) {
    struct Visit {
        bool operator()(const DistanceJointDef& d) const { return isRigidDistance(d); }
        bool operator()(const RevoluteJointDef& d) const { return !d.enableMotor && !d.enableSpring; }
        bool operator()(const PrismaticJointDef& d) const { return !d.enableMotor && !d.enableSpring; }
        bool operator()(const WheelJointDef& d) const { return !d.enableMotor && !d.enableSpring; }
        bool operator()(const WeldJointDef& d) const { return d.linearHertz == 0.0f && d.angularHertz == 0.0f; }
        bool operator()(const MotorJointDef&) const { return false; }
        bool operator()(const MouseJointDef&) const { return false; }
        bool operator()(const PulleyJointDef&) const { return true; }
        bool operator()(const GearJointDef&) const { return true; }
    };
    return std::visit(Visit{}, j.def);
}

void makeVelocityLag(Body& b, Vec2 gravity, float halfSubstep) {
    const bool split = b.splitKick;
    b.splitKick = false;
    b.splitChosen = true;
    if (!split || b.type != BodyType::dynamic_body) return;
    b.v = b.v - halfSubstep * (b.gravityScale * gravity + b.invMass * b.force);
    b.w -= halfSubstep * b.invInertia * b.torque;
}

void splitFreeBodies(WorldState& w, float h, bool soft) {
    SolverArrays& s = w.solver;
    s.splitKickCount = 0;
    s.movingStates = 0;
    const std::size_t n = s.stateBodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        const BodyIntegration& in = s.integration[i];
        s.movingStates += in.movedByForces ? 1 : 0;
        if (in.jointed) continue;  // (splitJointedBodies)
        // A contact row: any colour bit or the overflow bit.
        const bool split = soft && in.movedByForces &&
                           s.contactColourMasks[static_cast<std::size_t>(s.stateBodies[i])] == 0;
        recordChoice(w, i, split, h, soft);
        if (split) halveKick(w, static_cast<int>(i), h);
    }
}

void groupJointedStates(SolverArrays& s) {
    const int n = static_cast<int>(s.stateBodies.size());
    std::vector<int>& group = s.splitKickGroup;
    std::vector<std::uint8_t>& drives = s.splitKickDrives;
    group.assign(static_cast<std::size_t>(n), -1);
    drives.assign(static_cast<std::size_t>(n), 0);
    auto moving = [&](int i) { return i >= 0 && i < n && s.integration[static_cast<std::size_t>(i)].movedByForces; };
    auto find = [&](int i) {
        while (group[static_cast<std::size_t>(i)] != i) {
            int& p = group[static_cast<std::size_t>(i)];
            p = group[static_cast<std::size_t>(p)];
            i = p;
        }
        return i;
    };
    for (const JointSlot& slot : s.jointSlots) {
        const int sides[4] = {slot.a, slot.b, slot.c, slot.d};
        for (int side : sides) {
            if (!moving(side)) continue;
            if (group[static_cast<std::size_t>(side)] < 0) group[static_cast<std::size_t>(side)] = side;
            if (!slot.onlyHolds) drives[static_cast<std::size_t>(side)] = 1;
        }
        for (int k = 1; k < 4; ++k) {
            if (!moving(sides[0]) || !moving(sides[k])) continue;
            const int ra = find(sides[0]), rb = find(sides[k]);
            if (ra != rb) group[static_cast<std::size_t>(ra)] = rb;
        }
    }
    // Every member names its root, and the root holds the group's flag.
    for (int i = 0; i < n; ++i)
        if (group[static_cast<std::size_t>(i)] >= 0) {
            const int root = find(i);
            if (drives[static_cast<std::size_t>(i)]) drives[static_cast<std::size_t>(root)] = 1;
        }
    for (int i = 0; i < n; ++i)
        if (group[static_cast<std::size_t>(i)] >= 0) group[static_cast<std::size_t>(i)] = find(i);
}

void splitJointedBodies(WorldState& w, float h, bool soft) {
    if (w.joints.count == 0) return;
    SolverArrays& s = w.solver;
    const std::size_t n = s.stateBodies.size();
    const std::vector<int>& group = s.splitKickGroup;
    // A group is held (not split) when one of its bodies has a contact row
    // or a joint that does more than hold (groupJointedStates).
    std::vector<std::uint8_t>& held = s.splitKickHeld;
    held = s.splitKickDrives;
    auto hasRow = [&](std::size_t i) { return s.contactColourMasks[static_cast<std::size_t>(s.stateBodies[i])] != 0; };
    for (std::size_t i = 0; i < n; ++i)
        if (group[i] >= 0 && hasRow(i)) held[static_cast<std::size_t>(group[i])] = 1;
    for (std::size_t i = 0; i < n; ++i) {
        const BodyIntegration& in = s.integration[i];
        if (!in.jointed) continue;
        const bool split = soft && in.movedByForces &&
                           (group[i] >= 0 ? !held[static_cast<std::size_t>(group[i])] : !hasRow(i));
        recordChoice(w, i, split, h, soft);
        if (split) halveKick(w, static_cast<int>(i), h);
    }
}

void kickAfterDrift(SolverArrays& s, float h, float maxSpeed) {
    const std::size_t n = s.stateBodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        const BodyIntegration& in = s.integration[i];
        if (!in.split) continue;
        // The first half's arithmetic (integrateVelocities); a velocity that
        // is not finite is left for stopNonFiniteBodies.
        kickVelocity(s.states[i], in, h, maxSpeed);
    }
}

}  // namespace i2d::detail
