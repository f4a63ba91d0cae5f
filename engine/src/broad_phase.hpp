// The broadphase: an AABB tree of fattened shape boxes per body type, the
// buffer of proxies that moved, and the set of pairs that already have a
// contact. Static shapes never query, so a level's static geometry costs
// nothing while nothing moves near it; kinematic shapes query the dynamic
// tree only (a contact needs a dynamic body), and continuous collision finds
// the few kinematic shapes near a fast body in their own small tree instead
// of among every moving shape (as Box2D v3 keeps a tree per body type:
// Catto, 2024, Box2D v3.0, broad_phase.c).
//
// A proxy moves in its tree only when its shape leaves the fat box; only
// moved proxies query for new pairs, so the cost per step follows how much
// moved, not how much exists.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "dynamic_tree.hpp"
#include "pair_set.hpp"
#include "shape.hpp"

namespace i2d::detail {

struct WorldState;

struct BroadPhase {
    DynamicTree staticTree;                 ///< shapes of static bodies
    DynamicTree kinematicTree;              ///< shapes of kinematic bodies
    DynamicTree dynamicTree;                ///< shapes of dynamic bodies
    std::vector<int> moveBuffer;            ///< shapes whose proxies moved or were created
    std::vector<std::uint8_t> proxyLeaves;  ///< per awake body: a shape left its fat box this step (refreshProxies)
    PairSet pairs;                          ///< shape pairs that have a contact
    std::vector<int> motionSet;             ///< bodies whose velocity the game set since the last step (noteMotionSet)
    /// Per shape slot: the box in the broadphase tree (grown by the margin;
    /// that of a shape without a proxy means nothing). Apart from the
    /// shapes: every contact's update checks its two boxes each step, and
    /// read from the shapes (248 bytes each) that check missed the cache
    /// twice a contact, three quarters of the update's time in many_pyramids.
    std::vector<AABB> fatBoxes;

    DynamicTree& tree(BodyType type) {
        return type == BodyType::static_body ? staticTree
                                             : (type == BodyType::kinematic_body ? kinematicTree : dynamicTree);
    }
    /// The three trees in the order every query visits them: static,
    /// kinematic, dynamic.
    std::array<const DynamicTree*, 3> trees() const { return {&staticTree, &kinematicTree, &dynamicTree}; }
    /// Calls visit(shape) for the proxies of all three trees whose boxes
    /// overlap `box`, in trees() order; stops where visit returns false.
    template <class Visit>
    void queryAll(const AABB& box, Visit&& visit) const {
        bool more = true;
        auto until = [&](int s) { return more = visit(s); };
        for (const DynamicTree* tree : trees())
            if (more) tree->query(box, until);
    }

    const AABB& fatBox(int shape) const { return fatBoxes[static_cast<std::size_t>(shape)]; }
    AABB& fatBox(int shape) { return fatBoxes[static_cast<std::size_t>(shape)]; }

    /// Puts a moving shape into the move buffer (once).
    void markMoved(Shape& shape, int index) {
        if (!shape.moved && !shape.inStaticTree()) {
            shape.moved = true;
            moveBuffer.push_back(index);
        }
    }

    /// Calls onPair(s, other) for every pair of a moved shape with a shape
    /// whose fat box overlaps its own and that may touch it (one of the two
    /// is dynamic): distinct shapes of distinct bodies without a contact
    /// yet, each pair of two moved shapes once. Then empties the move
    /// buffer. Deterministic: the buffer is in the order the
    /// proxies moved and the trees are visited in a fixed order.
    template <class OnPair>
    void findNewPairs(SlotArray<Shape>& shapes, OnPair&& onPair) {
        for (int s : moveBuffer) {
            const Shape& sh = shapes[s];
            const AABB box = fatBox(s);
            auto visit = [&](int other) {
                if (other == s) return true;
                const Shape& o = shapes[other];
                // Both moved: the pair is handled once, from the lower index.
                if (o.moved && other < s && !o.inStaticTree()) return true;
                if (o.body == sh.body) return true;
                if (pairs.contains(pairKey(s, other))) return true;
                onPair(s, other);
                return true;
            };
            dynamicTree.query(box, visit);
            if (sh.treeType == BodyType::dynamic_body) {
                kinematicTree.query(box, visit);
                staticTree.query(box, visit);
            }
        }
        for (int s : moveBuffer) shapes[s].moved = false;
        moveBuffer.clear();
    }
};

/// Inserts the shape's proxy into the tree of its body's type. A new static
/// shape makes the moving shapes around it look for pairs again.
void createProxy(WorldState& w, int shape);
void destroyProxy(WorldState& w, int shape);

/// Refreshes the proxies of a body's shapes after it moved; after a step of
/// dt, a box that must move is stretched ahead along the body's velocity.
void synchronizeProxies(WorldState& w, int body, float dt = 0.0f);
/// Whether a shape of each of `count` bodies (the world's body slots at
/// `bodies`) left its fat box, into `leaves` (1: it left; synchronizeProxies
/// then moves it). Reads the world and writes these bodies' Body::boxSlack
/// and pose only: the solve's write-back asks it of every awake body on the
/// workers, where the bodies are in the cache (proxyLeaves).
void leftFatBoxes(WorldState& w, const int* bodies, std::size_t count, std::uint8_t* leaves);
/// The game set the body's velocity (or created it moving): at the next
/// step's start its fat boxes are made to hold its motion over that step
/// (coverSetMotions), as a step's end does for the velocity it leaves.
void noteMotionSet(WorldState& w, int body);
/// At a step's start, before the pairs are found: each body of
/// BroadPhase::motionSet whose fat boxes do not hold its motion over the
/// step of dt has them moved (synchronizeProxies).
void coverSetMotions(WorldState& w, float dt);
/// synchronizeProxies for the awake bodies the step's write-back found
/// outside their fat boxes (BroadPhase::proxyLeaves) or continuous collision
/// moved since, in the awake list's order; their marks are cleared, so a
/// second call moves only what was marked in between.
void refreshProxies(WorldState& w, float dt);

/// A static body was moved: its proxies never query, so the moving shapes
/// overlapping its shapes are woken and put in the move buffer to find the
/// new pairs from their side.
void wakeShapesAround(WorldState& w, int staticBody);

}  // namespace i2d::detail
