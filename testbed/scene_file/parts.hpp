// Testbed — the parts of a scene file, each read from its JSON object with
// the checks of json_checks.hpp: world settings, bodies and shapes, joints,
// and the Builder that collects them (generators add to it too).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "scene_file/json_checks.hpp"

namespace tb::scene_file {

/// The "world" object.
i2d::WorldSettings parseWorld(const json& j, const Loc& loc);
/// A shape's "filter" object.
i2d::Filter parseFilter(const json& j, const Loc& loc);
/// One element of a body's "shapes".
ShapeDesc parseShape(const json& j, const Loc& loc);
/// A body object; templates (inside generators) may not set name or position.
BodyDesc parseBody(const json& j, const Loc& loc, bool isTemplate);

// A joint waiting for its body references to be resolved (bodies may be
// named after the joint that uses them, and generators add bodies).
struct PendingJoint {
    Loc loc;
    std::string name;  ///< the joint's "name", empty when none
    // A reference is a body name (string) or index (integer) given at refLoc,
    // or an already known index (chain links).
    const json* refA = nullptr;
    Loc refALoc;
    int indexA = -1;
    const json* refB = nullptr;
    Loc refBLoc;
    int indexB = -1;
    JointDefs def{};  ///< its index is the joint type
    // Values the file left to the initial layout (joint_layout.cpp).
    bool hasLength = false;          ///< distance: "length" given
    bool hasReferenceAngle = false;  ///< revolute, prismatic, weld: "reference_angle" given
    bool hasLengthA = false;         ///< pulley: "length_a" given
    bool hasLengthB = false;
    // A gear's joints: a joint name (string) or an index into the file's "joints" (integer).
    const json* ref1 = nullptr;
    Loc ref1Loc;
    const json* ref2 = nullptr;
    Loc ref2Loc;

    i2d::JointType type() const { return static_cast<i2d::JointType>(def.index()); }
};

/// A definition of the given type with the engine's defaults.
JointDefs defaultJointDef(i2d::JointType type);
/// Allows on `o` the feature fields a joint of this type takes in a
/// generator: distance: length, spring, limit; revolute: spring, limit, motor;
/// and collide_connected.
void allowJointOptions(Obj& o, i2d::JointType type);
/// Reads those fields into pj (whose def holds the type).
void parseJointOptions(const Obj& o, PendingJoint& pj);
/// Allows on `o` every field of a joint of this type but the common ones
/// (comment, type, name) and reads them into pj: bodies (or a gear's joints),
/// anchors, settings (joint_fields.cpp).
void allowJointFields(Obj& o, i2d::JointType type);
void parseJointFields(const Obj& o, PendingJoint& pj);
/// One element of "joints".
PendingJoint parseJoint(const json& j, const Loc& loc);

struct Builder;
/// The joint `pj` (bld.joints[index]) with its references resolved and the
/// values it left to the initial layout measured (length, reference angle,
/// pulley lengths); `done` holds the joints before it, already resolved.
JointDesc resolveJoint(const PendingJoint& pj, const Builder& bld, const std::vector<JointDesc>& done);

/// The bodies and joints of a scene while its file is read.
struct Builder {
    const std::string* file;
    std::vector<BodyDesc> bodies;
    std::map<std::string, int> names;       ///< named body → index
    std::vector<PendingJoint> joints;       ///< generators' joints first, then the file's "joints"
    std::size_t fileJointBase = 0;          ///< index in `joints` of the file's joints[0]
    std::map<std::string, int> jointNames;  ///< named joint → index in `joints`

    /// Appends a body, refusing a duplicate name and more than kMaxBodies bodies.
    void addBody(BodyDesc b, const Loc& loc);
    /// The index of a body reference: a name (string) or an index (integer).
    int resolve(const json& ref, const Loc& loc) const;
    /// The index in `joints` of a gear's joint reference (a joint name or an
    /// index into the file's "joints"), which must come before the gear at `self`.
    int resolveJoint(const json& ref, const Loc& loc, std::size_t self) const;
};

/// A scene's "platformer" section (platformer_fields.cpp), its body
/// references resolved against the bodies read so far.
PlatformerDesc parsePlatformer(const json& j, const Loc& loc, const Builder& bld);

}  // namespace tb::scene_file
