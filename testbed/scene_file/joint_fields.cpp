// Testbed — the fields of each joint type in a scene file (see parts.hpp and
// docs/scene-format.md, "Joints"). Ranges follow the engine's checks
// (impulse2d/joints.hpp), so a file the loader takes is one the engine takes.
#include <cmath>
#include <numbers>
#include <tuple>

#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

namespace {

constexpr double kPi = std::numbers::pi;
const Range kRate{0, kMaxRate};
const Range kForce{0, kMaxForce};

void bodies(const Obj& o, PendingJoint& pj) {
    pj.refA = &o.get("body_a");
    pj.refALoc = o.at("body_a");
    pj.refB = &o.get("body_b");
    pj.refBLoc = o.at("body_b");
}

template <class D>
void anchors(const Obj& o, D& d) {
    d.localAnchorA = o.vec("anchor_a", {}, kMaxCoordinate);
    d.localAnchorB = o.vec("anchor_b", {}, kMaxCoordinate);
}

template <class D>
void referenceAngle(const Obj& o, PendingJoint& pj, D& d) {
    pj.hasReferenceAngle = o.has("reference_angle");
    d.referenceAngle = o.f("reference_angle", 0.0f, {-kPi, kPi});
}

i2d::Vec2 axis(const Obj& o, i2d::Vec2 def) {
    const i2d::Vec2 a = o.vec("axis_a", def, kMaxCoordinate);
    if (!(i2d::length(a) >= 1.0e-6f)) fail(o.at("axis_a"), "the axis must not be zero");
    return a;
}

// A gear's joint: a joint name (string) or an index into the file's "joints" (integer).
void jointRef(const Obj& o, const char* key, const json*& ref, Loc& loc) {
    ref = &o.get(key);
    loc = o.at(key);
    if (!ref->is_string() && !ref->is_number_integer())
        fail(loc, "expected a joint name (string) or an index into joints (integer), got " + typeName(*ref));
}

}  // namespace

void allowJointFields(Obj& o, i2d::JointType type) {
    using JT = i2d::JointType;
    allowJointOptions(o, type);
    if (type != JT::gear) o.allow({"body_a", "body_b"});
    switch (type) {
        case JT::distance: o.allow({"anchor_a", "anchor_b"}); break;
        case JT::revolute: o.allow({"anchor_a", "anchor_b", "reference_angle"}); break;
        case JT::prismatic: o.allow({"anchor_a", "anchor_b", "axis_a", "reference_angle"}); break;
        case JT::weld:
            o.allow({"anchor_a", "anchor_b", "reference_angle", "linear_hertz", "linear_damping_ratio", "angular_hertz",
                     "angular_damping_ratio"});
            break;
        case JT::wheel: o.allow({"anchor_a", "anchor_b", "axis_a"}); break;
        case JT::motor:
            o.allow({"linear_offset", "angular_offset", "max_force", "max_torque", "correction_factor"});
            break;
        case JT::mouse: o.allow({"target", "hertz", "damping_ratio", "max_force"}); break;
        case JT::pulley:
            o.allow({"ground_anchor_a", "ground_anchor_b", "anchor_a", "anchor_b", "length_a", "length_b", "ratio"});
            break;
        case JT::gear: o.allow({"joint1", "joint2", "ratio"}); break;
    }
}

void parseJointFields(const Obj& o, PendingJoint& pj) {
    if (pj.type() != i2d::JointType::gear) bodies(o, pj);
    parseJointOptions(o, pj);  // spring, limit, motor, length, collide_connected
    std::visit(
        [&](auto& d) {
            using D = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<D, i2d::DistanceJointDef>) {
                anchors(o, d);
            } else if constexpr (std::is_same_v<D, i2d::RevoluteJointDef>) {
                anchors(o, d);
                referenceAngle(o, pj, d);
            } else if constexpr (std::is_same_v<D, i2d::PrismaticJointDef>) {
                anchors(o, d);
                d.localAxisA = axis(o, d.localAxisA);
                referenceAngle(o, pj, d);
            } else if constexpr (std::is_same_v<D, i2d::WeldJointDef>) {
                anchors(o, d);
                referenceAngle(o, pj, d);
                d.linearHertz = o.f("linear_hertz", d.linearHertz, kRate);
                d.linearDampingRatio = o.f("linear_damping_ratio", d.linearDampingRatio, kRate);
                d.angularHertz = o.f("angular_hertz", d.angularHertz, kRate);
                d.angularDampingRatio = o.f("angular_damping_ratio", d.angularDampingRatio, kRate);
            } else if constexpr (std::is_same_v<D, i2d::WheelJointDef>) {
                anchors(o, d);
                d.localAxisA = axis(o, d.localAxisA);
            } else if constexpr (std::is_same_v<D, i2d::MotorJointDef>) {
                d.linearOffset = o.vec("linear_offset", d.linearOffset, kMaxCoordinate);
                d.angularOffset = o.f("angular_offset", d.angularOffset, {-kPi, kPi});
                d.maxForce = o.f("max_force", d.maxForce, kForce);
                d.maxTorque = o.f("max_torque", d.maxTorque, kForce);
                d.correctionFactor = o.f("correction_factor", d.correctionFactor, {0, 1});
            } else if constexpr (std::is_same_v<D, i2d::MouseJointDef>) {
                d.target = o.reqVec("target", kMaxCoordinate);
                d.hertz = o.f("hertz", d.hertz, {0, kMaxRate, true});
                d.dampingRatio = o.f("damping_ratio", d.dampingRatio, kRate);
                d.maxForce = o.f("max_force", d.maxForce, kForce);
            } else if constexpr (std::is_same_v<D, i2d::PulleyJointDef>) {
                d.groundAnchorA = o.reqVec("ground_anchor_a", kMaxCoordinate);
                d.groundAnchorB = o.reqVec("ground_anchor_b", kMaxCoordinate);
                anchors(o, d);
                for (auto [key, has, len] : {std::tuple{"length_a", &pj.hasLengthA, &d.lengthA},
                                             std::tuple{"length_b", &pj.hasLengthB, &d.lengthB}}) {
                    *has = o.has(key);
                    if (!*has) continue;
                    *len = o.reqF(key, {0, kMaxSize, true});
                    if (*len < i2d::kLinearSlop) fail(o.at(key), "a pulley length must be at least 0.005 m");
                }
                d.ratio = o.f("ratio", d.ratio, {0, kMaxRate, true});
            } else if constexpr (std::is_same_v<D, i2d::GearJointDef>) {
                jointRef(o, "joint1", pj.ref1, pj.ref1Loc);
                jointRef(o, "joint2", pj.ref2, pj.ref2Loc);
                d.ratio = o.f("ratio", d.ratio, {-kMaxRate, kMaxRate});
                if (d.ratio == 0.0f) fail(o.at("ratio"), "a gear ratio must not be zero");
            }
        },
        pj.def);
}

}  // namespace tb::scene_file
