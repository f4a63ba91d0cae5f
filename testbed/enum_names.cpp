// Testbed — the enum name tables (see enum_names.hpp). The names are part of
// the scene-file format and the command-line and JSON interfaces.
#include "enum_names.hpp"

#include <array>

namespace tb {

namespace {

using PC = i2d::PositionCorrection;
using IM = i2d::ImpactModel;
using BT = i2d::BodyType;
using ST = i2d::ShapeType;
using JT = i2d::JointType;

constexpr std::array<EnumName<PC>, 3> kCorrections{{
    {PC::soft_step, "soft_step"},
    {PC::baumgarte, "baumgarte"},
    {PC::split, "split"},
}};

constexpr std::array<EnumName<IM>, 2> kImpactModels{{
    {IM::closed_form, "closed_form"},
    {IM::velocity_bias, "velocity_bias"},
}};

constexpr std::array<EnumName<BT>, 3> kBodyTypes{{
    {BT::dynamic_body, "dynamic"},
    {BT::static_body, "static"},
    {BT::kinematic_body, "kinematic"},
}};

constexpr std::array<EnumName<ST>, 4> kShapeTypes{{
    {ST::circle, "circle"},
    {ST::capsule, "capsule"},
    {ST::segment, "segment"},
    {ST::polygon, "polygon"},
}};

constexpr std::array<EnumName<JT>, 9> kJointTypes{{
    {JT::distance, "distance"},
    {JT::revolute, "revolute"},
    {JT::prismatic, "prismatic"},
    {JT::weld, "weld"},
    {JT::wheel, "wheel"},
    {JT::motor, "motor"},
    {JT::mouse, "mouse"},
    {JT::pulley, "pulley"},
    {JT::gear, "gear"},
}};

constexpr std::array<EnumName<EngineKind>, 2> kEngines{{
    {EngineKind::impulse2d, "impulse2d"},
    {EngineKind::box2d, "box2d"},
}};

constexpr std::array<EnumName<ErrorMetric>, 6> kErrorMetrics{{
    {ErrorMetric::max_excursion, "max_excursion"},
    {ErrorMetric::max_sway, "max_sway"},
    {ErrorMetric::max_penetration, "max_penetration"},
    {ErrorMetric::joint_stretch, "joint_stretch"},
    {ErrorMetric::rebound_error, "rebound_error"},
    {ErrorMetric::energy_drift, "energy_drift"},
}};

}  // namespace

template <>
std::span<const EnumName<PC>> enumNames() {
    return kCorrections;
}
template <>
std::span<const EnumName<IM>> enumNames() {
    return kImpactModels;
}
template <>
std::span<const EnumName<BT>> enumNames() {
    return kBodyTypes;
}
template <>
std::span<const EnumName<ST>> enumNames() {
    return kShapeTypes;
}
template <>
std::span<const EnumName<JT>> enumNames() {
    return kJointTypes;
}
template <>
std::span<const EnumName<EngineKind>> enumNames() {
    return kEngines;
}
template <>
std::span<const EnumName<ErrorMetric>> enumNames() {
    return kErrorMetrics;
}

}  // namespace tb
