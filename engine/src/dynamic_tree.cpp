#include "dynamic_tree.hpp"

#include <algorithm>
#include <cmath>

#include "slot_array.hpp"

namespace i2d::detail {

int DynamicTree::allocateNode() {
    if (freeList_ == kNull) {
        // Grown by an eighth when full (grownCapacity), not doubled: a tree
        // of n proxies has 2n − 1 nodes, and doubling would leave up to 64 %
        // of them unused.
        if (nodes_.size() == nodes_.capacity()) nodes_.reserve(grownCapacity(nodes_.size()));
        nodes_.push_back(Node{});
        return static_cast<int>(nodes_.size()) - 1;
    }
    int id = freeList_;
    freeList_ = nodes_[static_cast<std::size_t>(id)].parent;
    nodes_[static_cast<std::size_t>(id)] = Node{};
    return id;
}

void DynamicTree::freeNode(int node) {
    Node& n = nodes_[static_cast<std::size_t>(node)];
    n.parent = freeList_;
    n.height = -1;
    freeList_ = node;
}

int DynamicTree::createProxy(const AABB& fatBox, int userIndex) {
    int leaf = allocateNode();
    Node& n = nodes_[static_cast<std::size_t>(leaf)];
    n.box = fatBox;
    n.userIndex = userIndex;
    n.height = 0;
    insertLeaf(leaf);
    ++proxyCount_;
    return leaf;
}

void DynamicTree::destroyProxy(int proxy) {
    removeLeaf(proxy);
    freeNode(proxy);
    --proxyCount_;
}

void DynamicTree::moveProxy(int proxy, const AABB& fatBox) {
    removeLeaf(proxy);
    nodes_[static_cast<std::size_t>(proxy)].box = fatBox;
    insertLeaf(proxy);
}

// Insertion descends toward the sibling that minimises the increase in total
// perimeter (the 2D surface-area heuristic), then refits and rebalances the
// ancestors on the way back up.
void DynamicTree::insertLeaf(int leaf) {
    if (root_ == kNull) {
        root_ = leaf;
        nodes_[static_cast<std::size_t>(root_)].parent = kNull;
        return;
    }
    const AABB leafBox = nodes_[static_cast<std::size_t>(leaf)].box;
    int index = root_;
    while (!nodes_[static_cast<std::size_t>(index)].isLeaf()) {
        const Node& n = nodes_[static_cast<std::size_t>(index)];
        float area = perimeter(n.box);
        float combined = perimeter(unionOf(n.box, leafBox));
        // Cost of making a new parent here, and the inherited cost pushed to children.
        float cost = 2.0f * combined;
        float inherited = 2.0f * (combined - area);
        auto childCost = [&](int c) {
            const Node& ch = nodes_[static_cast<std::size_t>(c)];
            float grown = perimeter(unionOf(leafBox, ch.box));
            return ch.isLeaf() ? grown + inherited : (grown - perimeter(ch.box)) + inherited;
        };
        float cost1 = childCost(n.child1);
        float cost2 = childCost(n.child2);
        if (cost < cost1 && cost < cost2) break;
        index = cost1 < cost2 ? n.child1 : n.child2;
    }
    int sibling = index;
    int oldParent = nodes_[static_cast<std::size_t>(sibling)].parent;
    int newParent = allocateNode();
    {
        Node& p = nodes_[static_cast<std::size_t>(newParent)];
        p.parent = oldParent;
        p.box = unionOf(leafBox, nodes_[static_cast<std::size_t>(sibling)].box);
        p.height = nodes_[static_cast<std::size_t>(sibling)].height + 1;
        p.child1 = sibling;
        p.child2 = leaf;
    }
    if (oldParent != kNull) {
        Node& op = nodes_[static_cast<std::size_t>(oldParent)];
        (op.child1 == sibling ? op.child1 : op.child2) = newParent;
    } else {
        root_ = newParent;
    }
    nodes_[static_cast<std::size_t>(sibling)].parent = newParent;
    nodes_[static_cast<std::size_t>(leaf)].parent = newParent;

    for (index = nodes_[static_cast<std::size_t>(leaf)].parent; index != kNull;) {
        index = balance(index);
        Node& n = nodes_[static_cast<std::size_t>(index)];
        const Node& c1 = nodes_[static_cast<std::size_t>(n.child1)];
        const Node& c2 = nodes_[static_cast<std::size_t>(n.child2)];
        n.height = 1 + std::max(c1.height, c2.height);
        n.box = unionOf(c1.box, c2.box);
        index = n.parent;
    }
}

void DynamicTree::removeLeaf(int leaf) {
    if (leaf == root_) {
        root_ = kNull;
        return;
    }
    int parent = nodes_[static_cast<std::size_t>(leaf)].parent;
    const Node& p = nodes_[static_cast<std::size_t>(parent)];
    int grandParent = p.parent;
    int sibling = p.child1 == leaf ? p.child2 : p.child1;
    if (grandParent != kNull) {
        Node& g = nodes_[static_cast<std::size_t>(grandParent)];
        (g.child1 == parent ? g.child1 : g.child2) = sibling;
        nodes_[static_cast<std::size_t>(sibling)].parent = grandParent;
        freeNode(parent);
        for (int index = grandParent; index != kNull;) {
            index = balance(index);
            Node& n = nodes_[static_cast<std::size_t>(index)];
            const Node& c1 = nodes_[static_cast<std::size_t>(n.child1)];
            const Node& c2 = nodes_[static_cast<std::size_t>(n.child2)];
            n.box = unionOf(c1.box, c2.box);
            n.height = 1 + std::max(c1.height, c2.height);
            index = n.parent;
        }
    } else {
        root_ = sibling;
        nodes_[static_cast<std::size_t>(sibling)].parent = kNull;
        freeNode(parent);
    }
}

// A left or right rotation when the subtrees' heights differ by more than
// one; returns the index of the node now at a's place.
int DynamicTree::balance(int iA) {
    Node& A = nodes_[static_cast<std::size_t>(iA)];
    if (A.isLeaf() || A.height < 2) return iA;
    int iB = A.child1;
    int iC = A.child2;
    Node& B = nodes_[static_cast<std::size_t>(iB)];
    Node& C = nodes_[static_cast<std::size_t>(iC)];
    int diff = C.height - B.height;

    auto rotateUp = [&](int iA_, int iUp, int iOther, bool upIsChild2) {
        Node& a = nodes_[static_cast<std::size_t>(iA_)];
        Node& up = nodes_[static_cast<std::size_t>(iUp)];
        int iF = up.child1;
        int iG = up.child2;
        Node& F = nodes_[static_cast<std::size_t>(iF)];
        Node& G = nodes_[static_cast<std::size_t>(iG)];
        up.child1 = iA_;
        up.parent = a.parent;
        a.parent = iUp;
        if (up.parent != kNull) {
            Node& pp = nodes_[static_cast<std::size_t>(up.parent)];
            (pp.child1 == iA_ ? pp.child1 : pp.child2) = iUp;
        } else {
            root_ = iUp;
        }
        const Node& other = nodes_[static_cast<std::size_t>(iOther)];
        int keep, give;
        if (F.height > G.height) {
            keep = iF;
            give = iG;
        } else {
            keep = iG;
            give = iF;
        }
        up.child2 = keep;
        (upIsChild2 ? a.child2 : a.child1) = give;
        nodes_[static_cast<std::size_t>(give)].parent = iA_;
        const Node& g = nodes_[static_cast<std::size_t>(give)];
        const Node& k = nodes_[static_cast<std::size_t>(keep)];
        a.box = unionOf(other.box, g.box);
        a.height = 1 + std::max(other.height, g.height);
        up.box = unionOf(a.box, k.box);
        up.height = 1 + std::max(a.height, k.height);
        return iUp;
    };

    if (diff > 1) return rotateUp(iA, iC, iB, true);
    if (diff < -1) return rotateUp(iA, iB, iC, false);
    return iA;
}

bool DynamicTree::segmentHitsBox(const AABB& b, Vec2 p, Vec2 d, float maxFraction) {
    // Slab test of the segment p + t·d, t ∈ [0, maxFraction].
    float tmin = 0.0f;
    float tmax = maxFraction;
    const float pc[2] = {p.x, p.y};
    const float dc[2] = {d.x, d.y};
    const float lo[2] = {b.lower.x, b.lower.y};
    const float hi[2] = {b.upper.x, b.upper.y};
    for (int i = 0; i < 2; ++i) {
        if (std::fabs(dc[i]) < 1.0e-12f) {
            if (pc[i] < lo[i] || pc[i] > hi[i]) return false;
        } else {
            float inv = 1.0f / dc[i];
            float t1 = (lo[i] - pc[i]) * inv;
            float t2 = (hi[i] - pc[i]) * inv;
            if (t1 > t2) std::swap(t1, t2);
            tmin = std::max(tmin, t1);
            tmax = std::min(tmax, t2);
            if (tmin > tmax) return false;
        }
    }
    return true;
}

bool DynamicTree::validateNode(int index) const {
    const Node& n = nodes_[static_cast<std::size_t>(index)];
    if (n.isLeaf()) return n.height == 0;
    const Node& c1 = nodes_[static_cast<std::size_t>(n.child1)];
    const Node& c2 = nodes_[static_cast<std::size_t>(n.child2)];
    if (c1.parent != index || c2.parent != index) return false;
    if (n.height != 1 + std::max(c1.height, c2.height)) return false;
    if (!contains(n.box, c1.box) || !contains(n.box, c2.box)) return false;
    if (std::abs(c1.height - c2.height) > 1) return false;
    return validateNode(n.child1) && validateNode(n.child2);
}

bool DynamicTree::validate() const {
    if (root_ == kNull) return proxyCount_ == 0;
    if (nodes_[static_cast<std::size_t>(root_)].parent != kNull) return false;
    return validateNode(root_);
}

}  // namespace i2d::detail
