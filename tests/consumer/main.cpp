// A minimal game using the installed package: a box falls onto the ground.
#include <impulse2d/impulse2d.hpp>

#include <cstdio>

int main() {
    i2d::World world;
    i2d::BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {}, i2d::makeBox(10.0f, 0.5f));
    i2d::BodyId box = world.createBody({.type = i2d::BodyType::dynamic_body, .position = {0.0f, 3.0f}});
    world.createPolygonShape(box, {.density = 1.0f}, i2d::makeBox(0.5f, 0.5f));
    for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
    float y = world.position(box).y;
    std::printf("box at y = %.3f\n", y);
    // Resting on the ground top (y = 0.5) with its half-height 0.5 → y ≈ 1.
    return (y > 0.9f && y < 1.1f) ? 0 : 1;
}
