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
    // A reference is a body name (string) or index (integer) given at refLoc,
    // or an already known index (chain links).
    const json* refA = nullptr;
    Loc refALoc;
    int indexA = -1;
    const json* refB = nullptr;
    Loc refBLoc;
    int indexB = -1;
    i2d::DistanceJointDef def{};
    bool hasLength = false;
};

/// The options a joint and a chain generator share: length, spring, limit, collide_connected.
void parseJointOptions(const Obj& o, PendingJoint& pj);
/// One element of "joints".
PendingJoint parseJoint(const json& j, const Loc& loc);

/// The bodies and joints of a scene while its file is read.
struct Builder {
    const std::string* file;
    std::vector<BodyDesc> bodies;
    std::map<std::string, int> names;  ///< named body → index
    std::vector<PendingJoint> joints;

    /// Appends a body, refusing a duplicate name and more than kMaxBodies bodies.
    void addBody(BodyDesc b, const Loc& loc);
    /// The index of a body reference: a name (string) or an index (integer).
    int resolve(const json& ref, const Loc& loc) const;
};

}  // namespace tb::scene_file
