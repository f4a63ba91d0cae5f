// The domino row (dominoes; Box2D v3's "Double Domino"): 15 dominoes
// 0.25 × 1 m at 1 m spacing, friction 0.6, the first struck at its top with
// (0.2, 0) N·s. The hard case's criterion: all 15 topple, in order, and none
// turns faster than 20 rad/s (a domino kicked up or bounced back). Stepped
// with sleeping off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace {

TEST(Dominoes, AllFifteenToppleInOrderWithoutBeingKicked) {
    tb::SceneDesc desc = tb::loadSceneDesc("dominoes", TB_TEST_ASSETS_DIR);
    desc.settings.enableSleep = false;
    tb::Scene scene = tb::buildScene(desc);
    i2d::World& world = *scene.world;
    std::vector<i2d::BodyId> dominoes;
    for (i2d::BodyId b : world.bodies())
        if (world.bodyType(b) == i2d::BodyType::dynamic_body) dominoes.push_back(b);
    ASSERT_EQ(dominoes.size(), 15u);
    std::sort(dominoes.begin(), dominoes.end(),
              [&](i2d::BodyId a, i2d::BodyId b) { return world.position(a).x < world.position(b).x; });
    // When each domino first leans past 45° (it cannot stand up again from
    // there: its centre is past its foot), −1 until then.
    std::vector<float> toppledAt(dominoes.size(), -1.0f);
    float fastest = 0.0f;
    const int steps = static_cast<int>(10.0f / desc.dt);
    for (int s = 1; s <= steps; ++s) {
        world.step(desc.dt);
        for (std::size_t i = 0; i < dominoes.size(); ++i) {
            fastest = std::max(fastest, std::abs(world.angularVelocity(dominoes[i])));
            if (toppledAt[i] < 0.0f && std::abs(world.angle(dominoes[i])) > 0.25f * 3.14159265f)
                toppledAt[i] = static_cast<float>(s) * desc.dt;
        }
    }
    std::printf("[figure] dominoes: the last toppled at %.2f s, fastest turn %.2f rad/s\n", toppledAt.back(), fastest);
    for (std::size_t i = 0; i < dominoes.size(); ++i) {
        EXPECT_GE(toppledAt[i], 0.0f) << "domino " << i << " still stands";
        if (i > 0) {
            EXPECT_GT(toppledAt[i], toppledAt[i - 1]) << "domino " << i << " fell before the one behind it";
        }
    }
    // The hard case's bound. A domino toppling about its foot turns at most
    // √(ω₀² + 2·g·Δh·m/I) ≈ 6.5 rad/s by the time it lies flat: its centre
    // falls Δh = 0.39 m (from 0.52 m above the foot to 0.125 m), I = 0.354·m
    // about the foot, ω₀ = 4.5 rad/s the first one's strike, g = 10.
    // 20 rad/s is a kick.
    EXPECT_LT(fastest, 20.0f);
}

}  // namespace
