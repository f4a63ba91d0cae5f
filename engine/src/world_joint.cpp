// World: the public API facade for joints — creating the distance joint
// (validated), destroying joints and reading them. The joint bookkeeping is
// in joint.cpp, the distance joint's rows in distance_joint.cpp.
#include <algorithm>

#include "impulse2d/world.hpp"
#include "joint.hpp"
#include "validation.hpp"
#include "world_state.hpp"

namespace i2d {

using detail::fail;

JointId World::createDistanceJoint(const DistanceJointDef& def) {
    auto& w = state();
    w.checkUnlocked();
    int a = w.bodyIndex(def.bodyA);
    int b = w.bodyIndex(def.bodyB);
    if (a == b) fail("a joint needs two different bodies");
    detail::requireBounded(def.localAnchorA, "localAnchorA");
    detail::requireBounded(def.localAnchorB, "localAnchorB");
    detail::requireBounded(def.length, "joint length");
    if (!(def.length > 0.0f)) fail("joint length must be > 0");
    detail::requireInRange(def.hertz, 0.0f, detail::kMaxRate, "joint hertz");
    detail::requireInRange(def.dampingRatio, 0.0f, detail::kMaxRate, "joint damping ratio");
    detail::requireNonNegative(def.minLength, "joint minLength");
    if (!(def.maxLength >= 0.0f) || std::isnan(def.maxLength)) fail("joint maxLength must be >= 0");
    if (def.enableLimit && def.minLength > def.maxLength) fail("joint minLength must be <= maxLength");

    int j = w.joints.allocate();
    detail::DistanceJoint& jt = w.joints[j];
    jt.def = def;
    jt.bodyA = a;
    jt.bodyB = b;
    detail::linkJoint(w, j);
    return w.jointHandle(j);
}

void World::destroyJoint(JointId id) {
    auto& w = state();
    w.checkUnlocked();
    detail::destroyJoint(w, w.jointIndex(id));
}

bool World::isValid(JointId id) const { return state().find(id, state().joints) != detail::kNullIndex; }

BodyId World::jointBodyA(JointId id) const { return state().bodyHandle(state().joints[state().jointIndex(id)].bodyA); }
BodyId World::jointBodyB(JointId id) const { return state().bodyHandle(state().joints[state().jointIndex(id)].bodyB); }
DistanceJointDef World::distanceJointDef(JointId id) const { return state().joints[state().jointIndex(id)].def; }

float World::distanceJointCurrentLength(JointId id) const {
    const auto& w = state();
    const detail::DistanceJoint& jt = w.joints[w.jointIndex(id)];
    Vec2 pA = transformPoint(w.bodies[jt.bodyA].xf, jt.def.localAnchorA);
    Vec2 pB = transformPoint(w.bodies[jt.bodyB].xf, jt.def.localAnchorB);
    return distance(pA, pB);
}

void World::setDistanceJointLength(JointId id, float length) {
    auto& w = state();
    w.checkUnlocked();
    int j = w.jointIndex(id);
    detail::requireBounded(length, "joint length");
    if (!(length > 0.0f)) fail("joint length must be > 0");
    detail::DistanceJoint& jt = w.joints[j];
    jt.def.length = length;
    jt.impulse = 0.0f;
    detail::wakeBody(w, jt.bodyA);
    detail::wakeBody(w, jt.bodyB);
}

float World::jointForce(JointId id) const { return state().joints[state().jointIndex(id)].lastForce; }

}  // namespace i2d
