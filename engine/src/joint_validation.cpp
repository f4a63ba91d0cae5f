// Checks of the joint definitions' values (see joint_validation.hpp and the
// ranges in impulse2d/joints.hpp).
#include "joint_validation.hpp"

#include <cmath>

#include "validation.hpp"

namespace i2d::detail {

namespace {

constexpr float kPi = 3.1415927f;  // π rounded up in single precision

/// Largest force, torque or speed accepted: finite and far beyond any use.
constexpr float kMaxEffort = 1.0e30f;

void requireEffort(float v, const char* name) { requireInRange(v, 0.0f, kMaxEffort, name); }
void requireSpring(float hertz, float dampingRatio) {
    requireInRange(hertz, 0.0f, kMaxRate, "joint hertz");
    requireInRange(dampingRatio, 0.0f, kMaxRate, "joint damping ratio");
}
void requireAxis(Vec2 axis) {
    requireBounded(axis, "joint axis");
    if (!(lengthSquared(axis) > 1.0e-12f)) fail("joint axis must not be zero");
}
void requireRange(float lower, float upper, const char* lowerName, const char* upperName) {
    requireBounded(lower, lowerName);
    requireBounded(upper, upperName);
    if (lower > upper) fail(std::string("joint ") + lowerName + " must be <= " + upperName);
}
void requireAnchors(Vec2 a, Vec2 b) {
    requireBounded(a, "localAnchorA");
    requireBounded(b, "localAnchorB");
}

}  // namespace

void validateJointDef(const DistanceJointDef& def) {
    requireAnchors(def.localAnchorA, def.localAnchorB);
    requireBounded(def.length, "joint length");
    if (!(def.length > 0.0f)) fail("joint length must be > 0");
    requireSpring(def.hertz, def.dampingRatio);
    requireNonNegative(def.minLength, "joint minLength");
    if (!(def.maxLength >= 0.0f) || std::isnan(def.maxLength)) fail("joint maxLength must be >= 0");
    // Always, as the other joints' ranges: a limit enabled later (World::enableJointLimit) would
    // otherwise hold neither bound, and the def read back could not be set again.
    if (def.minLength > def.maxLength) fail("joint minLength must be <= maxLength");
}

void validateJointDef(const RevoluteJointDef& def) {
    requireAnchors(def.localAnchorA, def.localAnchorB);
    requireInRange(def.referenceAngle, -kPi, kPi, "joint referenceAngle");
    requireInRange(def.lowerAngle, -0.99f * kPi, 0.99f * kPi, "joint lowerAngle");
    requireInRange(def.upperAngle, -0.99f * kPi, 0.99f * kPi, "joint upperAngle");
    requireRange(def.lowerAngle, def.upperAngle, "lowerAngle", "upperAngle");
    requireBounded(def.motorSpeed, "joint motorSpeed");
    requireEffort(def.maxMotorTorque, "joint maxMotorTorque");
    requireSpring(def.hertz, def.dampingRatio);
}

void validateJointDef(const PrismaticJointDef& def) {
    requireAnchors(def.localAnchorA, def.localAnchorB);
    requireAxis(def.localAxisA);
    requireInRange(def.referenceAngle, -kPi, kPi, "joint referenceAngle");
    requireRange(def.lowerTranslation, def.upperTranslation, "lowerTranslation", "upperTranslation");
    requireBounded(def.motorSpeed, "joint motorSpeed");
    requireEffort(def.maxMotorForce, "joint maxMotorForce");
    requireSpring(def.hertz, def.dampingRatio);
}

void validateJointDef(const WeldJointDef& def) {
    requireAnchors(def.localAnchorA, def.localAnchorB);
    requireInRange(def.referenceAngle, -kPi, kPi, "joint referenceAngle");
    requireSpring(def.linearHertz, def.linearDampingRatio);
    requireSpring(def.angularHertz, def.angularDampingRatio);
}

void validateJointDef(const WheelJointDef& def) {
    requireAnchors(def.localAnchorA, def.localAnchorB);
    requireAxis(def.localAxisA);
    requireSpring(def.hertz, def.dampingRatio);
    requireRange(def.lowerTranslation, def.upperTranslation, "lowerTranslation", "upperTranslation");
    requireBounded(def.motorSpeed, "joint motorSpeed");
    requireEffort(def.maxMotorTorque, "joint maxMotorTorque");
}

void validateJointDef(const MotorJointDef& def) {
    requireBounded(def.linearOffset, "joint linearOffset");
    requireInRange(def.angularOffset, -kPi, kPi, "joint angularOffset");
    requireEffort(def.maxForce, "joint maxForce");
    requireEffort(def.maxTorque, "joint maxTorque");
    requireUnitInterval(def.correctionFactor, "joint correctionFactor");
}

void validateJointDef(const MouseJointDef& def) {
    requireBounded(def.target, "joint target");
    requireInRange(def.hertz, 0.0f, kMaxRate, "joint hertz");
    if (!(def.hertz > 0.0f)) fail("mouse joint hertz must be > 0");
    requireInRange(def.dampingRatio, 0.0f, kMaxRate, "joint damping ratio");
    requireEffort(def.maxForce, "joint maxForce");
}

void validateJointDef(const PulleyJointDef& def) {
    requireBounded(def.groundAnchorA, "joint groundAnchorA");
    requireBounded(def.groundAnchorB, "joint groundAnchorB");
    requireAnchors(def.localAnchorA, def.localAnchorB);
    requireBounded(def.lengthA, "joint lengthA");
    requireBounded(def.lengthB, "joint lengthB");
    if (!(def.lengthA > 0.0f) || !(def.lengthB > 0.0f)) fail("pulley joint lengths must be > 0");
    requireBounded(def.ratio, "joint ratio");
    if (!(def.ratio > 0.0f)) fail("pulley joint ratio must be > 0");
}

void validateJointDef(const GearJointDef& def) {
    requireBounded(def.ratio, "joint ratio");
    if (def.ratio == 0.0f) fail("gear joint ratio must not be zero");
}

}  // namespace i2d::detail
