// Testbed — the one table from enum values to the names used in scene files,
// on the command line, in `testbed run --json` and on screen. Parsing and
// printing both read it, so a name can never be accepted in one place and
// printed differently in another.
#pragma once

#include <impulse2d/impulse2d.hpp>

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "error_metric.hpp"
#include "simulation.hpp"

namespace tb {

template <class E>
struct EnumName {
    E value;
    const char* name;
};

/// Every named value of E, in the order error messages list them.
/// Specialised (in enum_names.cpp) for each enum below.
template <class E>
std::span<const EnumName<E>> enumNames();

template <>
std::span<const EnumName<i2d::PositionCorrection>> enumNames();  // soft_step, baumgarte, split
template <>
std::span<const EnumName<i2d::ImpactModel>> enumNames();  // closed_form, velocity_bias
template <>
std::span<const EnumName<i2d::BodyType>> enumNames();  // dynamic, static, kinematic
template <>
std::span<const EnumName<i2d::ShapeType>> enumNames();  // circle, capsule, segment, polygon
template <>
std::span<const EnumName<i2d::JointType>> enumNames();  // distance, revolute, prismatic, weld, wheel, motor, ...
template <>
std::span<const EnumName<EngineKind>> enumNames();  // impulse2d, box2d
template <>
std::span<const EnumName<ErrorMetric>> enumNames();  // max_excursion, ...; none has no name

/// The name of `value`; "" for a value without one (ErrorMetric::none).
template <class E>
const char* enumName(E value) {
    for (const EnumName<E>& e : enumNames<E>())
        if (e.value == value) return e.name;
    return "";
}

/// The value called `name`, if any.
template <class E>
std::optional<E> enumFromName(std::string_view name) {
    for (const EnumName<E>& e : enumNames<E>())
        if (name == e.name) return e.value;
    return std::nullopt;
}

/// The names joined for a message: `quote` around each, `separator` between
/// them and `lastSeparator` before the last ("a, b or c"; "\"a\", \"b\", \"c\"").
template <class E>
std::string enumNameList(std::string_view quote = "", std::string_view separator = ", ",
                         std::string_view lastSeparator = " or ") {
    std::string list;
    const auto names = enumNames<E>();
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) list += i + 1 == names.size() ? lastSeparator : separator;
        list += quote;
        list += names[i].name;
        list += quote;
    }
    return list;
}

}  // namespace tb
