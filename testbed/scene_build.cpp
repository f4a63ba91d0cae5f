// Testbed — SceneDesc → i2d::World.
#include "scene_build.hpp"

#include "game/platformer.hpp"

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

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
                if (s.chain) {
                    world.createChain(id, {.points = s.chainPoints,
                                           .isLoop = s.chainLoop,
                                           .friction = s.def.friction,
                                           .restitution = s.def.restitution,
                                           .filter = s.def.filter,
                                           .enableContactEvents = s.def.enableContactEvents,
                                           .userData = s.def.userData});
                    continue;
                }
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
    std::vector<i2d::JointId> joints;
    joints.reserve(desc.joints.size());
    for (std::size_t i = 0; i < desc.joints.size(); ++i) {
        const JointDesc& j = desc.joints[i];
        std::string where = "joints[" + std::to_string(i) + "]";
        const int bodies = static_cast<int>(scene.bodies.size());
        if (j.bodyA < 0 || j.bodyB < 0 || j.bodyA >= bodies || j.bodyB >= bodies)
            throw SceneError((desc.file.empty() ? desc.name : desc.file) + ": " + where + ": body index out of range");
        if (j.type() == i2d::JointType::gear &&
            (j.joint1 < 0 || j.joint2 < 0 || j.joint1 >= static_cast<int>(i) || j.joint2 >= static_cast<int>(i)))
            throw SceneError((desc.file.empty() ? desc.name : desc.file) + ": " + where +
                             ": a gear must refer to joints before it");
        const i2d::BodyId a = scene.bodies[static_cast<std::size_t>(j.bodyA)];
        const i2d::BodyId b = scene.bodies[static_cast<std::size_t>(j.bodyB)];
        try {
            joints.push_back(std::visit(
                [&](auto d) -> i2d::JointId {
                    using D = decltype(d);
                    if constexpr (std::is_same_v<D, i2d::GearJointDef>) {
                        d.joint1 = joints[static_cast<std::size_t>(j.joint1)];
                        d.joint2 = joints[static_cast<std::size_t>(j.joint2)];
                        return world.createGearJoint(d);
                    } else {
                        d.bodyA = a;
                        d.bodyB = b;
                        if constexpr (std::is_same_v<D, i2d::DistanceJointDef>)
                            return world.createDistanceJoint(d);
                        else if constexpr (std::is_same_v<D, i2d::RevoluteJointDef>)
                            return world.createRevoluteJoint(d);
                        else if constexpr (std::is_same_v<D, i2d::PrismaticJointDef>)
                            return world.createPrismaticJoint(d);
                        else if constexpr (std::is_same_v<D, i2d::WeldJointDef>)
                            return world.createWeldJoint(d);
                        else if constexpr (std::is_same_v<D, i2d::WheelJointDef>)
                            return world.createWheelJoint(d);
                        else if constexpr (std::is_same_v<D, i2d::MotorJointDef>)
                            return world.createMotorJoint(d);
                        else if constexpr (std::is_same_v<D, i2d::MouseJointDef>)
                            return world.createMouseJoint(d);
                        else
                            return world.createPulleyJoint(d);
                    }
                },
                j.def));
        } catch (const i2d::Error& e) {
            refused(desc, where, e);
        }
    }
    if (desc.platformer) scene.game = std::make_shared<PlatformerGame>(scene, *desc.platformer);
    return scene;
}

}  // namespace tb
