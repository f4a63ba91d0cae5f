// Testbed — did anything tunnel or snag? Measured the same way in every
// engine, from the scene description and the bodies' samples only.
//
// tunnelled  a dynamic body whose centre of mass went through a static
//            solid shape (entered it through one face and left it through a
//            face turned the other way, in one step or several) or crossed a
//            static segment and got more than kBeyond past its line (a chain
//            segment only from its colliding side); a bullet also counts when
//            it went through a dynamic body that is not a bullet (its path
//            taken in that body's frame, before and after each step). A
//            centre that sinks into a shape and comes back out the way it
//            went in (a thin card resting on the ground, 2 mm thick) is
//            penetration, not tunnelling. Shapes that do not collide
//            (filters, sensors, a joint between the two bodies) are skipped.
// snagged    a driven body (BodyDesc::driveSpeed) whose horizontal speed after
//            a step (from the 6th on: the first settle the placement) was
//            below half its drive speed: something caught it.
// The largest vertical speed of the driven bodies after the 5th step is
// kept too (a seam kicking them up).
#pragma once

#include <vector>

#include "scene.hpp"
#include "simulation.hpp"

namespace tb {

class CrossingCheck {
public:
    explicit CrossingCheck(const SceneDesc& desc);

    /// Before the first step.
    void start(const Simulation& sim);
    /// After each step.
    void observe(const Simulation& sim);

    int tunnelled() const { return tunnelledCount_; }
    int snagged() const { return snaggedCount_; }
    int driven() const { return static_cast<int>(driven_.size()); }
    float drivenMaxVerticalSpeed() const { return drivenMaxVy_; }

    /// How far past a segment's line a centre must get to have tunnelled (m):
    /// the speculative distance, beyond any resting penetration.
    static constexpr float kBeyond = 0.02f;

    /// A centre inside a solid shape, or past a segment, since an earlier step.
    struct Inside {
        int mover = -1, body = -1, shape = -1;
        i2d::Vec2 entryNormal{};  ///< outward normal where it entered, in the shape's body frame
        int segment = -1;         ///< the segment crossed (a chain's index; 0 for a segment shape), -1 for a solid
    };

private:
    /// Whether the centre's path, a → b in the shape's body frame, completes
    /// a passage through shape `k` of `body` (updating the insides).
    bool passes(int mover, int body, int k, i2d::Vec2 a, i2d::Vec2 b);

    const SceneDesc& desc_;
    std::vector<Inside> insides_;
    std::vector<BodySample> previous_;
    std::vector<char> tunnelledBody_, snaggedBody_;
    std::vector<int> statics_, bullets_, driven_;
    long steps_ = 0;
    int tunnelledCount_ = 0, snaggedCount_ = 0;
    float drivenMaxVy_ = 0.0f;
};

}  // namespace tb
