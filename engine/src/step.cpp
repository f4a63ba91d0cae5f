// The step pipeline and sleeping.
//
//   broadphase pairs → narrowphase (manifolds, events) → impacts (closed-form
//   law) → solve velocities / integrate / correct positions (solver.cpp) →
//   continuous collision of fast bodies against static shapes (continuous.cpp)
//   → refresh bounding boxes → sleep
#include <algorithm>
#include <chrono>

#include "world_impl.hpp"

namespace i2d::detail {

namespace {
using Clock = std::chrono::steady_clock;
float msSince(Clock::time_point t0) {
    return std::chrono::duration<float, std::milli>(Clock::now() - t0).count();
}
}  // namespace

void WorldImpl::step(float dt) {
    locked = true;
    struct Unlock {
        bool& flag;
        ~Unlock() { flag = false; }
    } unlock{locked};

    beginEvents.clear();
    endEvents.clear();
    sensorBeginEvents.clear();
    sensorEndEvents.clear();

    auto t0 = Clock::now();
    auto t = t0;
    updatePairs();
    profile.pairs = msSince(t);

    t = Clock::now();
    collide();
    profile.collide = msSince(t);

    t = Clock::now();
    resolveImpacts(dt);
    profile.impacts = msSince(t);

    t = Clock::now();
    solve(dt);
    profile.solve = msSince(t);

    t = Clock::now();
    if (settings.enableContinuous) solveContinuous();
    for (int b : awakeBodies) synchronizeShapes(b);
    profile.continuous = msSince(t);

    t = Clock::now();
    updateSleep(dt);
    profile.sleep = msSince(t);
    profile.step = msSince(t0);
}

// Islands are found afresh each step with a union-find over the awake bodies
// linked by touching contacts and joints (static bodies do not link). An
// island whose every body has rested for timeToSleep falls asleep as a
// whole; it is remembered so that waking one body wakes all of it.
void WorldImpl::updateSleep(float dt) {
    const bool sleepOn = settings.enableSleep;
    const float linTol2 = settings.linearSleepTolerance * settings.linearSleepTolerance;
    const float angTol2 = settings.angularSleepTolerance * settings.angularSleepTolerance;
    for (int b : awakeBodies) {
        Body& body = bodies[b];
        if (!sleepOn || !body.enableSleep || lengthSquared(body.v) > linTol2 || body.w * body.w > angTol2) {
            body.sleepTime = 0.0f;
        } else {
            body.sleepTime += dt;
        }
    }
    if (!sleepOn || awakeBodies.empty()) return;

    // Quick exit: no body has rested long enough.
    bool anyCandidate = false;
    for (int b : awakeBodies) anyCandidate = anyCandidate || bodies[b].sleepTime >= settings.timeToSleep;
    if (!anyCandidate) return;

    const std::size_t n = awakeBodies.size();
    unionParent.resize(n);
    for (std::size_t i = 0; i < n; ++i) unionParent[i] = static_cast<int>(i);
    auto find = [&](int i) {
        while (unionParent[static_cast<std::size_t>(i)] != i) {
            int& p = unionParent[static_cast<std::size_t>(i)];
            p = unionParent[static_cast<std::size_t>(p)];
            i = p;
        }
        return i;
    };
    auto unite = [&](int a, int b) {
        a = find(a);
        b = find(b);
        if (a != b) unionParent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    };
    // awakeIndex is each body's slot in awakeBodies.
    for (int c : activeContacts) {
        const Contact& ct = contacts[c];
        if (!ct.alive || !ct.touching || ct.isSensor) continue;
        const Body& a = bodies[ct.bodyA];
        const Body& b = bodies[ct.bodyB];
        if (a.type == BodyType::static_body || b.type == BodyType::static_body) continue;
        if (a.awakeIndex == kNullIndex || b.awakeIndex == kNullIndex) continue;
        unite(a.awakeIndex, b.awakeIndex);
    }
    for (int j = 0; j < joints.capacity(); ++j) {
        const DistanceJoint& jt = joints[j];
        if (!jt.alive) continue;
        const Body& a = bodies[jt.bodyA];
        const Body& b = bodies[jt.bodyB];
        if (a.awakeIndex == kNullIndex || b.awakeIndex == kNullIndex) continue;
        if (a.type == BodyType::static_body || b.type == BodyType::static_body) continue;
        unite(a.awakeIndex, b.awakeIndex);
    }
    // Minimum rest time per island root.
    std::vector<float> minTime(n, 1.0e30f);
    for (std::size_t i = 0; i < n; ++i) {
        int r = find(static_cast<int>(i));
        minTime[static_cast<std::size_t>(r)] = std::min(minTime[static_cast<std::size_t>(r)], bodies[awakeBodies[i]].sleepTime);
    }
    std::vector<std::vector<int>> islands;
    std::vector<int> islandOfRoot(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        int r = find(static_cast<int>(i));
        if (minTime[static_cast<std::size_t>(r)] < settings.timeToSleep) continue;
        int& k = islandOfRoot[static_cast<std::size_t>(r)];
        if (k < 0) {
            k = static_cast<int>(islands.size());
            islands.emplace_back();
        }
        islands[static_cast<std::size_t>(k)].push_back(awakeBodies[i]);
    }
    for (const auto& island : islands) putIslandToSleep(island);
}

void WorldImpl::putIslandToSleep(const std::vector<int>& members) {
    int island;
    if (!freeIslands.empty()) {
        island = freeIslands.back();
        freeIslands.pop_back();
    } else {
        island = static_cast<int>(sleepingIslands.size());
        sleepingIslands.emplace_back();
    }
    sleepingIslands[static_cast<std::size_t>(island)] = members;
    for (int b : members) {
        Body& body = bodies[b];
        removeAwake(b);
        body.awake = false;
        body.v = {};
        body.w = 0.0f;
        body.force = {};
        body.torque = 0.0f;
        body.sleepIsland = island;
    }
}

}  // namespace i2d::detail
