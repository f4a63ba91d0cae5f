// The broadphase tree against brute force on random moving boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "dynamic_tree.hpp"

using i2d::AABB;
using i2d::detail::DynamicTree;

namespace {
AABB randomBox(std::mt19937& rng) {
    std::uniform_real_distribution<float> pos(-50.0f, 50.0f), size(0.1f, 4.0f);
    float x = pos(rng), y = pos(rng);
    return {{x, y}, {x + size(rng), y + size(rng)}};
}
}  // namespace

TEST(DynamicTree, QueriesMatchBruteForceWhileProxiesMove) {
    std::mt19937 rng(12345);
    DynamicTree tree;
    std::vector<AABB> boxes;
    std::vector<int> proxies;
    for (int i = 0; i < 500; ++i) {
        boxes.push_back(randomBox(rng));
        proxies.push_back(tree.createProxy(boxes.back(), i));
    }
    ASSERT_TRUE(tree.validate());
    std::uniform_int_distribution<int> pick(0, 499);
    for (int round = 0; round < 50; ++round) {
        // Move a fifth of the proxies, destroy and recreate a few.
        for (int k = 0; k < 100; ++k) {
            int i = pick(rng);
            boxes[static_cast<std::size_t>(i)] = randomBox(rng);
            tree.moveProxy(proxies[static_cast<std::size_t>(i)], boxes[static_cast<std::size_t>(i)]);
        }
        for (int k = 0; k < 5; ++k) {
            int i = pick(rng);
            tree.destroyProxy(proxies[static_cast<std::size_t>(i)]);
            boxes[static_cast<std::size_t>(i)] = randomBox(rng);
            proxies[static_cast<std::size_t>(i)] = tree.createProxy(boxes[static_cast<std::size_t>(i)], i);
        }
        ASSERT_TRUE(tree.validate()) << "round " << round;
        for (int q = 0; q < 20; ++q) {
            AABB query = randomBox(rng);
            std::set<int> fromTree, brute;
            tree.query(query, [&](int user) {
                fromTree.insert(user);
                return true;
            });
            for (int i = 0; i < 500; ++i)
                if (i2d::overlaps(boxes[static_cast<std::size_t>(i)], query)) brute.insert(i);
            ASSERT_EQ(fromTree, brute);
        }
    }
    EXPECT_EQ(tree.proxyCount(), 500);
    // Balanced: height stays logarithmic (an AVL-balanced tree of 500 leaves is ≤ 1.44·log2(500) ≈ 13).
    EXPECT_LE(tree.height(), 14);
}

TEST(DynamicTree, RayCastVisitsEveryBoxTheSegmentCrosses) {
    std::mt19937 rng(7);
    DynamicTree tree;
    std::vector<AABB> boxes;
    for (int i = 0; i < 300; ++i) {
        boxes.push_back(randomBox(rng));
        tree.createProxy(boxes.back(), i);
    }
    i2d::Vec2 p{-60.0f, -3.0f}, d{120.0f, 7.0f};
    std::set<int> visited;
    tree.rayCast(p, d, 1.0f, [&](int user, float maxFraction) {
        visited.insert(user);
        return maxFraction;
    });
    // Brute force: sample the segment densely; every box containing a sample must be visited.
    for (int k = 0; k <= 20000; ++k) {
        float t = static_cast<float>(k) / 20000.0f;
        i2d::Vec2 q = p + t * d;
        for (int i = 0; i < 300; ++i) {
            const AABB& b = boxes[static_cast<std::size_t>(i)];
            if (q.x >= b.lower.x && q.x <= b.upper.x && q.y >= b.lower.y && q.y <= b.upper.y) {
                ASSERT_TRUE(visited.count(i)) << i;
            }
        }
    }
}

TEST(DynamicTree, WorldPairsMatchBruteForceOnRandomMovingBodies) {
    // Bodies in zero gravity moving through each other (a shared negative group
    // keeps them from colliding, so their paths stay random). The world's
    // broadphase answers box queries; brute force over every shape's box must agree.
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> pos(-20.0f, 20.0f), vel(-5.0f, 5.0f);
    i2d::World world({.gravity = {0, 0}});
    std::vector<i2d::BodyId> bodies;
    for (int i = 0; i < 200; ++i) {
        i2d::BodyId b = world.createBody({.type = i2d::BodyType::dynamic_body,
                                          .position = {pos(rng), pos(rng)},
                                          .linearVelocity = {vel(rng), vel(rng)}});
        world.createCircleShape(b, {.filter = {.groupIndex = -1}}, {{0, 0}, 0.5f});
        bodies.push_back(b);
    }
    for (int step = 0; step < 120; ++step) {
        world.step(1.0f / 60.0f);
        if (step % 10 != 0) continue;
        i2d::AABB query{{pos(rng), pos(rng)}, {0, 0}};
        query.upper = {query.lower.x + 6.0f, query.lower.y + 6.0f};
        auto found = world.overlapAABB(query);
        std::set<std::uint32_t> fromWorld, brute;
        for (auto s : found) fromWorld.insert(s.index1);
        for (auto b : bodies) {
            for (auto s : world.bodyShapes(b))
                if (i2d::overlaps(world.shapeAABB(s), query)) brute.insert(s.index1);
        }
        ASSERT_EQ(fromWorld, brute) << "step " << step;
    }
}
