// Internal state of a World: flat arrays of bodies, shapes, contacts and
// joints addressed by slot index, plus the broadphase and the solver's
// per-step scratch arrays. Not part of the public API.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "dynamic_tree.hpp"
#include "impulse2d/types.hpp"
#include "impulse2d/world.hpp"

namespace i2d::detail {

inline constexpr int kNullIndex = -1;

struct Body {
    BodyType type = BodyType::static_body;
    Transform xf{};         ///< origin and rotation
    Vec2 center{};          ///< centre of mass, world
    Vec2 localCenter{};     ///< centre of mass, body frame
    Vec2 v{};
    float w = 0.0f;
    Vec2 force{};
    float torque = 0.0f;
    float mass = 0.0f, invMass = 0.0f;
    float inertia = 0.0f, invInertia = 0.0f;  ///< about the centre of mass
    float linearDamping = 0.0f, angularDamping = 0.0f;
    float gravityScale = 1.0f;
    float sleepTime = 0.0f;
    /// Farthest core point of a solid shape from the centre of mass (m); −1
    /// when the body has no solid shape. Bounds how far a turn moves its
    /// surface (continuous.cpp). Set by updateMass.
    float reach = -1.0f;
    bool fixedRotation = false;
    bool awake = true;
    bool enableSleep = true;
    bool alive = false;
    std::uint32_t generation = 1;
    int awakeIndex = kNullIndex;   ///< position in WorldImpl::awakeBodies
    int sleepIsland = kNullIndex;  ///< sleeping island this body belongs to
    int solverIndex = kNullIndex;  ///< index into the solver arrays during a step
    std::uintptr_t userData = 0;
    std::vector<int> shapes;
    std::vector<int> contacts;
    std::vector<int> joints;
};

struct Shape {
    ShapeType type = ShapeType::circle;
    int body = kNullIndex;
    Circle circle{};
    Capsule capsule{};
    Segment segment{};
    Polygon polygon{};
    float density = 1.0f, friction = 0.6f, restitution = 0.0f;
    Filter filter{};
    bool isSensor = false;
    bool enableContactEvents = true;
    bool enableSensorEvents = true;
    bool alive = false;
    bool inStaticTree = false;
    std::uint32_t generation = 1;
    int proxy = DynamicTree::kNull;
    bool moved = false;  ///< in the broadphase move buffer
    AABB fatAABB{};
    std::uintptr_t userData = 0;
};

struct Contact {
    int shapeA = kNullIndex, shapeB = kNullIndex;
    int bodyA = kNullIndex, bodyB = kNullIndex;
    Manifold manifold{};
    float normalImpulse[2]{};
    float tangentImpulse[2]{};
    float friction = 0.0f, restitution = 0.0f;
    std::uint64_t key = 0;
    std::uint32_t generation = 1;
    std::uint32_t stamp = 0;  ///< step stamp, to gather each active contact once
    bool alive = false;
    bool touching = false;
    bool isSensor = false;
    bool enableEvents = false;
};

struct DistanceJoint {
    DistanceJointDef def{};
    int bodyA = kNullIndex, bodyB = kNullIndex;
    float impulse = 0.0f;       ///< rigid/spring axial impulse
    float lowerImpulse = 0.0f;  ///< min-length limit
    float upperImpulse = 0.0f;  ///< max-length limit
    float lastForce = 0.0f;
    // Solver scratch, filled by prepare for the current step.
    int a = kNullIndex, b = kNullIndex;  ///< solver body indices
    Vec2 rA{}, rB{};          ///< anchors relative to the centres of mass at step start (world)
    Vec2 deltaCenter{};       ///< centre B − centre A at step start
    float axialMass = 0.0f;
    float invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
    float biasImpulse = 0.0f; ///< split mode position impulse
    bool alive = false;
    std::uint32_t generation = 1;
};

/// Solver state of one awake body during a step (flat, streamed by the solver).
struct BodyState {
    Vec2 v{};
    float w = 0.0f;
    float invMass = 0.0f;
    float invInertia = 0.0f;
    Vec2 dp{};   ///< change of the centre of mass since the step began
    Rot dq{};    ///< rotation since the step began
};

template <class T>
struct SlotArray {
    std::vector<T> items;
    std::vector<int> freeSlots;
    int count = 0;

    int allocate() {
        int i;
        if (!freeSlots.empty()) {
            i = freeSlots.back();
            freeSlots.pop_back();
            std::uint32_t gen = items[static_cast<std::size_t>(i)].generation;
            items[static_cast<std::size_t>(i)] = T{};
            items[static_cast<std::size_t>(i)].generation = gen;
        } else {
            items.emplace_back();
            i = static_cast<int>(items.size()) - 1;
        }
        items[static_cast<std::size_t>(i)].alive = true;
        ++count;
        return i;
    }
    void release(int i) {
        T& t = items[static_cast<std::size_t>(i)];
        t.alive = false;
        ++t.generation;
        if (t.generation == 0) t.generation = 1;
        freeSlots.push_back(i);
        --count;
    }
    T& operator[](int i) { return items[static_cast<std::size_t>(i)]; }
    const T& operator[](int i) const { return items[static_cast<std::size_t>(i)]; }
    int capacity() const { return static_cast<int>(items.size()); }
};


/// Solver row data of one contact point (see contact_solver.cpp).
struct ContactPointConstraint {
    Vec2 rA{}, rB{};              ///< anchors relative to the centres of mass at step start
    float adjustedSeparation = 0; ///< separation − (rB − rA)·n, so s = (Δ)·n + this
    float normalMass = 0, tangentMass = 0;
    float normalImpulse = 0, tangentImpulse = 0;
    float maxNormalImpulse = 0;
    float relativeVelocity = 0;   ///< normal approach speed at step start (for restitution)
    float restitutionBias = 0;    ///< seed 001 eq. 8.2.1 target, baumgarte/split modes
    float biasImpulse = 0;        ///< split mode: accumulated push impulse
};

struct ContactConstraint {
    int contact = kNullIndex;
    int a = kNullIndex, b = kNullIndex;  ///< state indices; an immovable side uses the zero state
    Vec2 normal{};
    float friction = 0, restitution = 0;
    float invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
    float biasRate = 0, massScale = 1, impulseScale = 0;  ///< soft contact coefficients
    float maxPush = 0;  ///< push speed cap of this contact (m/s), shared among a body's deep contacts
    bool deepOverlap = false;  ///< a point overlaps by more than kDeepOverlap (solver.cpp)
    int pointCount = 0;
    ContactPointConstraint points[2];
};

class WorldImpl {
public:
    explicit WorldImpl(const WorldSettings& s) : settings(s) {}

    WorldSettings settings;
    SlotArray<Body> bodies;
    SlotArray<Shape> shapes;
    SlotArray<Contact> contacts;
    SlotArray<DistanceJoint> joints;

    std::vector<int> awakeBodies;
    std::vector<std::vector<int>> sleepingIslands;
    std::vector<int> freeIslands;

    DynamicTree staticTree;   ///< shapes of static bodies: never query
    DynamicTree movingTree;   ///< shapes of kinematic and dynamic bodies
    std::vector<int> moveBuffer;  ///< shapes whose proxies moved or were created
    std::unordered_map<std::uint64_t, int> pairs;  ///< shape-pair key → contact

    std::vector<ContactBeginEvent> beginEvents;
    std::vector<ContactEndEvent> endEvents;
    std::vector<SensorBeginEvent> sensorBeginEvents;
    std::vector<SensorEndEvent> sensorEndEvents;

    // Per-step scratch, kept to avoid allocation in steady state.
    std::vector<int> activeContacts;
    std::vector<int> scratch;
    std::vector<BodyState> states;  ///< awake bodies, then one zero state for immovable sides
    std::vector<int> stateBodies;   ///< body index of each state (awake bodies only)
    std::vector<Vec2> biasV;       ///< split mode pseudo-velocities
    std::vector<float> biasW;
    std::vector<ContactConstraint> constraints;        ///< in colour order (solver.cpp)
    std::vector<ContactConstraint> constraintScratch;  ///< the colour sort's other buffer
    std::vector<std::uint64_t> colourBits;             ///< per colour, one bit per state
    std::vector<int> colourCounts;
    std::vector<std::uint8_t> constraintColours;
    std::vector<int> activeJoints;
    std::vector<int> deepContactCount;  ///< per solver body: contacts overlapping deeper than kDeepOverlap
    std::vector<int> unionParent;
    std::vector<std::uint32_t> impactChanged;

    Profile profile{};
    std::uint32_t stepStamp = 0;
    bool locked = false;  ///< true while stepping or drawing (see checkUnlocked)

    // --- helpers (world.cpp) ---
    BodyId bodyHandle(int i) const { return {static_cast<std::uint32_t>(i + 1), bodies[i].generation}; }
    ShapeId shapeHandle(int i) const { return {static_cast<std::uint32_t>(i + 1), shapes[i].generation}; }
    JointId jointHandle(int i) const { return {static_cast<std::uint32_t>(i + 1), joints[i].generation}; }
    int bodyIndex(BodyId id) const;   ///< throws on null or stale
    int shapeIndex(ShapeId id) const;
    int jointIndex(JointId id) const;
    void checkUnlocked() const;

    int createShape(int body, const ShapeDef& def, ShapeType type);
    void destroyShapeInternal(int shape);
    void updateMass(int body);
    void wakeBody(int body);
    void putIslandToSleep(const std::vector<int>& islandBodies);
    void addAwake(int body);
    void removeAwake(int body);
    void synchronizeShapes(int body);  ///< refresh AABBs / proxies after a move
    AABB computeShapeAABB(const Shape& shape, const Transform& xf) const;

    // --- broadphase and contacts (contacts.cpp) ---
    void createProxy(int shape);
    void destroyProxy(int shape);
    void updatePairs();
    void createContact(int shapeA, int shapeB);
    void destroyContact(int contact, bool emitEvents);
    void collide();
    bool updateContact(int contact);  ///< false when the contact was destroyed
    Manifold computeManifold(const Contact& c) const;
    bool jointPreventsCollision(int bodyA, int bodyB) const;

    // --- impacts (impacts.cpp) ---
    void resolveImpacts(float dt);

    // --- solver (solver.cpp) ---
    void solve(float dt);

    // --- continuous collision (continuous.cpp), after solve() ---
    void solveContinuous();
    float solidReach(const Body& body) const;  ///< Body::reach from its shapes

    // --- sleep (sleep.cpp) ---
    void updateSleep(float dt);

    void step(float dt);
};

}  // namespace i2d::detail
