#include "test_scene.hpp"

namespace tbtest {

tb::Scene makeTestScene() {
    tb::Scene scene;
    scene.desc.name = "render-test";
    scene.desc.camera = tb::Camera{{0.0f, kCameraY}, kCameraHeight};
    scene.world = std::make_unique<i2d::World>(scene.desc.settings);
    i2d::World& w = *scene.world;

    i2d::BodyId ground = w.createBody({.position = {0.0f, -1.0f}});
    w.createPolygonShape(ground, {}, i2d::makeBox(30.0f, 1.0f));
    scene.bodies.push_back(ground);
    scene.named["ground"] = ground;

    i2d::BodyId box = w.createBody({.type = i2d::BodyType::dynamic_body, .position = {-3.0f, 4.0f}, .angle = 0.3f});
    w.createPolygonShape(box, {.density = 1.0f}, i2d::makeBox(1.0f, 1.0f));
    scene.bodies.push_back(box);

    i2d::BodyId ball = w.createBody({.type = i2d::BodyType::dynamic_body, .position = {3.0f, 6.0f}});
    w.createCircleShape(ball, {.density = 1.0f}, i2d::Circle{{0.0f, 0.0f}, 1.0f});
    scene.bodies.push_back(ball);
    return scene;
}

}  // namespace tbtest
