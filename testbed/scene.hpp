// Testbed — scenes: an engine-agnostic description parsed from a scene file
// (or built in code), and its instantiation as an Impulse2D world.
//
// The description is plain data so the same scene can be built in another
// engine (the Box2D 2.4.1 backend used by the validation and benchmarks).
#pragma once

#include <impulse2d/impulse2d.hpp>

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tb {

/// Error in a scene file: what() reads "FILE: FIELD.PATH: what is wrong".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ShapeDesc {
    i2d::ShapeType type = i2d::ShapeType::polygon;
    i2d::Circle circle{};
    i2d::Capsule capsule{};
    i2d::Segment segment{};
    i2d::Polygon polygon{};  ///< built through makePolygon/makeBox from the file's data
    i2d::ShapeDef def{};
};

struct BodyDesc {
    std::string name;  ///< empty when unnamed; named bodies are measured
    i2d::BodyDef def{};
    std::vector<ShapeDesc> shapes;
};

struct DistanceJointDesc {
    int bodyA = -1;  ///< index into SceneDesc::bodies
    int bodyB = -1;
    i2d::DistanceJointDef def{};  ///< bodyA/bodyB handles filled when built
};

struct Camera {
    i2d::Vec2 center{};
    float height = 20.0f;  ///< world metres visible vertically
};

struct SceneDesc {
    std::string name;
    std::string description;
    std::string file;  ///< source file, empty for scenes built in code
    i2d::WorldSettings settings{};
    float dt = 1.0f / 60.0f;
    std::vector<BodyDesc> bodies;
    std::vector<DistanceJointDesc> joints;
    std::optional<Camera> camera;  ///< none: fit the scene's bounds
};

/// A scene built as an Impulse2D world.
struct Scene {
    SceneDesc desc;
    std::unique_ptr<i2d::World> world;
    std::vector<i2d::BodyId> bodies;  ///< bodies[i] built from desc.bodies[i]
    std::map<std::string, i2d::BodyId> named;
};

}  // namespace tb
