// Testbed — instantiating a tb::SceneDesc as an Impulse2D world.
#pragma once

#include "scene.hpp"

namespace tb {

/// Build the world of a scene: bodies in order (Scene::bodies[i] is
/// desc.bodies[i]), their shapes, then the joints. Named bodies are listed in
/// Scene::named. An engine refusal (i2d::Error) is reported as SceneError
/// naming the file and the body, shape or joint index.
Scene buildScene(const SceneDesc& desc);

}  // namespace tb
