// Testbed — a scene as a Box2D 2.4.1 world, behind the Simulation interface.
//
// Box2D is the reference the validation and benchmarks hold Impulse2D
// against; it lives in the testbed, never in the engine. The mapping keeps
// what both engines share (bodies, materials, circles, polygons, segments,
// joints of every type, gravity, damping) identical, gives every dynamic body
// the mass properties Impulse2D computes for it, and lists in notes() what
// Box2D 2.4.1 has no equivalent for, so nothing is dropped silently.
#include <box2d/box2d.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>

#include "box2d_joints.hpp"
#include "simulation.hpp"

namespace tb {
namespace {

b2Vec2 toB2(i2d::Vec2 v) { return {v.x, v.y}; }

b2BodyType toB2(i2d::BodyType t) {
    switch (t) {
        case i2d::BodyType::static_body: return b2_staticBody;
        case i2d::BodyType::kinematic_body: return b2_kinematicBody;
        case i2d::BodyType::dynamic_body: break;
    }
    return b2_dynamicBody;
}

/// Whether b2PolygonShape::Set (2.4.1) takes these points: it welds points
/// closer than half of b2_linearSlop and needs 3 of them not on one line.
bool box2dAcceptsPolygon(const b2Vec2* v, int count) {
    b2Vec2 kept[b2_maxPolygonVertices];
    int n = 0;
    const float weld = 0.5f * b2_linearSlop;
    for (int i = 0; i < count; ++i) {
        bool unique = true;
        for (int j = 0; j < n && unique; ++j) unique = b2DistanceSquared(v[i], kept[j]) >= weld * weld;
        if (unique) kept[n++] = v[i];
    }
    if (n < 3) return false;
    // Not all on one line: some point off the line through the first two.
    for (int i = 2; i < n; ++i)
        if (b2Cross(kept[1] - kept[0], kept[i] - kept[0]) != 0.0f) return true;
    return false;
}

/// A shape's tangent speed travels in its fixture's user data (the float's
/// bits); Box2D 2.4.1 sets tangent speed per contact, in a pre-solve listener.
std::uintptr_t packSpeed(float speed) {
    std::uint32_t bits;
    std::memcpy(&bits, &speed, sizeof bits);
    return bits;
}

float unpackSpeed(b2Fixture* f) {
    const auto bits = static_cast<std::uint32_t>(f->GetUserData().pointer);
    float speed;
    std::memcpy(&speed, &bits, sizeof speed);
    return speed;
}

/// Conveyor belts: each contact's tangent speed is the sum of its two
/// fixtures' (ShapeDef::tangentSpeed); 2.4.1's friction row aims at it with
/// the same sign convention (tangent = normal × 1, the normal turned clockwise).
class TangentSpeedListener final : public b2ContactListener {
public:
    void PreSolve(b2Contact* contact, const b2Manifold*) override {
        contact->SetTangentSpeed(unpackSpeed(contact->GetFixtureA()) + unpackSpeed(contact->GetFixtureB()));
    }
};

class Box2DSimulation final : public Simulation {
public:
    Box2DSimulation(const SceneDesc& desc, const Box2DSettings& settings)
        : world_(toB2(desc.settings.gravity)), settings_(settings) {
        const i2d::WorldSettings& ws = desc.settings;
        world_.SetAllowSleeping(ws.enableSleep);
        world_.SetWarmStarting(ws.enableWarmStarting);
        world_.SetContinuousPhysics(ws.enableContinuous);
        bodies_.reserve(desc.bodies.size());
        for (const BodyDesc& b : desc.bodies) bodies_.push_back(createBody(b, ws));
        for (std::size_t i = 0; i < desc.joints.size(); ++i) createJoint(desc, desc.joints[i], i);
        describeDifferences(desc);
        if (anyTangentSpeed_) world_.SetContactListener(&tangentSpeed_);
        keepDrives(desc);
    }

    EngineKind engine() const override { return EngineKind::box2d; }
    void step(float dt) override {
        applyDrives();
        world_.Step(dt, settings_.velocityIterations, settings_.positionIterations);
    }
    int bodyCount() const override { return static_cast<int>(bodies_.size()); }
    int jointCount() const override { return world_.GetJointCount(); }

    int touchingContactCount() const override {
        int n = 0;
        for (const b2Contact* c = world_.GetContactList(); c; c = c->GetNext())
            if (c->IsTouching()) ++n;
        return n;
    }

    float maxPenetration() const override {
        float worst = 0.0f;
        for (const b2Contact* c = world_.GetContactList(); c; c = c->GetNext()) {
            if (!c->IsTouching()) continue;
            b2WorldManifold wm;
            c->GetWorldManifold(&wm);
            for (int i = 0; i < c->GetManifold()->pointCount; ++i) worst = std::max(worst, -wm.separations[i]);
        }
        return worst;
    }

    void driveX(int index, float vx) override {
        b2Body* b = bodies_[static_cast<std::size_t>(index)];
        b->SetLinearVelocity({vx, b->GetLinearVelocity().y});
    }

    BodySample sample(int index) const override {
        const b2Body* b = bodies_[static_cast<std::size_t>(index)];
        BodySample s;
        const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity(), c = b->GetWorldCenter();
        s.x = p.x;
        s.y = p.y;
        s.angle = b->GetAngle();
        s.vx = v.x;
        s.vy = v.y;
        s.w = b->GetAngularVelocity();
        s.cx = c.x;
        s.cy = c.y;
        s.dynamic = b->GetType() == b2_dynamicBody;
        if (s.dynamic) {
            s.mass = b->GetMass();
            // Box2D reports inertia about the body origin; shift it to the centre of mass.
            const b2Vec2 lc = b->GetLocalCenter();
            s.inertia = b->GetInertia() - s.mass * b2Dot(lc, lc);
        }
        s.gravityScale = b->GetGravityScale();
        s.awake = b->IsAwake();
        return s;
    }

private:
    void note(const std::string& what) {
        if (noted_.insert(what).second) notes_.push_back(what);
    }

    b2Body* createBody(const BodyDesc& b, const i2d::WorldSettings& ws) {
        b2BodyDef bd;
        bd.type = toB2(b.def.type);
        bd.position = toB2(b.def.position);
        bd.angle = b.def.angle;
        bd.linearVelocity = toB2(b.def.linearVelocity);
        bd.angularVelocity = b.def.angularVelocity;
        bd.linearDamping = b.def.linearDamping;
        bd.angularDamping = b.def.angularDamping;
        bd.gravityScale = b.def.gravityScale;
        bd.fixedRotation = b.def.fixedRotation;
        bd.awake = b.def.isAwake;
        bd.allowSleep = b.def.enableSleep;
        bd.bullet = b.def.isBullet;
        b2Body* body = world_.CreateBody(&bd);

        // Mass properties as Impulse2D computes them (parallel-axis sum), so
        // that the two engines move the same bodies even where a shape has to
        // be built differently (capsules, rounded polygons).
        double mass = 0, mx = 0, my = 0, inertiaOrigin = 0;
        for (const ShapeDesc& s : b.shapes) {
            i2d::MassData md{};
            switch (s.type) {
                case i2d::ShapeType::circle: md = i2d::computeMass(s.circle, s.def.density); break;
                case i2d::ShapeType::capsule: md = i2d::computeMass(s.capsule, s.def.density); break;
                case i2d::ShapeType::polygon: md = i2d::computeMass(s.polygon, s.def.density); break;
                case i2d::ShapeType::segment: break;  // chains too
            }
            mass += md.mass;
            mx += double(md.mass) * md.center.x;
            my += double(md.mass) * md.center.y;
            inertiaOrigin += md.rotationalInertia +
                             double(md.mass) * (double(md.center.x) * md.center.x + double(md.center.y) * md.center.y);
            addShape(body, s, ws);
        }
        if (bd.type == b2_dynamicBody && mass > 0) {
            b2MassData md;
            md.mass = static_cast<float>(mass);
            md.center = {static_cast<float>(mx / mass), static_cast<float>(my / mass)};
            md.I = static_cast<float>(inertiaOrigin);  // about the body origin, as b2MassData wants
            body->SetMassData(&md);
        }
        return body;
    }

    // A chain as b2ChainShape: one-sided on the same (right) side, with ghost
    // vertices. Box2D 2.4.1's open chain needs a ghost at each end; the
    // straight continuation is given, so its ends collide as a flat
    // continuation where Impulse2D's are rounded corners.
    void addChain(b2Body* body, const ShapeDesc& s, b2FixtureDef& fd) {
        std::vector<b2Vec2> v;
        v.reserve(s.chainPoints.size());
        for (i2d::Vec2 p : s.chainPoints) v.push_back(toB2(p));
        b2ChainShape chain;
        const int n = static_cast<int>(v.size());
        if (s.chainLoop) {
            chain.CreateLoop(v.data(), n);
        } else {
            note("open chains: Box2D 2.4.1 needs ghost vertices at the ends; the straight continuations are given");
            const b2Vec2 prev = 2.0f * v[0] - v[1], next = 2.0f * v[n - 1] - v[n - 2];
            chain.CreateChain(v.data(), n, prev, next);
        }
        fd.density = 0.0f;
        fd.shape = &chain;
        body->CreateFixture(&fd);
    }

    void addShape(b2Body* body, const ShapeDesc& s, const i2d::WorldSettings& ws) {
        b2FixtureDef fd;
        fd.density = s.def.density;
        fd.friction = s.def.friction;
        fd.restitution = s.def.restitution;
        fd.restitutionThreshold = ws.restitutionThreshold;
        fd.isSensor = s.def.isSensor;
        fd.userData.pointer = packSpeed(s.def.tangentSpeed);
        anyTangentSpeed_ = anyTangentSpeed_ || s.def.tangentSpeed != 0.0f;
        if (s.def.rollingResistance > 0.0f)
            note("rolling resistance: Box2D 2.4.1 has none; shapes roll there without it");
        fd.filter.categoryBits = static_cast<uint16>(s.def.filter.categoryBits & 0xFFFFu);
        fd.filter.maskBits = static_cast<uint16>(s.def.filter.maskBits & 0xFFFFu);
        fd.filter.groupIndex = static_cast<int16>(s.def.filter.groupIndex);
        if ((s.def.filter.categoryBits >> 16) != 0 || s.def.filter.groupIndex < INT16_MIN ||
            s.def.filter.groupIndex > INT16_MAX)
            note("collision filters: Box2D 2.4.1 has 16 category bits and 16-bit groups; higher bits were dropped");

        if (s.chain) {
            addChain(body, s, fd);
            return;
        }
        switch (s.type) {
            case i2d::ShapeType::circle: {
                b2CircleShape c;
                c.m_p = toB2(s.circle.center);
                c.m_radius = s.circle.radius;
                fd.shape = &c;
                body->CreateFixture(&fd);
                break;
            }
            case i2d::ShapeType::segment: {
                b2EdgeShape e;
                e.SetTwoSided(toB2(s.segment.point1), toB2(s.segment.point2));
                fd.shape = &e;
                body->CreateFixture(&fd);
                break;
            }
            case i2d::ShapeType::polygon: {
                b2Vec2 v[b2_maxPolygonVertices];
                for (int i = 0; i < s.polygon.count; ++i) v[i] = toB2(s.polygon.vertices[i]);
                if (!box2dAcceptsPolygon(v, s.polygon.count)) {
                    // b2PolygonShape::Set would assert (or, without asserts,
                    // substitute a 2 x 2 m box): keep the sliver's long axis
                    // as an edge, whose 1 cm skin is the closest Box2D has.
                    note("slivers: a polygon thinner than Box2D 2.4.1's 2.5 mm vertex welding is an edge (segment) "
                         "between its two farthest vertices there, with Box2D's 1 cm skin");
                    int a = 0, b = 1;
                    for (int i = 0; i < s.polygon.count; ++i)
                        for (int j = i + 1; j < s.polygon.count; ++j)
                            if (b2DistanceSquared(v[i], v[j]) > b2DistanceSquared(v[a], v[b])) a = i, b = j;
                    b2EdgeShape e;
                    e.SetTwoSided(v[a], v[b]);
                    fd.shape = &e;
                    body->CreateFixture(&fd);
                    break;
                }
                b2PolygonShape p;
                p.Set(v, s.polygon.count);
                if (s.polygon.radius > p.m_radius) {
                    p.m_radius = s.polygon.radius;
                    note("rounded polygons: given to Box2D 2.4.1 as its polygon with that skin radius");
                }
                note("polygons: Box2D 2.4.1 adds a 1 cm skin (b2_polygonRadius) around every polygon, so its "
                     "boxes collide 1 cm larger than their vertices");
                fd.shape = &p;
                body->CreateFixture(&fd);
                break;
            }
            case i2d::ShapeType::capsule: {
                // No capsule in 2.4.1: a box over the core segment and a
                // circle at each end cover the same outline (the box is shrunk
                // by Box2D's polygon skin).
                note("capsules: Box2D 2.4.1 has none; each is a box plus two end circles with the capsule's mass");
                const i2d::Vec2 c1 = s.capsule.center1, c2 = s.capsule.center2;
                const float r = s.capsule.radius;
                b2CircleShape end;
                end.m_radius = r;
                fd.shape = &end;
                end.m_p = toB2(c1);
                body->CreateFixture(&fd);
                end.m_p = toB2(c2);
                body->CreateFixture(&fd);
                const i2d::Vec2 d = c2 - c1;
                b2PolygonShape core;
                core.SetAsBox(0.5f * i2d::length(d), std::max(r - b2_polygonRadius, b2_linearSlop),
                              toB2(0.5f * (c1 + c2)), std::atan2(d.y, d.x));
                fd.shape = &core;
                body->CreateFixture(&fd);
                break;
            }
        }
    }

    void createJoint(const SceneDesc& desc, const JointDesc& j, std::size_t index) {
        const std::string where = (desc.file.empty() ? desc.name : desc.file) + ": joints[" + std::to_string(index) +
                                  "]";
        if (j.bodyA < 0 || j.bodyB < 0 || j.bodyA >= bodyCount() || j.bodyB >= bodyCount())
            throw SceneError(where + ": body index out of range");
        if (j.type() == i2d::JointType::gear) {
            // Box2D 2.4.1 asserts (or crashes without asserts) on a gear over anything else.
            for (int k : {j.joint1, j.joint2}) {
                if (k < 0 || k >= static_cast<int>(joints_.size()))
                    throw SceneError(where + ": a gear must refer to joints before it");
                const b2JointType t = joints_[static_cast<std::size_t>(k)]->GetType();
                if (t != e_revoluteJoint && t != e_prismaticJoint)
                    throw SceneError(where + ": a gear couples revolute or prismatic joints");
            }
        }
        joints_.push_back(createBox2DJoint(world_, bodies_, joints_, j, [this](const std::string& s) { note(s); }));
    }

    void describeDifferences(const SceneDesc& desc) {
        const i2d::WorldSettings& ws = desc.settings;
        bool restitution = false;
        for (const BodyDesc& b : desc.bodies)
            for (const ShapeDesc& s : b.shapes) restitution = restitution || s.def.restitution > 0;
        if (ws.impactModel == i2d::ImpactModel::closed_form && restitution)
            note("impacts: Box2D 2.4.1 applies restitution as a velocity bias in its contact solver; the "
                 "closed-form impact law (Stronge restitution with friction) has no equivalent there");
        // Box2D 2.4.1 clamps motion to b2_maxTranslation per step; say so when
        // a body starts faster than that (e.g. bullets at 60 Hz above 120 m/s).
        for (const BodyDesc& b : desc.bodies) {
            if (i2d::length(b.def.linearVelocity) * desc.dt > b2_maxTranslation)
                note("speed limit: Box2D 2.4.1 moves a body at most b2_maxTranslation = 2 m per step, slower "
                     "than some bodies of this scene start");
            if (std::abs(b.def.angularVelocity) * desc.dt > b2_maxRotation)
                note("spin limit: Box2D 2.4.1 turns a body at most b2_maxRotation = 90 degrees per step, slower "
                     "than some bodies of this scene start");
        }
        if (desc.platformer)
            note("platformer: the game (player control, one-way platforms, moving platforms, coins) is played "
                 "only in Impulse2D; here the bodies stay as the file places them");
        // Box2D 2.4.1's sleep thresholds are compile-time constants.
        if (ws.enableSleep && (ws.timeToSleep != b2_timeToSleep || ws.linearSleepTolerance != b2_linearSleepTolerance ||
                               ws.angularSleepTolerance != b2_angularSleepTolerance))
            note("sleep: Box2D 2.4.1 puts bodies to sleep by its fixed thresholds (0.01 m/s, 2 degrees/s, 0.5 s), "
                 "not the scene's");
    }

    TangentSpeedListener tangentSpeed_;  ///< declared before world_, which points at it
    bool anyTangentSpeed_ = false;
    b2World world_;
    Box2DSettings settings_;
    std::vector<b2Body*> bodies_;
    std::vector<b2Joint*> joints_;  ///< joints_[i] made from desc.joints[i]
    std::set<std::string> noted_;
};

}  // namespace

bool box2dAvailable() { return true; }

std::unique_ptr<Simulation> makeBox2DSimulation(const SceneDesc& desc, const Box2DSettings& settings) {
    return std::make_unique<Box2DSimulation>(desc, settings);
}

}  // namespace tb
