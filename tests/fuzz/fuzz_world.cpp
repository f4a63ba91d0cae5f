// Fuzz target: a world driven by a random sequence of operations — create
// and destroy bodies, shapes and joints of every type, apply impulses and forces, teleport,
// change types and settings, step — interleaved with calls carrying
// arbitrary floats (NaN, infinities, huge values) and stale handles.
// Properties: refused calls throw i2d::Error and change nothing; after every
// step every body is finite and no faster than the world's speed limit;
// the counts agree with what was created and destroyed.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "byte_reader.hpp"
#include "fuzz_check.hpp"

using namespace i2d;

namespace {

// What a refused call must leave untouched (compared bit for bit).
std::vector<float> snapshot(const World& w) {
    std::vector<float> s{static_cast<float>(w.bodyCount()), static_cast<float>(w.shapeCount()),
                         static_cast<float>(w.jointCount()), static_cast<float>(w.awakeBodyCount())};
    for (BodyId b : w.bodies()) {
        Transform xf = w.transform(b);
        Vec2 v = w.linearVelocity(b);
        s.insert(s.end(), {xf.p.x, xf.p.y, xf.q.c, xf.q.s, v.x, v.y, w.angularVelocity(b), w.mass(b)});
    }
    return s;
}

bool same(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

struct Driver {
    fuzz::ByteReader& in;
    World world;
    std::vector<BodyId> live;
    std::vector<BodyId> dead;
    std::vector<JointId> joints;

    Driver(fuzz::ByteReader& input, const WorldSettings& settings) : in(input), world(settings) {}

    float any() { return in.anyFloat(); }
    float range(float lo, float hi) { return in.real(lo, hi); }
    Vec2 vec(float r) { return {range(-r, r), range(-r, r)}; }
    // Mostly sensible values, sometimes anything at all.
    float maybeBad(float lo, float hi) { return in.integer(0, 7) == 0 ? any() : range(lo, hi); }

    BodyId pickLive() { return live[in.integer<std::size_t>(0, live.size() - 1)]; }

    // Runs a call that may be refused; a refusal must change nothing.
    template <class F>
    bool attempt(F&& call, int line) {
        std::vector<float> before = snapshot(world);
        try {
            call();
            if (trace) std::fprintf(stderr, "line %d: done\n", line);
            return true;
        } catch (const Error& e) {
            if (trace) std::fprintf(stderr, "line %d: refused: %s\n", line, e.what());
            I2D_FUZZ_CHECK(same(before, snapshot(world)));
            return false;
        }
    }
    // I2D_FUZZ_TRACE=1 prints every call and, after each step, every body.
    const bool trace = std::getenv("I2D_FUZZ_TRACE") != nullptr;

    void addShape(BodyId b) {
        ShapeDef def{.density = maybeBad(0.0f, 10.0f), .friction = range(0.0f, 1.5f), .restitution = range(0.0f, 1.0f)};
        def.isSensor = in.integer(0, 9) == 0;
        switch (in.integer(0, 3)) {
            case 0:
                attempt([&] { world.createCircleShape(b, def, {vec(1.0f), maybeBad(0.02f, 3.0f)}); }, __LINE__);
                break;
            case 1:
                attempt(
                    [&] {
                        world.createCapsuleShape(b, def, {vec(1.0f), vec(1.0f), maybeBad(0.02f, 1.0f)});
                    },
                    __LINE__);
                break;
            case 2: {
                std::vector<Vec2> pts;
                int n = in.integer(3, 8);
                for (int i = 0; i < n; ++i) pts.push_back(vec(2.0f));
                auto poly = makePolygon(computeHull(pts), in.flag() ? range(0.0f, 0.3f) : 0.0f);
                if (poly && trace) {
                    std::fprintf(stderr, "polygon radius %.9g density %.9g:", poly->radius, def.density);
                    for (int i = 0; i < poly->count; ++i)
                        std::fprintf(stderr, " (%.9g, %.9g)", poly->vertices[i].x, poly->vertices[i].y);
                    std::fprintf(stderr, "\n");
                }
                if (poly) attempt([&] { world.createPolygonShape(b, def, *poly); }, __LINE__);
                break;
            }
            default: attempt([&] { world.createSegmentShape(b, def, {vec(5.0f), vec(5.0f)}); }, __LINE__); break;
        }
    }

    void createBody() {
        if (live.size() >= 64) return;
        int t = in.integer(0, 9);
        BodyDef def{.type = t == 0   ? BodyType::static_body
                            : t == 1 ? BodyType::kinematic_body
                                     : BodyType::dynamic_body,
                    .position = {maybeBad(-20.0f, 20.0f), range(-2.0f, 30.0f)},
                    .angle = range(-4.0f, 4.0f),
                    .linearVelocity = vec(20.0f),
                    .angularVelocity = range(-10.0f, 10.0f),
                    .isAwake = in.flag()};
        BodyId b{};
        attempt([&] { b = world.createBody(def); }, __LINE__);
        if (trace)
            std::fprintf(stderr, "body %u: type %d at (%g, %g) angle %g v (%g, %g) w %g\n", b.index1,
                         static_cast<int>(def.type), def.position.x, def.position.y, def.angle, def.linearVelocity.x,
                         def.linearVelocity.y, def.angularVelocity);
        if (b.isNull()) return;
        live.push_back(b);
        int shapes = in.integer(0, 3);
        for (int i = 0; i < shapes; ++i) addShape(b);
    }

    void destroyBody() {
        if (live.empty()) return;
        std::size_t i = in.integer<std::size_t>(0, live.size() - 1);
        int before = world.bodyCount();
        world.destroyBody(live[i]);
        I2D_FUZZ_CHECK(world.bodyCount() == before - 1 && !world.isValid(live[i]));
        dead.push_back(live[i]);
        live[i] = live.back();
        live.pop_back();
    }

    void useStaleHandle() {
        if (dead.empty()) return;
        BodyId b = dead[in.integer<std::size_t>(0, dead.size() - 1)];
        std::vector<float> before = snapshot(world);
        bool refused = false;
        try {
            switch (in.integer(0, 3)) {
                case 0: world.destroyBody(b); break;
                case 1: world.applyLinearImpulseToCenter(b, {1.0f, 0.0f}); break;
                case 2: world.createCircleShape(b, {}, {{0, 0}, 0.5f}); break;
                default: world.position(b); break;
            }
        } catch (const Error&) {
            refused = true;
        }
        I2D_FUZZ_CHECK(refused && same(before, snapshot(world)));
    }

    void poke() {
        if (live.empty()) return;
        BodyId b = pickLive();
        if (trace) std::fprintf(stderr, "body %u:\n", b.index1);
        switch (in.integer(0, 12)) {
            case 0: {
                // Read in the order written: the order in which a call's
                // arguments are evaluated is unspecified (GCC and Clang differ),
                // and an input found under one compiler must replay the same
                // under the other (the default test run replays the corpus).
                const Vec2 impulse{maybeBad(-50, 50), maybeBad(-50, 50)};
                const Vec2 point = vec(30.0f);
                attempt([&] { world.applyLinearImpulse(b, impulse, point); }, __LINE__);
                break;
            }
            case 1:
                attempt([&] { world.applyForceToCenter(b, {maybeBad(-1e3f, 1e3f), maybeBad(-1e3f, 1e3f)}); }, __LINE__);
                break;
            case 2: attempt([&] { world.applyTorque(b, maybeBad(-100, 100)); }, __LINE__); break;
            case 3: attempt([&] { world.applyAngularImpulse(b, maybeBad(-10, 10)); }, __LINE__); break;
            case 4:
                attempt([&] { world.setLinearVelocity(b, {maybeBad(-50, 50), maybeBad(-50, 50)}); }, __LINE__);
                break;
            case 5: attempt([&] { world.setAngularVelocity(b, maybeBad(-50, 50)); }, __LINE__); break;
            case 6: {
                const Vec2 position{maybeBad(-20, 20), maybeBad(-2, 30)};
                const float angle = maybeBad(-4, 4);  // (after the position: see case 0)
                attempt([&] { world.setTransform(b, position, angle); }, __LINE__);
                break;
            }
            case 7: attempt([&] { world.setBodyType(b, static_cast<BodyType>(in.integer(0, 2))); }, __LINE__); break;
            case 8: attempt([&] { world.setAwake(b, in.flag()); }, __LINE__); break;
            case 9: {
                auto shapes = world.bodyShapes(b);
                if (!shapes.empty())
                    world.destroyShape(shapes[in.integer<std::size_t>(0, shapes.size() - 1)]);
                else
                    addShape(b);
                break;
            }
            case 10:
                attempt(
                    [&] {
                        world.setMassData(b, {maybeBad(0.01f, 100), vec(1.0f), maybeBad(0.0f, 100)});
                    },
                    __LINE__);
                break;
            case 11: attempt([&] { world.setGravityScale(b, maybeBad(-2, 2)); }, __LINE__); break;
            default: attempt([&] { world.setFixedRotation(b, in.flag()); }, __LINE__); break;
        }
    }

    void joint() {
        if (in.flag() && !joints.empty()) {
            std::size_t i = in.integer<std::size_t>(0, joints.size() - 1);
            if (world.isValid(joints[i])) {
                world.destroyJoint(joints[i]);
            } else {
                attempt([&] { world.destroyJoint(joints[i]); }, __LINE__);
            }
            joints[i] = joints.back();
            joints.pop_back();
            return;
        }
        if (live.size() < 2) return;
        const BodyId a = pickLive(), b = pickLive();
        switch (in.integer(0, 8)) {
            case 0: {
                DistanceJointDef def{.bodyA = a,
                                     .bodyB = b,
                                     .localAnchorA = vec(0.5f),
                                     .localAnchorB = vec(0.5f),
                                     .length = maybeBad(0.1f, 5.0f),
                                     .enableSpring = in.flag(),
                                     .hertz = range(0.0f, 10.0f),
                                     .dampingRatio = range(0.0f, 2.0f),
                                     .enableLimit = in.flag(),
                                     .minLength = range(0.0f, 2.0f),
                                     .maxLength = range(2.0f, 6.0f)};
                attempt([&] { joints.push_back(world.createDistanceJoint(def)); }, __LINE__);
                break;
            }
            case 1: {
                RevoluteJointDef def{.bodyA = a,
                                     .bodyB = b,
                                     .localAnchorA = vec(0.5f),
                                     .localAnchorB = vec(0.5f),
                                     .referenceAngle = maybeBad(-1.0f, 1.0f),
                                     .enableLimit = in.flag(),
                                     .lowerAngle = range(-3.0f, 0.5f),
                                     .upperAngle = range(-0.5f, 3.0f),
                                     .enableMotor = in.flag(),
                                     .motorSpeed = maybeBad(-20.0f, 20.0f),
                                     .maxMotorTorque = maybeBad(0.0f, 1000.0f),
                                     .enableSpring = in.flag(),
                                     .hertz = range(0.0f, 10.0f),
                                     .dampingRatio = range(0.0f, 2.0f)};
                attempt([&] { joints.push_back(world.createRevoluteJoint(def)); }, __LINE__);
                break;
            }
            case 2: {
                PrismaticJointDef def{.bodyA = a,
                                      .bodyB = b,
                                      .localAnchorA = vec(0.5f),
                                      .localAnchorB = vec(0.5f),
                                      .localAxisA = vec(1.0f),
                                      .enableLimit = in.flag(),
                                      .lowerTranslation = range(-3.0f, 0.5f),
                                      .upperTranslation = maybeBad(-0.5f, 3.0f),
                                      .enableMotor = in.flag(),
                                      .motorSpeed = range(-10.0f, 10.0f),
                                      .maxMotorForce = maybeBad(0.0f, 1000.0f),
                                      .enableSpring = in.flag(),
                                      .hertz = range(0.0f, 10.0f),
                                      .dampingRatio = range(0.0f, 2.0f)};
                attempt([&] { joints.push_back(world.createPrismaticJoint(def)); }, __LINE__);
                break;
            }
            case 3: {
                WeldJointDef def{.bodyA = a,
                                 .bodyB = b,
                                 .localAnchorA = vec(0.5f),
                                 .localAnchorB = vec(0.5f),
                                 .linearHertz = range(0.0f, 10.0f),
                                 .angularHertz = maybeBad(0.0f, 10.0f)};
                attempt([&] { joints.push_back(world.createWeldJoint(def)); }, __LINE__);
                break;
            }
            case 4: {
                WheelJointDef def{.bodyA = a,
                                  .bodyB = b,
                                  .localAnchorA = vec(0.5f),
                                  .localAnchorB = vec(0.5f),
                                  .localAxisA = vec(1.0f),
                                  .hertz = maybeBad(0.0f, 10.0f),
                                  .enableMotor = in.flag(),
                                  .motorSpeed = range(-20.0f, 20.0f),
                                  .maxMotorTorque = range(0.0f, 100.0f)};
                attempt([&] { joints.push_back(world.createWheelJoint(def)); }, __LINE__);
                break;
            }
            case 5: {
                MotorJointDef def{.bodyA = a,
                                  .bodyB = b,
                                  .linearOffset = vec(2.0f),
                                  .angularOffset = range(-1.0f, 1.0f),
                                  .maxForce = maybeBad(0.0f, 1000.0f),
                                  .maxTorque = range(0.0f, 100.0f),
                                  .correctionFactor = range(0.0f, 1.0f)};
                attempt([&] { joints.push_back(world.createMotorJoint(def)); }, __LINE__);
                break;
            }
            case 6: {
                MouseJointDef def{.bodyA = a, .bodyB = b, .target = vec(5.0f), .maxForce = maybeBad(0.0f, 1.0e4f)};
                attempt([&] { joints.push_back(world.createMouseJoint(def)); }, __LINE__);
                break;
            }
            case 7: {
                PulleyJointDef def{.bodyA = a,
                                   .bodyB = b,
                                   .groundAnchorA = vec(5.0f),
                                   .groundAnchorB = vec(5.0f),
                                   .lengthA = range(0.5f, 5.0f),
                                   .lengthB = range(0.5f, 5.0f),
                                   .ratio = maybeBad(0.2f, 3.0f)};
                attempt([&] { joints.push_back(world.createPulleyJoint(def)); }, __LINE__);
                break;
            }
            default: {
                if (joints.size() < 2) return;
                const JointId j1 = joints[in.integer<std::size_t>(0, joints.size() - 1)];
                const JointId j2 = joints[in.integer<std::size_t>(0, joints.size() - 1)];
                GearJointDef def{.joint1 = j1, .joint2 = j2, .ratio = maybeBad(-3.0f, 3.0f)};
                attempt([&] { joints.push_back(world.createGearJoint(def)); }, __LINE__);
                break;
            }
        }
    }

    void settings() {
        WorldSettings s = world.settings();
        switch (in.integer(0, 4)) {
            case 0: s.gravity = {maybeBad(-20, 20), maybeBad(-20, 20)}; break;
            case 1: s.substeps = in.integer(0, 8); break;
            case 2: s.positionCorrection = static_cast<PositionCorrection>(in.integer(0, 3)); break;
            case 3:
                s.exactJointMassRatio = in.flag() ? 1.0f : maybeBad(0.5f, 50.0f);
                break;  // 1: every joint tree exact
            default: s.enableSleep = in.flag(); break;
        }
        if (trace)
            std::fprintf(stderr, "settings: gravity (%g, %g) substeps %d correction %d sleep %d\n", s.gravity.x,
                         s.gravity.y, s.substeps, static_cast<int>(s.positionCorrection), s.enableSleep ? 1 : 0);
        attempt([&] { world.setSettings(s); }, __LINE__);
    }

    void step() {
        float dt = in.flag() ? 1.0f / 60.0f : maybeBad(0.001f, 0.05f);
        if (trace) std::fprintf(stderr, "step %g\n", dt);
        const bool stepped = attempt([&] { world.step(dt); }, __LINE__);
        if (trace) {
            for (BodyId b : live) {
                Vec2 p = world.position(b), v = world.linearVelocity(b);
                std::fprintf(stderr, "  body %u type %d p (%g, %g) v (%g, %g) w %g m %g I %g\n", b.index1,
                             static_cast<int>(world.bodyType(b)), p.x, p.y, v.x, v.y, world.angularVelocity(b),
                             world.mass(b), world.rotationalInertia(b));
            }
        }
        I2D_FUZZ_CHECK(fuzz::worldIsFinite(world));
        // The speed limit, with 1% for the substep integration after the clamp.
        // Only after a step that ran: a refused step leaves whatever velocity
        // the caller set (setLinearVelocity accepts up to 1e7 m/s).
        if (!stepped) return;
        const float limit = world.settings().maxLinearSpeed * 1.01f;
        for (BodyId b : live)
            if (world.bodyType(b) == BodyType::dynamic_body) I2D_FUZZ_CHECK(length(world.linearVelocity(b)) <= limit);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::ByteReader in(data, size);
    WorldSettings settings;
    settings.positionCorrection = static_cast<PositionCorrection>(in.integer(0, 2));
    settings.impactModel = static_cast<ImpactModel>(in.integer(0, 1));
    settings.substeps = in.integer(1, 8);
    Driver d(in, settings);
    // Ground, so that things pile up and touch.
    BodyId ground = d.world.createBody({});
    d.world.createPolygonShape(ground, {}, makeOffsetBox(30.0f, 1.0f, {0.0f, -1.0f}, 0.0f));
    d.live.push_back(ground);

    int steps = 0;
    while (in.remaining() > 0 && steps < 300) {
        switch (in.integer(0, 9)) {
            case 0:
            case 1: d.createBody(); break;
            case 2: d.destroyBody(); break;
            case 3: d.useStaleHandle(); break;
            case 4:
            case 5: d.poke(); break;
            case 6: d.joint(); break;
            case 7: d.settings(); break;
            default:
                d.step();
                ++steps;
                break;
        }
    }
    for (int i = 0; i < 10; ++i) d.step();
    // Counts agree with the driver's bookkeeping; destroying everything empties the world.
    I2D_FUZZ_CHECK(d.world.bodyCount() == static_cast<int>(d.live.size()));
    for (BodyId b : d.live) d.world.destroyBody(b);
    I2D_FUZZ_CHECK(d.world.bodyCount() == 0 && d.world.shapeCount() == 0 && d.world.jointCount() == 0 &&
                   d.world.contactCount() == 0);
    d.world.step(1.0f / 60.0f);
    return 0;
}
