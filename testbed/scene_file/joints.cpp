// Testbed — one element of a scene file's "joints": its type, name and
// fields (joint_fields.cpp, joint_options.cpp); references are resolved later
// (joint_layout.cpp).
#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

PendingJoint parseJoint(const json& j, const Loc& loc) {
    Obj o(j, loc, {"comment", "type", "name"});
    o.str("comment", "");
    PendingJoint pj;
    pj.loc = loc;
    const i2d::JointType type = enumField(o, "type", i2d::JointType::distance);
    pj.def = defaultJointDef(type);
    allowJointFields(o, type);
    o.checkUnknown();
    if (o.has("name")) {
        pj.name = o.str("name", "");
        if (pj.name.empty()) fail(o.at("name"), "a joint name must not be empty");
    }
    parseJointFields(o, pj);
    return pj;
}

}  // namespace tb::scene_file
