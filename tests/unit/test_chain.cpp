// Chain shapes: checks of their points, one-sided collision, smooth sliding
// and rolling across their joints.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <impulse2d/impulse2d.hpp>

namespace {

using namespace i2d;

// Every refused chain throws i2d::Error and creates nothing.
TEST(Chain, BadInputIsRefusedAndChangesNothing) {
    World world;
    BodyId ground = world.createBody({});
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<std::vector<Vec2>> open = {
        {},                                             // no point
        {{0, 0}},                                       // one point
        {{0, 0}, {0, 0}},                               // coincident
        {{0, 0}, {1, 0}, {1.002f, 0}},                  // closer than the slop
        {{0, 0}, {nan, 0}},                             // not finite
        {{0, 0}, {inf, 1}},                             // not finite
        {{0, 0}, {2e7f, 0}},                            // out of range
        {{0, 0}, {2, 0}, {1, 0}},                       // folds back onto itself
        {{0, 0}, {2, 0}, {2, 1}, {1, -1}},              // crosses itself
        {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 0.002f}},  // touches itself
    };
    for (const auto& points : open) {
        EXPECT_THROW(world.createChain(ground, {.points = points}), Error) << points.size() << " points";
    }
    const std::vector<std::vector<Vec2>> loops = {
        {{0, 0}, {1, 0}},                  // too few for a loop
        {{0, 0}, {2, 0}, {0, 2}, {2, 2}},  // a bow tie: overlaps itself
        {{0, 0}, {1, 0}, {1, 1}, {0, 0}},  // the last point repeats the first
        {{0, 0}, {2, 0}, {1, 0}},          // flat: folds back
    };
    for (const auto& points : loops)
        EXPECT_THROW(world.createChain(ground, {.points = points, .isLoop = true}), Error) << points.size();
    const std::vector<Vec2> fine = {{0, 0}, {1, 0}, {2, 0.5f}};
    EXPECT_THROW(world.createChain(ground, {.points = fine, .friction = -1.0f}), Error);
    EXPECT_THROW(world.createChain(ground, {.points = fine, .restitution = 2.0f}), Error);
    EXPECT_THROW(world.createChain(BodyId{}, {.points = fine}), Error);
    EXPECT_EQ(world.shapeCount(), 0);
    EXPECT_TRUE(world.bodyShapes(ground).empty());
}

// A long terrain: the crossing test sweeps the segments' boxes instead of
// testing every pair, and must still find a crossing far apart in the point
// order and name the first crossing pair, as a test of every pair would.
TEST(Chain, ALongTerrainIsCheckedForCrossingsAndCreatedWhole) {
    World world;
    BodyId ground = world.createBody({});
    std::vector<Vec2> points;
    for (int i = 0; i < 20000; ++i) points.push_back({0.5f * static_cast<float>(i), std::sin(0.01f * i)});
    const std::vector<ShapeId> segments = world.createChain(ground, {.points = points});
    EXPECT_EQ(segments.size(), points.size() - 1);
    // Three more points turn back under the terrain and up through its start: the last segment
    // (20,001) crosses segment 0.
    points.push_back({points.back().x, -5.0f});
    points.push_back({0.25f, -5.0f});
    points.push_back({0.25f, 5.0f});
    try {
        world.createChain(ground, {.points = points});
        ADD_FAILURE() << "a chain crossing itself was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("segments 0 and 20001"), std::string::npos) << e.what();
    }
    EXPECT_EQ(world.shapeCount(), static_cast<int>(segments.size()));
}

// Destroying a segment makes its neighbours' ends on its side corners: their
// ghost vertices there were the removed segment's far ends, and the rule
// that drops a vertex normal leaning over the next segment kept dropping
// them as if it were still there.
TEST(Chain, DestroyingASegmentTurnsItsNeighboursEndsIntoCorners) {
    World world;
    BodyId ground = world.createBody({});
    const std::vector<Vec2> points = {{0, 0}, {1, 0}, {2, 0.5f}, {3, 0.5f}};
    const std::vector<ShapeId> segments = world.createChain(ground, {.points = points});
    ASSERT_EQ(segments.size(), 3u);
    world.destroyShape(segments[1]);
    const ChainSegment first = world.shapeChainSegment(segments[0]);
    const ChainSegment last = world.shapeChainSegment(segments[2]);
    EXPECT_EQ(first.ghost2, first.segment.point2);  // was {2, 0.5}
    EXPECT_EQ(last.ghost1, last.segment.point1);    // was {1, 0}
    EXPECT_EQ(first.ghost1, first.segment.point1);  // the chain's own end, as before
    EXPECT_EQ(last.ghost2, last.segment.point2);
}

TEST(Chain, SegmentsKnowTheirNeighbours) {
    World world;
    BodyId ground = world.createBody({});
    const std::vector<Vec2> points = {{0, 0}, {1, 0}, {2, 0.5f}, {3, 0.5f}};
    const std::vector<ShapeId> open = world.createChain(ground, {.points = points, .friction = 0.2f});
    ASSERT_EQ(open.size(), 3u);
    for (ShapeId s : open) {
        EXPECT_TRUE(world.isChainSegment(s));
        EXPECT_EQ(world.shapeType(s), ShapeType::segment);
        EXPECT_FLOAT_EQ(world.friction(s), 0.2f);
    }
    const ChainSegment middle = world.shapeChainSegment(open[1]);
    EXPECT_EQ(middle.ghost1, points[0]);
    EXPECT_EQ(middle.segment.point1, points[1]);
    EXPECT_EQ(middle.segment.point2, points[2]);
    EXPECT_EQ(middle.ghost2, points[3]);
    // An open chain's ends have no neighbour: the ghost is the end point.
    EXPECT_EQ(world.shapeChainSegment(open[0]).ghost1, points[0]);
    EXPECT_EQ(world.shapeChainSegment(open[2]).ghost2, points[3]);
    // A loop closes: 4 points, 4 segments, the last one's neighbour is the first.
    const std::vector<Vec2> square = {{10, 0}, {11, 0}, {11, 1}, {10, 1}};
    const std::vector<ShapeId> loop = world.createChain(ground, {.points = square, .isLoop = true});
    ASSERT_EQ(loop.size(), 4u);
    EXPECT_EQ(world.shapeChainSegment(loop[3]).segment.point2, square[0]);
    EXPECT_EQ(world.shapeChainSegment(loop[3]).ghost2, square[1]);
    EXPECT_EQ(world.shapeChainSegment(loop[0]).ghost1, square[3]);
    BodyId other = world.createBody({});
    ShapeId plain = world.createSegmentShape(other, {}, {{0, 0}, {1, 0}});
    EXPECT_FALSE(world.isChainSegment(plain));
    EXPECT_THROW(world.shapeChainSegment(plain), Error);
}

// A chain collides on its right side only: a floor drawn right to left
// (right side up) holds a ball dropped on it, and a ball thrown up at it from
// below passes through.
TEST(Chain, CollidesOnOneSideOnly) {
    World world;
    BodyId ground = world.createBody({});
    const std::vector<Vec2> floor = {{5, 0}, {0, 0}, {-5, 0}};
    world.createChain(ground, {.points = floor});
    BodyId above = world.createBody({.type = BodyType::dynamic_body, .position = {-2, 1}});
    world.createCircleShape(above, {}, {{0, 0}, 0.25f});
    BodyId below = world.createBody({.type = BodyType::dynamic_body, .position = {2, -1}, .linearVelocity = {0, 10}});
    world.createCircleShape(below, {}, {{0, 0}, 0.25f});
    float belowHighest = -1.0e30f;
    for (int i = 0; i < 120; ++i) {
        world.step(1.0f / 60.0f);
        belowHighest = std::max(belowHighest, world.position(below).y);
    }
    // Resting on the floor: centre one radius up, within the contact's 0.005 m slop.
    EXPECT_NEAR(world.position(above).y, 0.25f, 0.006f);
    // Thrown at 10 m/s from 1 m below, it rises 10²/(2·10) = 5 m without
    // the floor: well above it whatever the step's discretisation.
    EXPECT_GT(belowHighest, 3.0f);
}

struct Slide {
    float maxUpSpeed = 0.0f;
    float minSpeedX = 1.0e30f;
    float endX = 0.0f;
};

// A box, circle or capsule driven at `speed` across a chain of many short
// segments: flat (40 m of 0.25 m segments) or a gentle 0.5 m-high sine of
// 8 m wavelength, drawn right to left so its right side is up.
Slide slide(int mover, float speed, bool wavy) {
    WorldSettings s;
    s.enableSleep = false;
    World world(s);
    BodyId ground = world.createBody({});
    std::vector<Vec2> points;
    auto height = [&](float x) { return wavy ? 0.5f * std::sin(x * 6.2831853f / 8.0f) : 0.0f; };
    for (int i = 160; i >= 0; --i) {
        const float x = -20.0f + 0.25f * static_cast<float>(i);
        points.push_back({x, height(x)});
    }
    world.createChain(ground, {.points = points, .friction = 0.0f});
    const float x0 = -18.0f;
    BodyId body;
    if (mover == 0) {
        body = world.createBody(
            {.type = BodyType::dynamic_body, .position = {x0, height(x0) + 0.5f}, .fixedRotation = true});
        world.createPolygonShape(body, {.friction = 0.0f}, makeBox(0.3f, 0.5f));
    } else if (mover == 1) {
        body = world.createBody({.type = BodyType::dynamic_body, .position = {x0, height(x0) + 0.25f}});
        world.createCircleShape(body, {.friction = 0.0f}, {{0, 0}, 0.25f});
    } else {
        body = world.createBody({.type = BodyType::dynamic_body, .position = {x0, height(x0) + 0.2f}});
        world.createCapsuleShape(body, {.friction = 0.0f}, {{-0.3f, 0}, {0.3f, 0}, 0.2f});
    }
    Slide r;
    const float dt = 1.0f / 60.0f;
    // Steps to cover the 36 m to x = 18 and half a metre more; over the hills
    // a quarter more: a body driven at 12-20 m/s leaves the crests and lands
    // on the next up-slope (up to 21°), whose contact takes some of the
    // horizontal speed set before the step.
    const int steps = static_cast<int>(std::ceil((wavy ? 1.25f : 1.0f) * 36.5f / (speed * dt)));
    for (int i = 0; i < steps && world.position(body).x < 18.0f; ++i) {
        // Driven along the surface (a character controller): for the wavy
        // floor only the horizontal speed is set and the rest is gravity's.
        world.setLinearVelocity(body, {speed, world.linearVelocity(body).y});
        world.step(dt);
        if (i < 5) continue;  // settling of the exact placement
        const Vec2 v = world.linearVelocity(body);
        if (!wavy) r.maxUpSpeed = std::max(r.maxUpSpeed, std::abs(v.y));
        r.minSpeedX = std::min(r.minSpeedX, v.x);
    }
    r.endX = world.position(body).x;
    return r;
}

// Across 159 joints of a flat chain at up to 20 m/s nothing snags (the
// horizontal speed set before each step survives it within 1 %) and nothing
// leaves the floor (the 0.1 m/s). On the wavy chain (joints bent by
// up to 1.1°) nothing snags either; the vertical speed there follows the
// hills and is not a fault.
TEST(Chain, NothingSnagsOrJumpsAtJoints) {
    const char* names[] = {"box", "circle", "capsule"};
    for (int mover = 0; mover < 3; ++mover)
        for (float speed : {1.0f, 3.0f, 6.0f, 12.0f, 20.0f})
            for (bool wavy : {false, true}) {
                const Slide r = slide(mover, speed, wavy);
                const std::string what = std::string(names[mover]) + (wavy ? " on hills" : " on flat") + " at " +
                                         std::to_string(speed);
                EXPECT_LT(r.maxUpSpeed, 0.1f) << what;
                EXPECT_GE(r.endX, 18.0f) << what;
                if (!wavy) {
                    EXPECT_GT(r.minSpeedX, 0.99f * speed) << what;
                }
            }
}

// Debug draw: each chain segment, and a tick from its middle towards the side
// it collides on (its right side).
struct SegmentRecorder : DebugDraw {
    std::vector<std::pair<Vec2, Vec2>> segments;
    void drawSolidPolygon(const Transform&, const Vec2*, int, float, Color) override {}
    void drawSolidCircle(Vec2, float, Vec2, Color) override {}
    void drawSolidCapsule(Vec2, Vec2, float, Color) override {}
    void drawSegment(Vec2 p1, Vec2 p2, Color) override { segments.emplace_back(p1, p2); }
    void drawPoint(Vec2, float, Color) override {}
};

TEST(Chain, DebugDrawShowsTheCollidingSide) {
    World world;
    BodyId ground = world.createBody({});
    const std::vector<Vec2> points = {{2, 0}, {0, 0}, {-2, 0}};  // right to left: its right side is up
    world.createChain(ground, {.points = points});
    SegmentRecorder rec;
    world.draw(rec);
    ASSERT_EQ(rec.segments.size(), 4u);  // two segments, two ticks
    int ticksUp = 0;
    for (const auto& [a, b] : rec.segments)
        if (a.y == 0.0f && b.y > 0.0f) ++ticksUp;
    EXPECT_EQ(ticksUp, 2);
}

}  // namespace
