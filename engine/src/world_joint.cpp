// World: the public API facade for creating and destroying joints of every
// type, and what all joints share (bodies, type, user data). Definitions,
// features, state and reactions are in world_joint_state.cpp; the joint
// bookkeeping in joint.cpp; each type's rows in its own file.
#include <algorithm>

#include "impulse2d/world.hpp"
#include "joint.hpp"
#include "joint_rows.hpp"
#include "joint_validation.hpp"
#include "world_state.hpp"

namespace i2d {

using detail::fail;

namespace {

/// The bodies of a new joint: live handles of this world, two different
/// bodies, not both static.
std::pair<int, int> jointBodies(const detail::WorldState& w, BodyId bodyA, BodyId bodyB) {
    const int a = w.bodyIndex(bodyA);
    const int b = w.bodyIndex(bodyB);
    if (a == b) fail("a joint needs two different bodies");
    if (w.bodies[a].type == BodyType::static_body && w.bodies[b].type == BodyType::static_body)
        fail("a joint needs a body that can move: both bodies are static");
    return {a, b};
}

/// Allocates and links a joint of the definition's type between bodies a and b.
template <class Def>
JointId addJoint(detail::WorldState& w, JointType type, const Def& def, int a, int b,
                 void (*complete)(detail::WorldState&, detail::Joint&) = nullptr) {
    const int j = w.joints.allocate();
    detail::Joint& jt = w.joints[j];
    jt.type = type;
    jt.def = def;
    jt.bodyA = a;
    jt.bodyB = b;
    jt.collideConnected = def.collideConnected;
    jt.userData = def.userData;
    if (complete) complete(w, jt);
    detail::linkJoint(w, j);
    return w.jointHandle(j);
}

template <class Def>
JointId createSimple(detail::WorldState& w, JointType type, const Def& def,
                     void (*complete)(detail::WorldState&, detail::Joint&) = nullptr) {
    w.checkUnlocked();
    const auto [a, b] = jointBodies(w, def.bodyA, def.bodyB);
    detail::validateJointDef(def);
    return addJoint(w, type, def, a, b, complete);
}

}  // namespace

JointId World::createDistanceJoint(const DistanceJointDef& def) {
    return createSimple(state(), JointType::distance, def);
}
JointId World::createRevoluteJoint(const RevoluteJointDef& def) {
    return createSimple(state(), JointType::revolute, def);
}
JointId World::createPrismaticJoint(const PrismaticJointDef& def) {
    return createSimple(state(), JointType::prismatic, def);
}
JointId World::createWeldJoint(const WeldJointDef& def) { return createSimple(state(), JointType::weld, def); }
JointId World::createWheelJoint(const WheelJointDef& def) { return createSimple(state(), JointType::wheel, def); }
JointId World::createMotorJoint(const MotorJointDef& def) { return createSimple(state(), JointType::motor, def); }

JointId World::createMouseJoint(const MouseJointDef& def) {
    // Body B's point under the target is the one that is pulled.
    return createSimple(state(), JointType::mouse, def, [](detail::WorldState& w, detail::Joint& jt) {
        jt.localAnchorB = invTransformPoint(w.bodies[jt.bodyB].xf, std::get<MouseJointDef>(jt.def).target);
    });
}

JointId World::createPulleyJoint(const PulleyJointDef& def) { return createSimple(state(), JointType::pulley, def); }

JointId World::createGearJoint(const GearJointDef& def) {
    auto& w = state();
    w.checkUnlocked();
    const int j1 = w.jointIndex(def.joint1);
    const int j2 = w.jointIndex(def.joint2);
    if (j1 == j2) fail("a gear joint needs two different joints");
    for (int j : {j1, j2}) {
        const JointType t = w.joints[j].type;
        if (t != JointType::revolute && t != JointType::prismatic)
            fail("a gear joint couples revolute or prismatic joints only");
    }
    const int a = w.joints[j1].bodyB, b = w.joints[j2].bodyB;
    if (a == b) fail("a joint needs two different bodies");
    if (w.bodies[a].type == BodyType::static_body && w.bodies[b].type == BodyType::static_body)
        fail("a joint needs a body that can move: both bodies are static");
    detail::validateJointDef(def);
    const int g = w.joints.allocate();
    detail::Joint& jt = w.joints[g];
    jt.type = JointType::gear;
    jt.def = def;
    jt.bodyA = a;
    jt.bodyB = b;
    jt.joint1 = j1;
    jt.joint2 = j2;
    jt.collideConnected = def.collideConnected;
    jt.userData = def.userData;
    jt.gearError = 0.0f;  // the coupled coordinates are held where they are now
    detail::linkJoint(w, g);
    return w.jointHandle(g);
}

void World::destroyJoint(JointId id) {
    auto& w = state();
    w.checkUnlocked();
    detail::destroyJoint(w, w.jointIndex(id));
}

bool World::isValid(JointId id) const { return state().find(id, state().joints) != detail::kNullIndex; }
JointType World::jointType(JointId id) const { return state().joints[state().jointIndex(id)].type; }
BodyId World::jointBodyA(JointId id) const { return state().bodyHandle(state().joints[state().jointIndex(id)].bodyA); }
BodyId World::jointBodyB(JointId id) const { return state().bodyHandle(state().joints[state().jointIndex(id)].bodyB); }
std::uintptr_t World::jointUserData(JointId id) const { return state().joints[state().jointIndex(id)].userData; }
void World::setJointUserData(JointId id, std::uintptr_t data) {
    auto& w = state();
    detail::Joint& jt = w.joints[w.jointIndex(id)];
    jt.userData = data;
    std::visit([&](auto& def) { def.userData = data; }, jt.def);
}

}  // namespace i2d
