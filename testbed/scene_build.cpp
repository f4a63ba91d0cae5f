// Testbed — SceneDesc → i2d::World.
#include "scene_build.hpp"

#include <string>

namespace tb {
namespace {

[[noreturn]] void refused(const SceneDesc& desc, const std::string& where, const i2d::Error& e) {
    throw SceneError((desc.file.empty() ? desc.name : desc.file) + ": " + where +
                     ": the engine refused it: " + e.what());
}

}  // namespace

Scene buildScene(const SceneDesc& desc) {
    Scene scene;
    scene.desc = desc;
    try {
        scene.world = std::make_unique<i2d::World>(desc.settings);
    } catch (const i2d::Error& e) {
        refused(desc, "world", e);
    }
    i2d::World& world = *scene.world;
    scene.bodies.reserve(desc.bodies.size());
    for (std::size_t i = 0; i < desc.bodies.size(); ++i) {
        const BodyDesc& b = desc.bodies[i];
        std::string where = "bodies[" + std::to_string(i) + "]" + (b.name.empty() ? "" : " ('" + b.name + "')");
        i2d::BodyId id;
        try {
            id = world.createBody(b.def);
        } catch (const i2d::Error& e) {
            refused(desc, where, e);
        }
        for (std::size_t k = 0; k < b.shapes.size(); ++k) {
            const ShapeDesc& s = b.shapes[k];
            try {
                switch (s.type) {
                    case i2d::ShapeType::circle: world.createCircleShape(id, s.def, s.circle); break;
                    case i2d::ShapeType::capsule: world.createCapsuleShape(id, s.def, s.capsule); break;
                    case i2d::ShapeType::segment: world.createSegmentShape(id, s.def, s.segment); break;
                    case i2d::ShapeType::polygon: world.createPolygonShape(id, s.def, s.polygon); break;
                }
            } catch (const i2d::Error& e) {
                refused(desc, where + ".shapes[" + std::to_string(k) + "]", e);
            }
        }
        scene.bodies.push_back(id);
        if (!b.name.empty()) scene.named[b.name] = id;
    }
    for (std::size_t i = 0; i < desc.joints.size(); ++i) {
        const DistanceJointDesc& j = desc.joints[i];
        std::string where = "joints[" + std::to_string(i) + "]";
        if (j.bodyA < 0 || j.bodyB < 0 || j.bodyA >= static_cast<int>(scene.bodies.size()) ||
            j.bodyB >= static_cast<int>(scene.bodies.size()))
            throw SceneError((desc.file.empty() ? desc.name : desc.file) + ": " + where + ": body index out of range");
        i2d::DistanceJointDef def = j.def;
        def.bodyA = scene.bodies[static_cast<std::size_t>(j.bodyA)];
        def.bodyB = scene.bodies[static_cast<std::size_t>(j.bodyB)];
        try {
            world.createDistanceJoint(def);
        } catch (const i2d::Error& e) {
            refused(desc, where, e);
        }
    }
    return scene;
}

}  // namespace tb
