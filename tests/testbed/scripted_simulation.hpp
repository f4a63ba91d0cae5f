// A tb::Simulation whose body states the test writes (the trajectory is
// scripted), for testing what the testbed measures from a run.
#pragma once

#include <cstddef>
#include <vector>

#include "simulation.hpp"

namespace tb::test {

class ScriptedSimulation : public Simulation {
public:
    std::vector<BodySample> bodies;

    EngineKind engine() const override { return EngineKind::impulse2d; }
    void step(float) override {}
    int bodyCount() const override { return static_cast<int>(bodies.size()); }
    BodySample sample(int i) const override { return bodies[static_cast<std::size_t>(i)]; }
    void driveX(int i, float vx) override { bodies[static_cast<std::size_t>(i)].vx = vx; }
    int jointCount() const override { return 0; }
    int touchingContactCount() const override { return 0; }
    float maxPenetration() const override { return 0.0f; }

    /// Puts body i at (x, y) (origin and centre of mass) with velocity (vx, vy).
    void place(int i, float x, float y, float vx = 0.0f, float vy = 0.0f) {
        BodySample& s = bodies[static_cast<std::size_t>(i)];
        s.x = s.cx = x;
        s.y = s.cy = y;
        s.vx = vx;
        s.vy = vy;
    }
};

}  // namespace tb::test
