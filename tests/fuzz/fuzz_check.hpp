// Shared by the fuzz targets: a property check that stops the run with a
// message (libFuzzer then saves the input as a crash artifact).
#pragma once

#include <cstdio>
#include <cstdlib>

#include <impulse2d/impulse2d.hpp>

#define I2D_FUZZ_CHECK(cond)                                                                                           \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            std::fprintf(stderr, "%s:%d: property violated: %s\n", __FILE__, __LINE__, #cond);                         \
            std::abort();                                                                                              \
        }                                                                                                              \
    } while (false)

namespace i2d::fuzz {

/// Every body of the world has a finite transform and finite velocities.
inline bool worldIsFinite(const World& world) {
    for (BodyId b : world.bodies()) {
        Transform xf = world.transform(b);
        if (!isFinite(xf.p) || !isFinite(xf.q.c) || !isFinite(xf.q.s)) return false;
        if (!isFinite(world.linearVelocity(b)) || !isFinite(world.angularVelocity(b))) return false;
    }
    return true;
}

}  // namespace i2d::fuzz
