// The per-step cost of continuous collision, Impulse2D against Box2D 2.4.1
// in the same run (issue #14).
//
//   ccd_cost [--bodies N] [--seconds S] [--repeats R]
//
// An arena of four static walls 0.1 m thick (40 × 40 m, inside thick outer
// blocks so that nothing escapes even without continuous collision), with N
// small dynamic bodies (circles, boxes and capsules-as-Box2D-boxes of
// 0.1-0.2 m) flying at 50-300 m/s, spinning up to 100 rad/s, restitution 1,
// no gravity: every body is fast in every step. Each engine runs the same
// bodies, interleaved, R times. The cost of continuous collision per step is
// the time of the stage as each engine profiles it (Impulse2D:
// Profile::sweeps; Box2D 2.4.1: b2Profile::solveTOI), median over the runs,
// and its ratio between the engines is printed; the step time with
// continuous collision off is given too, but the runs then differ (bodies
// sink into the outer blocks), so it is no measure of the stage. A second
// case makes every body a bullet (swept against the other bodies too, in
// both engines), and a third has the bodies at rest, apart (nothing fast:
// what the stage costs when it has nothing to do).
#include <box2d/box2d.h>
#include <impulse2d/impulse2d.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Shot {
    float x, y, vx, vy, w, angle, size;
    int kind;  // 0 circle, 1 box
};

std::vector<Shot> makeShots(int n, bool resting) {
    std::mt19937 rng(12345);
    auto u = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
    std::vector<Shot> shots;
    for (int i = 0; i < n; ++i) {
        Shot s{};
        s.size = u(0.1f, 0.2f);
        s.kind = i % 2;
        if (resting) {  // a grid 1.8 m apart, 20 to a row: nothing touches
            s.x = -18.0f + 1.8f * static_cast<float>(i % 20);
            s.y = -18.0f + 1.8f * static_cast<float>(i / 20);
        } else {
            s.x = u(-18.0f, 18.0f);
            s.y = u(-18.0f, 18.0f);
            const float speed = u(50.0f, 300.0f), dir = u(0.0f, 6.2831853f);
            s.vx = speed * std::cos(dir);
            s.vy = speed * std::sin(dir);
            s.w = u(-100.0f, 100.0f);
            s.angle = u(-3.14f, 3.14f);
        }
        shots.push_back(s);
    }
    return shots;
}

// Walls: inner faces at ±20 m, 0.1 m thin walls backed by 10 m blocks 1 m behind.
struct Wall {
    float cx, cy, hx, hy;
};
std::vector<Wall> walls() {
    return {
        {0, -20.05f, 20.1f, 0.05f}, {0, 20.05f, 20.1f, 0.05f}, {-20.05f, 0, 0.05f, 20.1f}, {20.05f, 0, 0.05f, 20.1f},
        {0, -36, 40, 15},           {0, 36, 40, 15},           {-36, 0, 15, 40},           {36, 0, 15, 40}};
}

struct Timing {
    double step = 0;  ///< ms per step
    double ccd = 0;   ///< ms per step in the continuous stage (Impulse2D: Profile::sweeps; Box2D: solveTOI)
};

Timing runImpulse(const std::vector<Shot>& shots, bool continuous, bool bullets, int steps) {
    i2d::WorldSettings s;
    s.gravity = {0, 0};
    s.enableSleep = false;
    s.enableContinuous = continuous;
    i2d::World world(s);
    i2d::BodyId ground = world.createBody({});
    for (const Wall& w : walls())
        world.createPolygonShape(ground, {.restitution = 1.0f}, i2d::makeOffsetBox(w.hx, w.hy, {w.cx, w.cy}, 0));
    for (const Shot& sh : shots) {
        i2d::BodyId b = world.createBody({.type = i2d::BodyType::dynamic_body,
                                          .position = {sh.x, sh.y},
                                          .angle = sh.angle,
                                          .linearVelocity = {sh.vx, sh.vy},
                                          .angularVelocity = sh.w,
                                          .isBullet = bullets});
        if (sh.kind == 0)
            world.createCircleShape(b, {.restitution = 1.0f}, {{0, 0}, sh.size});
        else
            world.createPolygonShape(b, {.restitution = 1.0f}, i2d::makeBox(sh.size, sh.size));
    }
    Timing t;
    auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) {
        world.step(1.0f / 60.0f);
        t.ccd += world.profile().sweeps;
    }
    t.step = std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / steps;
    t.ccd /= steps;
    return t;
}

Timing runBox2D(const std::vector<Shot>& shots, bool continuous, bool bullets, int steps) {
    b2World world(b2Vec2(0, 0));
    world.SetAllowSleeping(false);
    world.SetContinuousPhysics(continuous);
    b2BodyDef gd;
    b2Body* ground = world.CreateBody(&gd);
    for (const Wall& w : walls()) {
        b2PolygonShape p;
        p.SetAsBox(w.hx, w.hy, b2Vec2(w.cx, w.cy), 0);
        b2FixtureDef fd;
        fd.shape = &p;
        fd.restitution = 1.0f;
        ground->CreateFixture(&fd);
    }
    for (const Shot& sh : shots) {
        b2BodyDef bd;
        bd.type = b2_dynamicBody;
        bd.position.Set(sh.x, sh.y);
        bd.angle = sh.angle;
        bd.linearVelocity.Set(sh.vx, sh.vy);
        bd.angularVelocity = sh.w;
        bd.bullet = bullets;
        b2Body* b = world.CreateBody(&bd);
        b2FixtureDef fd;
        fd.restitution = 1.0f;
        fd.density = 1.0f;
        b2CircleShape c;
        b2PolygonShape p;
        if (sh.kind == 0) {
            c.m_radius = sh.size;
            fd.shape = &c;
        } else {
            p.SetAsBox(sh.size, sh.size);
            fd.shape = &p;
        }
        b->CreateFixture(&fd);
    }
    Timing t;
    auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) {
        world.Step(1.0f / 60.0f, 8, 3);
        t.ccd += world.GetProfile().solveTOI;
    }
    t.step = std::chrono::duration<double, std::milli>(Clock::now() - t0).count() / steps;
    t.ccd /= steps;
    return t;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

void runCase(const char* name, const std::vector<Shot>& shots, bool bullets, int steps, int repeats, bool last) {
    std::vector<double> istep, iccd, ioff, bstep, bccd, boff;
    for (int k = 0; k < repeats; ++k) {
        std::fprintf(stderr, "\r%s: run %d/%d   ", name, k + 1, repeats);
        const Timing i = runImpulse(shots, true, bullets, steps), b = runBox2D(shots, true, bullets, steps);
        istep.push_back(i.step);
        iccd.push_back(i.ccd);
        bstep.push_back(b.step);
        bccd.push_back(b.ccd);
        ioff.push_back(runImpulse(shots, false, bullets, steps).step);
        boff.push_back(runBox2D(shots, false, bullets, steps).step);
    }
    std::fprintf(stderr, "\n");
    const double is = median(istep), ic = median(iccd), bs = median(bstep), bc = median(bccd);
    std::printf(
        " \"%s\":{\"bodies\":%zu,\"impulse2d\":{\"ms_per_step\":%.4f,\"ccd_ms_per_step\":%.4f,\"ccd_share\":%.3f,"
        "\"ms_per_step_without\":%.4f},\"box2d_8_3\":{\"ms_per_step\":%.4f,\"ccd_ms_per_step\":%.4f,\"ccd_share\":%.3f,"
        "\"ms_per_step_without\":%.4f},\"ccd_ratio\":%.2f,\"step_ratio\":%.2f}%s\n",
        name, shots.size(), is, ic, ic / is, median(ioff), bs, bc, bc / bs, median(boff), bc > 0 ? ic / bc : 0.0,
        is / bs, last ? "" : ",");
}

}  // namespace

int main(int argc, char** argv) {
    int bodies = 200, repeats = 3;
    float seconds = 5.0f;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--bodies"))
            bodies = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--seconds"))
            seconds = std::strtof(argv[i + 1], nullptr);
        else if (!std::strcmp(argv[i], "--repeats"))
            repeats = std::atoi(argv[i + 1]);
    }
    const int steps = static_cast<int>(seconds * 60.0f);
    std::printf("{\n");
    runCase("fast", makeShots(bodies, false), false, steps, repeats, false);
    runCase("fast_bullets", makeShots(bodies, false), true, steps, repeats, false);
    runCase("resting", makeShots(bodies, true), false, steps, repeats, true);
    std::printf("}\n");
    return 0;
}
