// Impulse2D — the World: owns bodies, shapes and joints and advances them in time.
//
// Typical use:
//   i2d::World world;                                   // gravity (0, −10)
//   auto ground = world.createBody({});                 // static
//   world.createPolygonShape(ground, {}, i2d::makeBox(50, 1));
//   auto box = world.createBody({.type = i2d::BodyType::dynamic_body, .position = {0, 4}});
//   world.createPolygonShape(box, {.density = 1}, i2d::makeBox(0.5f, 0.5f));
//   for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f);
//
// Units: SI throughout — metres (m), seconds (s), kilograms (kg), radians
// (rad, counter-clockwise positive), newtons (N), newton-seconds (N·s).
// Positions and vectors are in world coordinates unless a name says "local".
//
// Errors: see error.hpp — a refused call throws i2d::Error and changes nothing.
// Every call that takes a handle throws i2d::Error for a null, stale
// (destroyed) or forged handle, and for a handle made by another World; this
// is not repeated below. "Bounded" below
// means finite with every component in [−1e7, 1e7]. Calls marked "locked"
// below (those that create, destroy, move or wake things) also throw when
// made from inside World::draw (a DebugDraw that calls back into its world).
// Threading: a World is not thread-safe; different worlds may be used from
// different threads. A step may share its work with the game's task system
// (setTaskSystem). Determinism: the same build, the same calls in the same
// order give bit-identical results.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "impulse2d/debug_draw.hpp"
#include "impulse2d/error.hpp"
#include "impulse2d/geometry.hpp"
#include "impulse2d/mover.hpp"
#include "impulse2d/tasks.hpp"
#include "impulse2d/types.hpp"

namespace i2d {

namespace detail {
struct WorldState;
}

class World {
public:
    /// An empty world with the given settings. Throws i2d::Error when a
    /// setting is out of range (see setSettings).
    explicit World(const WorldSettings& settings = {});
    ~World();
    /// A moved-from World may only be assigned to or destroyed; any other
    /// call on it throws i2d::Error.
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // ---- Stepping -------------------------------------------------------

    /// Advance the world by dt seconds (finite, in [1e-6, 1]; use a fixed
    /// value, usually 1/60; another length is allowed, and the impulses carried
    /// from the last step are scaled to it). Runs: broadphase pairs → narrowphase → impacts →
    /// velocity solve → integrate → position correction → continuous
    /// collision of fast bodies against static and kinematic shapes → sleep. Events of this step are
    /// readable afterwards until the next step; forces applied before it are
    /// used and then cleared. Throws i2d::Error for dt NaN, ±∞, ≤ 0 (also −0),
    /// < 1e-6 s or > 1 s, and when called from inside draw (locked).
    void step(float dt);

    /// Current settings; changes made with setSettings apply from the next step.
    const WorldSettings& settings() const;
    /// Replace all settings at once (locked). Turning enableSleep off wakes
    /// every sleeping body. Throws i2d::Error, changing nothing, when: gravity
    /// is not bounded; velocityIterations or substeps is outside [1, 1000],
    /// positionIterations outside [0, 1000]; pushFactor is outside [0, 1];
    /// penetrationSlop, maxPushSpeed, restitutionThreshold, impactThreshold,
    /// speculativeDistance, aabbMargin, timeToSleep or a sleep tolerance is
    /// negative or non-finite; penetrationSlop > 1 m, speculativeDistance or
    /// aabbMargin > 10 m; a hertz or damping ratio is outside [0, 1e6];
    /// maxLinearSpeed is not in (0, 1e7]; positionCorrection or impactModel
    /// is not one of the enum's values.
    void setSettings(const WorldSettings& settings);
    /// The task system the world's steps may share their work with
    /// (impulse2d/tasks.hpp); null, the default, steps on the calling thread.
    /// The world does not own it: it must outlive the world or be replaced
    /// first. Results are bit-identical for any task system and worker count.
    /// Locked.
    void setTaskSystem(TaskSystem* tasks);
    TaskSystem* taskSystem() const;
    /// Set the gravity acceleration (m/s², locked), applied from the next step.
    /// Does not wake sleeping bodies. The weight a body no longer has is taken
    /// out of what its supports carry, so a pile whose gravity is turned off
    /// is not thrown up. Throws i2d::Error unless bounded.
    void setGravity(Vec2 gravity);
    /// Gravity acceleration (m/s²).
    Vec2 gravity() const;

    // ---- Bodies ---------------------------------------------------------

    /// Create a body without shapes (locked); it gets its mass from the shapes
    /// added later. A static body ignores the def's velocities, a body with
    /// fixedRotation its angular velocity. With isAwake false (and sleep
    /// enabled in the world and the def) the body starts asleep. Throws
    /// i2d::Error when position, angle (rad), linearVelocity (m/s),
    /// angularVelocity (rad/s) or gravityScale is not bounded, a damping (1/s)
    /// is negative or non-finite, or the type is not a BodyType value.
    BodyId createBody(const BodyDef& def);
    /// Destroys the body with its shapes, their contacts and the joints
    /// attached to it, waking the bodies at the other end of those joints
    /// (locked). Touching contacts add their end events to the event buffers.
    /// The load the body put on the contacts and joints below it is taken out
    /// of their warm start, so what it rested on does not jump. The handle
    /// becomes stale.
    void destroyBody(BodyId id);
    /// True when the handle names a live body; never throws.
    bool isValid(BodyId id) const;

    /// Static, kinematic or dynamic.
    BodyType bodyType(BodyId id) const;
    /// Change the body's type (locked): its contacts are dropped and found
    /// again by the next step, its mass is recomputed from its shapes (an
    /// override by setMassData is lost) and it is woken; a body made static
    /// loses its velocity. Throws i2d::Error for a type that is not a
    /// BodyType value.
    void setBodyType(BodyId id, BodyType type);
    /// Body origin (world, m).
    Vec2 position(BodyId id) const;
    /// Body angle (rad, counter-clockwise), in [−π, π].
    float angle(BodyId id) const;
    /// Body rotation (cosine and sine of the angle).
    Rot rotation(BodyId id) const;
    /// Body origin and rotation together.
    Transform transform(BodyId id) const;
    /// Teleport the body's origin to `position` (m) at `angle` (rad), keeping
    /// its velocity (locked). Wakes it and the bodies it touches; moving a
    /// static body also wakes the bodies near its shapes. A joint this leaves
    /// more than 5 cm open, off its axis or off its length, or 0.1 rad off its
    /// angle (as creating one so does), is closed over the next steps by
    /// moving the bodies without giving them a velocity (revolute, rigid weld,
    /// prismatic, wheel and rigid distance joints; docs/joints.md,
    /// "Stretched joints").
    /// Throws i2d::Error when position or angle is not bounded.
    void setTransform(BodyId id, Vec2 position, float angle);
    /// Centre of mass, world frame (m).
    Vec2 worldCenterOfMass(BodyId id) const;
    /// Centre of mass in the body frame, relative to the body origin (m).
    Vec2 localCenterOfMass(BodyId id) const;

    /// Velocity of the centre of mass (m/s).
    Vec2 linearVelocity(BodyId id) const;
    /// Angular velocity (rad/s, counter-clockwise).
    float angularVelocity(BodyId id) const;
    /// Set the velocity of the centre of mass (m/s, locked). Ignored for a
    /// static body; a non-zero velocity wakes the body. Throws i2d::Error
    /// unless bounded.
    void setLinearVelocity(BodyId id, Vec2 v);
    /// Set the angular velocity (rad/s, locked). Ignored for a static body and
    /// a body with fixed rotation; a non-zero value wakes the body. Throws
    /// i2d::Error unless bounded.
    void setAngularVelocity(BodyId id, float w);
    /// Velocity (m/s) of the world point `worldPoint` (m) if it moved with the
    /// body: v + ω × (worldPoint − centre of mass). Throws i2d::Error unless
    /// worldPoint is bounded.
    Vec2 velocityAtPoint(BodyId id, Vec2 worldPoint) const;

    /// Add a force (N) at a world point (m) for the next step, then it is
    /// cleared (locked). Only dynamic bodies are affected; with wake false a
    /// sleeping body ignores it. Throws i2d::Error unless force and point are
    /// bounded. A force applied in one step and not (or less) in the next no
    /// longer loads the contacts and joints that held the body against it:
    /// the body is not thrown back when the game lets go (its torque is not
    /// followed so).
    void applyForce(BodyId id, Vec2 force, Vec2 worldPoint, bool wake = true);
    /// applyForce at the centre of mass: no torque.
    void applyForceToCenter(BodyId id, Vec2 force, bool wake = true);
    /// Add a torque (N·m) for the next step, as applyForce. Throws i2d::Error
    /// unless bounded.
    void applyTorque(BodyId id, float torque, bool wake = true);
    /// Add an impulse (N·s) at a world point (m): the velocities change at once
    /// (locked). Only dynamic bodies are affected; with wake false a sleeping
    /// body ignores it. Throws i2d::Error unless impulse and point are bounded
    /// and the resulting velocities are too (a bounded impulse on a body of
    /// tiny mass can give it a velocity beyond 1e7 m/s: refused).
    void applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint, bool wake = true);
    /// applyLinearImpulse at the centre of mass: no change of angular velocity.
    void applyLinearImpulseToCenter(BodyId id, Vec2 impulse, bool wake = true);
    /// Add an angular impulse (N·m·s), as applyLinearImpulse. Throws
    /// i2d::Error unless bounded.
    void applyAngularImpulse(BodyId id, float impulse, bool wake = true);

    /// Mass (kg): 0 for static and kinematic bodies; 1 for a dynamic body
    /// whose shapes have no mass.
    float mass(BodyId id) const;
    /// Rotational inertia about the centre of mass (kg·m²).
    float rotationalInertia(BodyId id) const;
    /// Mass (kg), centre of mass (body frame, m) and rotational inertia about
    /// it (kg·m²).
    MassData massData(BodyId id) const;
    /// Override the mass computed from the shapes (locked). Creating or
    /// destroying a shape, setDensity, setFixedRotation and setBodyType later
    /// recompute it from the shapes. Throws i2d::Error for a body that is not
    /// dynamic; mass ≤ 0, non-finite, or too small to invert; a centre not
    /// bounded; inertia < 0, non-finite, or positive but too small to invert.
    /// Inertia 0 means no rotation.
    void setMassData(BodyId id, const MassData& massData);
    /// Recompute mass properties from the shapes' densities (locked).
    void resetMassData(BodyId id);

    /// Linear damping c (1/s): each (sub)step of length h scales the velocity
    /// by 1/(1 + h·c).
    float linearDamping(BodyId id) const;
    /// Throws i2d::Error when damping (1/s) is negative or non-finite.
    void setLinearDamping(BodyId id, float damping);
    /// Angular damping (1/s).
    float angularDamping(BodyId id) const;
    /// Throws i2d::Error when damping (1/s) is negative or non-finite.
    void setAngularDamping(BodyId id, float damping);
    /// Multiplier of the world's gravity for this body (dimensionless).
    float gravityScale(BodyId id) const;
    /// Any bounded value (negative makes the body fall up); the weight the
    /// body no longer has is released from its supports at the next step, as
    /// for setGravity. Throws i2d::Error when scale is not bounded.
    void setGravityScale(BodyId id, float scale);
    /// True when the body cannot rotate (infinite rotational inertia).
    bool isFixedRotation(BodyId id) const;
    /// Stop (true) or allow (false) the body's rotation (locked): sets the
    /// angular velocity to 0 when true and recomputes the mass from the shapes
    /// (an override by setMassData is lost).
    void setFixedRotation(BodyId id, bool flag);
    /// True when the body is a bullet (BodyDef::isBullet).
    bool isBullet(BodyId id) const;
    /// Make the body a bullet (swept against non-bullet dynamic bodies too) or not.
    void setBullet(BodyId id, bool flag);
    /// The value given in BodyDef::userData or by setUserData; never read by
    /// the engine.
    std::uintptr_t userData(BodyId id) const;
    /// Store any value with the body (a pointer or an index of the game's).
    void setUserData(BodyId id, std::uintptr_t data);

    /// False for static and sleeping bodies.
    bool isAwake(BodyId id) const;
    /// Wake the body (and the island it fell asleep with), or put this body to
    /// sleep at once (locked); ignored for static bodies.
    void setAwake(BodyId id, bool awake);
    /// Allow (true) or forbid (false) this body to sleep; forbidding wakes it.
    void enableSleep(BodyId id, bool flag);

    /// The body's shapes, in the order they were added.
    std::vector<ShapeId> bodyShapes(BodyId id) const;
    /// The body's contacts whose shapes touch (sensors excluded), with their
    /// manifolds and the impulses of the last step, in contact-slot order.
    std::vector<ContactData> bodyContacts(BodyId id) const;

    /// Take the body out of the simulation and out of every query, keeping
    /// it (and its shapes and joints) in memory (locked): its contacts end
    /// (end events with the next step), its shapes leave the broadphase, it
    /// stops moving and its joints act on nothing. Its state can still be
    /// read and set. Disabling a disabled body does nothing.
    void disableBody(BodyId id);
    /// Put a disabled body back into the simulation, awake (locked). Its
    /// contacts are found again by the next step. Enabling an enabled body
    /// does nothing.
    void enableBody(BodyId id);
    /// False while the body is disabled.
    bool isEnabled(BodyId id) const;

    /// The joints attached to the body, in the order they were created.
    std::vector<JointId> bodyJoints(BodyId id) const;
    /// Every live body, in creation-slot order.
    std::vector<BodyId> bodies() const;

    // ---- Shapes ---------------------------------------------------------

    // Every create*Shape attaches a shape given in the body frame (m) to
    // `body` and recomputes the body's mass from its shapes (locked). A
    // sleeping body stays asleep. Each throws i2d::Error when the ShapeDef
    // is out of range — density outside [0, 1e9] kg/m², friction outside
    // [0, 1e3], restitution outside [0, 1], any of them non-finite — or when
    // the geometry is refused as listed at each function.

    /// Throws i2d::Error when the centre is not bounded or the radius is not
    /// in (0, 1e5] m.
    ShapeId createCircleShape(BodyId body, const ShapeDef& def, const Circle& circle);
    /// Throws i2d::Error when a centre is not bounded, the radius is not in
    /// (0, 1e5] m, or the centres are no more than kLinearSlop (5 mm) apart
    /// (use a circle).
    ShapeId createCapsuleShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
    /// Build the polygon with makePolygon or makeBox. Throws i2d::Error for
    /// fewer than 3 or more than 8 vertices; a radius outside [0, 1e5] m;
    /// vertices or centroid not bounded; normals that are not unit length or
    /// not the outward normals of their edges; an edge shorter than 0.5 mm; a
    /// polygon that is not convex and counter-clockwise, thinner than 0.5 mm,
    /// or whose centroid lies outside it.
    ShapeId createPolygonShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
    /// Segments have no area: they add no mass and suit static bodies. Throws
    /// i2d::Error when a point is not bounded or the points are no more than
    /// kLinearSlop (5 mm) apart.
    ShapeId createSegmentShape(BodyId body, const ShapeDef& def, const Segment& segment);
    /// Creates the segments of a chain (ChainDef) on the body, in order (a
    /// loop's last segment joins the last point to the first), and returns
    /// them. Each is a segment shape (no mass) that collides on its right side
    /// only and smoothly across its joints; it can be inspected, changed and
    /// destroyed like any shape. Throws i2d::Error, creating nothing, when the
    /// body handle is invalid, there are fewer than 2 points (3 for a loop), a
    /// point is not bounded, two consecutive points are no more than
    /// kLinearSlop apart, the chain crosses, touches or folds back on itself,
    /// or friction or restitution is out of range.
    std::vector<ShapeId> createChain(BodyId body, const ChainDef& def);
    /// Destroy the shape and its contacts and wake its body (locked); with
    /// updateBodyMass false the body keeps its mass until resetMassData.
    void destroyShape(ShapeId id, bool updateBodyMass = true);
    /// True when the handle names a live shape; never throws.
    bool isValid(ShapeId id) const;

    /// Circle, capsule, segment or polygon.
    ShapeType shapeType(ShapeId id) const;
    /// The body the shape is attached to.
    BodyId shapeBody(ShapeId id) const;
    // The shape's geometry in its body frame. Each throws i2d::Error when the
    // shape is of another type (see shapeType).
    Circle shapeCircle(ShapeId id) const;
    Capsule shapeCapsule(ShapeId id) const;
    Polygon shapePolygon(ShapeId id) const;
    Segment shapeSegment(ShapeId id) const;
    /// True when the shape is a segment of a chain (createChain).
    bool isChainSegment(ShapeId id) const;
    /// A chain segment with its ghost vertices; throws i2d::Error for any other shape.
    ChainSegment shapeChainSegment(ShapeId id) const;
    /// Density (kg/m²).
    float density(ShapeId id) const;
    /// Set the density (kg/m², locked); with updateBodyMass the body's mass is
    /// recomputed at once, otherwise at the next resetMassData or shape change.
    /// Throws i2d::Error when density is outside [0, 1e9] or non-finite.
    void setDensity(ShapeId id, float density, bool updateBodyMass = true);
    /// Coulomb friction coefficient μ (dimensionless).
    float friction(ShapeId id) const;
    /// Contacts that already exist keep the friction mixed when they began
    /// (μ = √(μa·μb)); contacts that begin later use the new value. Throws i2d::Error when friction is outside [0, 1e3] or non-finite.
    void setFriction(ShapeId id, float friction);
    /// Coefficient of restitution e (dimensionless).
    float restitution(ShapeId id) const;
    /// Contacts that already exist keep the restitution mixed when they began
    /// (e = max(ea, eb)); contacts that begin later use the new value. Throws i2d::Error when restitution is outside [0, 1] or non-finite.
    void setRestitution(ShapeId id, float restitution);
    /// The shape's collision filter (categories, mask, group).
    Filter filter(ShapeId id) const;
    /// Change the collision filter (locked): the shape's contacts are dropped
    /// and the next step looks for its pairs again.
    void setFilter(ShapeId id, const Filter& filter);
    /// True for a sensor: it reports overlaps and makes no contact (fixed at creation).
    bool isSensor(ShapeId id) const;
    /// The value given in ShapeDef::userData or by setUserData; never read by the engine.
    std::uintptr_t userData(ShapeId id) const;
    /// Store any value with the shape (a pointer or an index of the game's).
    void setUserData(ShapeId id, std::uintptr_t data);
    /// Rolling resistance (ShapeDef::rollingResistance). Contacts that already
    /// exist keep the value mixed when they began.
    float rollingResistance(ShapeId id) const;
    /// Throws i2d::Error unless resistance is in [0, 1e3].
    void setRollingResistance(ShapeId id, float resistance);
    /// Surface speed along the contact tangent (ShapeDef::tangentSpeed, m/s).
    /// Applies to existing contacts from the next step.
    float tangentSpeed(ShapeId id) const;
    /// Throws i2d::Error unless speed is bounded.
    void setTangentSpeed(ShapeId id, float speed);
    /// The shape's tight bounding box at its body's current pose (world, m).
    AABB shapeAABB(ShapeId id) const;

    // ---- Joints ---------------------------------------------------------
    // Creating a joint (locked) wakes both bodies; unless collideConnected,
    // their existing contacts are dropped and their shapes stop colliding.
    // Every create… throws i2d::Error, creating nothing, when a body handle is
    // null, stale, forged or of another world, bodyA == bodyB, both bodies
    // are static, or a value is outside the range its definition gives
    // (impulse2d/joints.hpp): non-finite or unbounded anchors, axes or
    // targets, a zero axis, negative or non-finite hertz, damping ratio, force
    // or torque, a lower limit above the upper one.

    JointId createDistanceJoint(const DistanceJointDef& def);
    JointId createRevoluteJoint(const RevoluteJointDef& def);
    JointId createPrismaticJoint(const PrismaticJointDef& def);
    JointId createWeldJoint(const WeldJointDef& def);
    JointId createWheelJoint(const WheelJointDef& def);
    JointId createMotorJoint(const MotorJointDef& def);
    JointId createMouseJoint(const MouseJointDef& def);
    JointId createPulleyJoint(const PulleyJointDef& def);
    /// Also throws when either joint is not a revolute or prismatic joint,
    /// the two joints are the same, or the ratio is zero or not finite.
    JointId createGearJoint(const GearJointDef& def);

    /// Destroy the joint and wake both its bodies (locked); they may collide
    /// again from the next step. Gear joints built on it are destroyed too. A
    /// joint is also destroyed with either body.
    void destroyJoint(JointId id);
    /// True when the handle names a live joint of this world; never throws.
    bool isValid(JointId id) const;
    JointType jointType(JointId id) const;
    /// The joint's bodies (for a gear joint: the second bodies of its two joints).
    BodyId jointBodyA(JointId id) const;
    BodyId jointBodyB(JointId id) const;
    /// The value given in the definition's userData; never read by the engine.
    std::uintptr_t jointUserData(JointId id) const;
    void setJointUserData(JointId id, std::uintptr_t data);

    // Definitions: read back a joint's current definition, or change it
    // (locked; wakes both bodies). A new definition must name the same bodies
    // (and, for a gear, the same joints) and is checked as at creation; the
    // joint keeps its accumulated impulses unless a feature is turned off.
    // The getter and setter of another type than the joint's throw i2d::Error.

    DistanceJointDef distanceJointDef(JointId id) const;
    void setDistanceJointDef(JointId id, const DistanceJointDef& def);
    RevoluteJointDef revoluteJointDef(JointId id) const;
    void setRevoluteJointDef(JointId id, const RevoluteJointDef& def);
    PrismaticJointDef prismaticJointDef(JointId id) const;
    void setPrismaticJointDef(JointId id, const PrismaticJointDef& def);
    WeldJointDef weldJointDef(JointId id) const;
    void setWeldJointDef(JointId id, const WeldJointDef& def);
    WheelJointDef wheelJointDef(JointId id) const;
    void setWheelJointDef(JointId id, const WheelJointDef& def);
    MotorJointDef motorJointDef(JointId id) const;
    void setMotorJointDef(JointId id, const MotorJointDef& def);
    MouseJointDef mouseJointDef(JointId id) const;
    void setMouseJointDef(JointId id, const MouseJointDef& def);
    PulleyJointDef pulleyJointDef(JointId id) const;
    void setPulleyJointDef(JointId id, const PulleyJointDef& def);
    GearJointDef gearJointDef(JointId id) const;
    void setGearJointDef(JointId id, const GearJointDef& def);

    // Features that games change while running (locked; wake both bodies).

    /// Distance, revolute, prismatic and wheel joints: turn the limit on or off.
    void enableJointLimit(JointId id, bool flag);
    /// Revolute, prismatic and wheel joints: turn the motor on or off.
    void enableJointMotor(JointId id, bool flag);
    /// Distance, revolute, prismatic and wheel joints: turn the spring on or off.
    void enableJointSpring(JointId id, bool flag);
    /// Revolute and wheel joints (rad/s), prismatic joints (m/s); bounded.
    void setJointMotorSpeed(JointId id, float speed);
    /// Mouse joints: move the target (world, m; bounded).
    void setMouseJointTarget(JointId id, Vec2 target);
    /// Set the rest length (m, locked), reset the joint's accumulated impulse
    /// and wake both bodies. Throws i2d::Error unless length is in (0, 1e7].
    void setDistanceJointLength(JointId id, float length);

    // Joint state, from the bodies' current poses and velocities.

    /// Current distance between the anchors (m).
    float distanceJointCurrentLength(JointId id) const;
    /// angle(B) − angle(A) − referenceAngle, in (−π, π] (rad).
    float revoluteJointAngle(JointId id) const;
    /// ω_B − ω_A (rad/s).
    float revoluteJointSpeed(JointId id) const;
    /// Prismatic and wheel joints: anchor B's offset from anchor A along the axis (m).
    float jointTranslation(JointId id) const;
    /// Prismatic and wheel joints: the rate of the translation (m/s).
    float jointTranslationSpeed(JointId id) const;
    /// Pulley joints: the current lengths on each side (m).
    float pulleyJointLengthA(JointId id) const;
    float pulleyJointLengthB(JointId id) const;

    // What the joint did in the last step in which it was awake: the
    // accumulated impulse divided by the interval it acted over, which in
    // soft_step is the last substep (each substep solves anew from the warm
    // start, so these are the joint's forces at the end of the step, as a
    // force sensor would read them), the whole step otherwise.

    /// Force the joint applied to body B at its anchor (N, world).
    Vec2 jointReactionForce(JointId id) const;
    /// Torque the joint applied to body B (N·m).
    float jointReactionTorque(JointId id) const;
    /// Revolute and wheel joints: the motor's torque (N·m); prismatic: the motor's force (N).
    float jointMotorEffort(JointId id) const;
    /// Magnitude of the constraint force (N): |jointReactionForce|; for a
    /// distance joint, the magnitude of its axial force.
    float jointForce(JointId id) const;

    // ---- Events of the last step ----------------------------------------
    // Each list holds the events of the last step. It changes only when the
    // next step() begins, whatever is called in between: a span stays valid
    // and unchanged until then, so bodies and shapes may be destroyed while
    // iterating it. A contact reports events when either shape enables
    // contact events; a sensor pair when the sensor enables sensor events.
    //
    // Every begin event is followed by exactly one end event for the same
    // pair. Destroying a shape or body, disabling a body, creating a joint
    // (unless collideConnected), changing a filter or a body type between
    // steps ends the touching contacts they drop: those end events are
    // reported with the next step, before that step's own events.
    //
    // The handles in an end event name shapes that may no longer exist (the
    // shape or its body was destroyed): isValid(handle) is then false and
    // every other call with the handle throws i2d::Error. A stale handle never
    // names another shape, so it can still be compared with handles the game
    // kept (e.g. as a key of its own map).

    /// Pairs of shapes that began to touch in the last step, with their manifold.
    std::span<const ContactBeginEvent> contactBeginEvents() const;
    /// Pairs of shapes that stopped touching in the last step.
    std::span<const ContactEndEvent> contactEndEvents() const;
    /// Touching contacts that closed faster than WorldSettings::hitEventThreshold
    /// in the last step, for shapes that enable hit events.
    std::span<const ContactHitEvent> contactHitEvents() const;
    /// Shapes that began to overlap a sensor in the last step.
    std::span<const SensorBeginEvent> sensorBeginEvents() const;
    /// Shapes that stopped overlapping a sensor in the last step.
    std::span<const SensorEndEvent> sensorEndEvents() const;

    // ---- Callbacks ------------------------------------------------------
    // Both are called inside step() while the world is locked: they may read
    // the world (positions, velocities, user data, queries) but not change
    // it: a locked call throws i2d::Error, which leaves step() with that
    // step unfinished (its bodies not moved). A callback should not throw
    // for the same reason. A world without callbacks pays nothing for them;
    // an empty function removes one.

    /// A filter called when the broadphase finds a new pair that passes the
    /// shapes' Filters (and joints and sensors): return false and the pair
    /// makes no contact. Called again only when the shapes' boxes part and
    /// meet again, or after setFilter on either shape.
    void setCustomFilter(CustomFilterFn fn);
    /// Called each step for each contact whose shapes touch (sensors
    /// excluded; manifold with points), after its manifold is computed:
    /// return false to switch the contact off for this step. One-way
    /// platforms: switch off contacts whose normal does not push the body up
    /// (docs/guide.md). Called for contacts with an awake body only. A
    /// contact whose body the step's impact stage strikes may gain points
    /// at the new velocity (docs/impacts.md): it is called again with that
    /// manifold, and false then keeps the one it had.
    void setPreSolve(PreSolveFn fn);

    // ---- Queries --------------------------------------------------------
    // Queries read the world and may be called from inside draw. Each throws
    // i2d::Error when a point, translation or box corner (m) is not bounded.
    // Disabled bodies are never reported. A QueryFilter's accept is called
    // with the world locked.

    /// Closest shape hit by the ray origin → origin + translation (world, m);
    /// sensors are skipped, and so is a shape the ray starts inside. On equal
    /// fractions the shape created in the lower slot wins.
    std::optional<RayResult> rayCastClosest(Vec2 origin, Vec2 translation, const QueryFilter& filter = {}) const;
    /// Any shape the ray hits (sensors skipped), the first one found: the
    /// cheapest test of whether a line of sight is blocked.
    std::optional<RayResult> rayCastAny(Vec2 origin, Vec2 translation, const QueryFilter& filter = {}) const;
    /// Every shape the ray hits (sensors skipped), nearest first.
    std::vector<RayResult> rayCastAll(Vec2 origin, Vec2 translation, const QueryFilter& filter = {}) const;
    /// Shapes whose tight bounding boxes overlap the box (sensors included),
    /// in slot order.
    std::vector<ShapeId> overlapAABB(const AABB& box, const QueryFilter& filter = {}) const;
    /// Solid shapes containing the point, boundary included (segments never;
    /// sensors included), in slot order.
    std::vector<ShapeId> queryPoint(Vec2 point, const QueryFilter& filter = {}) const;

    /// Sweep `proxy` (world) along `translation` (m) and return the first
    /// shape it touches (sensors skipped): the fraction at which the gap
    /// between the surfaces has closed to within 0.1·kLinearSlop (0.5 mm)
    /// — never past the touch —, the point on the hit shape and its outward
    /// normal. A proxy that already touches a shape at its start hits it at
    /// fraction 0 (normal: from that shape towards the proxy where the
    /// surfaces are apart, −translation's direction where they overlap). On
    /// equal fractions the lower slot wins. Throws i2d::Error when
    /// translation or a proxy point is not bounded, the proxy has no points
    /// or more than kMaxPolygonVertices, or its radius is negative, not
    /// finite or over 1e5 m.
    std::optional<ShapeCastResult> castShape(const ShapeProxy& proxy, Vec2 translation,
                                             const QueryFilter& filter = {}) const;
    /// Shapes that overlap `proxy` (world; surfaces touching counts), sensors
    /// included, in slot order. Segments count as thin solids. Throws as
    /// castShape for a bad proxy.
    std::vector<ShapeId> overlapShape(const ShapeProxy& proxy, const QueryFilter& filter = {}) const;

    // ---- The character mover (impulse2d/mover.hpp) ----------------------

    /// The planes of the shapes (sensors skipped) that a capsule (world, m)
    /// touches or overlaps: for each, the normal from the shape's nearest
    /// point towards the capsule's core and the overlap depth. A shape whose
    /// core the capsule's core crosses has no normal and gives no plane.
    /// In slot order. Throws i2d::Error unless the centres are bounded and
    /// the radius is in (0, 1e5] m.
    std::vector<CollisionPlane> collideMover(const Capsule& mover, const QueryFilter& filter = {}) const;
    /// How far (fraction of `translation`, in [0, 1]) the capsule (world)
    /// can move before it would overlap a shape (sensors skipped) by more
    /// than kLinearSlop. Shapes it already overlaps that much are left to
    /// collideMover's planes (they do not stop the cast). Throws i2d::Error
    /// as collideMover, or when translation is not bounded.
    float castMover(const Capsule& mover, Vec2 translation, const QueryFilter& filter = {}) const;

    // ---- Helpers --------------------------------------------------------

    /// Push dynamic bodies away from a point (locked); see ExplosionDef.
    /// Each shape within radius + falloff of the centre (by its nearest
    /// point) gives its body `impulse` scaled by the falloff, directed from the
    /// centre to that point (to the shape's body centre when the centre is
    /// inside the shape), applied at that point; bodies are woken. Throws
    /// i2d::Error, changing nothing, when the centre is not bounded; radius,
    /// falloff or impulse is negative, not finite or over 1e7; or an impulse
    /// would give a body a velocity beyond the bounds applyLinearImpulse
    /// accepts.
    void explode(const ExplosionDef& def);

    // ---- Inspection -----------------------------------------------------

    /// Live bodies of every type.
    int bodyCount() const;
    /// Awake non-static bodies (the ones the next step moves).
    int awakeBodyCount() const;
    /// Live shapes, sensors included.
    int shapeCount() const;
    /// Live joints.
    int jointCount() const;
    /// Non-sensor contacts whose shapes touch (manifold with at least one point).
    int contactCount() const;
    /// The same contacts with their manifolds and accumulated impulses, in slot order.
    std::vector<ContactData> contacts() const;
    /// Time spent in each stage of the last step (ms).
    const Profile& profile() const;
    /// Draw every shape (but those of disabled bodies), joint and (by the
    /// drawer's flags) AABB and contact, in world coordinates. While it runs, the world is locked: a drawer
    /// that calls a locked function gets i2d::Error.
    void draw(DebugDraw& drawer) const;

private:
    [[noreturn]] static void throwMovedFrom();
    /// The world's state; throws i2d::Error for a moved-from World.
    detail::WorldState& state() const {
        if (!state_) throwMovedFrom();
        return *state_;
    }

    std::unique_ptr<detail::WorldState> state_;
};

}  // namespace i2d
