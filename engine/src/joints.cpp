// Distance joints: creation, destruction and accessors (the rows are solved
// in solver.cpp).
#include <algorithm>

#include "impulse2d/world.hpp"
#include "validation.hpp"
#include "world_impl.hpp"

namespace i2d {

using detail::fail;

JointId World::createDistanceJoint(const DistanceJointDef& def) {
    impl_->checkUnlocked();
    auto& w = *impl_;
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
    w.bodies[a].joints.push_back(j);
    w.bodies[b].joints.push_back(j);
    // Joined bodies that may not collide lose their contacts at once.
    if (!def.collideConnected) {
        std::vector<int> cs = w.bodies[a].contacts;
        for (int c : cs) {
            const detail::Contact& ct = w.contacts[c];
            if ((ct.bodyA == a && ct.bodyB == b) || (ct.bodyA == b && ct.bodyB == a)) w.destroyContact(c, true);
        }
    }
    w.wakeBody(a);
    w.wakeBody(b);
    return w.jointHandle(j);
}

void World::destroyJoint(JointId id) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int j = w.jointIndex(id);
    detail::DistanceJoint& jt = w.joints[j];
    for (int b : {jt.bodyA, jt.bodyB}) {
        auto& list = w.bodies[b].joints;
        list.erase(std::remove(list.begin(), list.end(), j), list.end());
        w.wakeBody(b);
        // The bodies may collide again: let the broadphase look.
        for (int s : w.bodies[b].shapes) {
            detail::Shape& sh = w.shapes[s];
            if (!sh.moved && !sh.inStaticTree && sh.proxy != detail::DynamicTree::kNull) {
                sh.moved = true;
                w.moveBuffer.push_back(s);
            }
        }
    }
    w.joints.release(j);
}

bool World::isValid(JointId id) const {
    if (id.isNull() || id.index1 > static_cast<std::uint32_t>(impl_->joints.capacity())) return false;
    int i = static_cast<int>(id.index1) - 1;
    return impl_->joints[i].alive && impl_->joints[i].generation == id.generation;
}

BodyId World::jointBodyA(JointId id) const { return impl_->bodyHandle(impl_->joints[impl_->jointIndex(id)].bodyA); }
BodyId World::jointBodyB(JointId id) const { return impl_->bodyHandle(impl_->joints[impl_->jointIndex(id)].bodyB); }
DistanceJointDef World::distanceJointDef(JointId id) const { return impl_->joints[impl_->jointIndex(id)].def; }

float World::distanceJointCurrentLength(JointId id) const {
    const auto& w = *impl_;
    const detail::DistanceJoint& jt = w.joints[w.jointIndex(id)];
    Vec2 pA = transformPoint(w.bodies[jt.bodyA].xf, jt.def.localAnchorA);
    Vec2 pB = transformPoint(w.bodies[jt.bodyB].xf, jt.def.localAnchorB);
    return distance(pA, pB);
}

void World::setDistanceJointLength(JointId id, float length) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int j = w.jointIndex(id);
    detail::requireBounded(length, "joint length");
    if (!(length > 0.0f)) fail("joint length must be > 0");
    detail::DistanceJoint& jt = w.joints[j];
    jt.def.length = length;
    jt.impulse = 0.0f;
    w.wakeBody(jt.bodyA);
    w.wakeBody(jt.bodyB);
}

float World::jointForce(JointId id) const { return impl_->joints[impl_->jointIndex(id)].lastForce; }

}  // namespace i2d
