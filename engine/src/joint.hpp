// Joints: what the world keeps of a joint of any type, the per-step row every
// joint type fills (JointConstraint), and the bookkeeping that links joints to
// bodies. Each type's constraint maths is in its own file
// (distance_joint.cpp, revolute_joint.cpp, …, gear_joint.cpp); joint_solver.cpp
// prepares, colours and dispatches the rows.
#pragma once

#include <cstdint>
#include <variant>

#include "body.hpp"
#include "impulse2d/joints.hpp"
#include "slot_array.hpp"
#include "soft_constraint.hpp"

namespace i2d::detail {

struct WorldState;

/// Impulses a joint accumulates, kept between steps for the warm start. What
/// each holds depends on the type (see each joint's file); unused ones stay 0.
struct JointImpulses {
    Vec2 linear{};         ///< point constraint (N·s, world)
    float angular = 0.0f;  ///< angle constraint (N·m·s)
    float axial = 0.0f;    ///< a scalar row: distance, perpendicular, pulley, gear
    float spring = 0.0f;
    float motor = 0.0f;
    float lower = 0.0f;  ///< limits, ≥ 0
    float upper = 0.0f;
};

using JointDefVariant = std::variant<DistanceJointDef, RevoluteJointDef, PrismaticJointDef, WeldJointDef, WheelJointDef,
                                     MotorJointDef, MouseJointDef, PulleyJointDef, GearJointDef>;

struct Joint {
    JointDefVariant def;  ///< as given (handles included), changed by the set…Def calls
    int bodyA = kNullIndex, bodyB = kNullIndex;
    int joint1 = kNullIndex, joint2 = kNullIndex;  ///< gear: the coupled joints
    /// Neighbours in each body's list of joints (Body::firstJoint): [0] in
    /// bodyA's, [1] in bodyB's.
    int prevJoint[2] = {kNullIndex, kNullIndex}, nextJoint[2] = {kNullIndex, kNullIndex};
    /// gear: its error coordinate1 + ratio·coordinate2 − (that at creation), kept
    /// from step to step so that it follows any number of turns (gear_joint.cpp)
    float gearError = 0.0f;
    Vec2 localAnchorB{};  ///< mouse: body B's point that is pulled (body frame)
    JointImpulses impulses;
    Vec2 reactionForce{};  ///< N, on body B, over the last step it was awake
    float reactionTorque = 0.0f;
    float motorEffort = 0.0f;
    float lastForce = 0.0f;
    std::uint32_t generation = 1;
    JointType type = JointType::distance;
    bool collideConnected = false;
    bool alive = false;
    /// A hinge the wide path would take that was a deep joint when a step
    /// last looked (isDeepJoint): the joint plan keeps it off the wide path.
    /// Kept here, not in the plan, so that a kept plan and one made again
    /// decide alike; a change makes the plan again for the next step.
    bool deepHinge = false;
    /// Left by the game with its point, axis or length more than
    /// kStretchedJointError off, or its angle more than kStretchedJointAngle (judgeStretch), and
    /// not yet closed within half of them
    /// (isStretched, world_state.hpp): the joint plan puts it in an exact tree whatever the
    /// masses, and a step whose trees hold such a joint solves them rigid and
    /// closes their error on pseudo-velocities (pushJointTrees).
    bool stretched = false;
    std::uintptr_t userData = 0;
};

// ---- Per-step rows ---------------------------------------------------------
// Each type's row data; plain values, written by the type's prepare.

struct DistanceRow {
    float length, minLength, maxLength, hertz, dampingRatio;  ///< (the axial mass is the frame's: axialMassOf)
    bool rigid;                                               ///< not a spring (or a spring pinned by equal limits)
    bool enableLimit;
};
struct RevoluteRow {
    float axialMass, referenceAngle, lowerAngle, upperAngle, motorSpeed, maxMotorTorque, hertz, dampingRatio;
    bool enableLimit, enableMotor, enableSpring;
};
struct PrismaticRow {
    Vec2 axisA;  ///< the axis in world at step start (turns with A)
    float referenceAngle, lower, upper, motorSpeed, maxMotorForce, hertz, dampingRatio;
    bool enableLimit, enableMotor, enableSpring;
};
struct WeldRow {
    float axialMass, referenceAngle, linearHertz, linearDampingRatio, angularHertz, angularDampingRatio;
};
struct WheelRow {
    Vec2 axisA;
    float axialMass, lower, upper, motorSpeed, maxMotorTorque, hertz, dampingRatio;
    bool enableLimit, enableMotor, enableSpring;
};
struct MotorRow {
    float axialMass, angularOffset, maxForce, maxTorque, correctionRate;  ///< correctionRate = factor / dt
};
struct MouseRow {
    Vec2 targetFromCenterB;  ///< target − centre B at step start
    float hertz, dampingRatio, maxForce;
};
struct PulleyRow {
    Vec2 groundFromCenterA;  ///< ground anchor A − centre A at step start
    Vec2 groundFromCenterB;
    float ratio, constant;
};
/// The gear couples joint1 (C → A) and joint2 (D → B): bodies A, B are the
/// row's a, b; C, D are c, d.
struct GearRow {
    // Joint 1: revolute (angle of A relative to C) or prismatic (translation of A along C's axis).
    Vec2 axisC, rCAnchor, rAAnchor, deltaCenterCA;  ///< prismatic 1 only
    Vec2 axisD, rDAnchor, rBAnchor, deltaCenterDB;  ///< prismatic 2 only
    float reference1, reference2;                   ///< prismatic: the translation at step start
    float ratio, errorAtStart;                      ///< errorAtStart: Joint::gearError when the step began
    bool prismatic1, prismatic2;
};

union JointRow {
    DistanceRow distance;
    RevoluteRow revolute;
    PrismaticRow prismatic;
    WeldRow weld;
    WheelRow wheel;
    MotorRow motor;
    MouseRow mouse;
    PulleyRow pulley;
    GearRow gear;
    JointRow() : distance{} {}
};

/// One joint's rows during a step, in the contiguous array the passes stream
/// through (in colour order, see joint_solver.cpp).
struct JointConstraint {
    int joint = kNullIndex;
    JointType type = JointType::distance;
    /// Its equality rows are solved exactly with its tree (joint_tree.cpp),
    /// not in the Gauss-Seidel sweep.
    bool inTree : 1 = false;
    /// The entries of its anchors' point matrix fit single precision with room
    /// for their products (solvePointRows in joint_rows.hpp).
    bool singlePrecision : 1 = false;
    /// A deep joint this step (isDeepJoint, world_state.hpp): rigid in the
    /// soft step's biased pass, its error pushed on pseudo-velocities.
    bool deep : 1 = false;
    /// Its limit pulled in this position's solve and was let go until the
    /// positions change (the tree's active set, joint_tree.cpp).
    bool limitReleased : 1 = false;
    /// JointSlot::treePushed: its tree may be pushed (buildJointTrees).
    bool treePushed : 1 = false;
    /// JointSlot::treeLoop: its equality rows close a loop of the exact
    /// trees and are solved with them (inTree is set too).
    bool treeLoop : 1 = false;
    /// JointSlot::treeSpring: its spring is solved with the exact trees.
    bool treeSpring : 1 = false;
    /// A joint solved with its tree whose limit (a revolute joint's angle, a
    /// slider's translation, a rope's or limited spring's length) is held by
    /// the tree in this factorization: −1 the lower, +1 the upper, 0 none
    /// (joint_tree.cpp).
    std::int8_t treeLimit = 0;
    int a = kNullIndex, b = kNullIndex;  ///< solver body indices; kNullIndex for a body that does not move
    int c = kNullIndex, d = kNullIndex;  ///< gear only: the frames of its two joints
    float invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
    float invMassC = 0, invIC = 0, invMassD = 0, invID = 0;
    Vec2 rA{}, rB{};         ///< anchors relative to the centres of mass at step start (world)
    Vec2 deltaCenter{};      ///< centre B − centre A at step start
    Rot qA{}, qB{};          ///< rotations of A and B at step start
    JointImpulses impulses;  ///< accumulated this step, warm started from the joint
    JointRow row;
};

static_assert(sizeof(JointConstraint) == 212, "the layout docs/architecture.md gives");

/// What the colouring, the tree search and the wide path need of a joint,
/// gathered before any row is written (joint_solver.cpp).
struct JointSlot {
    int joint = kNullIndex;
    int a = kNullIndex, b = kNullIndex, c = kNullIndex, d = kNullIndex;  ///< as JointConstraint's
    float invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
    /// How each side gives at the joint's anchor: 1/m + |r|²/I (r from the
    /// centre of mass to the anchor), the inverse of the mass the joint's rows
    /// move there; the side's inverse mass for a joint without anchors, 0 for
    /// a side that does not move (anchorMobility, joint_solver.cpp).
    float anchorInvMassA = 0, anchorInvMassB = 0;
    bool movesC = false, movesD = false;  ///< gear: its joints' frames move
    std::uint8_t equalityRows = 0;        ///< rows the exact tree solve could take (joint_tree.cpp)
    bool rowsOnlyAtLimit = false;         ///< those rows are a limit's, handed over while it holds (a rope)
    bool inTree = false;
    bool wide = false;       ///< solved eight at a time (wide_revolute.cpp), with no JointConstraint
    bool deepHinge = false;  ///< kept off the wide path as a deep joint (Joint::deepHinge)
    bool stretched = false;  ///< Joint::stretched when the plan was made (its tree is solved exactly: selectTreeJoints)
    bool pointLoad = false;  ///< a hinge or a weld with a rigid point: carries its load at a point (holdsLoadAtPoint)
    bool spring = false;     ///< has a spring the tree solve can take (hasSpringRow)
    /// In a tree no swept loop closes, of hinges and welds with a rigid point
    /// or holding a stretched joint: the tree is pushed (rigid in the biased pass, its
    /// error closed by pushJointTrees) while none of its bodies touches
    /// anything, or always when it holds a stretched joint (selectTreeJoints,
    /// buildJointTrees).
    bool treePushed = false;
    /// Its equality rows close a loop through exact trees (both its moving
    /// sides in trees solved exactly): they are solved with the trees as
    /// auxiliary rows (joint_tree.cpp), not swept beside them. inTree is set
    /// too (its equality rows leave the sweep), but it is no edge of a tree.
    bool treeLoop = false;
    /// Its spring (hasSpringRow) acts between bodies of exact trees: it is
    /// solved with them as an auxiliary row with its own compliance
    /// (joint_tree.cpp), not swept beside them.
    bool treeSpring = false;
    /// No spring, motor or drive: its rows only hold (a rigid row, a limit),
    /// and its bodies may have their forces split (split_kick.hpp).
    bool onlyHolds = false;
};

/// What a joint's solve needs besides its row and its bodies' states.
struct JointContext {
    float h = 0.0f, invH = 0.0f;  ///< the (sub)step
    SolvePass pass = SolvePass::soft_bias;
    Softness jointSoft;       ///< softness of rigid rows in the soft_bias pass
    float pushFactor = 0.0f;  ///< β of baumgarte (and of split's push)
    float maxLinearSpeed = 0.0f;
};

/// Which of a joint's two lists (Joint::nextJoint) is body b's.
inline int jointSide(const Joint& jt, int b) { return jt.bodyA == b ? 0 : 1; }

/// The joints of body b, in creation order: for (int j : bodyJoints(w.joints, w.bodies[b], b)).
class BodyJoints {
public:
    BodyJoints(const SlotArray<Joint>& joints, int first, int body) : joints_(&joints), first_(first), body_(body) {}
    struct Iterator {
        const SlotArray<Joint>* joints;
        int body;
        int j;
        int operator*() const { return j; }
        Iterator& operator++() {
            const Joint& jt = (*joints)[j];
            j = jt.nextJoint[jointSide(jt, body)];
            return *this;
        }
        bool operator!=(const Iterator& o) const { return j != o.j; }
    };
    Iterator begin() const { return {joints_, body_, first_}; }
    Iterator end() const { return {joints_, body_, kNullIndex}; }

private:
    const SlotArray<Joint>* joints_;
    int first_;
    int body_;
};
inline BodyJoints bodyJoints(const SlotArray<Joint>& joints, const Body& body, int b) {
    return {joints, body.firstJoint, b};
}

/// Links a new joint to its bodies, drops the contacts between them when
/// they may not collide, and wakes both.
void linkJoint(WorldState& w, int joint);

/// Unlinks and frees a joint and every gear joint built on it; wakes the
/// bodies and lets the broadphase look at their shapes again (they may
/// collide now).
void destroyJoint(WorldState& w, int joint);

/// Wraps an angle to (−π, π].
inline float unwindAngle(float a) {
    constexpr float kPi = 3.14159265358979f;
    if (a > kPi) return a - 2.0f * kPi;
    if (a <= -kPi) return a + 2.0f * kPi;
    return a;
}

/// angle(B) − angle(A) − `reference` at the bodies' poses now, in (−π, π].
float jointAngleNow(const WorldState& w, const Joint& joint, float reference);

/// A distance joint whose length is held (not a spring, or a spring pinned
/// by equal limits).
inline bool isRigidDistance(const DistanceJointDef& def) {
    return !(def.enableSpring && (!def.enableLimit || def.minLength < def.maxLength));
}

/// Whether a joint's equality rows hold a point: a revolute joint's, a
/// weld's without springs (the rows of other joints are soft or judged along
/// their own axes). Only such a point makes a deep or a stretched joint.
bool holdsPoint(const Joint& joint);

/// How far a joint's bodies are from where its equality rows hold them, at
/// their poses now: the point's opening (a revolute joint, a rigid weld), the
/// distance off the axis (a prismatic or wheel joint) or off the length (a
/// rigid distance joint), m; the angle off its reference (a rigid weld, a
/// prismatic joint), rad. Zero for springs and drives (a distance joint's
/// spring, a soft weld, motor, mouse, pulley and gear joints).
struct JointStretch {
    float linear = 0.0f, angular = 0.0f;
};
JointStretch jointStretch(const WorldState& w, const Joint& joint);

/// Makes joint `j` a stretched joint (Joint::stretched) when its point, axis
/// or length is further than kStretchedJointError off, or its angle further than
/// kStretchedJointAngle (jointStretch), in soft_step. Called where the game
/// sets where the bodies are or where the anchors are: a joint created, a
/// body moved, a definition or the settings changed. An error the solver
/// leaves is the soft rows' to close; an error the game makes can be any
/// size, and closed by the soft rows at biasRate·C it flung a chain created
/// with its joints 1 m open at 246 m/s, 37 times its energy
/// (docs/joints.md, "Stretched joints").
void judgeStretch(WorldState& w, int j);

/// A joint's two anchor points in world coordinates at the bodies' current
/// poses (for a motor joint: A's target point and B's origin; a mouse joint:
/// the target and B's point; a gear: the two bodies' origins).
struct JointAnchors {
    Vec2 a, b;
};
JointAnchors jointAnchors(const WorldState& w, const Joint& joint);

}  // namespace i2d::detail
