// The benchmark pyramid (Box2D v3's large_pyramid): `base` boxes of
// half-extent 0.5 on the bottom row, one fewer on each row above, friction
// 0.6, density 1, resting on a static ground whose top is y = 0. The same
// layout in Impulse2D and in Box2D 2.4.1, so the two run the same scene.
#pragma once

#include <box2d/box2d.h>
#include <impulse2d/impulse2d.hpp>

namespace bench {

/// Centre of box i (0-based) of a row of n boxes at height `row`.
inline i2d::Vec2 pyramidBoxCentre(int row, int i, int n) {
    return {static_cast<float>(i) - 0.5f * static_cast<float>(n - 1), 0.5f + static_cast<float>(row)};
}

/// Builds the pyramid in `world`; returns the top box.
inline i2d::BodyId buildPyramid(i2d::World& world, int base, float groundHalfWidth) {
    i2d::BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {}, i2d::makeOffsetBox(groundHalfWidth, 1.0f, {0, -1}, 0));
    i2d::BodyId top;
    for (int row = 0; row < base; ++row) {
        const int n = base - row;
        for (int i = 0; i < n; ++i) {
            top = world.createBody({.type = i2d::BodyType::dynamic_body, .position = pyramidBoxCentre(row, i, n)});
            world.createPolygonShape(top, {.density = 1.0f, .friction = 0.6f}, i2d::makeBox(0.5f, 0.5f));
        }
    }
    return top;
}

/// The same pyramid in Box2D 2.4.1; returns the top box.
inline b2Body* buildPyramid(b2World& world, int base, float groundHalfWidth) {
    b2BodyDef gd;
    b2PolygonShape gs;
    gs.SetAsBox(groundHalfWidth, 1.0f, b2Vec2(0, -1), 0);
    world.CreateBody(&gd)->CreateFixture(&gs, 0.0f);
    b2PolygonShape box;
    box.SetAsBox(0.5f, 0.5f);
    b2FixtureDef fd;
    fd.shape = &box;
    fd.density = 1.0f;
    fd.friction = 0.6f;
    b2Body* top = nullptr;
    for (int row = 0; row < base; ++row) {
        const int n = base - row;
        for (int i = 0; i < n; ++i) {
            b2BodyDef bd;
            bd.type = b2_dynamicBody;
            const i2d::Vec2 c = pyramidBoxCentre(row, i, n);
            bd.position.Set(c.x, c.y);
            top = world.CreateBody(&bd);
            top->CreateFixture(&fd);
        }
    }
    return top;
}

}  // namespace bench
