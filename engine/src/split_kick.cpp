// Forces split around the drift (split_kick.hpp says why and where).
#include "split_kick.hpp"

#include <algorithm>
#include <cmath>
#include <variant>
#include <vector>

#include "integration.hpp"
#include "joint.hpp"
#include "union_find.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// A velocity moved by `by` (±h/2) of the accelerations a and α, from one
/// meaning to the other (recordChoice), within the speed limits the
/// integration keeps (maxSpeed, and maxSpin the angular one of a substep).
/// A body of 10⁻³² kg·m² under a torque had its spin so moved to −2·10³⁰
/// rad/s before the impact stage, which turned it by 6·10²⁸ rad and left its
/// rotation zero, then NaN (fuzz_world). Where the move is not finite the
/// velocity is kept as it is.
void moveMeaning(Vec2& v, float& w, float by, Vec2 a, float alpha, float maxSpeed, float maxSpin) {
    const Vec2 moved = v + by * a;
    const float spun = w + by * alpha;
    if (std::isfinite(moved.x) && std::isfinite(moved.y)) v = limitSpeed(moved, maxSpeed);
    if (std::isfinite(spun)) w = std::clamp(spun, -maxSpin, maxSpin);
}

/// State i's choice this step (split or not) against its last: when it
/// changed, the body's velocity is moved from one meaning to the other by
/// half a substep of its gravity. Semi-implicit Euler keeps, in uniform
/// gravity, E + (h/2)·m·(g·v) (docs/validation.md, energy audit), the split
/// keeps E: moved so, a body's energy is the same quantity on both sides of
/// the switch. Taken as it was instead, a bob whose joint swung it past a
/// floor within the speculative margin gained (h/2)·m·g·|v_y| at each entry
/// and exit, 166 % of its swing in 20 s at one substep. Only gravity, which
/// acts for good: moved by a force the game applies for a few steps (a
/// jump), the move outlives the force as momentum no force gave (a box
/// pushed off the ground at 60·g for two steps rose 56 % too high at one
/// substep). The joints' pull is left out too; the joint rows take that part
/// back along the directions they hold. What is left is semi-implicit
/// Euler's own error, which it keeps in the position ((h/2)·(v − v₀) over
/// an episode, its velocity exact under forces constant over each step): a
/// box pushed up from rest at 3·g for ten steps rises 3 % short of its exact
/// apex at one substep and 0.6 % at four (semi-implicit Euler throughout:
/// exact, the position's error vanishing at the apex; not moved when it
/// leaves the ground: 1.3 % and 0.4 % too high). A body's first choice
/// takes its velocity as it is; the other modes never split and take a
/// velocity as they find it, as they always have.
void recordChoice(WorldState& w, std::size_t i, bool split, float h, bool soft) {
    SolverArrays& s = w.solver;
    const BodyIntegration& in = s.integration[i];
    if (in.splitBefore == static_cast<std::uint8_t>(split)) return;
    Body& body = w.bodies[s.stateBodies[i]];
    body.splitKick = split;
    body.splitChosen = true;
    if (in.splitBefore == kSplitNotChosen || !soft || !in.movedByForces) return;
    BodyState& st = s.states[i];
    moveMeaning(st.v, st.w, split ? 0.5f * h : -0.5f * h, body.gravityScale * w.settings.gravity, 0.0f,
                w.settings.maxLinearSpeed, kMaxRotationPerStep / h);
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

void makeVelocityLag(Body& b, Vec2 gravity, float halfSubstep, float maxSpeed, float maxSpin) {
    const bool split = b.splitKick;
    b.splitKick = false;
    b.splitChosen = true;
    if (!split || b.type != BodyType::dynamic_body) return;
    moveMeaning(b.v, b.w, -halfSubstep, b.gravityScale * gravity + b.invMass * b.force, b.invInertia * b.torque,
                maxSpeed, maxSpin);
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
    std::vector<int>& group = s.splitKickGroup;
    std::vector<std::uint8_t>& drives = s.splitKickDrives;
    if (s.jointSlots.empty()) {  // (a world without joints plans every step, and keeps nothing here)
        std::vector<int>().swap(group);
        std::vector<std::uint8_t>().swap(drives);
        return;
    }
    const int n = static_cast<int>(s.stateBodies.size());
    group.assign(static_cast<std::size_t>(n), -1);
    drives.assign(static_cast<std::size_t>(n), 0);
    auto moving = [&](int i) { return i >= 0 && i < n && s.integration[static_cast<std::size_t>(i)].movedByForces; };
    auto find = [&](int i) { return unionFindRoot(group, i); };
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
    // A state's group root, −1 without one (no joint of the plan's: the
    // plan has no slot when every jointed body is asleep or disabled).
    const bool grouped = s.splitKickGroup.size() == n;
    auto groupOf = [&](std::size_t i) { return grouped ? s.splitKickGroup[i] : -1; };
    // A group is held (not split) when one of its bodies has a contact row
    // or a joint that does more than hold (groupJointedStates).
    std::vector<std::uint8_t>& held = s.splitKickHeld;
    held = s.splitKickDrives;
    auto hasRow = [&](std::size_t i) { return s.contactColourMasks[static_cast<std::size_t>(s.stateBodies[i])] != 0; };
    for (std::size_t i = 0; i < n; ++i)
        if (groupOf(i) >= 0 && hasRow(i)) held[static_cast<std::size_t>(groupOf(i))] = 1;
    for (std::size_t i = 0; i < n; ++i) {
        const BodyIntegration& in = s.integration[i];
        if (!in.jointed) continue;
        const int root = groupOf(i);
        const bool split = soft && in.movedByForces && (root >= 0 ? !held[static_cast<std::size_t>(root)] : !hasRow(i));
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
