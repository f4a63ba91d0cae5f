// The warm starts a step begins with (warm_start.hpp says why).
#include "warm_start.hpp"

#include "lost_load.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

void scale(JointImpulses& j, float r) {
    j.linear = r * j.linear;
    j.angular *= r;
    j.axial *= r;
    j.spring *= r;
    j.motor *= r;
    j.lower *= r;
    j.upper *= r;
}

}  // namespace

void carryWarmStarts(WorldState& w, float dt) {
    const float h = dt / static_cast<float>(solverSubsteps(w.settings));
    // Every contact and joint, asleep or not: a sleeping island's warm starts
    // are applied when it wakes, at that step's substep. A world stepped at
    // one rate never comes here.
    if (w.lastSubstep > 0.0f && h != w.lastSubstep) {
        const float r = h / w.lastSubstep;
        for (int c = 0; c < w.contacts.capacity(); ++c) {
            Contact& ct = w.contacts[c];
            if (!ct.alive) continue;
            for (int i = 0; i < 2; ++i) {
                ct.normalImpulse[i] *= r;
                ct.tangentImpulse[i] *= r;
            }
        }
        for (int j = 0; j < w.joints.capacity(); ++j)
            if (w.joints[j].alive) scale(w.joints[j].impulses, r);
    }
    w.lastSubstep = h;
    releaseRemovedForces(w, h);
}

}  // namespace i2d::detail
