// Bodies: what the world keeps of each body between steps, and the two
// compact records the solver streams through during a step.
//
//   Body             everything about a body (transform, velocity, mass,
//                    damping, forces, links to its shapes, contacts and joints)
//   BodyState        32 bytes per awake body: what every solver pass reads
//                    and writes (velocity and the motion since the step began)
//   BodyIntegration  28 bytes per awake body: the constant inputs of the
//                    velocity integration, gathered once per step
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "impulse2d/types.hpp"
#include "slot_array.hpp"

namespace i2d::detail {

struct WorldState;
struct Shape;

struct Body {
    // What the solver's preparation reads of every body, every step (joint
    // slots, contact rows), and what the narrowphase reads of both bodies of
    // every contact (pose, velocities, reach), in the first 64 bytes.
    Transform xf{};                ///< origin and rotation
    Vec2 center{};                 ///< centre of mass, world
    Vec2 localCenter{};            ///< centre of mass, body frame
    float invMass = 0.0f;          ///< 1/kg
    float invInertia = 0.0f;       ///< about the centre of mass
    int solverIndex = kNullIndex;  ///< index into the solver arrays during a step
    bool awake = true;
    bool enabled = true;  ///< false: out of the simulation and the broadphase (World::disableBody)
    bool fixedRotation = false;
    bool isBullet : 1 = false;  ///< also swept against non-bullet dynamic bodies (continuous.cpp)
    /// Its forces were split around its drift in the last step it was
    /// solved (split_kick.hpp): v is its true velocity, not the lagging
    /// one of semi-implicit Euler.
    bool splitKick : 1 = false;
    /// It has been through a step's choice of kick (split_kick.hpp). Until
    /// then its velocity (the game's) is taken as it is by whichever kick
    /// its first step chooses.
    bool splitChosen : 1 = false;
    Vec2 v{};        ///< velocity of the centre of mass (m/s)
    float w = 0.0f;  ///< angular velocity (rad/s)
    /// Farthest core point of a solid shape from the centre of mass (m); −1
    /// when the body has no solid shape. Bounds how far a turn moves its
    /// surface (continuous.cpp, a kept manifold's reuse, the speculative
    /// margin). Set by updateMass for a dynamic body; a static or kinematic
    /// body's (from its origin) grows as shapes are added and stays when one
    /// is destroyed, an upper bound that every reader may take.
    float reach = -1.0f;
    Vec2 force{};         ///< accumulated for the next step (N)
    float torque = 0.0f;  ///< N·m
    float mass = 0.0f;
    float inertia = 0.0f;  ///< about the centre of mass
    float linearDamping = 0.0f, angularDamping = 0.0f;
    float gravityScale = 1.0f;
    float sleepTime = 0.0f;  ///< seconds at rest (island.cpp)
    /// The highest its centre of mass has been, along −gravity, at the end of
    /// a step (m; −∞ before its first step). A push between bodies does not
    /// lift a body above it (deep_overlap.cpp).
    float highest = -std::numeric_limits<float>::infinity();
    std::uint32_t generation = 1;
    int awakeIndex = kNullIndex;   ///< position in IslandSet::awakeBodies
    int sleepIsland = kNullIndex;  ///< sleeping island this body belongs to
    BodyType type = BodyType::static_body;
    bool enableSleep = true;
    bool alive = false;
    bool motionSet = false;                               ///< in BroadPhase::motionSet
    int firstShape = kNullIndex, lastShape = kNullIndex;  ///< the body's shapes, in creation order (shape.hpp)
    /// Where the body was (origin and rotation) when its shapes' boxes were
    /// last measured inside their fat boxes, and the least room they had
    /// there (m; 0: measure again). Until its shapes may have moved that far
    /// the boxes still hold them, and leftFatBoxes computes none (broad_phase.cpp).
    Vec2 boxOrigin{};
    Rot boxRotation{};
    float boxSlack = 0.0f;
    int jointCount = 0;  ///< how many joints the list below holds (here, it fills what alignment would pad)
    std::uintptr_t userData = 0;
    std::vector<int> contacts;  ///< contact slots
    /// The body's joints, in creation order, linked through the joints
    /// (Joint::nextJoint; joint.hpp, bodyJoints): most bodies have none, and
    /// a vector per body cost each 24 bytes.
    int firstJoint = kNullIndex, lastJoint = kNullIndex;
};
static_assert(sizeof(Body) <= 192, "three cache lines: memory per body is held below Box2D 2.4.1's");

/// The velocity of body b as the impact stage and its look read it, the
/// lagging one of semi-implicit Euler (impact_stage.cpp): its stored velocity
/// less a·h/2 when its forces were split around its drift (Body::splitKick,
/// split_kick.hpp), `a` its free acceleration and `halfSubstep` h/2.
inline Vec2 laggingVelocity(const Body& b, Vec2 a, float halfSubstep) {
    return b.splitKick ? b.v - halfSubstep * a : b.v;
}

/// A bound on |Δθ| for a rotation dq: |Δθ| ≤ (π/2)·|sin Δθ| while the turn
/// is under a quarter, π beyond; without atan2, for the many bodies that
/// hardly turn (continuous collision, the broadphase's fat boxes).
inline float turnBoundOf(Rot dq) { return dq.c >= 0.0f ? 1.5707964f * std::abs(dq.s) : 3.1415927f; }

/// Solver state of one awake body during a step. The constraint passes of
/// every substep read and write only this array (and the constraint rows),
/// so it is kept to half a cache line. Positions are not here: the solver
/// works with the motion since the step began (dp, dq), which keeps the
/// separations it computes free of the round-off of large coordinates, and
/// the transform is updated once at the end of the step.
struct BodyState {
    Vec2 v{};        ///< linear velocity (m/s)
    float w = 0.0f;  ///< angular velocity (rad/s)
    /// soft_step, in a step with a deep overlap: the speed along up (against
    /// gravity) the positions last moved with, before the relax pass
    /// (payPushLift, solver.cpp); it also keeps the record at 32 bytes. The
    /// wide passes carry it unchanged.
    float upBeforeRelax = 0.0f;
    Vec2 dp{};  ///< change of the centre of mass since the step began
    Rot dq{};   ///< rotation since the step began
};
static_assert(sizeof(BodyState) == 32, "BodyState is streamed by every solver pass: keep it at 32 bytes");

/// BodyIntegration::splitBefore of a body no step has chosen a kick for yet.
inline constexpr std::uint8_t kSplitNotChosen = 2;

/// What the velocity integration of each substep needs besides BodyState,
/// gathered once per step (forces, gravity and damping do not change within it).
struct BodyIntegration {
    Vec2 linearAcceleration{};         ///< gravityScale·g + F/m (m/s²)
    float torque = 0.0f;               ///< N·m
    float invInertia = 0.0f;           ///< 1/(kg·m²)
    float linearDampingFactor = 1.0f;  ///< 1/(1 + h·c), h the substep
    float angularDampingFactor = 1.0f;
    bool movedByForces = false;    ///< dynamic; kinematic bodies keep their velocity
    std::uint8_t splitBefore = 0;  ///< as the step began: 1 split, 0 not, kSplitNotChosen (split_kick.hpp)
    bool jointed = false;          ///< the body has a joint (split_kick.hpp)
    bool split = false;            ///< its forces are split this step (split_kick.hpp)
};
static_assert(sizeof(BodyIntegration) == 28, "the size docs/architecture.md gives");

/// A body's pose at the step's start, kept when a stage before the solver
/// moves the body (the impact stage's time-of-impact shift), so that
/// continuous collision sweeps the whole motion of the step and the contact
/// rows see the shift; valid while stamp is the world's step stamp. Per body
/// slot in WorldState::impactStarts, sized at the world's first strike: a
/// world that never strikes anything keeps none (20 bytes a body).
struct StepStart {
    Vec2 center{};
    Rot q{};
    std::uint32_t stamp = 0;
};

/// Mass, centre of mass and rotational inertia from the body's shapes
/// (parallel-axis sum); keeps the velocity of the centre of mass consistent
/// when the centre shifts. Static and kinematic bodies get no mass.
void updateMass(WorldState& w, int body);

/// Body::reach from the body's solid shapes.
float solidReach(const WorldState& w, const Body& body);
/// The farthest core point of a solid shape from `from` (body coordinates); −1 for a sensor.
float shapeReach(const Shape& shape, Vec2 from);

/// True when a joint between the two bodies forbids their shapes to collide.
bool jointPreventsCollision(const WorldState& w, int bodyA, int bodyB);

}  // namespace i2d::detail
