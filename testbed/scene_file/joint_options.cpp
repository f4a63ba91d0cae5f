// Testbed — a joint's optional features in a scene file: the spring, limit
// and motor objects (present = enabled) and collide_connected. Joints and the
// chain and grid generators share them (see parts.hpp).
#include <cmath>
#include <numbers>

#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

namespace {

constexpr double kPi = std::numbers::pi;

// "spring": {hertz, damping_ratio}; absent leaves the definition's setting.
// `mayBeFalse`: the wheel's spring is on by default, `"spring": false` turns it off.
void readSpring(const Obj& o, bool& enable, float& hertz, float& dampingRatio, bool mayBeFalse) {
    if (!o.has("spring")) return;
    const json& v = o.get("spring");
    if (mayBeFalse && v.is_boolean()) {
        if (v.get<bool>()) fail(o.at("spring"), "expected an object {hertz, damping_ratio} or false");
        enable = false;
        return;
    }
    Obj sp(v, o.at("spring"), {"comment", "hertz", "damping_ratio"});
    sp.checkUnknown();
    enable = true;
    hertz = sp.f("hertz", hertz, {0, kMaxRate});
    dampingRatio = sp.f("damping_ratio", dampingRatio, {0, kMaxRate});
}

// "limit": {LOWER, UPPER}, both required, LOWER ≤ UPPER.
void readLimit(const Obj& o, const char* lowerKey, const char* upperKey, const Range& r, bool& enable, float& lower,
               float& upper) {
    if (!o.has("limit")) return;
    Obj li(o.get("limit"), o.at("limit"), {"comment", lowerKey, upperKey});
    li.checkUnknown();
    enable = true;
    lower = li.reqF(lowerKey, r);
    upper = li.reqF(upperKey, r);
    if (lower > upper)
        fail(li.at(lowerKey),
             fmt(lower) + " is above " + upperKey + " " + fmt(upper) + " (must be ≤ " + upperKey + ")");
}

// "motor": {motor_speed (default 0), MAX (required)}.
void readMotor(const Obj& o, const char* maxKey, double maxSpeed, bool& enable, float& speed, float& maxEffort) {
    if (!o.has("motor")) return;
    Obj mo(o.get("motor"), o.at("motor"), {"comment", "motor_speed", maxKey});
    mo.checkUnknown();
    enable = true;
    speed = mo.f("motor_speed", 0.0f, {-maxSpeed, maxSpeed});
    maxEffort = mo.reqF(maxKey, {0, kMaxForce});
}

void readDistanceOptions(const Obj& o, i2d::DistanceJointDef& d, bool& hasLength) {
    if (o.has("length")) {
        hasLength = true;
        d.length = o.reqF("length", {0, kMaxSize, true});
        if (d.length < i2d::kLinearSlop) fail(o.at("length"), "a joint length must be at least 0.005 m");
    }
    readSpring(o, d.enableSpring, d.hertz, d.dampingRatio, false);  // hertz 0 + a limit: a rope
    if (o.has("limit")) {
        Obj li(o.get("limit"), o.at("limit"), {"comment", "min", "max"});
        li.checkUnknown();
        d.enableLimit = true;
        d.minLength = li.f("min", 0.0f, {0, kMaxSize});
        d.maxLength = li.f("max", static_cast<float>(kMaxSize), {0, kMaxSize});
        if (d.maxLength < d.minLength) fail(li.at("max"), "limit max must be ≥ min");
    }
}

}  // namespace

JointDefs defaultJointDef(i2d::JointType type) {
    switch (type) {
        case i2d::JointType::distance: return i2d::DistanceJointDef{};
        case i2d::JointType::revolute: return i2d::RevoluteJointDef{};
        case i2d::JointType::prismatic: return i2d::PrismaticJointDef{};
        case i2d::JointType::weld: return i2d::WeldJointDef{};
        case i2d::JointType::wheel: return i2d::WheelJointDef{};
        case i2d::JointType::motor: return i2d::MotorJointDef{};
        case i2d::JointType::mouse: return i2d::MouseJointDef{};
        case i2d::JointType::pulley: return i2d::PulleyJointDef{};
        case i2d::JointType::gear: return i2d::GearJointDef{};
    }
    return i2d::DistanceJointDef{};
}

void allowJointOptions(Obj& o, i2d::JointType type) {
    o.allow({"collide_connected"});
    switch (type) {
        case i2d::JointType::distance: o.allow({"length", "spring", "limit"}); break;
        case i2d::JointType::revolute:
        case i2d::JointType::prismatic:
        case i2d::JointType::wheel: o.allow({"spring", "limit", "motor"}); break;
        default: break;
    }
}

void parseJointOptions(const Obj& o, PendingJoint& pj) {
    const Range angle{-0.99 * kPi, 0.99 * kPi};
    const Range translation{-kMaxSize, kMaxSize};
    std::visit(
        [&](auto& d) {
            using D = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<D, i2d::DistanceJointDef>) {
                readDistanceOptions(o, d, pj.hasLength);
            } else if constexpr (std::is_same_v<D, i2d::RevoluteJointDef>) {
                readSpring(o, d.enableSpring, d.hertz, d.dampingRatio, false);
                readLimit(o, "lower_angle", "upper_angle", angle, d.enableLimit, d.lowerAngle, d.upperAngle);
                readMotor(o, "max_motor_torque", kMaxSpeed, d.enableMotor, d.motorSpeed, d.maxMotorTorque);
            } else if constexpr (std::is_same_v<D, i2d::PrismaticJointDef>) {
                readSpring(o, d.enableSpring, d.hertz, d.dampingRatio, false);
                readLimit(o, "lower_translation", "upper_translation", translation, d.enableLimit, d.lowerTranslation,
                          d.upperTranslation);
                readMotor(o, "max_motor_force", kMaxSpeed, d.enableMotor, d.motorSpeed, d.maxMotorForce);
            } else if constexpr (std::is_same_v<D, i2d::WheelJointDef>) {
                readSpring(o, d.enableSpring, d.hertz, d.dampingRatio, true);
                readLimit(o, "lower_translation", "upper_translation", translation, d.enableLimit, d.lowerTranslation,
                          d.upperTranslation);
                readMotor(o, "max_motor_torque", kMaxSpeed, d.enableMotor, d.motorSpeed, d.maxMotorTorque);
            }
            d.collideConnected = o.boolean("collide_connected", false);
        },
        pj.def);
}

}  // namespace tb::scene_file
