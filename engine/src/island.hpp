// Awake and sleeping bodies. The awake bodies are kept in one list (the
// solver's working set); an island of bodies that has rested long enough
// falls asleep as a whole and is remembered, so waking any of its bodies
// wakes all of it: its contacts hold impulses that only make sense together.
// Islands are found afresh each step by a union-find over the awake bodies
// linked by touching contacts and joints (static bodies do not link), so
// nothing is kept up to date while bodies move.
#pragma once

#include <vector>

namespace i2d::detail {

struct WorldState;

struct IslandSet {
    std::vector<int> awakeBodies;                   ///< body slots; Body::awakeIndex is the position here
    std::vector<std::vector<int>> sleepingIslands;  ///< members of each sleeping island
    std::vector<int> freeIslands;                   ///< unused entries of sleepingIslands
    std::vector<int> unionParent;                   ///< scratch of the union-find
};

void addAwake(WorldState& w, int body);
void removeAwake(WorldState& w, int body);
/// Wakes the body and the whole island it fell asleep with (static bodies: nothing).
void wakeBody(WorldState& w, int body);
/// Puts the bodies to sleep as one island (velocities and forces cleared).
void putIslandToSleep(WorldState& w, const std::vector<int>& members);
/// A body created asleep: an island of its own.
void sleepAlone(WorldState& w, int body);
/// Removes a body that is being destroyed from its sleeping island.
void leaveIsland(WorldState& w, int body);

/// The sleep stage of a step: accumulates each awake body's rest time and
/// puts to sleep every island whose bodies have all rested timeToSleep.
void updateSleep(WorldState& w, float dt);

}  // namespace i2d::detail
