// Memory held by a simulation, per body and per touching contact, measured
// the same way for Impulse2D and Box2D 2.4.1 (used by sweep and
// memory_footprint).
#pragma once

#include <cstddef>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "scene.hpp"
#include "simulation.hpp"

namespace bench {

/// Columns of 10 boxes (1 m, touching) 1.5 m apart on one ground box: `count`
/// bodies in columns, resting, one contact per box below it.
inline tb::SceneDesc columnsScene(int count, bool touching) {
    tb::SceneDesc d;
    d.name = touching ? "columns" : "scattered";
    const int perColumn = 10;
    const int columns = (count + perColumn - 1) / perColumn;
    const float width = columns * 1.5f;
    tb::BodyDesc ground;
    ground.def.position = {0.5f * width, -1.0f};
    tb::ShapeDesc gs;
    gs.polygon = i2d::makeBox(0.5f * width + 5.0f, 1.0f);
    ground.shapes.push_back(gs);
    if (touching) d.bodies.push_back(ground);
    for (int i = 0; i < count; ++i) {
        tb::BodyDesc b;
        b.def.type = i2d::BodyType::dynamic_body;
        const int c = i / perColumn, r = i % perColumn;
        // Scattered: a sparse grid far above the ground, 3 m apart, nothing touches.
        b.def.position = touching ? i2d::Vec2{c * 1.5f, 0.5f + static_cast<float>(r)}
                                  : i2d::Vec2{c * 3.0f, 100.0f + 3.0f * static_cast<float>(r)};
        tb::ShapeDesc s;
        s.polygon = i2d::makeBox(0.5f, 0.5f);
        b.shapes.push_back(s);
        d.bodies.push_back(b);
    }
    if (!touching) d.settings.gravity = {0.0f, 0.0f};
    return d;
}

inline std::size_t heapInUse() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    // Heap chunks plus the large blocks glibc maps separately (its mmap
    // threshold moves at run time, so a big array may land in either).
    const struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
#else
    return 0;
#endif
}

/// Heap bytes held by a simulation of `desc` after `steps` steps.
inline std::size_t heldBytes(const tb::SceneDesc& desc, tb::EngineKind engine, int steps, int* contacts) {
    const std::size_t before = heapInUse();
    auto sim = tb::makeSimulation(desc, engine);
    for (int i = 0; i < steps; ++i) sim->step(desc.dt);
    const std::size_t after = heapInUse();
    if (contacts) *contacts = sim->touchingContactCount();
    return after > before ? after - before : 0;
}

}  // namespace bench
