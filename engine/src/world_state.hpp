// The state of one World: the store of every module, addressed by slot
// index, and the conversion between slots and the handles users hold. Not
// part of the public API.
//
// Modules and the direction of their calls (docs/architecture.md):
//   body, island → broad_phase → contact → joint, shape
//     → impact_stage, contact_solver, distance_joint, continuous → solver
//   and the API facade (world*.cpp, debug_draw.cpp) on top.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "body.hpp"
#include "broad_phase.hpp"
#include "contact.hpp"
#include "events.hpp"
#include "impact_stage.hpp"
#include "impulse2d/types.hpp"
#include "island.hpp"
#include "joint.hpp"
#include "lost_load.hpp"
#include "shape.hpp"
#include "slot_array.hpp"
#include "solver.hpp"
#include "stage_runner.hpp"
#include "validation.hpp"

namespace i2d::detail {

struct WorldState {
    WorldState(const WorldSettings& s, std::uint32_t id) : settings(s), worldId(id) {}

    WorldSettings settings;
    std::uint32_t worldId;  ///< stamped into every handle of this world

    SlotArray<Body> bodies;
    SlotArray<Shape> shapes;
    SlotArray<Contact> contacts;
    SlotArray<Joint> joints;

    IslandSet islands;
    BroadPhase broadPhase;
    EventBuffers events;
    SolverArrays solver;

    // Per-step lists of the narrowphase and the impact stage.
    std::vector<int> activeContacts;  ///< contacts with an awake body, updated this step, slot order
    std::vector<int> gatherScratch;
    std::vector<std::uint8_t> gatherMarks;     ///< per contact slot: free, or gathered (collide's scratch)
    std::vector<std::uint8_t> collideUpdates;  ///< per gathered contact: what its manifold update found (contact.cpp)
    std::vector<ContactLook> collideLooks;     ///< per gathered contact: its look (contact.cpp)
    std::vector<std::uint32_t> impactChanged;
    std::vector<float> impactTime, impactBodyTime;
    std::vector<Vec2> impactBodyDv;       ///< per body slot: its change of velocity in the impact stage
    std::vector<float> impactBodyDw;      ///< ... and of angular velocity
    std::vector<StepStart> impactStarts;  ///< per body slot: its start, if the impact stage moved it (body.hpp)
    std::vector<int> impactStruckBodies, impactStruckContacts;  ///< what the last impact stage wrote
    std::vector<int> impactFreshlyStruck;                       ///< scratch: the bodies one sweep of the stage struck
    // The impact stage's shock pass (impact_stage.cpp): scratch, kept so a
    // step allocates nothing once grown. shockLocal is per body slot, −1
    // between passes.
    std::vector<ShockEdge> shockEdges;
    std::vector<int> shockLocal, shockBodies, shockLevel, shockOffset, shockAdjacent, shockFill;
    std::vector<ShockSaved> shockSaved;
    /// The impact stage's rigid clusters (bodies rigidly welded together,
    /// struck as one body): per body slot its cluster, −1 outside one (reset
    /// through weldClusterBodies); each cluster's bodies from
    /// weldClusterStart[k] in weldClusterBodies.
    std::vector<int> weldCluster, weldClusterStart, weldClusterBodies;
    std::vector<int> weldClusterScratch, weldClusterNumber, weldClusterGrouped;  ///< findWeldClusters' scratch
    /// Per body slot: its place in the lost loads being released
    /// (lost_load.cpp), −1 outside a release.
    std::vector<int> lostLoadPlace;
    /// The bodies given a force (World::applyForce) since the last step,
    /// listed when their force stops being zero; and the forces of the last
    /// step (releaseRemovedForces, lost_load.hpp).
    std::vector<int> forcedBodies;
    std::vector<AppliedLoad> appliedLoads;
    std::vector<RescaledBody> rescaledBodies;  ///< bodies given a new gravity scale since the last step
    Vec2 lastGravity{};                        ///< the gravity of the last step, valid once gravityStepped
    bool gravityStepped = false;
    /// releaseRemovedForces' list, kept so a step allocates nothing once grown.
    std::vector<LostLoad> removedForceScratch;
    /// Per contact slot: when a destroyed contact or joint last took the
    /// contact's load away (releaseLostLoads), as 1 + the stamp of the step
    /// before; 0 if never. Sized at the first such release. Its soft rows
    /// push out the sag the load had pressed in, and the relax sweep must
    /// take that push back (listRelaxedAgainBlocks, solver.cpp).
    std::vector<std::uint32_t> unloadedAt;
    std::uint32_t lastUnloadedAt = 0;      ///< the latest of unloadedAt, 0 once it is past (listRelaxedAgainBlocks)
    std::vector<ContactLook> activeLooks;  ///< per active contact (contact.hpp)

    // Callbacks (World::setCustomFilter, setPreSolve); empty when not set.
    /// The game's task system (World::setTaskSystem), not owned; null: one thread.
    TaskSystem* tasks = nullptr;
    StageRunner runner;  ///< the step's parallel stages (stage_runner.cpp)

    CustomFilterFn customFilter;
    PreSolveFn preSolve;

    /// Rolling resistance and tangent speed by contact slot; empty until a
    /// contact has either (contact.hpp, ContactSurface).
    std::vector<ContactSurface> contactSurfaces;

    Profile profile{};
    std::uint32_t stepStamp = 0;
    /// The step stamp of the last step in which the impact stage moved a
    /// body's start (impactStarts): the row preparation reads no body's
    /// start in a step without any.
    std::uint32_t startsShiftedAt = 0;
    float stepDt = 0.0f;  ///< the step's Δt, set as it begins (the narrowphase's speculative margins)
    /// The substep (Δt in one-pass modes) the warm starts were found at, 0
    /// before the first step (warm_start.hpp).
    float lastSubstep = 0.0f;
    bool locked = false;    ///< true while stepping or drawing (see checkUnlocked)
    bool stepping = false;  ///< true inside step(): end events go to this step's lists, not the pending ones

    /// The body's pose at the step's start if the impact stage moved it in
    /// this step (StepStart), else null. `body` is one of `bodies`.
    const StepStart* shiftedStart(const Body& body) const {
        if (startsShiftedAt != stepStamp) return nullptr;  // no body's start moved in this step
        const auto i = static_cast<std::size_t>(&body - bodies.items.data());
        return i < impactStarts.size() && impactStarts[i].stamp == stepStamp ? &impactStarts[i] : nullptr;
    }

    void checkUnlocked() const {
        if (locked) fail("the world cannot be changed while it is stepping or drawing");
    }

    BodyId bodyHandle(int i) const { return {static_cast<std::uint32_t>(i + 1), bodies[i].generation, worldId}; }
    ShapeId shapeHandle(int i) const { return {static_cast<std::uint32_t>(i + 1), shapes[i].generation, worldId}; }
    JointId jointHandle(int i) const { return {static_cast<std::uint32_t>(i + 1), joints[i].generation, worldId}; }

    /// Slot of a live object named by a handle of this world, or kNullIndex.
    template <class Tag, class T>
    int find(Handle<Tag> id, const SlotArray<T>& store) const {
        if (id.isNull() || id.world != worldId) return kNullIndex;
        // Compared unsigned: a forged index beyond INT_MAX must not wrap negative.
        if (id.index1 > static_cast<std::uint32_t>(store.capacity())) return kNullIndex;
        const int i = static_cast<int>(id.index1) - 1;
        return store[i].alive && store[i].generation == id.generation ? i : kNullIndex;
    }

    /// Slot of the object a handle names; throws i2d::Error for a null handle,
    /// one of another world, or one whose object was destroyed.
    template <class Tag, class T>
    int require(Handle<Tag> id, const SlotArray<T>& store, const char* what) const {
        if (id.isNull()) fail(std::string("null ") + what + " handle");
        if (id.world != worldId && id.world != 0)
            fail(std::string("invalid ") + what + " handle: it was made by another world");
        const int i = find(id, store);
        if (i == kNullIndex) fail(std::string("stale or invalid ") + what + " handle");
        return i;
    }

    int bodyIndex(BodyId id) const { return require(id, bodies, "body"); }
    int shapeIndex(ShapeId id) const { return require(id, shapes, "shape"); }
    int jointIndex(JointId id) const { return require(id, joints, "joint"); }
};

/// A joint's anchors further apart than this (m), while one of its bodies
/// touches something through a contact, make it a deep joint (isDeepJoint).
/// The depth at which a contact's overlap is pushed on pseudo-velocities.
inline constexpr float kDeepJointError = kDeepOverlap;

/// Whether `body` touches a shape of another body through a (solid) contact.
inline bool touchesThroughContact(const WorldState& w, int body) {
    for (int c : w.bodies[body].contacts) {
        const Contact& ct = w.contacts[c];
        if (ct.touching && !ct.isSensor) return true;
    }
    return false;
}

/// Whether a joint whose anchors are `separation` apart is a deep joint
/// this step: in soft_step, anchors more than kDeepJointError apart while
/// one of its bodies touches something through a contact. The soft push
/// that closes such a joint is a velocity given to its bodies, which the
/// relax pass takes back from the joint's rows but not from a body the
/// contact handed it on to: a heavy body landing on a light one pinned to
/// the world drags the pin open, and the stretched joint's push threw the
/// heavy body back up faster than it came (docs/joints.md, "A stretched
/// joint beside a contact"). A deep joint's rows are rigid in the biased
/// pass and its error is pushed on pseudo-velocities, which move the bodies
/// for the substep only (joint_solver.cpp, pushJoints). Only the point of
/// a revolute joint or a rigid weld is judged (the callers); a joint solved
/// with an exact tree never is (joint_tree.cpp solves its rows together).
inline bool isDeepJoint(const WorldState& w, const Joint& joint, Vec2 separation) {
    return w.settings.positionCorrection == PositionCorrection::soft_step &&
           lengthSquared(separation) > kDeepJointError * kDeepJointError &&
           (touchesThroughContact(w, joint.bodyA) || touchesThroughContact(w, joint.bodyB));
}

/// A joint the game leaves with its point, axis or length further off than this
/// (m), or its angle further than kStretchedJointAngle (rad), is a stretched
/// joint (Joint::stretched, judgeStretch in joint.cpp) until both close within
/// half of that (isStretched).
inline constexpr float kStretchedJointError = kDeepJointError;
/// The turn that moves a point half a metre from the joint by kStretchedJointError.
inline constexpr float kStretchedJointAngle = 0.1f;

/// Whether a joint `stretch` off (jointStretch, joint.hpp) is stretched, given
/// whether it was: from the full errors on, until within half of them.
inline bool isStretched(bool was, JointStretch stretch) {
    const float scale = was ? 0.5f : 1.0f;
    return stretch.linear > scale * kStretchedJointError || std::fabs(stretch.angular) > scale * kStretchedJointAngle;
}

/// A contact as the API reports it (World::contacts, World::bodyContacts).
inline ContactData contactData(const WorldState& w, int c) {
    const Contact& ct = w.contacts[c];
    ContactData d;
    d.shapeA = w.shapeHandle(ct.shapeA);
    d.shapeB = w.shapeHandle(ct.shapeB);
    d.manifold = ct.manifold;
    for (int i = 0; i < 2; ++i) {
        d.normalImpulse[i] = ct.normalImpulse[i];
        d.tangentImpulse[i] = ct.tangentImpulse[i];
    }
    return d;
}

}  // namespace i2d::detail
