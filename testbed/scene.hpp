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
#include <type_traits>
#include <variant>
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
    /// A chain ("type": "chain"): type is segment, and the chain's points
    /// and loop flag are here (i2d::World::createChain; b2ChainShape).
    bool chain = false;
    std::vector<i2d::Vec2> chainPoints;
    bool chainLoop = false;
};

struct BodyDesc {
    std::string name;  ///< empty when unnamed; named bodies are measured
    i2d::BodyDef def{};
    std::vector<ShapeDesc> shapes;
    /// A scripted player ("drive_speed"): its horizontal velocity is set to
    /// this (m/s) before every step, its vertical one left to the physics.
    std::optional<float> driveSpeed;
};

/// Every joint definition, in the order of i2d::JointType (def.index() is the type).
using JointDefs =
    std::variant<i2d::DistanceJointDef, i2d::RevoluteJointDef, i2d::PrismaticJointDef, i2d::WeldJointDef,
                 i2d::WheelJointDef, i2d::MotorJointDef, i2d::MouseJointDef, i2d::PulleyJointDef, i2d::GearJointDef>;
static_assert(std::variant_size_v<JointDefs> == static_cast<std::size_t>(i2d::JointType::gear) + 1);
static_assert(std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(i2d::JointType::wheel), JointDefs>,
                             i2d::WheelJointDef>);

/// One joint of a scene. Body handles (and a gear's joint handles) in `def`
/// are filled when the scene is built; the indices here say which.
struct JointDesc {
    std::string name;  ///< empty when unnamed; a gear may name the joints it couples
    int bodyA = -1;    ///< index into SceneDesc::bodies (a gear: joint1's bodyB)
    int bodyB = -1;    ///< (a gear: joint2's bodyB)
    int joint1 = -1;   ///< a gear only: index into SceneDesc::joints of an earlier revolute or prismatic joint
    int joint2 = -1;
    JointDefs def{};  ///< distance unless set otherwise

    i2d::JointType type() const { return static_cast<i2d::JointType>(def.index()); }
    template <class Def>
    const Def& as() const {
        return std::get<Def>(def);
    }
    template <class Def>
    Def& as() {
        return std::get<Def>(def);
    }
};

struct Camera {
    i2d::Vec2 center{};
    float height = 20.0f;  ///< world metres visible vertically
};

/// The player's controls for one step: move ∈ [−1, 1] (left, right), jump.
struct PlayerInput {
    float move = 0.0f;
    bool jump = false;
};

/// A scene file's "platformer" section: which bodies play which part in the
/// small game the testbed runs on top of the world (testbed/game/platformer.cpp).
struct PlatformerDesc {
    int player = -1;          ///< index into SceneDesc::bodies: a dynamic body
    std::vector<int> oneWay;  ///< static or kinematic bodies passable from below
    struct Path {
        int body = -1;  ///< a kinematic body moved back and forth
        i2d::Vec2 from{}, to{};
        float period = 4.0f;  ///< s for a full there-and-back
    };
    std::vector<Path> moving;
    std::vector<int> coins;  ///< bodies whose sensor shapes are collected when the player touches them
    float runSpeed = 5.0f;   ///< m/s
    float jumpSpeed = 7.0f;  ///< m/s, upwards
    /// Scripted input for `run` and `render`: each entry holds until its time (s).
    struct Key {
        float until = 0.0f;
        PlayerInput input;
    };
    std::vector<Key> script;
};

struct SceneDesc {
    std::string name;
    std::string description;
    std::string file;  ///< source file, empty for scenes built in code
    i2d::WorldSettings settings{};
    float dt = 1.0f / 60.0f;
    std::vector<BodyDesc> bodies;
    std::vector<JointDesc> joints;  ///< in creation order (a gear after the joints it couples)
    std::optional<Camera> camera;   ///< none: fit the scene's bounds
    std::optional<PlatformerDesc> platformer;
    /// Workers the Impulse2D world steps on (a run option, `--threads`, not
    /// part of the scene file): above 1 it gets a tb::ThreadPool.
    int threads = 1;
};

class PlatformerGame;

/// A scene built as an Impulse2D world.
struct Scene {
    SceneDesc desc;
    std::unique_ptr<i2d::World> world;
    std::vector<i2d::BodyId> bodies;  ///< bodies[i] built from desc.bodies[i]
    std::map<std::string, i2d::BodyId> named;
    /// The platformer played on this world (scenes with a "platformer" section).
    std::shared_ptr<PlatformerGame> game;
};

}  // namespace tb
