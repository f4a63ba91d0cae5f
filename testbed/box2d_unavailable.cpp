// Testbed — stand-in when the testbed is built without Box2D 2.4.1.
#include "simulation.hpp"

namespace tb {

bool box2dAvailable() { return false; }

std::unique_ptr<Simulation> makeBox2DSimulation(const SceneDesc&, const Box2DSettings&) {
    throw SceneError(
        "this testbed was built without the Box2D 2.4.1 backend (libbox2d-dev not found at configure time)");
}

}  // namespace tb
