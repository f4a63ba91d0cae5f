// Forces split around the drift for bodies that touch nothing
// (engine/src/split_kick.hpp): exact flight, and the moves of a velocity's
// meaning when a body starts or stops touching.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "world_fixtures.hpp"

using namespace i2d;

namespace {

constexpr float kG = 10.0f;  // the default gravity's magnitude (m/s²)

}  // namespace

// A body that touches nothing takes its gravity in two halves around each
// substep's drift: velocity Verlet, exact for a constant acceleration. A
// projectile's step-end positions lie on its parabola and its velocity is
// the true one, at 1 to 8 substeps. Bound: float rounding of |y| ≤ 15 m and
// |v| ≤ 20 m/s over at most 480 substeps of two half kicks each,
// N·ulp(16 m)/2 + 2·N·t·ulp(32 m/s)/2 with t = 1 s: 1e-3 m and 8e-3 m/s
// (the velocity's bound without the t, 2·N·ulp(32)/2).
TEST(SplitKick, AProjectileFliesItsParabolaAtEverySubstepCount) {
    for (int substeps : {1, 2, 3, 4, 8}) {
        WorldSettings s;
        s.enableSleep = false;
        s.substeps = substeps;
        World w(s);
        const Vec2 v0{3.0f, 12.0f};
        const BodyId ball = w.createBody(
            {.type = BodyType::dynamic_body, .position = {0.0f, 1.0f}, .linearVelocity = v0});
        w.createCircleShape(ball, {}, {{0.0f, 0.0f}, 0.25f});
        const double n = 60.0 * substeps;
        const double eps = 1.1920928955078125e-07;
        const double positionBound = n * eps * 16.0 + n * eps * 32.0;
        const double velocityBound = 2.0 * n * eps * 32.0;
        double worstY = 0.0, worstV = 0.0;
        for (int i = 1; i <= 60; ++i) {
            w.step(1.0f / 60.0f);
            const double t = i / 60.0;
            worstY = std::max(worstY, std::abs(w.position(ball).y - (1.0 + v0.y * t - 0.5 * kG * t * t)));
            worstV = std::max(worstV, std::abs(w.linearVelocity(ball).y - (v0.y - kG * t)));
        }
        EXPECT_LE(worstY, positionBound) << substeps << " substeps";
        EXPECT_LE(worstV, velocityBound) << substeps << " substeps";
    }
}

// A box at rest on a frictionless floor pushed up by a force for a few
// steps, then free. While it touches the floor it is integrated by
// semi-implicit Euler, whose velocity is exact under forces constant over
// each step and whose position runs ahead by (h/2)·(v − v₀); when it leaves
// the floor (its contact's speculative margin, maybe while still pushed)
// its velocity is moved by half a substep of gravity, not of the push. Moved
// by the push too (its whole free acceleration), the move outlived the push
// as momentum no force gave: pushed at 60·g for two steps, the box rose 56 %
// above its exact apex at one substep, 13 % at four. Bound: leaving at t_e
// with speed v_e, semi-implicit Euler's lead (h/2)·v_e raises the apex, and
// the move, −g·h/2 kept to the end of the push at T (speed v), lowers it by
// (g·h/2)·(T − t_e) + (h/2)·v; at most (h/2)·(v + g·T) either way.
TEST(SplitKick, ABoxPushedOffTheFloorRisesToItsApex) {
    struct Push {
        float times;  // the force over the weight
        int steps;
    };
    for (const Push push : {Push{3.0f, 10}, Push{60.0f, 2}, Push{1.5f, 30}})
        for (int substeps : {1, 2, 4}) {
            WorldSettings s;
            s.enableSleep = false;
            s.substeps = substeps;
            World w(s);
            test::makeGround(w, 50.0f, 0.0f);
            const BodyId box = test::makeBox(w, {0.0f, 0.5f}, 0.5f, 1.0f, 0.0f);
            for (int i = 0; i < 60; ++i) w.step(1.0f / 60.0f);
            const double y0 = w.position(box).y, m = w.mass(box);
            double apex = y0;
            for (int i = 0; i < 600; ++i) {
                if (i < push.steps) w.applyForceToCenter(box, {0.0f, push.times * static_cast<float>(m) * kG});
                w.step(1.0f / 60.0f);
                apex = std::max(apex, double(w.position(box).y));
            }
            // Exact for a force constant over each step: a = (k − 1)·g for T.
            const double a = (push.times - 1.0) * kG, T = push.steps / 60.0, v = a * T;
            const double exact = 0.5 * a * T * T + v * v / (2.0 * kG);
            const double h = 1.0 / 60.0 / substeps;
            std::printf("[figure] pushed at %.1f g for %d steps, %d substeps: apex %.4f m against %.4f\n",
                        double(push.times), push.steps, substeps, apex - y0, exact);
            EXPECT_NEAR(apex - y0, exact, 0.5 * h * (v + kG * T))
                << push.times << " g for " << push.steps << " steps, " << substeps << " substeps";
        }
}
