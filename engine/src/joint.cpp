// Joints: linking a joint to its bodies and unlinking it (what every joint
// type shares; the rows are in joint_solver.cpp and one file per type).
#include <algorithm>
#include <cmath>

#include "joint.hpp"
#include "lost_load.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// Appends joint j to the list of its body on `side` (Body::firstJoint).
void attachToBody(WorldState& w, int j, int side) {
    Joint& jt = w.joints[j];
    const int b = side == 0 ? jt.bodyA : jt.bodyB;
    Body& body = w.bodies[b];
    jt.prevJoint[side] = body.lastJoint;
    jt.nextJoint[side] = kNullIndex;
    if (body.lastJoint != kNullIndex) {
        Joint& last = w.joints[body.lastJoint];
        last.nextJoint[jointSide(last, b)] = j;
    } else {
        body.firstJoint = j;
    }
    body.lastJoint = j;
    ++body.jointCount;
}

/// Takes joint j out of the list of its body on `side`.
void detachFromBody(WorldState& w, int j, int side) {
    Joint& jt = w.joints[j];
    const int b = side == 0 ? jt.bodyA : jt.bodyB;
    Body& body = w.bodies[b];
    const int prev = jt.prevJoint[side], next = jt.nextJoint[side];
    if (prev != kNullIndex) {
        Joint& p = w.joints[prev];
        p.nextJoint[jointSide(p, b)] = next;
    } else {
        body.firstJoint = next;
    }
    if (next != kNullIndex) {
        Joint& n = w.joints[next];
        n.prevJoint[jointSide(n, b)] = prev;
    } else {
        body.lastJoint = prev;
    }
    jt.prevJoint[side] = jt.nextJoint[side] = kNullIndex;
    --body.jointCount;
}

}  // namespace

void linkJoint(WorldState& w, int j) {
    w.solver.jointPlanStale = true;
    Joint& jt = w.joints[j];
    const int a = jt.bodyA, b = jt.bodyB;
    attachToBody(w, j, 0);
    attachToBody(w, j, 1);
    // Joined bodies that may not collide lose their contacts at once.
    if (!jt.collideConnected) {
        const std::vector<int> list = w.bodies[a].contacts;
        for (int c : list) {
            const Contact& ct = w.contacts[c];
            if ((ct.bodyA == a && ct.bodyB == b) || (ct.bodyA == b && ct.bodyB == a)) destroyContact(w, c, true);
        }
    }
    wakeBody(w, a);
    wakeBody(w, b);
    judgeStretch(w, j);
}

void destroyJoint(WorldState& w, int j) {
    // Gear joints built on this joint go first: they cannot stand without it.
    for (int g = 0; g < w.joints.capacity(); ++g) {
        const Joint& gear = w.joints[g];
        if (gear.alive && gear.type == JointType::gear && (gear.joint1 == j || gear.joint2 == j)) destroyJoint(w, g);
    }
    w.solver.jointPlanStale = true;
    Joint& jt = w.joints[j];
    // The load it carried goes with it (lost_load.hpp).
    std::vector<LostLoad> lost;
    addJointLoss(w, jt, lost);
    detachFromBody(w, j, 0);
    detachFromBody(w, j, 1);
    for (int b : {jt.bodyA, jt.bodyB}) {
        wakeBody(w, b);
        // The bodies may collide again: let the broadphase look.
        for (int s : bodyShapes(w.shapes, w.bodies[b])) {
            Shape& sh = w.shapes[s];
            if (sh.proxy != DynamicTree::kNull) w.broadPhase.markMoved(sh, s);
        }
    }
    w.joints.release(j);
    releaseLostLoads(w, lost);
}

}  // namespace i2d::detail

namespace i2d::detail {

bool holdsPoint(const Joint& joint) {
    if (joint.type == JointType::revolute) return true;
    if (joint.type != JointType::weld) return false;
    const WeldJointDef& def = std::get<WeldJointDef>(joint.def);
    return def.linearHertz == 0.0f && def.angularHertz == 0.0f;
}

float jointAngleNow(const WorldState& w, const Joint& joint, float reference) {
    return unwindAngle(angleOf(invMulRot(w.bodies[joint.bodyA].xf.q, w.bodies[joint.bodyB].xf.q)) - reference);
}

JointStretch jointStretch(const WorldState& w, const Joint& joint) {
    const JointAnchors anchors = jointAnchors(w, joint);
    const Vec2 d = anchors.b - anchors.a;
    auto turn = [&](float reference) { return jointAngleNow(w, joint, reference); };
    // How far B's anchor is off the axis fixed in A.
    const Rot qA = w.bodies[joint.bodyA].xf.q;
    auto offAxis = [&](Vec2 localAxis) { return std::fabs(cross(rotate(qA, normalize(localAxis)), d)); };
    switch (joint.type) {
        case JointType::revolute: return {length(d), 0.0f};
        case JointType::weld: {
            if (!holdsPoint(joint)) return {};
            return {length(d), turn(std::get<WeldJointDef>(joint.def).referenceAngle)};
        }
        case JointType::prismatic: {
            const PrismaticJointDef& def = std::get<PrismaticJointDef>(joint.def);
            return {offAxis(def.localAxisA), turn(def.referenceAngle)};
        }
        case JointType::wheel: return {offAxis(std::get<WheelJointDef>(joint.def).localAxisA), 0.0f};
        case JointType::distance: {
            const DistanceJointDef& def = std::get<DistanceJointDef>(joint.def);
            if (!isRigidDistance(def)) return {};  // a spring: its stretch is physical
            return {std::fabs(length(d) - def.length), 0.0f};
        }
        default: return {};  // drives and couplings: no error the push closes
    }
}

void judgeStretch(WorldState& w, int j) {
    Joint& joint = w.joints[j];
    if (joint.stretched || w.settings.positionCorrection != PositionCorrection::soft_step) return;
    if (!isStretched(false, jointStretch(w, joint))) return;
    joint.stretched = true;
    w.solver.jointPlanStale = true;
}

JointAnchors jointAnchors(const WorldState& w, const Joint& joint) {
    const Transform& xfA = w.bodies[joint.bodyA].xf;
    const Transform& xfB = w.bodies[joint.bodyB].xf;
    return std::visit(
        [&](const auto& def) -> JointAnchors {
            using Def = std::decay_t<decltype(def)>;
            if constexpr (std::is_same_v<Def, MotorJointDef>) {
                return {transformPoint(xfA, def.linearOffset), xfB.p};
            } else if constexpr (std::is_same_v<Def, MouseJointDef>) {
                return {def.target, transformPoint(xfB, joint.localAnchorB)};
            } else if constexpr (std::is_same_v<Def, GearJointDef>) {
                return {xfA.p, xfB.p};
            } else {
                return {transformPoint(xfA, def.localAnchorA), transformPoint(xfB, def.localAnchorB)};
            }
        },
        joint.def);
}

}  // namespace i2d::detail
