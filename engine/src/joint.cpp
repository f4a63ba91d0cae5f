// Joints: linking a joint to its bodies and unlinking it (what every joint
// type shares; the rows are in distance_joint.cpp).
#include <algorithm>

#include "joint.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void linkJoint(WorldState& w, int j) {
    DistanceJoint& jt = w.joints[j];
    const int a = jt.bodyA, b = jt.bodyB;
    w.bodies[a].joints.push_back(j);
    w.bodies[b].joints.push_back(j);
    // Joined bodies that may not collide lose their contacts at once.
    if (!jt.def.collideConnected) {
        const std::vector<int> list = w.bodies[a].contacts;
        for (int c : list) {
            const Contact& ct = w.contacts[c];
            if ((ct.bodyA == a && ct.bodyB == b) || (ct.bodyA == b && ct.bodyB == a)) destroyContact(w, c, true);
        }
    }
    wakeBody(w, a);
    wakeBody(w, b);
}

void destroyJoint(WorldState& w, int j) {
    DistanceJoint& jt = w.joints[j];
    for (int b : {jt.bodyA, jt.bodyB}) {
        auto& list = w.bodies[b].joints;
        list.erase(std::remove(list.begin(), list.end(), j), list.end());
        wakeBody(w, b);
        // The bodies may collide again: let the broadphase look.
        for (int s : bodyShapes(w.shapes, w.bodies[b])) {
            Shape& sh = w.shapes[s];
            if (sh.proxy != DynamicTree::kNull) w.broadPhase.markMoved(sh, s);
        }
    }
    w.joints.release(j);
}

}  // namespace i2d::detail
