// The root of a union-find forest, shared by the passes that group bodies:
// the islands (island.cpp), the rigid weld clusters the impact stage strikes
// as one body (impact_stage.cpp) and the joint groups of the split kick
// (split_kick.cpp).
#pragma once

#include <cstddef>
#include <vector>

namespace i2d::detail {

/// The root of i in the forest `parent` (a root is its own parent), halving
/// the path on the way: each visited entry is pointed at its grandparent.
inline int unionFindRoot(std::vector<int>& parent, int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
        int& p = parent[static_cast<std::size_t>(i)];
        p = parent[static_cast<std::size_t>(p)];
        i = p;
    }
    return i;
}

}  // namespace i2d::detail
