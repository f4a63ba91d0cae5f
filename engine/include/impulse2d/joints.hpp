// Impulse2D — joint definitions: what each joint type constrains, with its
// defaults, units and valid ranges. A definition is a plain aggregate: fill in
// what differs, then World::create…Joint (docs/joints.md shows each type).
//
// Common to every definition:
//   bodyA, bodyB       two different bodies of the same world, not both static
//                      (for a gear joint they are taken from its two joints)
//   localAnchorA/B     anchor points in the bodies' frames, relative to their
//                      origins (m), bounded (|x| ≤ 1e7)
//   collideConnected   whether the two bodies' shapes still collide
//   userData           anything the game wants to keep with the joint
// Rigid parts of a joint are softened like contacts in soft_step
// (WorldSettings::jointHertz, jointDampingRatio; an exact tree of hinges and
// rigid welds touching nothing is rigid, WorldSettings::exactJointMassRatio)
// and pushed by the push factor in baumgarte and split. Springs, motors and limits are optional features,
// each off unless enabled.
#pragma once

#include <cstdint>

#include "impulse2d/id.hpp"
#include "impulse2d/math.hpp"

namespace i2d {

enum class JointType : std::uint8_t { distance, revolute, prismatic, weld, wheel, motor, mouse, pulley, gear };

/// Distance constraint between two anchor points (Tamis and Maggiore (2015),
/// Constraint based physics solver, §5.2). Rigid by default; with
/// enableSpring it becomes a spring of the given frequency and damping ratio;
/// with enableLimit its length is kept within [minLength, maxLength] (a rope:
/// enableSpring with hertz 0 and a limit).
struct DistanceJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};  ///< relative to body A's origin, body frame
    Vec2 localAnchorB{};
    float length = 1.0f;  ///< rest length (m), > 0
    bool enableSpring = false;
    float hertz = 0.0f;         ///< spring frequency (Hz), ≥ 0; 0 = no spring force
    float dampingRatio = 0.0f;  ///< ≥ 0
    bool enableLimit = false;
    float minLength = 0.0f;    ///< m, ≥ 0
    float maxLength = 1.0e9f;  ///< m, ≥ minLength
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// A hinge: the anchors coincide, the bodies turn freely about them. The joint
/// angle is angle(B) − angle(A) − referenceAngle (rad, counter-clockwise).
struct RevoluteJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};
    Vec2 localAnchorB{};
    float referenceAngle = 0.0f;  ///< angle(B) − angle(A) at which the joint angle is 0 (rad), |·| ≤ π
    bool enableLimit = false;
    float lowerAngle = 0.0f;  ///< rad, in [−0.99π, 0.99π], ≤ upperAngle
    float upperAngle = 0.0f;  ///< rad, in [−0.99π, 0.99π]
    bool enableMotor = false;
    float motorSpeed = 0.0f;      ///< target of the joint's angular speed (rad/s)
    float maxMotorTorque = 0.0f;  ///< N·m, ≥ 0
    bool enableSpring = false;    ///< a rotational spring towards joint angle 0
    float hertz = 0.0f;           ///< Hz, ≥ 0
    float dampingRatio = 0.0f;    ///< ≥ 0
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// A slider: body B moves along an axis fixed in body A and keeps its angle
/// relative to A. Translation is measured along the axis from anchor A to anchor B (m).
struct PrismaticJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};
    Vec2 localAnchorB{};
    Vec2 localAxisA{1.0f, 0.0f};  ///< in body A's frame; normalised, must not be zero
    float referenceAngle = 0.0f;  ///< angle(B) − angle(A) that is held (rad)
    bool enableLimit = false;
    float lowerTranslation = 0.0f;  ///< m, ≤ upperTranslation
    float upperTranslation = 0.0f;  ///< m
    bool enableMotor = false;
    float motorSpeed = 0.0f;     ///< target translation speed (m/s)
    float maxMotorForce = 0.0f;  ///< N, ≥ 0
    bool enableSpring = false;   ///< a spring towards translation 0
    float hertz = 0.0f;          ///< Hz, ≥ 0
    float dampingRatio = 0.0f;   ///< ≥ 0
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// Glues two bodies: the anchors coincide and the relative angle is held.
/// Rigid when a hertz is 0; soft (a spring) with a positive linear or angular hertz.
struct WeldJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};
    Vec2 localAnchorB{};
    float referenceAngle = 0.0f;       ///< angle(B) − angle(A) that is held (rad)
    float linearHertz = 0.0f;          ///< Hz, ≥ 0; 0 = rigid
    float linearDampingRatio = 0.0f;   ///< ≥ 0
    float angularHertz = 0.0f;         ///< Hz, ≥ 0; 0 = rigid
    float angularDampingRatio = 0.0f;  ///< ≥ 0
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// A wheel on a suspension: anchor B stays on the line through anchor A along
/// the axis (fixed in A), a spring along the axis holds it, and the wheel
/// turns freely or by a motor. Translation as for the prismatic joint.
struct WheelJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};
    Vec2 localAnchorB{};
    Vec2 localAxisA{0.0f, 1.0f};  ///< suspension axis in body A's frame; must not be zero
    bool enableSpring = true;
    float hertz = 1.0f;         ///< suspension frequency (Hz), ≥ 0
    float dampingRatio = 0.7f;  ///< ≥ 0
    bool enableLimit = false;
    float lowerTranslation = 0.0f;  ///< m, ≤ upperTranslation
    float upperTranslation = 0.0f;  ///< m
    bool enableMotor = false;
    float motorSpeed = 0.0f;      ///< target of the wheel's angular speed relative to A (rad/s)
    float maxMotorTorque = 0.0f;  ///< N·m, ≥ 0
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// Drives body B towards a position and angle relative to body A with limited
/// force and torque. With correctionFactor 0 it only resists relative motion
/// up to maxForce and maxTorque: against a static body, top-down friction (a
/// body sliding on the ground seen from above).
struct MotorJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 linearOffset{};            ///< B's origin from A's origin, in A's frame (m)
    float angularOffset = 0.0f;     ///< angle(B) − angle(A) (rad)
    float maxForce = 1.0f;          ///< N, ≥ 0
    float maxTorque = 1.0f;         ///< N·m, ≥ 0
    float correctionFactor = 0.3f;  ///< fraction of the offset error corrected per step, in [0, 1]
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// Pulls a point of body B towards a target in the world with a spring of
/// limited force (dragging a body with the mouse). bodyA is only a reference
/// (usually a static body); the target is in world coordinates.
struct MouseJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 target{};              ///< world point (m); body B's anchor is the point of B there at creation
    float hertz = 5.0f;         ///< Hz, > 0
    float dampingRatio = 0.7f;  ///< ≥ 0
    float maxForce = 1000.0f;   ///< N, ≥ 0 (a few times the body's weight)
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// Two bodies hung from two fixed ground points by one rope over pulleys:
/// lengthA + ratio·lengthB stays constant, lengthX the distance from ground
/// anchor X to body X's anchor.
struct PulleyJointDef {
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 groundAnchorA{};  ///< world point (m)
    Vec2 groundAnchorB{};
    Vec2 localAnchorA{};
    Vec2 localAnchorB{};
    float lengthA = 1.0f;  ///< rest length on A's side (m), > 0
    float lengthB = 1.0f;  ///< m, > 0
    float ratio = 1.0f;    ///< > 0 and finite
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

/// Couples two revolute or prismatic joints: coordinate1 + ratio·coordinate2
/// stays constant (angles in rad, translations in m), so with two revolutes
/// ω₂ = −ω₁/ratio. The gear's bodies are the second bodies (bodyB) of the
/// two joints; their first bodies are the frames the coordinates are measured
/// in. Destroying either joint destroys the gear.
struct GearJointDef {
    JointId joint1{};
    JointId joint2{};
    float ratio = 1.0f;  ///< non-zero and finite
    bool collideConnected = false;
    std::uintptr_t userData = 0;
};

}  // namespace i2d
