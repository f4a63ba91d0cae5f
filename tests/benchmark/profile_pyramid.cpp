// A driver for instruction-count profiles of pyramid steps (callgrind):
//
//   valgrind --tool=callgrind --collect-atstart=no profile_pyramid [--base N] [--warmup W] [--steps S]
//
// builds the pyramid of compare_box2d (base N, 60 Hz, sleeping off), runs W
// steps uninstrumented (settling, pair creation) and then S steps with
// callgrind's instrumentation on, so the counts are of steady-state steps.
// Outside valgrind the instrumentation macros do nothing and the program
// prints the top box's figures, which makes it a quick check as well.
#include <impulse2d/impulse2d.hpp>

#include "pyramid.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(I2D_HAVE_CALLGRIND)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#endif

int main(int argc, char** argv) {
    int base = 100, warmup = 30, steps = 10;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--base"))
            base = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--warmup"))
            warmup = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--steps"))
            steps = std::atoi(argv[i + 1]);
    }
    i2d::WorldSettings s;
    s.enableSleep = false;
    i2d::World world(s);
    const i2d::BodyId top = bench::buildPyramid(world, base, base * 1.0f + 10.0f);
    const i2d::Vec2 p0 = world.position(top);
    for (int i = 0; i < warmup; ++i) world.step(1.0f / 60.0f);
    CALLGRIND_START_INSTRUMENTATION;
    for (int i = 0; i < steps; ++i) world.step(1.0f / 60.0f);
    CALLGRIND_STOP_INSTRUMENTATION;
    const i2d::Vec2 p = world.position(top);
    std::printf("{\"base\":%d,\"steps\":%d,\"top_drop\":%.4f,\"top_dx\":%.4f}\n", base, warmup + steps, p0.y - p.y,
                p.x - p0.x);
    return 0;
}
