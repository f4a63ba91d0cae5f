// World: the public API facade for a joint's definition (read and change),
// the features games switch while running, the joint's state from the
// bodies' poses, and what it did over the last step.
#include <cmath>

#include "impulse2d/world.hpp"
#include "joint.hpp"
#include "joint_rows.hpp"
#include "joint_validation.hpp"
#include "world_state.hpp"

namespace i2d {

using detail::fail;

namespace {

const char* typeName(JointType t) {
    switch (t) {
        case JointType::distance: return "distance";
        case JointType::revolute: return "revolute";
        case JointType::prismatic: return "prismatic";
        case JointType::weld: return "weld";
        case JointType::wheel: return "wheel";
        case JointType::motor: return "motor";
        case JointType::mouse: return "mouse";
        case JointType::pulley: return "pulley";
        case JointType::gear: return "gear";
    }
    return "unknown";
}

template <class Def>
const Def& defOf(const detail::Joint& jt) {
    const Def* def = std::get_if<Def>(&jt.def);
    if (!def) fail(std::string("the joint is a ") + typeName(jt.type) + " joint");
    return *def;
}

/// Wakes both bodies of a joint that was changed, and has the next step plan
/// the joints again (SolverArrays::jointPlanStale) unless the change is to a
/// value the rows read from the definition every step (`replan` false: a
/// motor's speed, a mouse joint's target), which no plan depends on.
void wakeJoint(detail::WorldState& w, const detail::Joint& jt, bool replan = true) {
    if (replan) w.solver.jointPlanStale = true;
    detail::wakeBody(w, jt.bodyA);
    detail::wakeBody(w, jt.bodyB);
}

/// Applies a changed collideConnected: drop the contacts between the bodies
/// (now false) or let the broadphase find them again (now true).
void applyCollideConnected(detail::WorldState& w, detail::Joint& jt, bool collide) {
    if (jt.collideConnected == collide) return;
    jt.collideConnected = collide;
    if (!collide) {
        const std::vector<int> list = w.bodies[jt.bodyA].contacts;
        for (int c : list) {
            const detail::Contact& ct = w.contacts[c];
            if ((ct.bodyA == jt.bodyA && ct.bodyB == jt.bodyB) || (ct.bodyA == jt.bodyB && ct.bodyB == jt.bodyA))
                detail::destroyContact(w, c, true);
        }
    } else {
        for (int b : {jt.bodyA, jt.bodyB})
            for (int s : detail::bodyShapes(w.shapes, w.bodies[b])) {
                detail::Shape& sh = w.shapes[s];
                if (sh.proxy != detail::DynamicTree::kNull) w.broadPhase.markMoved(sh, s);
            }
    }
}

/// set…JointDef: the same bodies, a valid definition; features turned off lose
/// their impulse. A mouse joint keeps the point of body B it grabbed.
template <class Def>
void setDef(detail::WorldState& w, JointId id, const Def& def) {
    w.checkUnlocked();
    detail::Joint& jt = w.joints[w.jointIndex(id)];
    defOf<Def>(jt);
    if constexpr (std::is_same_v<Def, GearJointDef>) {
        if (w.jointIndex(def.joint1) != jt.joint1 || w.jointIndex(def.joint2) != jt.joint2)
            fail("a gear joint's joints cannot change (destroy it and create another)");
    } else {
        if (w.bodyIndex(def.bodyA) != jt.bodyA || w.bodyIndex(def.bodyB) != jt.bodyB)
            fail("a joint's bodies cannot change (destroy it and create another)");
    }
    detail::validateJointDef(def);
    jt.def = def;
    jt.userData = def.userData;
    if constexpr (requires { def.enableMotor; })
        if (!def.enableMotor) jt.impulses.motor = 0.0f;
    if constexpr (requires { def.enableSpring; })
        if (!def.enableSpring) jt.impulses.spring = 0.0f;
    if constexpr (requires { def.enableLimit; })
        if (!def.enableLimit) jt.impulses.lower = jt.impulses.upper = 0.0f;
    applyCollideConnected(w, jt, def.collideConnected);
    wakeJoint(w, jt);
    detail::judgeStretch(w, w.jointIndex(id));  // new anchors, axis or length may leave the joint open
}

/// Changes one field of the joint's definition through `edit`, which returns
/// false when the joint's type has no such feature. `replan` as wakeJoint's.
template <class Edit>
void editDef(detail::WorldState& w, JointId id, const char* feature, Edit edit, bool replan = true) {
    w.checkUnlocked();
    detail::Joint& jt = w.joints[w.jointIndex(id)];
    const bool done = std::visit(edit, jt.def);
    if (!done) fail(std::string("a ") + typeName(jt.type) + " joint has no " + feature);
    wakeJoint(w, jt, replan);
}

Vec2 anchorOf(const detail::WorldState& w, int body, Vec2 local) { return transformPoint(w.bodies[body].xf, local); }

}  // namespace

// ---- Definitions ------------------------------------------------------------

#define I2D_JOINT_DEF_ACCESSORS(Def, getter, setter)                                                                   \
    Def World::getter(JointId id) const { return defOf<Def>(state().joints[state().jointIndex(id)]); }                 \
    void World::setter(JointId id, const Def& def) { setDef(state(), id, def); }

I2D_JOINT_DEF_ACCESSORS(DistanceJointDef, distanceJointDef, setDistanceJointDef)
I2D_JOINT_DEF_ACCESSORS(RevoluteJointDef, revoluteJointDef, setRevoluteJointDef)
I2D_JOINT_DEF_ACCESSORS(PrismaticJointDef, prismaticJointDef, setPrismaticJointDef)
I2D_JOINT_DEF_ACCESSORS(WeldJointDef, weldJointDef, setWeldJointDef)
I2D_JOINT_DEF_ACCESSORS(WheelJointDef, wheelJointDef, setWheelJointDef)
I2D_JOINT_DEF_ACCESSORS(MotorJointDef, motorJointDef, setMotorJointDef)
I2D_JOINT_DEF_ACCESSORS(MouseJointDef, mouseJointDef, setMouseJointDef)
I2D_JOINT_DEF_ACCESSORS(PulleyJointDef, pulleyJointDef, setPulleyJointDef)
I2D_JOINT_DEF_ACCESSORS(GearJointDef, gearJointDef, setGearJointDef)

#undef I2D_JOINT_DEF_ACCESSORS

// ---- Features ---------------------------------------------------------------

void World::enableJointLimit(JointId id, bool flag) {
    editDef(state(), id, "limit", [&](auto& def) {
        if constexpr (requires { def.enableLimit; }) {
            def.enableLimit = flag;
            return true;
        }
        return false;
    });
    if (!flag) {
        auto& acc = state().joints[state().jointIndex(id)].impulses;
        acc.lower = acc.upper = 0.0f;
    }
}

void World::enableJointMotor(JointId id, bool flag) {
    editDef(state(), id, "motor", [&](auto& def) {
        if constexpr (requires { def.enableMotor; }) {
            def.enableMotor = flag;
            return true;
        }
        return false;
    });
    if (!flag) state().joints[state().jointIndex(id)].impulses.motor = 0.0f;
}

void World::enableJointSpring(JointId id, bool flag) {
    editDef(state(), id, "spring", [&](auto& def) {
        if constexpr (requires { def.enableSpring; }) {
            def.enableSpring = flag;
            return true;
        }
        return false;
    });
    if (!flag) state().joints[state().jointIndex(id)].impulses.spring = 0.0f;
}

void World::setJointMotorSpeed(JointId id, float speed) {
    detail::requireBounded(speed, "joint motorSpeed");
    editDef(
        state(), id, "motor",
        [&](auto& def) {
            if constexpr (requires { def.motorSpeed; }) {
                def.motorSpeed = speed;
                return true;
            }
            return false;
        },
        false);  // a game sets this every frame: the plan stays
}

void World::setMouseJointTarget(JointId id, Vec2 target) {
    detail::requireBounded(target, "joint target");
    editDef(
        state(), id, "target",
        [&](auto& def) {
            if constexpr (std::is_same_v<std::decay_t<decltype(def)>, MouseJointDef>) {
                def.target = target;
                return true;
            }
            return false;
        },
        false);  // a game sets this every frame: the plan stays
}

void World::setDistanceJointLength(JointId id, float length) {
    auto& w = state();
    w.checkUnlocked();
    const int j = w.jointIndex(id);
    detail::requireBounded(length, "joint length");
    if (!(length > 0.0f)) fail("joint length must be > 0");
    detail::Joint& jt = w.joints[j];
    DistanceJointDef def = defOf<DistanceJointDef>(jt);
    def.length = length;
    jt.def = def;
    jt.impulses.axial = 0.0f;
    wakeJoint(w, jt);
}

// ---- State ------------------------------------------------------------------

float World::distanceJointCurrentLength(JointId id) const {
    const auto& w = state();
    const detail::Joint& jt = w.joints[w.jointIndex(id)];
    const DistanceJointDef& def = defOf<DistanceJointDef>(jt);
    return distance(anchorOf(w, jt.bodyA, def.localAnchorA), anchorOf(w, jt.bodyB, def.localAnchorB));
}

float World::revoluteJointAngle(JointId id) const {
    const auto& w = state();
    const detail::Joint& jt = w.joints[w.jointIndex(id)];
    return detail::jointAngleNow(w, jt, defOf<RevoluteJointDef>(jt).referenceAngle);
}

float World::revoluteJointSpeed(JointId id) const {
    const auto& w = state();
    const detail::Joint& jt = w.joints[w.jointIndex(id)];
    defOf<RevoluteJointDef>(jt);
    return w.bodies[jt.bodyB].w - w.bodies[jt.bodyA].w;
}

namespace {
struct AxisNow {
    Vec2 axis, d, pA, pB;
};
AxisNow axisNow(const detail::WorldState& w, const detail::Joint& jt) {
    Vec2 localAxis, anchorA, anchorB;
    if (const auto* p = std::get_if<PrismaticJointDef>(&jt.def)) {
        localAxis = p->localAxisA, anchorA = p->localAnchorA, anchorB = p->localAnchorB;
    } else if (const auto* wh = std::get_if<WheelJointDef>(&jt.def)) {
        localAxis = wh->localAxisA, anchorA = wh->localAnchorA, anchorB = wh->localAnchorB;
    } else {
        fail(std::string("a ") + typeName(jt.type) + " joint has no translation");
    }
    AxisNow a;
    a.axis = rotate(w.bodies[jt.bodyA].xf.q, normalize(localAxis));
    a.pA = anchorOf(w, jt.bodyA, anchorA);
    a.pB = anchorOf(w, jt.bodyB, anchorB);
    a.d = a.pB - a.pA;
    return a;
}
}  // namespace

float World::jointTranslation(JointId id) const {
    const auto& w = state();
    const AxisNow a = axisNow(w, w.joints[w.jointIndex(id)]);
    return dot(a.axis, a.d);
}

float World::jointTranslationSpeed(JointId id) const {
    const auto& w = state();
    const detail::Joint& jt = w.joints[w.jointIndex(id)];
    const AxisNow a = axisNow(w, jt);
    const detail::Body& bA = w.bodies[jt.bodyA];
    const detail::Body& bB = w.bodies[jt.bodyB];
    // d/dt (u·d) with u turning with A: u̇·d + u·ḋ.
    const Vec2 vA = bA.v + cross(bA.w, a.pA - bA.center);
    const Vec2 vB = bB.v + cross(bB.w, a.pB - bB.center);
    return dot(cross(bA.w, a.axis), a.d) + dot(a.axis, vB - vA);
}

float World::pulleyJointLengthA(JointId id) const {
    const auto& w = state();
    const detail::Joint& jt = w.joints[w.jointIndex(id)];
    const PulleyJointDef& def = defOf<PulleyJointDef>(jt);
    return distance(def.groundAnchorA, anchorOf(w, jt.bodyA, def.localAnchorA));
}

float World::pulleyJointLengthB(JointId id) const {
    const auto& w = state();
    const detail::Joint& jt = w.joints[w.jointIndex(id)];
    const PulleyJointDef& def = defOf<PulleyJointDef>(jt);
    return distance(def.groundAnchorB, anchorOf(w, jt.bodyB, def.localAnchorB));
}

// ---- Reactions --------------------------------------------------------------

Vec2 World::jointReactionForce(JointId id) const { return state().joints[state().jointIndex(id)].reactionForce; }
float World::jointReactionTorque(JointId id) const { return state().joints[state().jointIndex(id)].reactionTorque; }

float World::jointMotorEffort(JointId id) const {
    const detail::Joint& jt = state().joints[state().jointIndex(id)];
    if (jt.type != JointType::revolute && jt.type != JointType::prismatic && jt.type != JointType::wheel)
        fail(std::string("a ") + typeName(jt.type) + " joint has no motor");
    return jt.motorEffort;
}

float World::jointForce(JointId id) const { return state().joints[state().jointIndex(id)].lastForce; }

}  // namespace i2d
