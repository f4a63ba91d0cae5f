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
// Errors: see error.hpp — a refused call throws i2d::Error and changes nothing.
// Threading: a World is not thread-safe; different worlds may be used from
// different threads. Determinism: the same build, the same calls in the same
// order give bit-identical results.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "impulse2d/debug_draw.hpp"
#include "impulse2d/error.hpp"
#include "impulse2d/geometry.hpp"
#include "impulse2d/types.hpp"

namespace i2d {

namespace detail {
struct WorldState;
}

class World {
public:
    explicit World(const WorldSettings& settings = {});
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // ---- Stepping -------------------------------------------------------

    /// Advance the world by dt seconds (finite, in [1e-6, 1]; use a fixed
    /// value, usually 1/60). Runs: broadphase pairs → narrowphase → impacts →
    /// velocity solve → integrate → position correction → continuous
    /// collision of fast bodies against static shapes → sleep. Events of this step are
    /// readable afterwards until the next step.
    void step(float dt);

    /// Current settings; changes apply from the next step. setSettings checks them.
    const WorldSettings& settings() const;
    void setSettings(const WorldSettings& settings);
    void setGravity(Vec2 gravity);
    Vec2 gravity() const;

    // ---- Bodies ---------------------------------------------------------

    BodyId createBody(const BodyDef& def);
    /// Destroys the body with its shapes and the joints attached to it.
    void destroyBody(BodyId id);
    bool isValid(BodyId id) const;

    BodyType bodyType(BodyId id) const;
    void setBodyType(BodyId id, BodyType type);
    /// Body origin (world) and rotation.
    Vec2 position(BodyId id) const;
    float angle(BodyId id) const;
    Rot rotation(BodyId id) const;
    Transform transform(BodyId id) const;
    /// Teleport the body (wakes it).
    void setTransform(BodyId id, Vec2 position, float angle);
    /// Centre of mass in world and body frames.
    Vec2 worldCenterOfMass(BodyId id) const;
    Vec2 localCenterOfMass(BodyId id) const;

    Vec2 linearVelocity(BodyId id) const;
    float angularVelocity(BodyId id) const;
    void setLinearVelocity(BodyId id, Vec2 v);
    void setAngularVelocity(BodyId id, float w);
    /// Velocity of a world point attached to the body.
    Vec2 velocityAtPoint(BodyId id, Vec2 worldPoint) const;

    /// Forces and torques act during the next step, then are cleared.
    void applyForce(BodyId id, Vec2 force, Vec2 worldPoint, bool wake = true);
    void applyForceToCenter(BodyId id, Vec2 force, bool wake = true);
    void applyTorque(BodyId id, float torque, bool wake = true);
    /// Impulses change the velocity at once.
    void applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint, bool wake = true);
    void applyLinearImpulseToCenter(BodyId id, Vec2 impulse, bool wake = true);
    void applyAngularImpulse(BodyId id, float impulse, bool wake = true);

    float mass(BodyId id) const;
    /// Rotational inertia about the centre of mass (kg·m²).
    float rotationalInertia(BodyId id) const;
    MassData massData(BodyId id) const;
    /// Override the mass computed from the shapes (mass > 0, inertia ≥ 0 for dynamic bodies).
    void setMassData(BodyId id, const MassData& massData);
    /// Recompute mass properties from the shapes' densities.
    void resetMassData(BodyId id);

    float linearDamping(BodyId id) const;
    void setLinearDamping(BodyId id, float damping);
    float angularDamping(BodyId id) const;
    void setAngularDamping(BodyId id, float damping);
    float gravityScale(BodyId id) const;
    void setGravityScale(BodyId id, float scale);
    bool isFixedRotation(BodyId id) const;
    void setFixedRotation(BodyId id, bool flag);
    std::uintptr_t userData(BodyId id) const;
    void setUserData(BodyId id, std::uintptr_t data);

    bool isAwake(BodyId id) const;
    void setAwake(BodyId id, bool awake);
    void enableSleep(BodyId id, bool flag);

    std::vector<ShapeId> bodyShapes(BodyId id) const;
    std::vector<JointId> bodyJoints(BodyId id) const;
    /// Every live body, in creation-slot order.
    std::vector<BodyId> bodies() const;

    // ---- Shapes ---------------------------------------------------------

    ShapeId createCircleShape(BodyId body, const ShapeDef& def, const Circle& circle);
    ShapeId createCapsuleShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
    ShapeId createPolygonShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
    /// Segments have no area: they add no mass and suit static bodies.
    ShapeId createSegmentShape(BodyId body, const ShapeDef& def, const Segment& segment);
    void destroyShape(ShapeId id, bool updateBodyMass = true);
    bool isValid(ShapeId id) const;

    ShapeType shapeType(ShapeId id) const;
    BodyId shapeBody(ShapeId id) const;
    Circle shapeCircle(ShapeId id) const;
    Capsule shapeCapsule(ShapeId id) const;
    Polygon shapePolygon(ShapeId id) const;
    Segment shapeSegment(ShapeId id) const;
    float density(ShapeId id) const;
    void setDensity(ShapeId id, float density, bool updateBodyMass = true);
    float friction(ShapeId id) const;
    void setFriction(ShapeId id, float friction);
    float restitution(ShapeId id) const;
    void setRestitution(ShapeId id, float restitution);
    Filter filter(ShapeId id) const;
    void setFilter(ShapeId id, const Filter& filter);
    bool isSensor(ShapeId id) const;
    std::uintptr_t userData(ShapeId id) const;
    AABB shapeAABB(ShapeId id) const;

    // ---- Joints ---------------------------------------------------------

    JointId createDistanceJoint(const DistanceJointDef& def);
    void destroyJoint(JointId id);
    bool isValid(JointId id) const;
    BodyId jointBodyA(JointId id) const;
    BodyId jointBodyB(JointId id) const;
    DistanceJointDef distanceJointDef(JointId id) const;
    /// Current distance between the anchors (m).
    float distanceJointCurrentLength(JointId id) const;
    void setDistanceJointLength(JointId id, float length);
    /// Magnitude of the constraint force over the last step (N).
    float jointForce(JointId id) const;

    // ---- Events of the last step ----------------------------------------

    std::span<const ContactBeginEvent> contactBeginEvents() const;
    std::span<const ContactEndEvent> contactEndEvents() const;
    std::span<const SensorBeginEvent> sensorBeginEvents() const;
    std::span<const SensorEndEvent> sensorEndEvents() const;

    // ---- Queries --------------------------------------------------------

    /// Closest shape hit by the ray origin → origin + translation.
    std::optional<RayResult> rayCastClosest(Vec2 origin, Vec2 translation, const QueryFilter& filter = {}) const;
    /// Every shape the ray hits, nearest first.
    std::vector<RayResult> rayCastAll(Vec2 origin, Vec2 translation, const QueryFilter& filter = {}) const;
    /// Shapes whose bounding boxes overlap the box.
    std::vector<ShapeId> overlapAABB(const AABB& box, const QueryFilter& filter = {}) const;
    /// Shapes containing the point.
    std::vector<ShapeId> queryPoint(Vec2 point, const QueryFilter& filter = {}) const;

    // ---- Inspection -----------------------------------------------------

    int bodyCount() const;
    int awakeBodyCount() const;
    int shapeCount() const;
    int jointCount() const;
    /// Contacts whose shapes touch (manifold with at least one point).
    int contactCount() const;
    std::vector<ContactData> contacts() const;
    const Profile& profile() const;
    /// Draw every shape, joint and (by the flags) AABB and contact.
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
