// Testbed — a scene file's "platformer" section (docs/scene-format.md): which
// bodies are the player, the one-way and moving platforms and the coins, the
// player's speeds and the script that plays it in `run` and `render`.
#include "scene_file/json_checks.hpp"
#include "scene_file/limits.hpp"
#include "scene_file/parts.hpp"

namespace tb::scene_file {

namespace {

std::vector<int> bodyList(const Obj& o, const char* key, const Builder& bld) {
    std::vector<int> out;
    if (!o.has(key)) return out;
    const json& arr = o.get(key);
    const Loc loc = o.at(key);
    if (!arr.is_array()) fail(loc, "expected an array of body names or indices, got " + typeName(arr));
    for (std::size_t i = 0; i < arr.size(); ++i) out.push_back(bld.resolve(arr[i], loc.at(i)));
    return out;
}

}  // namespace

PlatformerDesc parsePlatformer(const json& j, const Loc& loc, const Builder& bld) {
    Obj o(j, loc, {"comment", "player", "one_way", "moving", "coins", "run_speed", "jump_speed", "script"});
    o.checkUnknown();
    o.str("comment", "");
    PlatformerDesc d;
    d.player = bld.resolve(o.get("player"), o.at("player"));
    if (bld.bodies[static_cast<std::size_t>(d.player)].def.type != i2d::BodyType::dynamic_body)
        fail(o.at("player"), "the player must be a dynamic body");
    d.oneWay = bodyList(o, "one_way", bld);
    d.coins = bodyList(o, "coins", bld);
    for (std::size_t i = 0; i < d.coins.size(); ++i) {
        bool sensor = false;
        for (const ShapeDesc& s : bld.bodies[static_cast<std::size_t>(d.coins[i])].shapes)
            sensor = sensor || s.def.isSensor;
        if (!sensor) fail(o.at("coins").at(i), "a coin needs a sensor shape");
    }
    if (o.has("moving")) {
        const json& arr = o.get("moving");
        const Loc ml = o.at("moving");
        if (!arr.is_array()) fail(ml, "expected an array of paths, got " + typeName(arr));
        for (std::size_t i = 0; i < arr.size(); ++i) {
            Obj p(arr[i], ml.at(i), {"comment", "body", "from", "to", "period"});
            p.checkUnknown();
            p.str("comment", "");
            PlatformerDesc::Path path;
            path.body = bld.resolve(p.get("body"), p.at("body"));
            if (bld.bodies[static_cast<std::size_t>(path.body)].def.type != i2d::BodyType::kinematic_body)
                fail(p.at("body"), "a moving platform must be a kinematic body");
            path.from = p.reqVec("from", kMaxCoordinate);
            path.to = p.reqVec("to", kMaxCoordinate);
            path.period = p.f("period", path.period, {0, 1.0e4, true});
            d.moving.push_back(path);
        }
    }
    d.runSpeed = o.f("run_speed", d.runSpeed, {0, 1.0e3});
    d.jumpSpeed = o.f("jump_speed", d.jumpSpeed, {0, 1.0e3});
    if (o.has("script")) {
        const json& arr = o.get("script");
        const Loc sl = o.at("script");
        if (!arr.is_array()) fail(sl, "expected an array of {until, move, jump}, got " + typeName(arr));
        float last = 0.0f;
        for (std::size_t i = 0; i < arr.size(); ++i) {
            Obj k(arr[i], sl.at(i), {"comment", "until", "move", "jump"});
            k.checkUnknown();
            k.str("comment", "");
            PlatformerDesc::Key key;
            key.until = k.reqF("until", {0, 1.0e6});
            if (key.until < last) fail(sl.at(i).key("until"), "script times must not decrease");
            last = key.until;
            key.input.move = k.f("move", 0.0f, {-1, 1});
            key.input.jump = k.boolean("jump", false);
            d.script.push_back(key);
        }
    }
    return d;
}

}  // namespace tb::scene_file
