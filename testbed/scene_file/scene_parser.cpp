// Testbed — a scene file's text to a tb::SceneDesc: the top-level object,
// then the bodies (and generators) and joints, whose body references are
// resolved once every body is known (see scene_loader.hpp).
#include "scene_loader.hpp"

#include "scene_file/generators.hpp"
#include "scene_file/json_text.hpp"
#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb {

namespace scene_file {

void Builder::addBody(BodyDesc b, const Loc& loc) {
    if (static_cast<std::int64_t>(bodies.size()) >= kMaxBodies)
        fail(loc, "too many bodies (limit " + std::to_string(kMaxBodies) + ")");
    if (!b.name.empty()) {
        if (!names.emplace(b.name, static_cast<int>(bodies.size())).second)
            fail(loc, "duplicate body name '" + b.name + "'");
    }
    bodies.push_back(std::move(b));
}

int Builder::resolve(const json& ref, const Loc& loc) const {
    if (ref.is_string()) {
        auto it = names.find(ref.get<std::string>());
        if (it == names.end()) fail(loc, "unknown body name '" + ref.get<std::string>() + "'");
        return it->second;
    }
    if (ref.is_number_integer()) {
        std::int64_t n = static_cast<std::int64_t>(bodies.size());
        if (n == 0) fail(loc, "body index given but the scene has no bodies");
        return static_cast<int>(checkInt(ref, loc, 0, n - 1));
    }
    fail(loc, "expected a body name (string) or index (integer), got " + typeName(ref));
}

}  // namespace scene_file

using namespace scene_file;

SceneDesc parseSceneDesc(const std::string& text, const std::string& file, const std::string& name) {
    json root = parseJson(text, file);
    Loc loc{&file, {}};
    Obj o(root, loc,
          {"$schema", "comment", "name", "description", "dt", "world", "camera", "bodies", "joints", "platformer"});
    o.checkUnknown();
    o.str("$schema", "");
    o.str("comment", "");
    SceneDesc desc;
    desc.file = file;
    desc.name = o.str("name", name);
    desc.description = o.str("description", "");
    desc.dt = o.f("dt", desc.dt, {1.0e-6, 1});  // the engine's own bounds on a step (World::step)
    if (o.has("world")) desc.settings = parseWorld(o.get("world"), o.at("world"));
    if (o.has("camera")) {
        Obj c(o.get("camera"), o.at("camera"), {"comment", "center", "height"});
        c.checkUnknown();
        Camera cam;
        cam.center = c.vec("center", {}, kMaxCoordinate);
        cam.height = c.f("height", cam.height, {0, kMaxCoordinate, true});
        desc.camera = cam;
    }

    Builder bld{&file, {}, {}, {}, 0, {}};
    const json& bodies = o.get("bodies");
    Loc bl = o.at("bodies");
    if (!bodies.is_array()) fail(bl, "expected an array of bodies and generators, got " + typeName(bodies));
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const json& e = bodies[i];
        if (e.is_object() && e.contains("generator")) {
            expandGenerator(e, bl.at(i), bld);
        } else {
            bld.addBody(parseBody(e, bl.at(i), false), bl.at(i));
        }
    }
    bld.fileJointBase = bld.joints.size();
    if (o.has("joints")) {
        const json& js = o.get("joints");
        Loc jl = o.at("joints");
        if (!js.is_array()) fail(jl, "expected an array of joints, got " + typeName(js));
        for (std::size_t i = 0; i < js.size(); ++i) {
            PendingJoint pj = parseJoint(js[i], jl.at(i));
            if (!pj.name.empty() && !bld.jointNames.emplace(pj.name, static_cast<int>(bld.joints.size())).second)
                fail(jl.at(i).key("name"), "duplicate joint name '" + pj.name + "'");
            bld.joints.push_back(std::move(pj));
        }
    }

    desc.joints.reserve(bld.joints.size());
    for (const PendingJoint& pj : bld.joints) desc.joints.push_back(resolveJoint(pj, bld, desc.joints));
    if (o.has("platformer")) desc.platformer = parsePlatformer(o.get("platformer"), o.at("platformer"), bld);
    desc.bodies = std::move(bld.bodies);
    return desc;
}

}  // namespace tb
