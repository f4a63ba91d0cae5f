// Side-by-side timing and error of Impulse2D and Box2D 2.4.1 on the same
// scenes in the same run (issue: engine foundation, closing figures).
//
//   compare_box2d [--seconds S] [--base N] [--repeats R]
//
// pyramid: base N boxes of half-extent 0.5, friction 0.6, on a static ground,
// 60 Hz, sleeping off. Each engine runs S seconds, R times, interleaved; the
// report gives the median ms/step and the top box's drop and sideways drift
// at the end. static_field: one falling box alone, and the same box beside
// 10,000 static boxes (Impulse2D only: what a world pays for what it does
// not use).
#include <box2d/box2d.h>
#include <impulse2d/impulse2d.hpp>

#include "pyramid.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Result {
    double msPerStep = 0;  // mean over the run
    float drop = 0;        // top box: start height − end height (m)
    float drift = 0;       // top box: |x_end − x_start| (m)
    float maxSway = 0;     // top box: largest |x − x_start| during the run (m)
};

Result runImpulse(int base, int steps) {
    i2d::WorldSettings s;
    s.enableSleep = false;
    i2d::World world(s);
    const i2d::BodyId top = bench::buildPyramid(world, base, base * 1.0f + 10.0f);
    i2d::Vec2 p0 = world.position(top);
    Result r;
    auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) {
        world.step(1.0f / 60.0f);
        r.maxSway = std::max(r.maxSway, std::abs(world.position(top).x - p0.x));
    }
    r.msPerStep = std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / steps;
    i2d::Vec2 p = world.position(top);
    r.drop = p0.y - p.y;
    r.drift = std::abs(p.x - p0.x);
    return r;
}

Result runBox2D(int base, int steps, int velocityIterations, int positionIterations) {
    b2World world(b2Vec2(0.0f, -10.0f));
    world.SetAllowSleeping(false);
    b2Body* top = bench::buildPyramid(world, base, base * 1.0f + 10.0f);
    b2Vec2 p0 = top->GetPosition();
    Result r;
    auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) {
        world.Step(1.0f / 60.0f, velocityIterations, positionIterations);
        r.maxSway = std::max(r.maxSway, std::abs(top->GetPosition().x - p0.x));
    }
    r.msPerStep = std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / steps;
    b2Vec2 p = top->GetPosition();
    r.drop = p0.y - p.y;
    r.drift = std::abs(p.x - p0.x);
    return r;
}

double staticField(int staticCount, int steps) {
    i2d::World world;
    int side = 1;
    while (side * side < staticCount) ++side;
    int made = 0;
    for (int i = 0; i < side && made < staticCount; ++i) {
        for (int j = 0; j < side && made < staticCount; ++j, ++made) {
            i2d::BodyId b = world.createBody(
                {.position = {static_cast<float>(i) * 3.0f + 10.0f, static_cast<float>(j) * 3.0f}});
            world.createPolygonShape(b, {}, i2d::makeBox(0.5f, 0.5f));
        }
    }
    i2d::BodyId ground = world.createBody({});
    world.createPolygonShape(ground, {}, i2d::makeOffsetBox(5.0f, 0.5f, {0, -0.5f}, 0));
    i2d::BodyId body = world.createBody(
        {.type = i2d::BodyType::dynamic_body, .position = {0, 50.0f}, .enableSleep = false});
    world.createPolygonShape(body, {}, i2d::makeBox(0.5f, 0.5f));
    auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) world.step(1.0f / 60.0f);
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / steps;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    float seconds = 10.0f;
    int base = 100, repeats = 3;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--seconds"))
            seconds = std::strtof(argv[i + 1], nullptr);
        else if (!std::strcmp(argv[i], "--base"))
            base = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--repeats"))
            repeats = std::atoi(argv[i + 1]);
    }
    const int steps = static_cast<int>(seconds * 60.0f);
    std::vector<double> ti, tb;
    Result ri, rb;
    for (int k = 0; k < repeats; ++k) {
        std::fprintf(stderr, "\rpyramid base %d: run %d/%d", base, k + 1, repeats);
        ri = runImpulse(base, steps);
        rb = runBox2D(base, steps, 8, 3);
        ti.push_back(ri.msPerStep);
        tb.push_back(rb.msPerStep);
    }
    std::fprintf(stderr, "\n");
    double mi = median(ti), mb = median(tb);
    std::vector<double> alone, field;
    for (int k = 0; k < repeats; ++k) {
        alone.push_back(staticField(0, 600));
        field.push_back(staticField(10000, 600));
    }
    std::printf("{\"pyramid\":{\"base\":%d,\"boxes\":%d,\"seconds\":%.1f,\n", base, base * (base + 1) / 2, seconds);
    std::printf(" \"impulse2d\":{\"ms_per_step\":%.3f,\"top_drop\":%.4f,\"top_drift\":%.4f,\"top_max_sway\":%.4f},\n",
                mi, ri.drop, ri.drift, ri.maxSway);
    std::printf(" \"box2d_8_3\":{\"ms_per_step\":%.3f,\"top_drop\":%.4f,\"top_drift\":%.4f,\"top_max_sway\":%.4f},\n",
                mb, rb.drop, rb.drift, rb.maxSway);
    std::printf(" \"time_ratio\":%.3f},\n", mi / mb);
    double a = median(alone), f = median(field);
    std::printf("\"static_field\":{\"alone_ms\":%.5f,\"with_10000_static_ms\":%.5f,\"ratio\":%.2f}}\n", a, f, f / a);
    return 0;
}
