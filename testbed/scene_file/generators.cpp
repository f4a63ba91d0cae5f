// Testbed — scene-file generators (see generators.hpp).
#include "scene_file/generators.hpp"

#include <cmath>
#include <cstdlib>
#include <map>

#include "scene_file/limits.hpp"

namespace tb::scene_file {

namespace {

// The joint type of a chain ("joint_type") or a grid's links ("type"): distance (default) or revolute.
i2d::JointType linkJointType(const Obj& o, const char* key) {
    const i2d::JointType t = enumField(o, key, i2d::JointType::distance);
    if (t != i2d::JointType::distance && t != i2d::JointType::revolute)
        fail(o.at(key), "generators join bodies by \"distance\" or \"revolute\" joints");
    return t;
}

void setAnchors(PendingJoint& pj, i2d::Vec2 a, i2d::Vec2 b) {
    std::visit(
        [&](auto& d) {
            if constexpr (requires { d.localAnchorA; }) {
                d.localAnchorA = a;
                d.localAnchorB = b;
            }
        },
        pj.def);
}

}  // namespace

// Generators: see docs/scene-format.md, "Generators".
void expandGenerator(const json& j, const Loc& loc, Builder& bld) {
    Obj o(j, loc, {"comment", "generator", "body", "name_prefix", "name_first", "name_last", "name_at"});
    std::string kind = o.reqStr("generator");
    if (kind == "row") {
        o.allow({"count", "origin", "step", "copies", "copy_step"});
    } else if (kind == "grid") {
        o.allow({"columns", "rows", "origin", "spacing", "copies", "copy_step", "link"});
    } else if (kind == "pyramid") {
        o.allow({"base", "origin", "spacing", "copies", "copy_step"});
    } else if (kind == "chain") {
        o.allow({"count", "origin", "step", "anchor_prev", "anchor_next", "joint_type", "attach_start", "attach_end"});
        allowJointOptions(o, linkJointType(o, "joint_type"));
    } else {
        fail(o.at("generator"), "unknown generator \"" + kind + "\" (expected row, grid, pyramid or chain)");
    }
    o.checkUnknown();
    o.str("comment", "");
    BodyDesc tmpl = parseBody(o.get("body"), o.at("body"), true);

    // Positions relative to the generator's origin, in creation order.
    std::vector<i2d::Vec2> local;
    const std::int64_t maxCount = kMaxBodies;
    i2d::Vec2 origin = o.vec("origin", {}, kMaxCoordinate);
    if (kind == "row" || kind == "chain") {
        std::int64_t n = o.reqInt("count", 1, maxCount);
        i2d::Vec2 step = o.reqVec("step", kMaxSize);
        for (std::int64_t i = 0; i < n; ++i) local.push_back(static_cast<float>(i) * step);
    } else if (kind == "grid") {
        std::int64_t cols = o.reqInt("columns", 1, maxCount);
        std::int64_t rows = o.reqInt("rows", 1, maxCount);
        if (cols * rows > maxCount) fail(loc, "too many bodies (limit " + std::to_string(kMaxBodies) + ")");
        i2d::Vec2 sp = o.reqVec("spacing", kMaxSize);
        for (std::int64_t r = 0; r < rows; ++r)
            for (std::int64_t c = 0; c < cols; ++c)
                local.push_back({static_cast<float>(c) * sp.x, static_cast<float>(r) * sp.y});
    } else {                                           // pyramid
        std::int64_t base = o.reqInt("base", 1, 700);  // 700 → 245,350 bodies, just under the body limit
        i2d::Vec2 sp = o.reqVec("spacing", kMaxSize);
        for (std::int64_t r = 0; r < base; ++r) {
            std::int64_t n = base - r;
            for (std::int64_t c = 0; c < n; ++c)
                local.push_back(
                    {(static_cast<float>(c) - 0.5f * static_cast<float>(n - 1)) * sp.x, static_cast<float>(r) * sp.y});
        }
    }
    std::int64_t cx = 1, cy = 1;
    i2d::Vec2 copyStep{};
    if (o.has("copies")) {
        const json& c = o.get("copies");
        Loc cl = o.at("copies");
        if (!c.is_array() || c.size() != 2) fail(cl, "expected an array of 2 integers [columns, rows]");
        cx = checkInt(c[0], cl.at(0), 1, maxCount);
        cy = checkInt(c[1], cl.at(1), 1, maxCount);
        copyStep = o.reqVec("copy_step", kMaxCoordinate);
    } else if (o.has("copy_step")) {
        fail(o.at("copy_step"), "copy_step needs copies");
    }
    std::int64_t total = cx * cy * static_cast<std::int64_t>(local.size());
    if (total + static_cast<std::int64_t>(bld.bodies.size()) > kMaxBodies)
        fail(loc, "generator makes " + std::to_string(total) + " bodies; the limit is " + std::to_string(kMaxBodies) +
                      " per scene");

    std::string prefix = o.str("name_prefix", "");
    std::string first = o.str("name_first", "");
    std::string last = o.str("name_last", "");
    std::map<std::int64_t, std::string> nameAt;
    if (o.has("name_at")) {
        Obj na(o.get("name_at"), o.at("name_at"), {});
        for (auto it = o.get("name_at").begin(); it != o.get("name_at").end(); ++it) {
            Loc kl = na.loc().key(it.key());
            char* end = nullptr;
            long long idx = std::strtoll(it.key().c_str(), &end, 10);
            if (it.key().empty() || *end != '\0' || idx < 0 || idx >= total)
                fail(kl, "key must be a body index of this generator, from 0 to " + std::to_string(total - 1));
            if (!it.value().is_string() || it.value().get<std::string>().empty())
                fail(kl, "expected a non-empty name (string), got " + typeName(it.value()));
            nameAt[idx] = it.value().get<std::string>();
        }
    }
    int firstIndex = static_cast<int>(bld.bodies.size());
    std::int64_t k = 0;
    for (std::int64_t qy = 0; qy < cy; ++qy) {
        for (std::int64_t qx = 0; qx < cx; ++qx) {
            i2d::Vec2 off = origin +
                            i2d::Vec2{static_cast<float>(qx) * copyStep.x, static_cast<float>(qy) * copyStep.y};
            for (const i2d::Vec2& p : local) {
                BodyDesc b = tmpl;
                b.def.position = off + p;
                if (!i2d::isFinite(b.def.position) || std::fabs(b.def.position.x) > kMaxCoordinate ||
                    std::fabs(b.def.position.y) > kMaxCoordinate)
                    fail(loc, "generated position out of range: coordinates must have magnitude at most 1e7");
                if (auto it = nameAt.find(k); it != nameAt.end()) {
                    b.name = it->second;
                } else if (k == 0 && !first.empty()) {
                    b.name = first;
                } else if (k == total - 1 && !last.empty()) {
                    b.name = last;
                } else if (!prefix.empty()) {
                    b.name = prefix + std::to_string(k);
                }
                bld.addBody(std::move(b), loc);
                ++k;
            }
        }
    }

    if (kind == "grid" && o.has("link")) {
        // Joints between each body and its right and upper neighbours, centre to centre.
        if (o.has("copies")) fail(o.at("link"), "link cannot be combined with copies");
        Obj lo(o.get("link"), o.at("link"), {"comment", "type"});
        const i2d::JointType type = linkJointType(lo, "type");
        allowJointOptions(lo, type);
        lo.checkUnknown();
        PendingJoint base;
        base.def = defaultJointDef(type);
        parseJointOptions(lo, base);
        base.loc = o.at("link");
        int cols = static_cast<int>(o.reqInt("columns", 1, maxCount));
        int rows = static_cast<int>(o.reqInt("rows", 1, maxCount));
        // Distance links join the centres; revolute links hinge at the midpoint between the two bodies.
        const i2d::Vec2 sp = o.reqVec("spacing", kMaxSize);
        const bool hinge = type == i2d::JointType::revolute;
        const i2d::Vec2 halfX = hinge ? i2d::Vec2{0.5f * sp.x, 0.0f} : i2d::Vec2{};
        const i2d::Vec2 halfY = hinge ? i2d::Vec2{0.0f, 0.5f * sp.y} : i2d::Vec2{};
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < cols; ++c) {
                int i = firstIndex + r * cols + c;
                if (c + 1 < cols) {
                    PendingJoint pj = base;
                    pj.indexA = i;
                    pj.indexB = i + 1;
                    setAnchors(pj, halfX, -1.0f * halfX);
                    bld.joints.push_back(pj);
                }
                if (r + 1 < rows) {
                    PendingJoint pj = base;
                    pj.indexA = i;
                    pj.indexB = i + cols;
                    setAnchors(pj, halfY, -1.0f * halfY);
                    bld.joints.push_back(pj);
                }
            }
        }
    }
    if (kind != "chain") return;
    PendingJoint base;
    base.loc = loc;
    base.def = defaultJointDef(linkJointType(o, "joint_type"));
    i2d::Vec2 prevAnchor = o.vec("anchor_prev", {}, kMaxSize);
    i2d::Vec2 nextAnchor = o.vec("anchor_next", {}, kMaxSize);
    parseJointOptions(o, base);
    int n = static_cast<int>(local.size());
    auto attach = [&](const char* key, bool atStart) {
        if (!o.has(key)) return;
        Obj a(o.get(key), o.at(key), {"comment", "body", "anchor"});
        a.checkUnknown();
        PendingJoint pj = base;
        pj.loc = o.at(key);
        pj.hasLength = false;  // an attachment takes its length from the initial layout
        i2d::Vec2 anchor = a.vec("anchor", {}, kMaxCoordinate);
        int link = atStart ? firstIndex : firstIndex + n - 1;
        if (atStart) {
            pj.refA = &a.get("body");
            pj.refALoc = a.at("body");
            pj.indexB = link;
            setAnchors(pj, anchor, prevAnchor);
        } else {
            pj.indexA = link;
            pj.refB = &a.get("body");
            pj.refBLoc = a.at("body");
            setAnchors(pj, nextAnchor, anchor);
        }
        bld.joints.push_back(pj);
    };
    attach("attach_start", true);
    for (int i = 0; i + 1 < n; ++i) {
        PendingJoint pj = base;
        pj.indexA = firstIndex + i;
        pj.indexB = firstIndex + i + 1;
        setAnchors(pj, nextAnchor, prevAnchor);
        bld.joints.push_back(pj);
    }
    attach("attach_end", false);
}

}  // namespace tb::scene_file
