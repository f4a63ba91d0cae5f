// Dynamic AABB tree: a bounding-volume hierarchy of fattened boxes with
// surface-area-heuristic insertion and AVL-style rotations (the structure of
// Box2D's b2DynamicTree, written anew). Leaves carry a user index (a shape).
#pragma once

#include <cstdint>
#include <vector>

#include "impulse2d/math.hpp"

namespace i2d::detail {

class DynamicTree {
public:
    static constexpr int kNull = -1;

    int createProxy(const AABB& fatBox, int userIndex);
    void destroyProxy(int proxy);
    /// Replace the proxy's box (re-inserts the leaf).
    void moveProxy(int proxy, const AABB& fatBox);

    const AABB& fatAABB(int proxy) const { return nodes_[static_cast<std::size_t>(proxy)].box; }
    int userIndex(int proxy) const { return nodes_[static_cast<std::size_t>(proxy)].userIndex; }
    int proxyCount() const { return proxyCount_; }
    int height() const { return root_ == kNull ? 0 : nodes_[static_cast<std::size_t>(root_)].height; }

    /// Calls visit(userIndex) for every leaf whose box overlaps `box`;
    /// visit returns false to stop the query.
    template <class Visit>
    void query(const AABB& box, Visit&& visit) const {
        if (root_ == kNull) return;
        int stack[256];
        int top = 0;
        stack[top++] = root_;
        while (top > 0) {
            const Node& n = nodes_[static_cast<std::size_t>(stack[--top])];
            if (!overlaps(n.box, box)) continue;
            if (n.isLeaf()) {
                if (!visit(n.userIndex)) return;
            } else if (top + 2 <= 256) {
                stack[top++] = n.child1;
                stack[top++] = n.child2;
            }
        }
    }

    /// Calls visit(userIndex, maxFraction) for leaves whose box the segment
    /// p1 → p1 + maxFraction·d may cross. visit returns the new max fraction
    /// (clip the ray), or a negative number to stop.
    template <class Visit>
    void rayCast(Vec2 p1, Vec2 d, float maxFraction, Visit&& visit) const {
        if (root_ == kNull) return;
        int stack[256];
        int top = 0;
        stack[top++] = root_;
        while (top > 0) {
            const Node& n = nodes_[static_cast<std::size_t>(stack[--top])];
            if (!segmentHitsBox(n.box, p1, d, maxFraction)) continue;
            if (n.isLeaf()) {
                float f = visit(n.userIndex, maxFraction);
                if (f < 0.0f) return;
                maxFraction = f;
            } else if (top + 2 <= 256) {
                stack[top++] = n.child1;
                stack[top++] = n.child2;
            }
        }
    }

    /// Checks parent links, heights and box containment; for tests.
    bool validate() const;

private:
    struct Node {
        AABB box{};
        int parent = kNull;
        int child1 = kNull;
        int child2 = kNull;
        int height = 0;  ///< leaf 0; −1 for a free node
        int userIndex = -1;
        bool isLeaf() const { return child1 == kNull; }
    };

    static bool segmentHitsBox(const AABB& b, Vec2 p, Vec2 d, float maxFraction);
    int allocateNode();
    void freeNode(int node);
    void insertLeaf(int leaf);
    void removeLeaf(int leaf);
    int balance(int a);
    bool validateNode(int node) const;

    std::vector<Node> nodes_;
    int root_ = kNull;
    int freeList_ = kNull;
    int proxyCount_ = 0;
};

}  // namespace i2d::detail
