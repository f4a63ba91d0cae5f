// Awake and sleeping bodies: the awake list, waking an island, and the sleep
// stage of a step (island.hpp says how islands are found).
#include <algorithm>

#include "union_find.hpp"
#include "world_state.hpp"

namespace i2d::detail {

void addAwake(WorldState& w, int b) {
    Body& body = w.bodies[b];
    if (body.awakeIndex != kNullIndex) return;
    std::vector<int>& awake = w.islands.awakeBodies;
    body.awakeIndex = static_cast<int>(awake.size());
    awake.push_back(b);
}

void removeAwake(WorldState& w, int b) {
    Body& body = w.bodies[b];
    if (body.awakeIndex == kNullIndex) return;
    std::vector<int>& awake = w.islands.awakeBodies;
    int last = awake.back();
    awake[static_cast<std::size_t>(body.awakeIndex)] = last;
    w.bodies[last].awakeIndex = body.awakeIndex;
    awake.pop_back();
    body.awakeIndex = kNullIndex;
}

namespace {
int allocateIsland(IslandSet& set) {
    if (!set.freeIslands.empty()) {
        int island = set.freeIslands.back();
        set.freeIslands.pop_back();
        return island;
    }
    set.sleepingIslands.emplace_back();
    return static_cast<int>(set.sleepingIslands.size()) - 1;
}
}  // namespace

void wakeBody(WorldState& w, int b) {
    Body& body = w.bodies[b];
    if (body.type == BodyType::static_body || !body.enabled) return;
    if (body.sleepIsland != kNullIndex) {
        // Wake the whole island it fell asleep with: its contacts hold
        // impulses that only make sense together.
        IslandSet& set = w.islands;
        int island = body.sleepIsland;
        std::vector<int> members = std::move(set.sleepingIslands[static_cast<std::size_t>(island)]);
        set.sleepingIslands[static_cast<std::size_t>(island)].clear();
        set.freeIslands.push_back(island);
        for (int m : members) {
            Body& mb = w.bodies[m];
            if (!mb.alive || mb.sleepIsland != island) continue;
            mb.sleepIsland = kNullIndex;
            mb.awake = true;
            mb.sleepTime = 0.0f;
            addAwake(w, m);
        }
    }
    body.awake = true;
    body.sleepTime = 0.0f;
    addAwake(w, b);
}

void putIslandToSleep(WorldState& w, const std::vector<int>& members) {
    const int island = allocateIsland(w.islands);
    w.islands.sleepingIslands[static_cast<std::size_t>(island)] = members;
    for (int b : members) {
        Body& body = w.bodies[b];
        removeAwake(w, b);
        body.awake = false;
        body.v = {};
        body.w = 0.0f;
        body.force = {};
        body.torque = 0.0f;
        body.sleepIsland = island;
    }
}

void sleepAlone(WorldState& w, int b) {
    Body& body = w.bodies[b];
    body.awake = false;
    const int island = allocateIsland(w.islands);
    w.islands.sleepingIslands[static_cast<std::size_t>(island)] = {b};
    body.sleepIsland = island;
}

void leaveIsland(WorldState& w, int b) {
    Body& body = w.bodies[b];
    if (body.sleepIsland == kNullIndex) return;
    auto& members = w.islands.sleepingIslands[static_cast<std::size_t>(body.sleepIsland)];
    members.erase(std::remove(members.begin(), members.end(), b), members.end());
    body.sleepIsland = kNullIndex;
}

void updateSleep(WorldState& w, float dt) {
    const WorldSettings& set = w.settings;
    const std::vector<int>& awake = w.islands.awakeBodies;
    const bool sleepOn = set.enableSleep;
    const float linTol2 = set.linearSleepTolerance * set.linearSleepTolerance;
    const float angTol2 = set.angularSleepTolerance * set.angularSleepTolerance;
    for (int b : awake) {
        Body& body = w.bodies[b];
        if (!sleepOn || !body.enableSleep || lengthSquared(body.v) > linTol2 || body.w * body.w > angTol2) {
            body.sleepTime = 0.0f;
        } else {
            body.sleepTime += dt;
        }
    }
    if (!sleepOn || awake.empty()) return;

    // Quick exit: no body has rested long enough.
    bool anyCandidate = false;
    for (int b : awake) anyCandidate = anyCandidate || w.bodies[b].sleepTime >= set.timeToSleep;
    if (!anyCandidate) return;

    const std::size_t n = awake.size();
    std::vector<int>& parent = w.islands.unionParent;
    parent.resize(n);
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<int>(i);
    auto find = [&](int i) { return unionFindRoot(parent, i); };
    auto unite = [&](int a, int b) {
        a = find(a);
        b = find(b);
        if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    };
    // Links: touching contacts and joints between two awake, non-static bodies
    // (awakeIndex is each body's position in the awake list).
    auto link = [&](int bodyA, int bodyB) {
        const Body& a = w.bodies[bodyA];
        const Body& b = w.bodies[bodyB];
        if (a.type == BodyType::static_body || b.type == BodyType::static_body) return;
        if (a.awakeIndex == kNullIndex || b.awakeIndex == kNullIndex) return;
        unite(a.awakeIndex, b.awakeIndex);
    };
    for (int c : w.activeContacts) {
        const Contact& ct = w.contacts[c];
        if (!ct.alive || !ct.touching || ct.isSensor) continue;
        link(ct.bodyA, ct.bodyB);
    }
    for (int j = 0; j < w.joints.capacity(); ++j) {
        const Joint& jt = w.joints[j];
        if (jt.alive) link(jt.bodyA, jt.bodyB);
    }
    // Minimum rest time per island root.
    std::vector<float> minTime(n, 1.0e30f);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t r = static_cast<std::size_t>(find(static_cast<int>(i)));
        minTime[r] = std::min(minTime[r], w.bodies[awake[i]].sleepTime);
    }
    std::vector<std::vector<int>> islands;
    std::vector<int> islandOfRoot(n, -1);
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t r = static_cast<std::size_t>(find(static_cast<int>(i)));
        if (minTime[r] < set.timeToSleep) continue;
        int& k = islandOfRoot[r];
        if (k < 0) {
            k = static_cast<int>(islands.size());
            islands.emplace_back();
        }
        islands[static_cast<std::size_t>(k)].push_back(awake[i]);
    }
    for (const auto& island : islands) putIslandToSleep(w, island);
}

}  // namespace i2d::detail
