// Small scene builders shared by the world tests.
#pragma once

#include <impulse2d/impulse2d.hpp>

namespace i2d::test {

/// Static ground whose top face is the line y = 0, from x = −halfWidth to +halfWidth.
inline BodyId makeGround(World& world, float halfWidth = 50.0f, float friction = 0.6f) {
    BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {.friction = friction}, makeOffsetBox(halfWidth, 1.0f, {0.0f, -1.0f}, 0.0f));
    return ground;
}

inline BodyId makeBox(World& world, Vec2 position, float halfExtent = 0.5f, float density = 1.0f,
                      float friction = 0.6f) {
    BodyId body = world.createBody({.type = BodyType::dynamic_body, .position = position});
    world.createPolygonShape(body, {.density = density, .friction = friction}, i2d::makeBox(halfExtent, halfExtent));
    return body;
}

}  // namespace i2d::test
