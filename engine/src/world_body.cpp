// World: the public API facade for bodies — creation and destruction, type,
// transform, velocity, forces and impulses, mass, damping, sleep. Validates,
// then calls the body, island, shape, joint and broadphase modules.
#include <algorithm>

#include "impulse2d/world.hpp"
#include "joint.hpp"
#include "world_state.hpp"

namespace i2d {

using detail::fail;
using detail::requireBounded;
using detail::requireFinite;
using detail::requireNonNegative;

BodyId World::createBody(const BodyDef& def) {
    state().checkUnlocked();
    requireBounded(def.position, "body position");
    requireBounded(def.angle, "body angle");
    requireBounded(def.linearVelocity, "body linear velocity");
    requireBounded(def.angularVelocity, "body angular velocity");
    requireNonNegative(def.linearDamping, "linear damping");
    requireNonNegative(def.angularDamping, "angular damping");
    requireBounded(def.gravityScale, "gravity scale");
    if (static_cast<int>(def.type) > 2) fail("unknown body type");

    auto& w = state();
    int b = w.bodies.allocate();
    detail::Body& body = w.bodies[b];
    body.type = def.type;
    body.xf = {def.position, makeRot(def.angle)};
    body.center = def.position;
    body.linearDamping = def.linearDamping;
    body.angularDamping = def.angularDamping;
    body.gravityScale = def.gravityScale;
    body.fixedRotation = def.fixedRotation;
    body.isBullet = def.isBullet;
    body.enableSleep = def.enableSleep;
    body.userData = def.userData;
    if (def.type != BodyType::static_body) {
        body.v = def.linearVelocity;
        body.w = def.fixedRotation ? 0.0f : def.angularVelocity;
        if (lengthSquared(body.v) > 0.0f || body.w != 0.0f) detail::noteMotionSet(w, b);
    }
    detail::updateMass(w, b);
    if (def.type == BodyType::static_body) {
        body.awake = false;
    } else if (def.isAwake || !w.settings.enableSleep || !def.enableSleep) {
        body.awake = true;
        detail::addAwake(w, b);
    } else {
        // Created asleep: its own single-body island.
        detail::sleepAlone(w, b);
    }
    return w.bodyHandle(b);
}

void World::destroyBody(BodyId id) {
    auto& w = state();
    w.checkUnlocked();
    int b = w.bodyIndex(id);
    // Joints first (they wake the other body), then shapes with their contacts.
    // One at a time from the front: destroying a joint also destroys the
    // gear joints built on it, which may be further down this list.
    while (w.bodies[b].firstJoint != detail::kNullIndex) detail::destroyJoint(w, w.bodies[b].firstJoint);
    std::vector<int> shapes;
    for (int s : detail::bodyShapes(w.shapes, w.bodies[b])) shapes.push_back(s);
    for (int s : shapes) detail::destroyShape(w, s);
    detail::removeAwake(w, b);
    detail::leaveIsland(w, b);
    detail::Body& body = w.bodies[b];
    body.contacts.clear();
    w.bodies.release(b);
}

bool World::isValid(BodyId id) const { return state().find(id, state().bodies) != detail::kNullIndex; }

namespace {
// The bodies at the other end of a body's joints: they start or stop being
// held by it.
void wakeJointPartners(detail::WorldState& w, int b) {
    for (int j : detail::bodyJoints(w.joints, w.bodies[b], b)) {
        const detail::Joint& jt = w.joints[j];
        detail::wakeBody(w, jt.bodyA == b ? jt.bodyB : jt.bodyA);
    }
}
}  // namespace

void World::disableBody(BodyId id) {
    auto& w = state();
    w.checkUnlocked();
    int b = w.bodyIndex(id);
    if (!w.bodies[b].enabled) return;
    detail::destroyBodyContacts(w, b, detail::kNullIndex);
    for (int s : detail::bodyShapes(w.shapes, w.bodies[b])) detail::destroyProxy(w, s);
    wakeJointPartners(w, b);
    detail::removeAwake(w, b);
    detail::leaveIsland(w, b);
    detail::Body& body = w.bodies[b];
    body.awake = false;
    body.sleepTime = 0.0f;
    body.enabled = false;
    w.solver.jointPlanStale = true;  // its joints act on nothing now
}

void World::enableBody(BodyId id) {
    auto& w = state();
    w.checkUnlocked();
    int b = w.bodyIndex(id);
    detail::Body& body = w.bodies[b];
    if (body.enabled) return;
    body.enabled = true;
    w.solver.jointPlanStale = true;  // its joints act again
    for (int s : detail::bodyShapes(w.shapes, body)) detail::createProxy(w, s);
    detail::wakeBody(w, b);  // nothing for a static body: it stays "not awake"
    wakeJointPartners(w, b);
    // A static body's new proxies do not query: the moving shapes near it look again.
    if (body.type == BodyType::static_body) detail::wakeShapesAround(w, b);
}

bool World::isEnabled(BodyId id) const { return state().bodies[state().bodyIndex(id)].enabled; }

std::vector<ContactData> World::bodyContacts(BodyId id) const {
    const auto& w = state();
    const detail::Body& body = w.bodies[w.bodyIndex(id)];
    std::vector<int> slots;
    for (int c : body.contacts) {
        const detail::Contact& ct = w.contacts[c];
        if (ct.touching && !ct.isSensor) slots.push_back(c);
    }
    std::sort(slots.begin(), slots.end());
    std::vector<ContactData> out;
    out.reserve(slots.size());
    for (int c : slots) out.push_back(detail::contactData(w, c));
    return out;
}

BodyType World::bodyType(BodyId id) const { return state().bodies[state().bodyIndex(id)].type; }

void World::setBodyType(BodyId id, BodyType type) {
    auto& w = state();
    w.checkUnlocked();
    int b = w.bodyIndex(id);
    if (static_cast<int>(type) > 2) fail("unknown body type");
    detail::Body& body = w.bodies[b];
    if (body.type == type) return;
    // Simplest correct path: recreate the proxies in the right tree and
    // drop the contacts; the broadphase finds the pairs again next step.
    detail::destroyBodyContacts(w, b, detail::kNullIndex);
    for (int s : detail::bodyShapes(w.shapes, body)) detail::destroyProxy(w, s);
    detail::wakeBody(w, b);
    body.type = type;
    if (type == BodyType::static_body) {
        body.v = {};
        body.w = 0.0f;
        detail::removeAwake(w, b);
        body.awake = false;
    }
    for (int s : detail::bodyShapes(w.shapes, body)) detail::createProxy(w, s);
    detail::updateMass(w, b);
    // Now measured from the origin (updateMass keeps a static or kinematic body's reach).
    if (type != BodyType::dynamic_body) body.reach = detail::solidReach(w, body);
}

Vec2 World::position(BodyId id) const { return state().bodies[state().bodyIndex(id)].xf.p; }
float World::angle(BodyId id) const { return angleOf(state().bodies[state().bodyIndex(id)].xf.q); }
Rot World::rotation(BodyId id) const { return state().bodies[state().bodyIndex(id)].xf.q; }
Transform World::transform(BodyId id) const { return state().bodies[state().bodyIndex(id)].xf; }

void World::setTransform(BodyId id, Vec2 position, float angle) {
    auto& w = state();
    w.checkUnlocked();
    int b = w.bodyIndex(id);
    requireBounded(position, "position");
    requireBounded(angle, "angle");
    detail::Body& body = w.bodies[b];
    body.xf = {position, makeRot(angle)};
    body.center = transformPoint(body.xf, body.localCenter);
    detail::wakeBody(w, b);
    for (int j : detail::bodyJoints(w.joints, body, b)) detail::judgeStretch(w, j);  // the game may pull a joint open
    // Bodies touching a moved static body must notice it.
    for (int c : body.contacts) {
        const detail::Contact& ct = w.contacts[c];
        detail::wakeBody(w, ct.bodyA == b ? ct.bodyB : ct.bodyA);
    }
    detail::synchronizeProxies(w, b);
    detail::noteMotionSet(w, b);  // its boxes now hold where it is, not where its velocity takes it
    // Static proxies do not query: find the new pairs from the other side.
    if (body.type == BodyType::static_body) detail::wakeShapesAround(w, b);
}

Vec2 World::worldCenterOfMass(BodyId id) const { return state().bodies[state().bodyIndex(id)].center; }
Vec2 World::localCenterOfMass(BodyId id) const { return state().bodies[state().bodyIndex(id)].localCenter; }
Vec2 World::linearVelocity(BodyId id) const { return state().bodies[state().bodyIndex(id)].v; }
float World::angularVelocity(BodyId id) const { return state().bodies[state().bodyIndex(id)].w; }

void World::setLinearVelocity(BodyId id, Vec2 v) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    requireBounded(v, "linear velocity");
    detail::Body& body = state().bodies[b];
    if (body.type == BodyType::static_body) return;  // documented: static bodies do not move
    if (lengthSquared(v) > 0.0f) detail::wakeBody(state(), b);
    body.v = v;
    detail::noteMotionSet(state(), b);
}

void World::setAngularVelocity(BodyId id, float w) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    requireBounded(w, "angular velocity");
    detail::Body& body = state().bodies[b];
    if (body.type == BodyType::static_body || body.fixedRotation) return;
    if (w != 0.0f) detail::wakeBody(state(), b);
    body.w = w;
    detail::noteMotionSet(state(), b);
}

Vec2 World::velocityAtPoint(BodyId id, Vec2 p) const {
    const detail::Body& body = state().bodies[state().bodyIndex(id)];
    requireBounded(p, "point");
    return body.v + cross(body.w, p - body.center);
}

void World::applyForce(BodyId id, Vec2 force, Vec2 point, bool wake) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    requireBounded(force, "force");
    requireBounded(point, "point");
    detail::Body& body = state().bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (wake) detail::wakeBody(state(), b);
    if (!body.awake) return;  // a sleeping body ignores forces unless woken (as in Box2D)
    // Listed for the next step, which compares it with the last (releaseRemovedForces).
    if (body.force.x == 0.0f && body.force.y == 0.0f) state().forcedBodies.push_back(b);
    body.force += force;
    body.torque += cross(point - body.center, force);
}

void World::applyForceToCenter(BodyId id, Vec2 force, bool wake) {
    applyForce(id, force, state().bodies[state().bodyIndex(id)].center, wake);
}

void World::applyTorque(BodyId id, float torque, bool wake) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    requireBounded(torque, "torque");
    detail::Body& body = state().bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (wake) detail::wakeBody(state(), b);
    if (!body.awake) return;
    body.torque += torque;
}

void World::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 point, bool wake) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    requireBounded(impulse, "impulse");
    requireBounded(point, "point");
    detail::Body& body = state().bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (!wake && !body.awake) return;
    // On a body of tiny mass a bounded impulse can still give an unbounded
    // velocity (1e-37 kg: 1e38 m/s; found by fuzz_world): refused like an
    // out-of-range setLinearVelocity, before anything changes.
    const Vec2 v = body.v + body.invMass * impulse;
    const float w = body.w + body.invInertia * cross(point - body.center, impulse);
    requireBounded(v, "velocity after the impulse");
    requireBounded(w, "angular velocity after the impulse");
    if (wake) detail::wakeBody(state(), b);
    body.v = v;
    body.w = w;
    detail::noteMotionSet(state(), b);
}

void World::applyLinearImpulseToCenter(BodyId id, Vec2 impulse, bool wake) {
    applyLinearImpulse(id, impulse, state().bodies[state().bodyIndex(id)].center, wake);
}

void World::applyAngularImpulse(BodyId id, float impulse, bool wake) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    requireBounded(impulse, "angular impulse");
    detail::Body& body = state().bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (!wake && !body.awake) return;
    const float w = body.w + body.invInertia * impulse;
    requireBounded(w, "angular velocity after the impulse");  // see applyLinearImpulse
    if (wake) detail::wakeBody(state(), b);
    body.w = w;
    detail::noteMotionSet(state(), b);
}

float World::mass(BodyId id) const { return state().bodies[state().bodyIndex(id)].mass; }
float World::rotationalInertia(BodyId id) const { return state().bodies[state().bodyIndex(id)].inertia; }
MassData World::massData(BodyId id) const {
    const detail::Body& body = state().bodies[state().bodyIndex(id)];
    return {body.mass, body.localCenter, body.inertia};
}

void World::setMassData(BodyId id, const MassData& md) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    requireFinite(md.mass, "mass");
    requireBounded(md.center, "centre of mass");
    requireFinite(md.rotationalInertia, "rotational inertia");
    detail::Body& body = state().bodies[b];
    if (body.type != BodyType::dynamic_body) fail("only dynamic bodies have mass");
    if (!(md.mass > 0.0f)) fail("mass must be > 0");
    if (!isFinite(1.0f / md.mass)) fail("mass is too small (its inverse is not finite)");
    if (md.rotationalInertia < 0.0f) fail("rotational inertia must be >= 0");
    if (md.rotationalInertia > 0.0f && !isFinite(1.0f / md.rotationalInertia))
        fail("rotational inertia is too small (its inverse is not finite)");
    state().solver.jointPlanStale = true;  // the joints' rows read the masses
    body.mass = md.mass;
    body.invMass = 1.0f / md.mass;
    body.inertia = md.rotationalInertia;
    body.invInertia = (md.rotationalInertia > 0.0f && !body.fixedRotation) ? 1.0f / md.rotationalInertia : 0.0f;
    Vec2 oldCenter = body.center;
    body.localCenter = md.center;
    body.reach = detail::solidReach(state(), body);  // measured from the centre of mass
    body.center = transformPoint(body.xf, body.localCenter);
    body.v += cross(body.w, body.center - oldCenter);
}

void World::resetMassData(BodyId id) {
    state().checkUnlocked();
    detail::updateMass(state(), state().bodyIndex(id));
}

float World::linearDamping(BodyId id) const { return state().bodies[state().bodyIndex(id)].linearDamping; }
void World::setLinearDamping(BodyId id, float d) {
    int b = state().bodyIndex(id);
    requireNonNegative(d, "linear damping");
    state().bodies[b].linearDamping = d;
}
float World::angularDamping(BodyId id) const { return state().bodies[state().bodyIndex(id)].angularDamping; }
void World::setAngularDamping(BodyId id, float d) {
    int b = state().bodyIndex(id);
    requireNonNegative(d, "angular damping");
    state().bodies[b].angularDamping = d;
}
float World::gravityScale(BodyId id) const { return state().bodies[state().bodyIndex(id)].gravityScale; }
void World::setGravityScale(BodyId id, float s) {
    int b = state().bodyIndex(id);
    requireBounded(s, "gravity scale");
    detail::Body& body = state().bodies[b];
    // Listed for the next step, which takes the weight the body no longer
    // has out of its supports' warm starts (releaseRemovedForces).
    if (s != body.gravityScale) state().rescaledBodies.push_back({b, body.generation, body.gravityScale});
    body.gravityScale = s;
}
bool World::isFixedRotation(BodyId id) const { return state().bodies[state().bodyIndex(id)].fixedRotation; }
void World::setFixedRotation(BodyId id, bool flag) {
    state().checkUnlocked();
    int b = state().bodyIndex(id);
    detail::Body& body = state().bodies[b];
    body.fixedRotation = flag;
    if (flag) body.w = 0.0f;
    detail::updateMass(state(), b);
}
bool World::isBullet(BodyId id) const { return state().bodies[state().bodyIndex(id)].isBullet; }
void World::setBullet(BodyId id, bool flag) {
    state().checkUnlocked();
    state().bodies[state().bodyIndex(id)].isBullet = flag;
}
std::uintptr_t World::userData(BodyId id) const { return state().bodies[state().bodyIndex(id)].userData; }
void World::setUserData(BodyId id, std::uintptr_t data) { state().bodies[state().bodyIndex(id)].userData = data; }

bool World::isAwake(BodyId id) const { return state().bodies[state().bodyIndex(id)].awake; }
void World::setAwake(BodyId id, bool awake) {
    auto& w = state();
    w.checkUnlocked();
    int b = w.bodyIndex(id);
    detail::Body& body = w.bodies[b];
    if (body.type == BodyType::static_body) return;
    if (awake) {
        detail::wakeBody(w, b);
    } else if (body.awake) {
        // Put the body's island to sleep at once: the next sleep pass would
        // otherwise find it awake again through its touching neighbours.
        body.sleepTime = w.settings.timeToSleep;
        detail::putIslandToSleep(w, {b});
    }
}
void World::enableSleep(BodyId id, bool flag) {
    int b = state().bodyIndex(id);
    state().bodies[b].enableSleep = flag;
    if (!flag) detail::wakeBody(state(), b);
}

std::vector<ShapeId> World::bodyShapes(BodyId id) const {
    const detail::Body& body = state().bodies[state().bodyIndex(id)];
    std::vector<ShapeId> out;
    for (int s : detail::bodyShapes(state().shapes, body)) out.push_back(state().shapeHandle(s));
    return out;
}
std::vector<JointId> World::bodyJoints(BodyId id) const {
    const detail::Body& body = state().bodies[state().bodyIndex(id)];
    std::vector<JointId> out;
    for (int j : detail::bodyJoints(state().joints, body, state().bodyIndex(id))) out.push_back(state().jointHandle(j));
    return out;
}
std::vector<BodyId> World::bodies() const {
    std::vector<BodyId> out;
    for (int b = 0; b < state().bodies.capacity(); ++b)
        if (state().bodies[b].alive) out.push_back(state().bodyHandle(b));
    return out;
}

}  // namespace i2d
