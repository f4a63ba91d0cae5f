// Fuzz target: the scene loader on arbitrary text. A file is either refused
// with tb::SceneError naming the file (never another exception, never a
// crash) or it builds a world that steps with finite state.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "scene_build.hpp"
#include "scene_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    tb::SceneDesc desc;
    try {
        desc = tb::parseSceneDesc(text, "fuzz.json", "fuzz");
    } catch (const tb::SceneError& e) {
        I2D_FUZZ_CHECK(std::string(e.what()).rfind("fuzz.json: ", 0) == 0);
        return 0;
    }
    // Building and stepping is what a player's level file would do next.
    // Large generated scenes are valid but slow: keep each input fast.
    if (desc.bodies.size() > 400) return 0;
    tb::Scene scene;
    try {
        scene = tb::buildScene(desc);
    } catch (const tb::SceneError& e) {
        I2D_FUZZ_CHECK(std::string(e.what()).rfind("fuzz.json: ", 0) == 0);
        return 0;
    }
    for (int i = 0; i < 30; ++i) scene.world->step(desc.dt);
    I2D_FUZZ_CHECK(i2d::fuzz::worldIsFinite(*scene.world));
    return 0;
}
