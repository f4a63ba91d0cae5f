// The card house (card_house; docs/validation.md, "The card house"): 40 cards
// 2 mm thick and 40 cm long, friction 0.7, leaning in pairs at ±25° with flat
// cards across the pairs' tops, five levels. The hard case's criterion:
// it stands 10 s and no card moves more than 1 cm. Stepped with sleeping
// off, so nothing is held still by sleep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <impulse2d/impulse2d.hpp>

#include "scene_build.hpp"
#include "scene_loader.hpp"

namespace {

TEST(CardHouse, StandsTenSecondsWithoutSleeping) {
    tb::SceneDesc desc = tb::loadSceneDesc("card_house", TB_TEST_ASSETS_DIR);
    desc.settings.enableSleep = false;
    tb::Scene scene = tb::buildScene(desc);
    i2d::World& world = *scene.world;
    std::vector<i2d::BodyId> cards;
    for (i2d::BodyId b : world.bodies())
        if (world.bodyType(b) == i2d::BodyType::dynamic_body) cards.push_back(b);
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

}  // namespace
