// Shipped scenes against the bounds their hard cases set (Solver2D's and
// Box2D v3's samples; docs/validation.md), each stepped with sleeping off so
// that nothing is held still by sleep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace {

/// A shipped scene built with sleeping off.
struct SceneWithoutSleep {
    tb::SceneDesc desc;
    tb::Scene scene;
    explicit SceneWithoutSleep(const std::string& name)
        : desc(withoutSleep(tb::loadSceneDesc(name, TB_TEST_ASSETS_DIR))), scene(tb::buildScene(desc)) {}
    static tb::SceneDesc withoutSleep(tb::SceneDesc d) {
        d.settings.enableSleep = false;
        return d;
    }
    /// Its dynamic bodies, in creation order.
    std::vector<i2d::BodyId> dynamicBodies() const {
        std::vector<i2d::BodyId> out;
        for (i2d::BodyId b : scene.world->bodies())
            if (scene.world->bodyType(b) == i2d::BodyType::dynamic_body) out.push_back(b);
        return out;
    }
};

// The card house (card_house; docs/validation.md, "The card house"): 40 cards
// 2 mm thick and 40 cm long, friction 0.7, leaning in pairs at ±25° with flat
// cards across the pairs' tops, five levels. The hard case's criterion:
// it stands 10 s and no card moves more than 1 cm.
TEST(CardHouse, StandsTenSecondsWithoutSleeping) {
    SceneWithoutSleep run("card_house");
    i2d::World& world = *run.scene.world;
    const tb::SceneDesc& desc = run.desc;
    const std::vector<i2d::BodyId> cards = run.dynamicBodies();
    ASSERT_EQ(cards.size(), 40u);
    std::vector<i2d::Vec2> start, settled;
    for (i2d::BodyId b : cards) start.push_back(world.position(b));
    const int settle = static_cast<int>(1.0f / desc.dt), steps = static_cast<int>(10.0f / desc.dt);
    float fromStart = 0.0f, afterSettling = 0.0f;
    for (int s = 1; s <= steps; ++s) {
        world.step(desc.dt);
        if (s == settle)
            for (i2d::BodyId b : cards) settled.push_back(world.position(b));
        for (std::size_t i = 0; i < cards.size(); ++i) {
            const i2d::Vec2 p = world.position(cards[i]);
            fromStart = std::max(fromStart, i2d::length(p - start[i]));
            if (s > settle) afterSettling = std::max(afterSettling, i2d::length(p - settled[i]));
        }
    }
    std::printf("[figure] card house, 10 s without sleeping: largest move of a card %.4f m from its start, %.5f m "
                "after the first second\n",
                fromStart, afterSettling);
    // The layout starts with the leaning pairs' tops 6 mm apart and each
    // level's flat cards 2.3 mm above them: in its first second the house
    // closes those gaps (cards move up to 3.3 cm). After that the hard case's
    // 1 cm holds for every card (measured: 1.0 mm); a house that slips or
    // collapses moves its cards by tens of centimetres (the mirrored layout
    // shipped before fell flat within 2 s, its top 1.66 m lower).
    EXPECT_LT(afterSettling, 0.01f);
    // And settling is not collapse: every card within 5 cm of its start
    // (settling moves them up to 3.3 cm; a card that falls moves by a good
    // part of its 40 cm length).
    EXPECT_LT(fromStart, 0.05f);
}

// The domino row (dominoes; Box2D v3's "Double Domino"): 15 dominoes
// 0.25 × 1 m at 1 m spacing, friction 0.6, the first struck at its top with
// (0.2, 0) N·s. The hard case's criterion: all 15 topple, in order, and none
// turns faster than 20 rad/s (a domino kicked up or bounced back).
TEST(Dominoes, AllFifteenToppleInOrderWithoutBeingKicked) {
    SceneWithoutSleep run("dominoes");
    i2d::World& world = *run.scene.world;
    const tb::SceneDesc& desc = run.desc;
    std::vector<i2d::BodyId> dominoes = run.dynamicBodies();
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

// The shipped tall stacks (tall_stack20, tall_stack50: unit boxes dropped
// through 0.1 m gaps onto each other, alternating ±1 cm offsets, Solver2D's
// vertical stack) stand a minute with sleeping off, as the hard-cases issue
// asks. Standing, held two ways. Every box stays within 0.15 m of where it
// was created sideways, under a third of the half-width (0.5 m) at which a
// box tips off the one below (the stack validation cases' bound on the top's
// drift; a falling stack moves its boxes metres). And the top box ends no
// lower than resting exactly on the others, less, per contact layer, the
// 5 mm penetration slop and the soft contact's compression under the k boxes
// above it, k·g/ω² (ω = 2π·contactHertz), as the validation cases'
// top-height tolerance derives it: a box that fell out of the stack would
// take a metre off the top. Measured: 3.6 mm and 4.2 cm sideways (2.7 mm
// and 7.9 cm before the columns' tilt was solved exactly: the boxes landed
// bent and the soft rows held the bend), the tops 4.8 cm and 30 cm below
// resting exactly (bounds 12 cm and 38 cm).
TEST(TallStacks, StandAMinuteWithoutSleeping) {
    for (const auto& [name, layers] : {std::pair<const char*, int>{"tall_stack20", 20}, {"tall_stack50", 50}}) {
        SceneWithoutSleep run(name);
        i2d::World& world = *run.scene.world;
        const tb::SceneDesc& desc = run.desc;
        const std::vector<i2d::BodyId> boxes = run.dynamicBodies();
        ASSERT_EQ(boxes.size(), static_cast<std::size_t>(layers)) << name;
        std::vector<float> startX;
        for (i2d::BodyId b : boxes) startX.push_back(world.position(b).x);
        float sideways = 0.0f;
        const int steps = static_cast<int>(60.0f / desc.dt);
        for (int s = 0; s < steps; ++s) {
            world.step(desc.dt);
            for (std::size_t i = 0; i < boxes.size(); ++i)
                sideways = std::max(sideways, std::abs(world.position(boxes[i]).x - startX[i]));
        }
        // The ground's top is at y = 0 in both scenes: resting exactly, box i's
        // centre is at i + 0.5.
        const float rigidTop = static_cast<float>(layers) - 0.5f;
        const float omega = 2.0f * 3.14159265f * desc.settings.contactHertz;
        const float g = -desc.settings.gravity.y;
        const float n = static_cast<float>(layers);
        const float sag = desc.settings.penetrationSlop * n + g / (omega * omega) * n * (n + 1.0f) / 2.0f;
        const float top = world.position(boxes.back()).y;
        std::printf("[figure] %s, 60 s without sleeping: largest sideways move %.4f m, top %.4f m below resting "
                    "exactly (bound %.4f m)\n",
                    name, sideways, rigidTop - top, sag);
        EXPECT_LT(sideways, 0.15f) << name;
        EXPECT_GT(top, rigidTop - sag) << name;
    }
}

}  // namespace
