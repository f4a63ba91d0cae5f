// Continuous collision of fast bodies against static shapes.
//
// A body that moves further in one step than the speculative distance can end
// the step deep inside a static shape, or pass through a thin one: no contact
// exists at the step's start (the surface is beyond the speculative distance)
// and none at its end (the body is already through). After the solver has
// moved the bodies, each fast body's motion over the step is swept against
// the static shapes near its path; if it would touch one, the body is put
// back to the first time of impact along its sweep and keeps its velocity. The contact then
// exists at the next step's start, closer than the speculative distance, and
// the impact law and the solver stop the body at the surface. This is the
// dynamic-versus-static scheme of Box2D v3 (which sweeps only from half the
// body's thickness on; sweeping from the speculative distance also makes fast
// impacts happen at the surface); dynamic-versus-dynamic pairs are not swept
// (two fast bodies can still pass through each other).
//
// Time of impact by conservative advancement: with d(t) the distance between
// the two surfaces at time t ∈ [0, 1] of the step and B a bound on how fast
// any point of the moving shape travels (|Δc| + |Δθ|·r_max per step), d can
// shrink by at most B·Δt, so advancing t by (d − target)/B never steps past
// the first touch. Iterates until d is within the target band.
#include <algorithm>
#include <cmath>

#include "continuous.hpp"
#include "impulse2d/collision.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

// Pose of a body at time t ∈ [0, 1] of its sweep from (c0, angle0) by (dc, dAngle).
struct Sweep {
    Vec2 localCenter, c0, dc;
    float angle0 = 0.0f, dAngle = 0.0f;

    Transform at(float t) const {
        Transform xf;
        xf.q = makeRot(angle0 + t * dAngle);
        xf.p = c0 + t * dc - rotate(xf.q, localCenter);
        return xf;
    }
};

constexpr int kMaxAdvances = 30;

// First time t ∈ (0, 1) at which the moving core comes within `target` of
// the static core, or 1 when it does not within the step. A pair already
// within the target band at t = 0 touches or overlaps: its contact holds it,
// and sweeping it would stall a body sliding fast along the ground.
float timeOfImpact(const ShapeCore& moving, const Sweep& sweep, float bound, const ShapeCore& fixed,
                   const Transform& xfFixed, float target) {
    const float tolerance = 0.25f * kLinearSlop;
    const float radii = moving.radius + fixed.radius;
    float t = 0.0f;
    for (int i = 0; i < kMaxAdvances; ++i) {
        const DistanceResult r = shapeDistance(moving.points, moving.count, sweep.at(t), fixed.points, fixed.count,
                                               xfFixed);
        const float d = r.distance - radii;
        if (d <= target + tolerance) return i == 0 ? 1.0f : t;
        t += (d - target) / bound;
        if (t >= 1.0f) return 1.0f;
    }
    return t;  // still apart at t: stopping here is safe, if early
}

}  // namespace

void solveContinuous(WorldState& w) {
    const float target = kLinearSlop;
    for (std::size_t i = 0; i < w.solver.stateBodies.size(); ++i) {
        Body& body = w.bodies[w.solver.stateBodies[i]];
        if (body.type != BodyType::dynamic_body || body.reach < 0.0f) continue;
        const BodyState& s = w.solver.states[i];
        // |Δθ| ≤ (π/2)·|sin Δθ| while the turn is under a quarter: a bound
        // without atan2 for the many bodies that are not fast.
        const float turnBound = s.dq.c >= 0.0f ? 1.5707964f * std::abs(s.dq.s) : 3.1415927f;
        const float bound = length(s.dp) + turnBound * body.reach;
        // A body moving less than the speculative distance always meets a
        // surface through a contact made at the step's start. Beyond it, it
        // could end the step deep inside (or past) a static shape: swept.
        if (bound <= w.settings.speculativeDistance) continue;

        const float dAngle = angleOf(s.dq);
        Sweep sweep;
        sweep.localCenter = body.localCenter;
        sweep.c0 = body.center - s.dp;
        sweep.dc = s.dp;
        const float angle1 = angleOf(body.xf.q);
        sweep.dAngle = dAngle;
        sweep.angle0 = angle1 - dAngle;

        const Transform xf0 = sweep.at(0.0f), xf1 = body.xf;
        float tMin = 1.0f;
        for (int sh : bodyShapes(w.shapes, body)) {
            const Shape& shape = w.shapes[sh];
            if (shape.isSensor) continue;
            const ShapeCore core = shapeCore(shape);
            // The boxes at both ends, grown by how far the turn can carry a
            // point off the straight path between them (|Δθ|·r).
            AABB swept = unionOf(shapeAABB(shape, xf0), shapeAABB(shape, xf1));
            const float arc = turnBound * body.reach;
            swept.lower -= Vec2{arc, arc};
            swept.upper += Vec2{arc, arc};
            w.broadPhase.staticTree.query(swept, [&](int other) {
                const Shape& o = w.shapes[other];
                if (o.isSensor || !shouldCollide(shape.filter, o.filter)) return true;
                if (jointPreventsCollision(w, shape.body, o.body)) return true;
                const float t = timeOfImpact(core, sweep, bound, shapeCore(o), w.bodies[o.body].xf, target);
                tMin = std::min(tMin, t);
                return true;
            });
        }
        if (tMin < 1.0f) {
            const Transform xf = sweep.at(tMin);
            body.xf = xf;
            body.center = transformPoint(xf, body.localCenter);
        }
    }
}

}  // namespace i2d::detail
