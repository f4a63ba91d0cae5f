// World: the public API facade for the world as a whole — construction,
// settings, stepping, events and inspection. Bodies, shapes, joints, queries
// and debug drawing have their facades in world_body.cpp, world_shape.cpp,
// world_joint.cpp, world_query.cpp and debug_draw.cpp. Each entry point
// validates its arguments first and only then changes state, so a refused
// call leaves the world untouched.
#include <atomic>

#include "impulse2d/world.hpp"
#include "world_state.hpp"

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
    if (!(s.exactJointMassRatio >= 1.0f))
        fail("exactJointMassRatio must be >= 1 (infinity: no joint tree is solved exactly)");
    requireNonNegative(s.restitutionThreshold, "restitutionThreshold");
    requireNonNegative(s.hitEventThreshold, "hitEventThreshold");
    requireNonNegative(s.impactThreshold, "impactThreshold");
    requireNonNegative(s.speculativeDistance, "speculativeDistance");
    requireNonNegative(s.manifoldReuseDistance, "manifoldReuseDistance");
    requireNonNegative(s.aabbMargin, "aabbMargin");
    requireNonNegative(s.timeToSleep, "timeToSleep");
    requireNonNegative(s.linearSleepTolerance, "linearSleepTolerance");
    requireNonNegative(s.angularSleepTolerance, "angularSleepTolerance");
    requireBounded(s.maxLinearSpeed, "maxLinearSpeed");
    if (s.maxLinearSpeed <= 0.0f) fail("maxLinearSpeed must be > 0");
    if (s.penetrationSlop > 1.0f || s.speculativeDistance > 10.0f || s.aabbMargin > 10.0f ||
        s.manifoldReuseDistance > 10.0f)
        fail("penetrationSlop, speculativeDistance, aabbMargin or manifoldReuseDistance is unreasonably large");
    if (static_cast<int>(s.positionCorrection) > 2) fail("unknown positionCorrection");
    if (static_cast<int>(s.impactModel) > 1) fail("unknown impactModel");
}

/// A process-wide id for each new world, stamped into its handles; 0 is never
/// given (a handle with world 0 is null or forged).
std::uint32_t nextWorldId() {
    static std::atomic<std::uint32_t> counter{0};
    std::uint32_t id;
    do {
        id = counter.fetch_add(1, std::memory_order_relaxed) + 1;
    } while (id == 0);
    return id;
}

}  // namespace

World::World(const WorldSettings& settings) {
    validateSettings(settings);
    state_ = std::make_unique<detail::WorldState>(settings, nextWorldId());
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::throwMovedFrom() { fail("this World was moved from; it has no state"); }

const WorldSettings& World::settings() const { return state().settings; }

void World::setSettings(const WorldSettings& s) {
    detail::WorldState& w = state();
    w.checkUnlocked();
    validateSettings(s);
    bool sleepTurnedOff = w.settings.enableSleep && !s.enableSleep;
    // The room each body's shapes had in their fat boxes was measured with
    // the old speculative distance (Body::boxSlack): measure it again.
    if (s.speculativeDistance != w.settings.speculativeDistance)
        for (int b = 0; b < w.bodies.capacity(); ++b) w.bodies[b].boxSlack = 0.0f;
    const bool becameSoft = s.positionCorrection == PositionCorrection::soft_step &&
                            w.settings.positionCorrection != PositionCorrection::soft_step;
    w.settings = s;
    w.solver.jointPlanStale = true;  // the wide path and the exact trees depend on settings
    // Stretched joints are soft_step's (judgeStretch): judged when it starts.
    for (int j = 0; j < w.joints.capacity(); ++j) {
        if (!w.joints[j].alive) continue;
        if (s.positionCorrection != PositionCorrection::soft_step) w.joints[j].stretched = false;
        if (becameSoft) detail::judgeStretch(w, j);
    }
    if (sleepTurnedOff) {
        for (int b = 0; b < w.bodies.capacity(); ++b)
            if (w.bodies[b].alive && !w.bodies[b].awake) detail::wakeBody(w, b);
    }
}

void World::setTaskSystem(TaskSystem* tasks) {
    detail::WorldState& w = state();
    w.checkUnlocked();
    w.tasks = tasks;
}

TaskSystem* World::taskSystem() const { return state().tasks; }

void World::setGravity(Vec2 g) {
    detail::WorldState& w = state();
    w.checkUnlocked();
    requireBounded(g, "gravity");
    // The exact trees depend on the load gravity puts on them
    // (selectTreeJoints): the joint plan is made again when its strength
    // changes by more than a quarter, not for a turn of it.
    const float was = length(w.settings.gravity), now = length(g);
    if (now > 1.25f * was || was > 1.25f * now) w.solver.jointPlanStale = true;
    w.settings.gravity = g;
}

Vec2 World::gravity() const { return state().settings.gravity; }

void World::step(float dt) {
    detail::WorldState& w = state();
    w.checkUnlocked();
    requireFinite(dt, "time step");
    if (dt <= 0.0f) fail("time step must be > 0");
    if (dt > 1.0f) fail("time step must be <= 1 s");
    // The solver divides by the (sub)step: a denormal dt made 1/h infinite
    // and a kinematic body's position NaN (found by fuzz_world).
    if (dt < 1.0e-6f) fail("time step must be >= 1e-6 s");
    detail::stepWorld(w, dt);
}

// ---- Events and inspection --------------------------------------------------

std::span<const ContactBeginEvent> World::contactBeginEvents() const { return state().events.contactBegin; }
std::span<const ContactEndEvent> World::contactEndEvents() const { return state().events.contactEnd; }
std::span<const ContactHitEvent> World::contactHitEvents() const { return state().events.contactHit; }
std::span<const SensorBeginEvent> World::sensorBeginEvents() const { return state().events.sensorBegin; }
std::span<const SensorEndEvent> World::sensorEndEvents() const { return state().events.sensorEnd; }

int World::bodyCount() const { return state().bodies.count; }
int World::awakeBodyCount() const { return static_cast<int>(state().islands.awakeBodies.size()); }
int World::shapeCount() const { return state().shapes.count; }
int World::jointCount() const { return state().joints.count; }

int World::contactCount() const {
    const detail::WorldState& w = state();
    int n = 0;
    for (int c = 0; c < w.contacts.capacity(); ++c)
        if (w.contacts[c].alive && w.contacts[c].touching && !w.contacts[c].isSensor) ++n;
    return n;
}

std::vector<ContactData> World::contacts() const {
    const detail::WorldState& w = state();
    std::vector<ContactData> out;
    for (int c = 0; c < w.contacts.capacity(); ++c) {
        const detail::Contact& ct = w.contacts[c];
        if (!ct.alive || !ct.touching || ct.isSensor) continue;
        out.push_back(detail::contactData(w, c));
    }
    return out;
}

void World::setCustomFilter(CustomFilterFn fn) {
    auto& w = state();
    w.checkUnlocked();
    w.customFilter = std::move(fn);
}

void World::setPreSolve(PreSolveFn fn) {
    auto& w = state();
    w.checkUnlocked();
    w.preSolve = std::move(fn);
}

const Profile& World::profile() const { return state().profile; }

}  // namespace i2d
