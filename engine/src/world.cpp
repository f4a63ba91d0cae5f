// World: the public API. Each entry point validates its arguments first and
// only then changes state, so a refused call leaves the world untouched.
#include <algorithm>
#include <chrono>

#include "impulse2d/world.hpp"
#include "validation.hpp"
#include "world_impl.hpp"

namespace i2d {

using detail::fail;
using detail::requireBounded;
using detail::requireFinite;
using detail::requireInRange;
using detail::requireNonNegative;
using detail::requireUnitInterval;

namespace {

void validateSettings(const WorldSettings& s) {
    requireBounded(s.gravity, "gravity");
    if (s.velocityIterations < 1 || s.velocityIterations > 1000) fail("velocityIterations must be in [1, 1000]");
    if (s.positionIterations < 0 || s.positionIterations > 1000) fail("positionIterations must be in [0, 1000]");
    if (s.substeps < 1 || s.substeps > 1000) fail("substeps must be in [1, 1000]");
    requireUnitInterval(s.pushFactor, "pushFactor");
    requireNonNegative(s.penetrationSlop, "penetrationSlop");
    requireNonNegative(s.maxPushSpeed, "maxPushSpeed");
    requireInRange(s.contactHertz, 0.0f, detail::kMaxRate, "contactHertz");
    requireInRange(s.contactDampingRatio, 0.0f, detail::kMaxRate, "contactDampingRatio");
    requireInRange(s.jointHertz, 0.0f, detail::kMaxRate, "jointHertz");
    requireInRange(s.jointDampingRatio, 0.0f, detail::kMaxRate, "jointDampingRatio");
    requireNonNegative(s.restitutionThreshold, "restitutionThreshold");
    requireNonNegative(s.impactThreshold, "impactThreshold");
    requireNonNegative(s.speculativeDistance, "speculativeDistance");
    requireNonNegative(s.aabbMargin, "aabbMargin");
    requireNonNegative(s.timeToSleep, "timeToSleep");
    requireNonNegative(s.linearSleepTolerance, "linearSleepTolerance");
    requireNonNegative(s.angularSleepTolerance, "angularSleepTolerance");
    requireBounded(s.maxLinearSpeed, "maxLinearSpeed");
    if (s.maxLinearSpeed <= 0.0f) fail("maxLinearSpeed must be > 0");
    if (s.penetrationSlop > 1.0f || s.speculativeDistance > 10.0f || s.aabbMargin > 10.0f)
        fail("penetrationSlop, speculativeDistance or aabbMargin is unreasonably large");
    if (static_cast<int>(s.positionCorrection) > 2) fail("unknown positionCorrection");
    if (static_cast<int>(s.impactModel) > 1) fail("unknown impactModel");
}

void validateShapeDef(const ShapeDef& d) {
    requireInRange(d.density, 0.0f, detail::kMaxDensity, "shape density");
    requireInRange(d.friction, 0.0f, detail::kMaxFriction, "shape friction");
    requireUnitInterval(d.restitution, "shape restitution");
}

}  // namespace

// ---------------------------------------------------------------------------
// WorldImpl helpers

namespace detail {

void WorldImpl::checkUnlocked() const {
    if (locked) fail("the world cannot be changed while it is stepping or drawing");
}

int WorldImpl::bodyIndex(BodyId id) const {
    if (id.isNull()) fail("null body handle");
    // Compared unsigned: a forged index beyond INT_MAX must not wrap negative.
    if (id.index1 > static_cast<std::uint32_t>(bodies.capacity())) fail("stale or invalid body handle");
    int i = static_cast<int>(id.index1) - 1;
    if (!bodies[i].alive || bodies[i].generation != id.generation)
        fail("stale or invalid body handle");
    return i;
}

int WorldImpl::shapeIndex(ShapeId id) const {
    if (id.isNull()) fail("null shape handle");
    // Compared unsigned: a forged index beyond INT_MAX must not wrap negative.
    if (id.index1 > static_cast<std::uint32_t>(shapes.capacity())) fail("stale or invalid shape handle");
    int i = static_cast<int>(id.index1) - 1;
    if (!shapes[i].alive || shapes[i].generation != id.generation)
        fail("stale or invalid shape handle");
    return i;
}

int WorldImpl::jointIndex(JointId id) const {
    if (id.isNull()) fail("null joint handle");
    // Compared unsigned: a forged index beyond INT_MAX must not wrap negative.
    if (id.index1 > static_cast<std::uint32_t>(joints.capacity())) fail("stale or invalid joint handle");
    int i = static_cast<int>(id.index1) - 1;
    if (!joints[i].alive || joints[i].generation != id.generation)
        fail("stale or invalid joint handle");
    return i;
}

void WorldImpl::addAwake(int b) {
    Body& body = bodies[b];
    if (body.awakeIndex != kNullIndex) return;
    body.awakeIndex = static_cast<int>(awakeBodies.size());
    awakeBodies.push_back(b);
}

void WorldImpl::removeAwake(int b) {
    Body& body = bodies[b];
    if (body.awakeIndex == kNullIndex) return;
    int last = awakeBodies.back();
    awakeBodies[static_cast<std::size_t>(body.awakeIndex)] = last;
    bodies[last].awakeIndex = body.awakeIndex;
    awakeBodies.pop_back();
    body.awakeIndex = kNullIndex;
}

void WorldImpl::wakeBody(int b) {
    Body& body = bodies[b];
    if (body.type == BodyType::static_body) return;
    if (body.sleepIsland != kNullIndex) {
        // Wake the whole island it fell asleep with: its contacts hold
        // impulses that only make sense together.
        int island = body.sleepIsland;
        std::vector<int> members = std::move(sleepingIslands[static_cast<std::size_t>(island)]);
        sleepingIslands[static_cast<std::size_t>(island)].clear();
        freeIslands.push_back(island);
        for (int m : members) {
            Body& mb = bodies[m];
            if (!mb.alive || mb.sleepIsland != island) continue;
            mb.sleepIsland = kNullIndex;
            mb.awake = true;
            mb.sleepTime = 0.0f;
            addAwake(m);
        }
    }
    body.awake = true;
    body.sleepTime = 0.0f;
    addAwake(b);
}

void WorldImpl::updateMass(int b) {
    Body& body = bodies[b];
    body.mass = body.invMass = body.inertia = body.invInertia = 0.0f;
    body.localCenter = {};
    if (body.type != BodyType::dynamic_body) {
        body.center = transformPoint(body.xf, body.localCenter);
        return;
    }
    // Parallel-axis sum: I_origin = Σ (I_i + m_i |c_i|²); I_com = I_origin − M |c|².
    float inertiaAtOrigin = 0.0f;
    Vec2 weighted{};
    for (int s : body.shapes) {
        const Shape& sh = shapes[s];
        if (sh.density == 0.0f || sh.type == ShapeType::segment) continue;
        MassData md;
        switch (sh.type) {
            case ShapeType::circle: md = computeMass(sh.circle, sh.density); break;
            case ShapeType::capsule: md = computeMass(sh.capsule, sh.density); break;
            case ShapeType::polygon: md = computeMass(sh.polygon, sh.density); break;
            default: continue;
        }
        body.mass += md.mass;
        weighted += md.mass * md.center;
        inertiaAtOrigin += md.rotationalInertia + md.mass * dot(md.center, md.center);
    }
    // A positive mass too small to invert (denormal densities) counts as no
    // mass: 1/m would be infinite and the centre of mass 0·∞ = NaN.
    if (body.mass > 0.0f && isFinite(1.0f / body.mass)) {
        body.invMass = 1.0f / body.mass;
        body.localCenter = body.invMass * weighted;
        body.inertia = inertiaAtOrigin - body.mass * dot(body.localCenter, body.localCenter);
    } else {
        // A dynamic body without mass still needs one to move: 1 kg, no rotation.
        body.mass = 1.0f;
        body.invMass = 1.0f;
        body.inertia = 0.0f;
    }
    body.reach = solidReach(body);
    if (body.inertia > 0.0f && isFinite(1.0f / body.inertia) && !body.fixedRotation) {
        body.invInertia = 1.0f / body.inertia;
    } else {
        body.invInertia = 0.0f;
    }
    // Keep the velocity of the centre of mass consistent when it shifts.
    Vec2 oldCenter = body.center;
    body.center = transformPoint(body.xf, body.localCenter);
    body.v += cross(body.w, body.center - oldCenter);
}

AABB WorldImpl::computeShapeAABB(const Shape& sh, const Transform& xf) const {
    switch (sh.type) {
        case ShapeType::circle: return computeAABB(sh.circle, xf);
        case ShapeType::capsule: return computeAABB(sh.capsule, xf);
        case ShapeType::segment: return computeAABB(sh.segment, xf);
        case ShapeType::polygon: return computeAABB(sh.polygon, xf);
    }
    return {};
}

int WorldImpl::createShape(int b, const ShapeDef& def, ShapeType type) {
    int s = shapes.allocate();
    Shape& sh = shapes[s];
    sh.type = type;
    sh.body = b;
    sh.density = def.density;
    sh.friction = def.friction;
    sh.restitution = def.restitution;
    sh.filter = def.filter;
    sh.isSensor = def.isSensor;
    sh.enableContactEvents = def.enableContactEvents;
    sh.enableSensorEvents = def.enableSensorEvents;
    sh.userData = def.userData;
    return s;
}

void WorldImpl::destroyShapeInternal(int s) {
    Shape& sh = shapes[s];
    Body& body = bodies[sh.body];
    // Destroy the contacts of this shape (copy: destroyContact edits the list).
    std::vector<int> bodyContacts = body.contacts;
    for (int c : bodyContacts) {
        const Contact& ct = contacts[c];
        if (ct.shapeA == s || ct.shapeB == s) destroyContact(c, true);
    }
    destroyProxy(s);
    body.shapes.erase(std::find(body.shapes.begin(), body.shapes.end(), s));
    shapes.release(s);
}

void WorldImpl::synchronizeShapes(int b) {
    Body& body = bodies[b];
    for (int s : body.shapes) {
        Shape& sh = shapes[s];
        AABB box = computeShapeAABB(sh, body.xf);
        if (!contains(sh.fatAABB, box)) {
            float m = body.type == BodyType::static_body ? 0.0f : settings.aabbMargin;
            sh.fatAABB = {{box.lower.x - m, box.lower.y - m}, {box.upper.x + m, box.upper.y + m}};
            DynamicTree& tree = sh.inStaticTree ? staticTree : movingTree;
            tree.moveProxy(sh.proxy, sh.fatAABB);
            if (!sh.moved && !sh.inStaticTree) {
                sh.moved = true;
                moveBuffer.push_back(s);
            }
        }
    }
}

}  // namespace detail

// ---------------------------------------------------------------------------
// World

World::World(const WorldSettings& settings) {
    validateSettings(settings);
    impl_ = std::make_unique<detail::WorldImpl>(settings);
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

const WorldSettings& World::settings() const { return impl_->settings; }
void World::setSettings(const WorldSettings& s) {
    impl_->checkUnlocked();
    validateSettings(s);
    bool sleepTurnedOff = impl_->settings.enableSleep && !s.enableSleep;
    impl_->settings = s;
    if (sleepTurnedOff) {
        for (int b = 0; b < impl_->bodies.capacity(); ++b)
            if (impl_->bodies[b].alive && !impl_->bodies[b].awake) impl_->wakeBody(b);
    }
}
void World::setGravity(Vec2 g) {
    impl_->checkUnlocked();
    requireBounded(g, "gravity");
    impl_->settings.gravity = g;
}
Vec2 World::gravity() const { return impl_->settings.gravity; }

void World::step(float dt) {
    impl_->checkUnlocked();
    requireFinite(dt, "time step");
    if (dt <= 0.0f) fail("time step must be > 0");
    if (dt > 1.0f) fail("time step must be <= 1 s");
    // The solver divides by the (sub)step: a denormal dt made 1/h infinite
    // and a kinematic body's position NaN (found by fuzz_world).
    if (dt < 1.0e-6f) fail("time step must be >= 1e-6 s");
    impl_->step(dt);
}

// ---- Bodies -----------------------------------------------------------------

BodyId World::createBody(const BodyDef& def) {
    impl_->checkUnlocked();
    requireBounded(def.position, "body position");
    requireBounded(def.angle, "body angle");
    requireBounded(def.linearVelocity, "body linear velocity");
    requireBounded(def.angularVelocity, "body angular velocity");
    requireNonNegative(def.linearDamping, "linear damping");
    requireNonNegative(def.angularDamping, "angular damping");
    requireBounded(def.gravityScale, "gravity scale");
    if (static_cast<int>(def.type) > 2) fail("unknown body type");

    auto& w = *impl_;
    int b = w.bodies.allocate();
    detail::Body& body = w.bodies[b];
    body.type = def.type;
    body.xf = {def.position, makeRot(def.angle)};
    body.center = def.position;
    body.linearDamping = def.linearDamping;
    body.angularDamping = def.angularDamping;
    body.gravityScale = def.gravityScale;
    body.fixedRotation = def.fixedRotation;
    body.enableSleep = def.enableSleep;
    body.userData = def.userData;
    if (def.type != BodyType::static_body) {
        body.v = def.linearVelocity;
        body.w = def.fixedRotation ? 0.0f : def.angularVelocity;
    }
    w.updateMass(b);
    if (def.type == BodyType::static_body) {
        body.awake = false;
    } else if (def.isAwake || !w.settings.enableSleep || !def.enableSleep) {
        body.awake = true;
        w.addAwake(b);
    } else {
        // Created asleep: its own single-body island.
        body.awake = false;
        int island;
        if (!w.freeIslands.empty()) {
            island = w.freeIslands.back();
            w.freeIslands.pop_back();
        } else {
            island = static_cast<int>(w.sleepingIslands.size());
            w.sleepingIslands.emplace_back();
        }
        w.sleepingIslands[static_cast<std::size_t>(island)] = {b};
        body.sleepIsland = island;
    }
    return w.bodyHandle(b);
}

void World::destroyBody(BodyId id) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int b = w.bodyIndex(id);
    // Joints first (they wake the other body), then shapes with their contacts.
    std::vector<int> joints = w.bodies[b].joints;
    for (int j : joints) destroyJoint(w.jointHandle(j));
    std::vector<int> shapes = w.bodies[b].shapes;
    for (int s : shapes) w.destroyShapeInternal(s);
    w.removeAwake(b);
    detail::Body& body = w.bodies[b];
    if (body.sleepIsland != detail::kNullIndex) {
        auto& members = w.sleepingIslands[static_cast<std::size_t>(body.sleepIsland)];
        members.erase(std::remove(members.begin(), members.end(), b), members.end());
        body.sleepIsland = detail::kNullIndex;
    }
    body.shapes.clear();
    body.contacts.clear();
    body.joints.clear();
    w.bodies.release(b);
}

bool World::isValid(BodyId id) const {
    if (id.isNull() || id.index1 > static_cast<std::uint32_t>(impl_->bodies.capacity())) return false;
    int i = static_cast<int>(id.index1) - 1;
    return impl_->bodies[i].alive && impl_->bodies[i].generation == id.generation;
}

BodyType World::bodyType(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].type; }

void World::setBodyType(BodyId id, BodyType type) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int b = w.bodyIndex(id);
    if (static_cast<int>(type) > 2) fail("unknown body type");
    detail::Body& body = w.bodies[b];
    if (body.type == type) return;
    // Simplest correct path: recreate the proxies in the right tree and
    // drop the contacts; the broadphase finds the pairs again next step.
    std::vector<int> cs = body.contacts;
    for (int c : cs) w.destroyContact(c, true);
    for (int s : body.shapes) w.destroyProxy(s);
    w.wakeBody(b);
    body.type = type;
    if (type == BodyType::static_body) {
        body.v = {};
        body.w = 0.0f;
        w.removeAwake(b);
        body.awake = false;
    }
    for (int s : body.shapes) w.createProxy(s);
    w.updateMass(b);
}

Vec2 World::position(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].xf.p; }
float World::angle(BodyId id) const { return angleOf(impl_->bodies[impl_->bodyIndex(id)].xf.q); }
Rot World::rotation(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].xf.q; }
Transform World::transform(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].xf; }

void World::setTransform(BodyId id, Vec2 position, float angle) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int b = w.bodyIndex(id);
    requireBounded(position, "position");
    requireBounded(angle, "angle");
    detail::Body& body = w.bodies[b];
    body.xf = {position, makeRot(angle)};
    body.center = transformPoint(body.xf, body.localCenter);
    w.wakeBody(b);
    // Bodies touching a moved static body must notice it.
    for (int c : body.contacts) {
        const detail::Contact& ct = w.contacts[c];
        w.wakeBody(ct.bodyA == b ? ct.bodyB : ct.bodyA);
    }
    w.synchronizeShapes(b);
    if (body.type == BodyType::static_body) {
        // Static proxies are not in the move buffer; find new pairs from the other side.
        for (int s : body.shapes) {
            const detail::Shape& sh = w.shapes[s];
            w.staticTree.query(sh.fatAABB, [&](int other) {
                int ob = w.shapes[other].body;
                if (w.bodies[ob].type != BodyType::static_body) w.wakeBody(ob);
                if (!w.shapes[other].moved && !w.shapes[other].inStaticTree) {
                    w.shapes[other].moved = true;
                    w.moveBuffer.push_back(other);
                }
                return true;
            });
            w.movingTree.query(sh.fatAABB, [&](int other) {
                w.wakeBody(w.shapes[other].body);
                if (!w.shapes[other].moved) {
                    w.shapes[other].moved = true;
                    w.moveBuffer.push_back(other);
                }
                return true;
            });
        }
    }
}

Vec2 World::worldCenterOfMass(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].center; }
Vec2 World::localCenterOfMass(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].localCenter; }
Vec2 World::linearVelocity(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].v; }
float World::angularVelocity(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].w; }

void World::setLinearVelocity(BodyId id, Vec2 v) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    requireBounded(v, "linear velocity");
    detail::Body& body = impl_->bodies[b];
    if (body.type == BodyType::static_body) return;  // documented: static bodies do not move
    if (lengthSquared(v) > 0.0f) impl_->wakeBody(b);
    body.v = v;
}

void World::setAngularVelocity(BodyId id, float w) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    requireBounded(w, "angular velocity");
    detail::Body& body = impl_->bodies[b];
    if (body.type == BodyType::static_body || body.fixedRotation) return;
    if (w != 0.0f) impl_->wakeBody(b);
    body.w = w;
}

Vec2 World::velocityAtPoint(BodyId id, Vec2 p) const {
    const detail::Body& body = impl_->bodies[impl_->bodyIndex(id)];
    return body.v + cross(body.w, p - body.center);
}

void World::applyForce(BodyId id, Vec2 force, Vec2 point, bool wake) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    requireBounded(force, "force");
    requireBounded(point, "point");
    detail::Body& body = impl_->bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (wake) impl_->wakeBody(b);
    if (!body.awake) return;  // a sleeping body ignores forces unless woken (as in Box2D)
    body.force += force;
    body.torque += cross(point - body.center, force);
}

void World::applyForceToCenter(BodyId id, Vec2 force, bool wake) {
    applyForce(id, force, impl_->bodies[impl_->bodyIndex(id)].center, wake);
}

void World::applyTorque(BodyId id, float torque, bool wake) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    requireBounded(torque, "torque");
    detail::Body& body = impl_->bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (wake) impl_->wakeBody(b);
    if (!body.awake) return;
    body.torque += torque;
}

void World::applyLinearImpulse(BodyId id, Vec2 impulse, Vec2 point, bool wake) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    requireBounded(impulse, "impulse");
    requireBounded(point, "point");
    detail::Body& body = impl_->bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (wake) impl_->wakeBody(b);
    if (!body.awake) return;
    body.v += body.invMass * impulse;
    body.w += body.invInertia * cross(point - body.center, impulse);
}

void World::applyLinearImpulseToCenter(BodyId id, Vec2 impulse, bool wake) {
    applyLinearImpulse(id, impulse, impl_->bodies[impl_->bodyIndex(id)].center, wake);
}

void World::applyAngularImpulse(BodyId id, float impulse, bool wake) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    requireBounded(impulse, "angular impulse");
    detail::Body& body = impl_->bodies[b];
    if (body.type != BodyType::dynamic_body) return;
    if (wake) impl_->wakeBody(b);
    if (!body.awake) return;
    body.w += body.invInertia * impulse;
}

float World::mass(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].mass; }
float World::rotationalInertia(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].inertia; }
MassData World::massData(BodyId id) const {
    const detail::Body& body = impl_->bodies[impl_->bodyIndex(id)];
    return {body.mass, body.localCenter, body.inertia};
}

void World::setMassData(BodyId id, const MassData& md) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    requireFinite(md.mass, "mass");
    requireBounded(md.center, "centre of mass");
    requireFinite(md.rotationalInertia, "rotational inertia");
    detail::Body& body = impl_->bodies[b];
    if (body.type != BodyType::dynamic_body) fail("only dynamic bodies have mass");
    if (!(md.mass > 0.0f)) fail("mass must be > 0");
    if (!isFinite(1.0f / md.mass)) fail("mass is too small (its inverse is not finite)");
    if (md.rotationalInertia < 0.0f) fail("rotational inertia must be >= 0");
    if (md.rotationalInertia > 0.0f && !isFinite(1.0f / md.rotationalInertia))
        fail("rotational inertia is too small (its inverse is not finite)");
    body.mass = md.mass;
    body.invMass = 1.0f / md.mass;
    body.inertia = md.rotationalInertia;
    body.invInertia = (md.rotationalInertia > 0.0f && !body.fixedRotation) ? 1.0f / md.rotationalInertia : 0.0f;
    Vec2 oldCenter = body.center;
    body.localCenter = md.center;
    body.center = transformPoint(body.xf, body.localCenter);
    body.v += cross(body.w, body.center - oldCenter);
}

void World::resetMassData(BodyId id) {
    impl_->checkUnlocked();
    impl_->updateMass(impl_->bodyIndex(id));
}

float World::linearDamping(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].linearDamping; }
void World::setLinearDamping(BodyId id, float d) {
    int b = impl_->bodyIndex(id);
    requireNonNegative(d, "linear damping");
    impl_->bodies[b].linearDamping = d;
}
float World::angularDamping(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].angularDamping; }
void World::setAngularDamping(BodyId id, float d) {
    int b = impl_->bodyIndex(id);
    requireNonNegative(d, "angular damping");
    impl_->bodies[b].angularDamping = d;
}
float World::gravityScale(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].gravityScale; }
void World::setGravityScale(BodyId id, float s) {
    int b = impl_->bodyIndex(id);
    requireBounded(s, "gravity scale");
    impl_->bodies[b].gravityScale = s;
}
bool World::isFixedRotation(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].fixedRotation; }
void World::setFixedRotation(BodyId id, bool flag) {
    impl_->checkUnlocked();
    int b = impl_->bodyIndex(id);
    detail::Body& body = impl_->bodies[b];
    body.fixedRotation = flag;
    if (flag) body.w = 0.0f;
    impl_->updateMass(b);
}
std::uintptr_t World::userData(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].userData; }
void World::setUserData(BodyId id, std::uintptr_t data) { impl_->bodies[impl_->bodyIndex(id)].userData = data; }

bool World::isAwake(BodyId id) const { return impl_->bodies[impl_->bodyIndex(id)].awake; }
void World::setAwake(BodyId id, bool awake) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int b = w.bodyIndex(id);
    detail::Body& body = w.bodies[b];
    if (body.type == BodyType::static_body) return;
    if (awake) {
        w.wakeBody(b);
    } else if (body.awake) {
        // Put the body's island to sleep at once: the next sleep pass would
        // otherwise find it awake again through its touching neighbours.
        body.sleepTime = w.settings.timeToSleep;
        std::vector<int> island{b};
        w.putIslandToSleep(island);
    }
}
void World::enableSleep(BodyId id, bool flag) {
    int b = impl_->bodyIndex(id);
    impl_->bodies[b].enableSleep = flag;
    if (!flag) impl_->wakeBody(b);
}

std::vector<ShapeId> World::bodyShapes(BodyId id) const {
    const detail::Body& body = impl_->bodies[impl_->bodyIndex(id)];
    std::vector<ShapeId> out;
    for (int s : body.shapes) out.push_back(impl_->shapeHandle(s));
    return out;
}
std::vector<JointId> World::bodyJoints(BodyId id) const {
    const detail::Body& body = impl_->bodies[impl_->bodyIndex(id)];
    std::vector<JointId> out;
    for (int j : body.joints) out.push_back(impl_->jointHandle(j));
    return out;
}
std::vector<BodyId> World::bodies() const {
    std::vector<BodyId> out;
    for (int b = 0; b < impl_->bodies.capacity(); ++b)
        if (impl_->bodies[b].alive) out.push_back(impl_->bodyHandle(b));
    return out;
}

// ---- Shapes -----------------------------------------------------------------

namespace {
template <class Fill>
ShapeId addShape(detail::WorldImpl& w, BodyId bodyId, const ShapeDef& def, ShapeType type, Fill&& fill) {
    w.checkUnlocked();
    int b = w.bodyIndex(bodyId);
    validateShapeDef(def);
    int s = w.createShape(b, def, type);
    fill(w.shapes[s]);
    w.bodies[b].shapes.push_back(s);
    w.createProxy(s);
    // A sleeping body stays asleep (a level built asleep stays asleep, as in
    // Box2D): its new shape's contacts wake it when one begins to touch an
    // awake body.
    w.updateMass(b);
    return w.shapeHandle(s);
}
}  // namespace

ShapeId World::createCircleShape(BodyId body, const ShapeDef& def, const Circle& c) {
    requireBounded(c.center, "circle centre");
    requireFinite(c.radius, "circle radius");
    if (!(c.radius > 0.0f) || c.radius > detail::kMaxRadius) fail("circle radius must be in (0, 1e5]");
    return addShape(*impl_, body, def, ShapeType::circle, [&](detail::Shape& s) { s.circle = c; });
}

ShapeId World::createCapsuleShape(BodyId body, const ShapeDef& def, const Capsule& c) {
    requireBounded(c.center1, "capsule centre1");
    requireBounded(c.center2, "capsule centre2");
    requireFinite(c.radius, "capsule radius");
    if (!(c.radius > 0.0f) || c.radius > detail::kMaxRadius) fail("capsule radius must be in (0, 1e5]");
    if (distanceSquared(c.center1, c.center2) <= kLinearSlop * kLinearSlop)
        fail("capsule centres must be further apart than the linear slop (use a circle)");
    return addShape(*impl_, body, def, ShapeType::capsule, [&](detail::Shape& s) { s.capsule = c; });
}

ShapeId World::createPolygonShape(BodyId body, const ShapeDef& def, const Polygon& p) {
    if (p.count < 3 || p.count > kMaxPolygonVertices) fail("polygon must have 3 to 8 vertices (build it with makePolygon)");
    requireInRange(p.radius, 0.0f, detail::kMaxRadius, "polygon radius");
    for (int i = 0; i < p.count; ++i) {
        requireBounded(p.vertices[i], "polygon vertex");
        requireFinite(p.normals[i], "polygon normal");
        if (std::abs(lengthSquared(p.normals[i]) - 1.0f) > 1.0e-3f) fail("polygon normals must be unit length (build it with makePolygon)");
    }
    requireBounded(p.centroid, "polygon centroid");
    // Each edge at least kMinPolygonFeature long, with its outward normal:
    // the clockwise perpendicular of the edge.
    for (int i = 0; i < p.count; ++i) {
        Vec2 e = p.vertices[i + 1 < p.count ? i + 1 : 0] - p.vertices[i];
        float len = length(e);
        if (!(len >= detail::kMinPolygonFeature)) fail("polygon edge shorter than 0.0005 m");
        if (dot(p.normals[i], rightPerp(e)) < (1.0f - 1.0e-3f) * len)
            fail("polygon normal does not belong to its edge (build it with makePolygon)");
    }
    // Convex and counter-clockwise: every vertex lies behind every edge.
    for (int i = 0; i < p.count; ++i) {
        for (int j = 0; j < p.count; ++j) {
            if (dot(p.normals[i], p.vertices[j] - p.vertices[i]) > 10.0f * kLinearSlop)
                fail("polygon is not convex and counter-clockwise (build it with makePolygon)");
        }
    }
    // Not collinear: some vertex lies at least kMinPolygonFeature behind each edge.
    for (int i = 0; i < p.count; ++i) {
        float deepest = 0.0f;
        for (int j = 0; j < p.count; ++j) deepest = std::min(deepest, dot(p.normals[i], p.vertices[j] - p.vertices[i]));
        if (deepest > -detail::kMinPolygonFeature) fail("polygon is degenerate: thinner than 0.0005 m (collinear vertices)");
    }
    Polygon core = p;
    core.radius = 0.0f;
    if (!containsPoint(core, p.centroid)) fail("polygon centroid lies outside the polygon");
    return addShape(*impl_, body, def, ShapeType::polygon, [&](detail::Shape& s) { s.polygon = p; });
}

ShapeId World::createSegmentShape(BodyId body, const ShapeDef& def, const Segment& seg) {
    requireBounded(seg.point1, "segment point1");
    requireBounded(seg.point2, "segment point2");
    if (distanceSquared(seg.point1, seg.point2) <= kLinearSlop * kLinearSlop)
        fail("segment points must be further apart than the linear slop");
    return addShape(*impl_, body, def, ShapeType::segment, [&](detail::Shape& s) { s.segment = seg; });
}

void World::destroyShape(ShapeId id, bool updateBodyMass) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int s = w.shapeIndex(id);
    int b = w.shapes[s].body;
    w.destroyShapeInternal(s);
    w.wakeBody(b);
    if (updateBodyMass) w.updateMass(b);
}

bool World::isValid(ShapeId id) const {
    if (id.isNull() || id.index1 > static_cast<std::uint32_t>(impl_->shapes.capacity())) return false;
    int i = static_cast<int>(id.index1) - 1;
    return impl_->shapes[i].alive && impl_->shapes[i].generation == id.generation;
}

ShapeType World::shapeType(ShapeId id) const { return impl_->shapes[impl_->shapeIndex(id)].type; }
BodyId World::shapeBody(ShapeId id) const { return impl_->bodyHandle(impl_->shapes[impl_->shapeIndex(id)].body); }

namespace {
const detail::Shape& shapeOfType(const detail::WorldImpl& w, ShapeId id, ShapeType type) {
    const detail::Shape& s = w.shapes[w.shapeIndex(id)];
    if (s.type != type) fail("shape is of another type");
    return s;
}
}  // namespace

Circle World::shapeCircle(ShapeId id) const { return shapeOfType(*impl_, id, ShapeType::circle).circle; }
Capsule World::shapeCapsule(ShapeId id) const { return shapeOfType(*impl_, id, ShapeType::capsule).capsule; }
Polygon World::shapePolygon(ShapeId id) const { return shapeOfType(*impl_, id, ShapeType::polygon).polygon; }
Segment World::shapeSegment(ShapeId id) const { return shapeOfType(*impl_, id, ShapeType::segment).segment; }

float World::density(ShapeId id) const { return impl_->shapes[impl_->shapeIndex(id)].density; }
void World::setDensity(ShapeId id, float density, bool updateBodyMass) {
    impl_->checkUnlocked();
    int s = impl_->shapeIndex(id);
    requireInRange(density, 0.0f, detail::kMaxDensity, "density");
    impl_->shapes[s].density = density;
    if (updateBodyMass) impl_->updateMass(impl_->shapes[s].body);
}
float World::friction(ShapeId id) const { return impl_->shapes[impl_->shapeIndex(id)].friction; }
void World::setFriction(ShapeId id, float f) {
    int s = impl_->shapeIndex(id);
    requireInRange(f, 0.0f, detail::kMaxFriction, "friction");
    impl_->shapes[s].friction = f;
}
float World::restitution(ShapeId id) const { return impl_->shapes[impl_->shapeIndex(id)].restitution; }
void World::setRestitution(ShapeId id, float e) {
    int s = impl_->shapeIndex(id);
    requireUnitInterval(e, "restitution");
    impl_->shapes[s].restitution = e;
}
Filter World::filter(ShapeId id) const { return impl_->shapes[impl_->shapeIndex(id)].filter; }
void World::setFilter(ShapeId id, const Filter& f) {
    impl_->checkUnlocked();
    auto& w = *impl_;
    int s = w.shapeIndex(id);
    w.shapes[s].filter = f;
    // Re-evaluate pairs: drop this shape's contacts, let the broadphase find them again.
    int b = w.shapes[s].body;
    std::vector<int> cs = w.bodies[b].contacts;
    for (int c : cs)
        if (w.contacts[c].shapeA == s || w.contacts[c].shapeB == s) w.destroyContact(c, true);
    w.destroyProxy(s);
    w.createProxy(s);
}
bool World::isSensor(ShapeId id) const { return impl_->shapes[impl_->shapeIndex(id)].isSensor; }
std::uintptr_t World::userData(ShapeId id) const { return impl_->shapes[impl_->shapeIndex(id)].userData; }
AABB World::shapeAABB(ShapeId id) const {
    const detail::Shape& s = impl_->shapes[impl_->shapeIndex(id)];
    return impl_->computeShapeAABB(s, impl_->bodies[s.body].xf);
}

// ---- Events and inspection -----------------------------------------------------

std::span<const ContactBeginEvent> World::contactBeginEvents() const { return impl_->beginEvents; }
std::span<const ContactEndEvent> World::contactEndEvents() const { return impl_->endEvents; }
std::span<const SensorBeginEvent> World::sensorBeginEvents() const { return impl_->sensorBeginEvents; }
std::span<const SensorEndEvent> World::sensorEndEvents() const { return impl_->sensorEndEvents; }

int World::bodyCount() const { return impl_->bodies.count; }
int World::awakeBodyCount() const { return static_cast<int>(impl_->awakeBodies.size()); }
int World::shapeCount() const { return impl_->shapes.count; }
int World::jointCount() const { return impl_->joints.count; }
int World::contactCount() const {
    int n = 0;
    for (int c = 0; c < impl_->contacts.capacity(); ++c)
        if (impl_->contacts[c].alive && impl_->contacts[c].touching && !impl_->contacts[c].isSensor) ++n;
    return n;
}
std::vector<ContactData> World::contacts() const {
    std::vector<ContactData> out;
    for (int c = 0; c < impl_->contacts.capacity(); ++c) {
        const detail::Contact& ct = impl_->contacts[c];
        if (!ct.alive || !ct.touching || ct.isSensor) continue;
        ContactData d;
        d.shapeA = impl_->shapeHandle(ct.shapeA);
        d.shapeB = impl_->shapeHandle(ct.shapeB);
        d.manifold = ct.manifold;
        for (int i = 0; i < 2; ++i) {
            d.normalImpulse[i] = ct.normalImpulse[i];
            d.tangentImpulse[i] = ct.tangentImpulse[i];
        }
        out.push_back(d);
    }
    return out;
}
const Profile& World::profile() const { return impl_->profile; }

}  // namespace i2d
