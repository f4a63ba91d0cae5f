// Testbed — distance joints in a scene file (see parts.hpp).
#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

void parseJointOptions(const Obj& o, PendingJoint& pj) {
    if (o.has("length")) {
        pj.hasLength = true;
        pj.def.length = o.reqF("length", {0, kMaxSize, true});
        if (pj.def.length < i2d::kLinearSlop) fail(o.at("length"), "a joint length must be at least 0.005 m");
    }
    if (o.has("spring")) {
        Obj sp(o.get("spring"), o.at("spring"), {"comment", "hertz", "damping_ratio"});
        sp.checkUnknown();
        pj.def.enableSpring = true;
        pj.def.hertz = sp.f("hertz", 0.0f, {0, kMaxRate});
        pj.def.dampingRatio = sp.f("damping_ratio", 0.0f, {0, kMaxRate});
    }
    if (o.has("limit")) {
        Obj li(o.get("limit"), o.at("limit"), {"comment", "min", "max"});
        li.checkUnknown();
        pj.def.enableLimit = true;
        pj.def.minLength = li.f("min", 0.0f, {0, kMaxSize});
        pj.def.maxLength = li.f("max", static_cast<float>(kMaxSize), {0, kMaxSize});
        if (pj.def.maxLength < pj.def.minLength) fail(li.at("max"), "limit max must be ≥ min");
    }
    pj.def.collideConnected = o.boolean("collide_connected", false);
}

PendingJoint parseJoint(const json& j, const Loc& loc) {
    Obj o(j, loc,
          {"comment", "type", "body_a", "body_b", "anchor_a", "anchor_b", "length", "spring", "limit",
           "collide_connected"});
    o.checkUnknown();
    o.str("comment", "");
    std::string type = o.str("type", "distance");
    if (type != "distance") fail(o.at("type"), "unknown joint type \"" + type + "\" (expected \"distance\")");
    PendingJoint pj;
    pj.loc = loc;
    pj.refA = &o.get("body_a");
    pj.refALoc = o.at("body_a");
    pj.refB = &o.get("body_b");
    pj.refBLoc = o.at("body_b");
    pj.def.localAnchorA = o.vec("anchor_a", {}, kMaxCoordinate);
    pj.def.localAnchorB = o.vec("anchor_b", {}, kMaxCoordinate);
    parseJointOptions(o, pj);
    return pj;
}

}  // namespace tb::scene_file
