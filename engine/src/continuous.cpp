// Continuous collision of fast bodies.
//
// A body that moves further in one step than the speculative distance can end
// the step deep inside a static shape, or pass through a thin one: no contact
// exists at the step's start (the surface is beyond the speculative distance)
// and none at its end (the body is already through). After the solver has
// moved the bodies, each fast body's motion over the step is swept against
// the static shapes near its path; if it would touch one, the body is put
// back to the first time of impact along its sweep and keeps its velocity.
// The contact then exists at the next step's start, closer than the
// speculative distance, and the impact law and the solver stop the body at
// the surface. Kinematic bodies' shapes are swept against as well, along the
// body's motion relative to them (relativeTo), as Box2D 2.4.1 does. Bullets
// (BodyDef::isBullet) are swept afterwards, against the static and kinematic
// shapes and against the dynamic bodies that are not bullets, at the poses
// those have reached (so a bullet cannot pass a thin moving plank). Two fast
// non-bullet bodies can still pass through each other.
//
// A shape that already touches a surface when the step begins (within the
// target band of the sweep at t = 0) cannot be swept against it: the first
// time of impact is 0, and putting the body back there would stall a body
// sliding fast along the ground. Skipping the pair instead, as this stage
// once did, let a body that touched a wall in one step go through it in the
// next (a rotated or spinning box whose contact did not stop it). Such a pair
// is probed instead: the chord of the shape's centroid over the step is cast
// against the other shape, and if the centroid would enter it the body stops
// with its centroid its smallest extent short of the surface, and the
// centroid's approach speed is taken out. A body sliding along a surface, or
// onto the next tile of a floor, never has its centroid enter it; a body
// driving into a wall keeps its centroid in front, from where the contact
// pushes it back out on the side it came from. Box2D v3 has the same need
// and falls back to sweeping a small disc around the fast shape's centroid
// (Catto, 2025, Box2D v3.1, solver.c, the continuous query); the chord cast
// and the removal of the approach speed are this engine's.
//
// A hit is ignored when the shape only reaches the other one along its
// surface (onto the next segment of a floor: its centroid does not enter the
// other shape, it moves towards it by no more than the slop and ends the step
// overlapping it by no more than the speculative distance); stopping there
// stalled sliding bodies at every joint.
//
// A body put back to time t of the step (t ∈ [0, 1]) is given the velocity
// it had then, v − (1 − t)·Δt·a with a its free acceleration (gravity,
// force): keeping the velocity of the step's end gave it the speed gained
// over the rest of the step, which it never fell. A ball dropped from 5 m
// with e = 0.75 swept to the ground at 7.62 m/s instead of 7.50 came back
// 4 % too high, and 6 % after two more bounces.
//
// The sweep runs from the body's pose at the step's start: before the
// solver's motion, or before the impact stage's time-of-impact shift when
// that moved the body (StepStart, body.hpp), so no part of the step's motion
// escapes it.
//
// Time of impact by conservative advancement (Mirtich, 1996, Impulse-based
// dynamic simulation of rigid body systems; Catto, 2025, Box2D v3.1,
// b2TimeOfImpact): with d(t) the distance between the two surfaces at time
// t ∈ [0, 1] of the step and B a bound on how far any point of the moving
// shape travels relative to the other over the step (|Δc| + |Δθ|·r_max),
// d can shrink by at most B·Δt, so advancing t by (d − target)/B never steps
// past the first touch.
#include <algorithm>
#include <cmath>
#include <vector>

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

/// What a sweep of one shape against one other found.
struct Impact {
    float t = 1.0f;               ///< first time of impact, 1 when none within the step
    bool startsTouching = false;  ///< within the target band at t = 0
    Vec2 normal{};                ///< at t, from the other core towards the moving one
};

// First time t ∈ (0, 1) at which the moving core comes within `target` of
// the other core (at its end-of-step pose), or 1 when it does not within the
// step. `bound` is how far any point of the moving core can travel in the step.
Impact timeOfImpact(const ShapeCore& moving, const Sweep& sweep, float bound, const ShapeCore& other,
                    const Transform& xfOther, float target) {
    const float tolerance = std::min(0.25f * kLinearSlop, 0.25f * target);
    const float radii = moving.radius + other.radius;
    float t = 0.0f;
    for (int i = 0; i < kMaxAdvances; ++i) {
        const DistanceResult r = shapeDistance(moving.points, moving.count, sweep.at(t), other.points, other.count,
                                               xfOther);
        const float d = r.distance - radii;
        if (d <= target + tolerance)
            return i == 0 ? Impact{1.0f, true, {}} : Impact{t, false, normalize(r.pointA - r.pointB)};
        t += (d - target) / bound;
        if (t >= 1.0f) return {};
    }
    return {t, false, {}};  // still apart at t: stopping here is safe, if early
}

/// The centroid of a shape (its centre of mass; a segment's midpoint) and
/// the smallest distance from it to the shape's surface.
struct Centroid {
    Vec2 point{};
    float extent = 0.0f;
};

Centroid centroidOf(const Shape& shape, const ShapeCore& core) {
    Centroid c;
    if (const std::optional<MassData> md = shapeMass(shape)) {
        c.point = md->center;  // of the rounded shape, where a polygon's centroid is its core's
    } else {
        for (int i = 0; i < core.count; ++i) c.point += core.points[i];
        c.point *= 1.0f / static_cast<float>(core.count);
    }
    c.extent = core.radius;
    if (core.count >= 3) {
        // Polygon (counter-clockwise): the nearest edge's line.
        float nearest = INFINITY;
        for (int i = 0; i < core.count; ++i) {
            const Vec2 a = core.points[i], e = core.points[(i + 1) % core.count] - a;
            const float len = length(e);
            if (len > 0.0f) nearest = std::min(nearest, cross(e, c.point - a) / len);
        }
        if (isFinite(nearest)) c.extent += std::max(nearest, 0.0f);
    }
    return c;
}

struct Mover {
    Sweep sweep;
    float bound = 0.0f;      ///< how far any core point can travel in the step (m)
    float turnBound = 0.0f;  ///< |Δθ| bound (rad)
};

/// Whether some point of the body moved at least the speculative distance,
/// in the solver or in the impact stage's shift: one that moved less met
/// every surface it could reach through a contact made at the step's start
/// (a landing box whose impact shifted it onto the ground is not swept).
bool movedBeyondContacts(const WorldState& w, const Body& body, const BodyState& s) {
    const float spec = w.settings.speculativeDistance;
    const StepStart* start = w.shiftedStart(body);
    const Rot shift = start != nullptr ? invMulRot(start->q, invMulRot(s.dq, body.xf.q)) : Rot{};
    const float solverBound = length(s.dp) + turnBoundOf(s.dq) * body.reach;
    const float shiftBound = start != nullptr
                                 ? length((body.center - s.dp) - start->center) + turnBoundOf(shift) * body.reach
                                 : 0.0f;
    return !(solverBound <= spec && shiftBound <= spec);
}

/// Where a body's sweep starts: its pose at the step's start, before the
/// solver's motion (dp, dq), and before the impact stage's shift when that
/// moved the body; and its turn since.
struct SweepStart {
    Vec2 center;
    Rot rotation;
    Rot turn;
};

SweepStart sweepStartOf(const WorldState& w, const Body& body, const BodyState& s) {
    if (const StepStart* start = w.shiftedStart(body)) return {start->center, start->q, invMulRot(start->q, body.xf.q)};
    return {body.center - s.dp, invMulRot(s.dq, body.xf.q), s.dq};
}

/// The motion of an awake body over the step, or false when every point of
/// it moved less than the speculative distance (a surface it could reach was
/// then within the speculative distance at the step's start and has a
/// contact), unless it is `pressed` deep into a static or kinematic shape
/// (markPressedBodies).
bool makeMover(const WorldState& w, const Body& body, const BodyState& s, Mover& m, bool pressed) {
    if (!pressed && !movedBeyondContacts(w, body, s)) return false;
    const SweepStart start = sweepStartOf(w, body, s);
    const Vec2 c0 = start.center;
    const Rot dq = start.turn;
    const Vec2 dc = body.center - c0;
    m.turnBound = turnBoundOf(dq);
    m.bound = length(dc) + m.turnBound * body.reach;
    const float dAngle = angleOf(dq);
    m.sweep.localCenter = body.localCenter;
    m.sweep.c0 = c0;
    m.sweep.dc = dc;
    m.sweep.dAngle = dAngle;
    m.sweep.angle0 = angleOf(body.xf.q) - dAngle;
    return true;
}

/// True when `point` lies behind a chain segment (on its left side).
bool behindChain(const Shape& chain, const Transform& xf, Vec2 point) {
    const Vec2 p1 = transformPoint(xf, chain.geometry.segment.point1);
    const Vec2 p2 = transformPoint(xf, chain.geometry.segment.point2);
    return cross(p2 - p1, point - p1) > 0.0f;
}

/// Where a body's sweep stops.
struct Stop {
    float t = 1.0f;
    bool byProbe = false;  ///< a probe of a shape touching a static or kinematic surface at the step's start
    Vec2 normal{};         ///< the surface's normal at t, from the other shape towards the moving one
    /// The probe found the centroid already nearer the surface than its
    /// extent at the step's start (t = 0): the body is not put back, only
    /// its centroid's approach along the normal is taken out (sweepBody).
    bool holdApproach = false;
    /// The sweep the stop lies on: the body's own, or its motion relative to
    /// a kinematic body (relativeTo), whose pose at t is where the body ends
    /// the step, carried along by the kinematic body from t on.
    Sweep sweep{};
    Vec2 surfaceVelocity{};  ///< the other body's velocity at the body's centre (zero for a static one)
};

/// Where a point's chord over the step, from p0 to p1, enters the other
/// shape: the fraction along it and the distance covered along the
/// surface's normal over the whole step.
struct Entry {
    float fraction = 1.0f;
    float across = 0.0f;
    Vec2 normal{};  ///< world
};

std::optional<Entry> chordEntry(Vec2 p0, Vec2 p1, const Shape& other, const Transform& xfOther) {
    RayCastInput ray;
    ray.origin = invTransformPoint(xfOther, p0);
    ray.translation = invRotate(xfOther.q, p1 - p0);
    const std::optional<RayHit> hit = shapeRayCast(other, ray);
    if (!hit) return std::nullopt;
    // A chord that starts on a segment's line does not enter it from either
    // side: a body created with its centroid exactly on a thin static
    // segment was stopped at the start of every step, whichever way its
    // contact pushed it, and hung there half inside for good.
    if (other.type == ShapeType::segment && !(hit->fraction > 0.0f)) return std::nullopt;
    return Entry{hit->fraction, std::abs(dot(ray.translation, hit->normal)), rotate(xfOther.q, hit->normal)};
}

/// Whether the chord from p0 to p1 crosses a segment's line from one side to
/// the other within `reach` of the segment (past its ends too): a centroid
/// doing so takes its shape across the segment or onto its end. The ray cast
/// of chordEntry can miss a chord through the very end of a segment: a
/// circle shot within 10⁻⁶ m of the vertex two static segments share (or a
/// chain's) missed both, ended the step beyond them touching neither, and
/// the sweep took that for a graze and let it through (6 and 23 to 25 of
/// 4,785 aims, a chain's and two segments').
bool crossesSegment(Vec2 p0, Vec2 p1, const Shape& segment, const Transform& xf, float reach) {
    const Vec2 s1 = transformPoint(xf, segment.geometry.segment.point1);
    const Vec2 e = transformPoint(xf, segment.geometry.segment.point2) - s1;
    const float len = length(e);
    if (!(len > 0.0f)) return false;
    const float d0 = cross(e, p0 - s1), d1 = cross(e, p1 - s1);
    if (!((d0 > 0.0f && d1 < 0.0f) || (d0 < 0.0f && d1 > 0.0f))) return false;
    const Vec2 at = p0 + (d0 / (d0 - d1)) * (p1 - p0);
    const float along = dot(at - s1, e) / len;
    return along >= -reach && along <= len + reach;
}

/// A hit that needs no stop: the shape reaches the other one along its
/// surface (onto the next segment of a floor, the next tile) rather than
/// into it. Its centroid's chord does not enter the other shape, it moved
/// towards it by no more than the slop, and at the step's end it overlaps it
/// by no more than the speculative distance, which the contact made at the
/// next step's start resolves. Stopping such a body
/// at the first touch stalled it at every joint of a floor it slid along.
/// (Box2D v3 skips fast motion parallel to a chain segment the same way:
/// Catto, 2025, Box2D v3.1, solver.c.)
bool grazes(const Shape& shape, const ShapeCore& core, const Mover& m, const Shape& other, const ShapeCore& otherCore,
            const Transform& xfOther, float speculativeDistance) {
    const Centroid c = centroidOf(shape, core);
    const Transform xf1 = m.sweep.at(1.0f);
    const Vec2 p0 = transformPoint(m.sweep.at(0.0f), c.point), p1 = transformPoint(xf1, c.point);
    if (chordEntry(p0, p1, other, xfOther)) return false;
    if (other.type == ShapeType::segment && crossesSegment(p0, p1, other, xfOther, c.extent)) return false;
    const Manifold end = collideShapes(shape, xf1, other, xfOther, 0.0f);
    // Along the surface: the step's motion towards it (the normal points
    // from the moving shape to the other) is within the slop, beyond the gap
    // the shape had from it when the step began (which its contact, made
    // then, let it close). A ball rolling at 20 m/s with a hop of 6 mm over
    // the ground closed that gap and was put back to the start of its step,
    // 33 cm behind, where a kinematic wall pushing it then passed over it.
    const DistanceResult start = shapeDistance(core.points, core.count, m.sweep.at(0.0f), otherCore.points,
                                               otherCore.count, xfOther);
    const float gap = std::max(start.distance - core.radius - otherCore.radius, 0.0f);
    if (end.pointCount > 0 && dot(m.sweep.dc, end.normal) > kLinearSlop + gap) return false;
    for (int i = 0; i < end.pointCount; ++i)
        if (end.points[i].separation < -speculativeDistance) return false;
    return true;
}

/// The shape's centroid must not enter the other shape. Its chord over the
/// step (its exact path for a body of one shape, whose centroid is the
/// centre of mass) is cast against the other shape; on a hit the body stops
/// with its centroid its smallest extent before the surface along the
/// normal (or at the start, if it is nearer), so the contact pushes it back
/// on the side it came from. A body sliding along the surface, or across to
/// the next tile of a floor, never has its centroid enter it.
void probeCentroid(const Shape& shape, const ShapeCore& core, const Mover& m, const Shape& other,
                   const Transform& xfOther, Stop& stop) {
    const Centroid c = centroidOf(shape, core);
    const std::optional<Entry> e = chordEntry(transformPoint(m.sweep.at(0.0f), c.point),
                                              transformPoint(m.sweep.at(1.0f), c.point), other, xfOther);
    if (!e) return;
    const float t = e->across > 0.0f ? std::max(0.0f, e->fraction - c.extent / e->across) : 0.0f;
    if (t < stop.t) stop = {t, true, e->normal, t <= 0.0f};
}

/// Sweeps one shape of the moving body against one other shape; moves the stop earlier.
void sweepPair(const Shape& shape, const ShapeCore& core, const Mover& m, const Shape& other, const Transform& xfOther,
               float speculativeDistance, Stop& stop) {
    const ShapeCore otherCore = shapeCore(other);
    const Impact hit = timeOfImpact(core, m.sweep, m.bound, otherCore, xfOther, kLinearSlop);
    if (!hit.startsTouching) {
        if (hit.t < stop.t && !grazes(shape, core, m, other, otherCore, xfOther, speculativeDistance))
            stop = {hit.t, false, hit.normal};
        return;
    }
    // Already touching: the contact keeps the part that touches; the body's
    // centroid is kept from entering the other shape.
    probeCentroid(shape, core, m, other, xfOther, stop);
}

/// The body's state this step (after the write-back, which clears
/// Body::solverIndex), or kNullIndex for a body without one.
int stateIndexOf(const SolverArrays& s, int body) {
    const auto slot = static_cast<std::size_t>(body);
    const int i = slot < s.rowBodies.size() ? s.rowBodies[slot].state : kNullIndex;
    return i >= 0 && static_cast<std::size_t>(i) < s.stateBodies.size() &&
                   s.stateBodies[static_cast<std::size_t>(i)] == body
               ? i
               : kNullIndex;
}

/// Where a kinematic body was when the step began: its state's motion over
/// the step taken back; one without a state this step (asleep) did not move.
Transform kinematicStart(const WorldState& w, int body) {
    const Body& k = w.bodies[body];
    const int i = stateIndexOf(w.solver, body);
    if (i == kNullIndex) return k.xf;
    const BodyState& st = w.solver.states[static_cast<std::size_t>(i)];
    const Rot q0 = invMulRot(st.dq, k.xf.q);
    return {(k.center - st.dp) - rotate(q0, k.localCenter), q0};
}

/// The body's motion relative to a kinematic body that moved from k0 to k1
/// over the step, seen where the kinematic body ends it: the sweep runs from
/// the body's start carried along by the kinematic body's motion
/// (k1·k0⁻¹·start) to its end as it is. Against the kinematic body at k1 it
/// meets what the two motions meet, exactly when the kinematic body only
/// translates and along the straight relative path when it turns (the
/// relative path of a point then bends with the turn; within a step of a
/// drum turning 0.2 rad the two differ by r·0.005 at most). The body stopped
/// at t on it ends the step where it was relative to the kinematic body at
/// t: a body struck by a moving wall goes on with the wall. (Box2D 2.4.1
/// also sweeps dynamic bodies against kinematic ones: Catto, 2020, Box2D
/// 2.4.1, b2World::SolveTOI.)
Mover relativeTo(const Mover& m, const Body& body, const Transform& k0, const Transform& k1) {
    const Transform carried = mulTransforms(k1, invMulTransforms(k0, m.sweep.at(0.0f)));
    const float kTurn = angleOf(invMulRot(k0.q, k1.q));
    Mover r;
    r.sweep.localCenter = m.sweep.localCenter;
    r.sweep.c0 = transformPoint(carried, m.sweep.localCenter);
    r.sweep.dc = (m.sweep.c0 + m.sweep.dc) - r.sweep.c0;
    r.sweep.angle0 = m.sweep.angle0 + kTurn;
    r.sweep.dAngle = m.sweep.dAngle - kTurn;
    r.turnBound = std::abs(r.sweep.dAngle);
    r.bound = length(r.sweep.dc) + r.turnBound * body.reach;
    return r;
}

/// Sweeps the body against the static shapes and the kinematic bodies'
/// shapes, and, for a bullet, against the shapes of dynamic bodies that are
/// not bullets; moves it back to the first time of impact.
void sweepBody(WorldState& w, Body& body, const Mover& m, Vec2 rewind) {
    const Transform xf0 = m.sweep.at(0.0f), xf1 = body.xf;
    // The earliest stop along the sweep, and a probe that found the centroid
    // already nearer a static surface than its extent (holdApproach).
    Stop stop, hold;
    stop.sweep = m.sweep;
    for (int sh : bodyShapes(w.shapes, body)) {
        const Shape& shape = w.shapes[sh];
        if (shape.isSensor) continue;
        const ShapeCore core = shapeCore(shape);
        // The boxes at both ends, grown by how far the turn can carry a
        // point off the straight path between them (|Δθ|·r).
        AABB swept = unionOf(shapeAABB(shape, xf0), shapeAABB(shape, xf1));
        const float arc = m.turnBound * body.reach;
        swept.lower -= Vec2{arc, arc};
        swept.upper += Vec2{arc, arc};
        auto visit = [&](int other) {
            const Shape& o = w.shapes[other];
            if (o.isSensor || !shouldCollide(shape.filter, o.filter)) return true;
            const Body& ob = w.bodies[o.body];
            if (o.body == shape.body) return true;
            const bool kinematic = ob.type == BodyType::kinematic_body;
            // In the dynamic tree, for a bullet: the dynamic bodies that are
            // not bullets.
            if (o.treeType == BodyType::dynamic_body && (!body.isBullet || ob.isBullet)) return true;
            if (jointPreventsCollision(w, shape.body, o.body)) return true;
            const Mover pm = kinematic ? relativeTo(m, body, kinematicStart(w, o.body), ob.xf) : m;
            if (o.chainSegment &&
                behindChain(o, ob.xf, transformPoint(pm.sweep.at(0.0f), centroidOf(shape, core).point)))
                return true;  // one-sided: a body coming from behind passes
            // The game's filters hold here too: a pair its custom filter
            // refuses never collides, and a pair its pre-solve callback
            // switches off (a one-way platform passed from below) is not
            // swept, judged on the manifold at the step's end pose, grown by
            // the sweep's bound so that there is one.
            if (w.customFilter && !w.customFilter(w.shapeHandle(sh), w.shapeHandle(other))) return true;
            if (w.preSolve) {
                const Manifold at = collideShapes(shape, xf1, o, ob.xf, m.bound + w.settings.speculativeDistance);
                if (at.pointCount > 0 && !w.preSolve(w.shapeHandle(sh), w.shapeHandle(other), at)) return true;
            }
            Stop pair;
            sweepPair(shape, core, pm, o, ob.xf, w.settings.speculativeDistance, pair);
            pair.sweep = pm.sweep;
            // A static or kinematic body takes the approach's momentum; a
            // dynamic one takes it through the contact.
            pair.byProbe = pair.byProbe && (o.inStaticTree() || kinematic);
            // Held in place (below) only against a static surface: against a
            // kinematic one the stop at t = 0 carries the body along with it.
            pair.holdApproach = pair.holdApproach && pair.byProbe && o.inStaticTree();
            if (kinematic) pair.surfaceVelocity = ob.v + cross(ob.w, body.center - ob.center);
            if (pair.holdApproach) {
                if (!hold.holdApproach) hold = pair;
            } else if (pair.t < stop.t) {
                stop = pair;
            }
            return true;
        };
        w.broadPhase.staticTree.query(swept, visit);
        w.broadPhase.kinematicTree.query(swept, visit);
        if (body.isBullet) w.broadPhase.dynamicTree.query(swept, visit);
    }
    if (stop.t >= 1.0f && !hold.holdApproach) return;
    Transform xf = stop.sweep.at(stop.t);
    // Put back to the step's start, a body whose centroid began the step
    // nearer a static surface than its extent (partly through a thin floor)
    // lost the whole step's motion, and gravity brought the same approach
    // back in every step: a plank spun through a chain floor stayed where
    // it was for good, its velocity and spin (20 rad/s) never flown. It now
    // moves as far as the other shapes let it (the earliest other stop) and
    // only its centroid's approach along that surface's normal is taken out
    // of the move, as it is out of the velocity below.
    // (The move from the body's own start: a stop on a sweep relative to a
    // kinematic body starts where the kinematic body carried the body.)
    if (hold.holdApproach) {
        const float moved = stop.t * dot(stop.sweep.dc, hold.normal) + dot(stop.sweep.c0 - m.sweep.c0, hold.normal);
        xf.p -= std::min(0.0f, moved) * hold.normal;
    }
    body.xf = xf;
    body.center = transformPoint(xf, body.localCenter);
    // Its proxies are checked again (the write-back checked the step's end).
    w.broadPhase.proxyLeaves[static_cast<std::size_t>(body.awakeIndex)] = 1;
    // The velocity it had at the time of impact: the step's end less the
    // acceleration since, within the speed limit the solver holds (a body of
    // tiny mass under a force accelerates beyond any: fuzz_world found one of
    // 2e-16 kg left at 4e16 m/s).
    const Vec2 ended = body.v;
    body.v = limitSpeed(ended - (1.0f - stop.t) * rewind, w.settings.maxLinearSpeed);
    // Along each stop's normal (from the surface towards the body) that
    // velocity is held between two bounds:
    // - above: the rewind takes the acceleration back as if the body had
    //   flown free since; a body the contacts held did not. At the time it
    //   reached the surface it was not leaving it faster than it ended the
    //   step (nor leaving it at all, had it ended the step going in). A 1 kg
    //   box landing at 10 m/s under a 1,000 N push towards the ground, held
    //   by its contact 2 cm into the ground at the step's end, was put back
    //   on the surface leaving it at 6.5 m/s, and at the 400 m/s limit under
    //   100 kN.
    // - below, for a body stopped by a probe: it is driving into a static
    //   surface it already touches, and its contact did not stop it (one
    //   contact point, say, about which the body turned). Kept, that velocity
    //   would be put back again in every step and freeze the body where it
    //   is: the centroid's approach speed is taken out, as an inelastic
    //   impact of the centroid with the static surface would (the surface
    //   takes the momentum).
    // Against a kinematic body both bounds hold relative to its surface.
    for (const Stop* at : {&stop, &hold}) {
        if (at->normal.x == 0.0f && at->normal.y == 0.0f) continue;
        const float most = std::max(dot(ended - at->surfaceVelocity, at->normal), 0.0f);
        const float away = dot(body.v - at->surfaceVelocity, at->normal);
        if (away > most)
            body.v -= (away - most) * at->normal;
        else if (at->byProbe && away < 0.0f)
            body.v -= away * at->normal;
    }
    // Matched to a kinematic surface's speed along the normal, the body is
    // still held to the speed limit (a kinematic body may move at any speed).
    body.v = limitSpeed(body.v, w.settings.maxLinearSpeed);
}

/// Whether a static or kinematic body's shape may lie across a non-bullet
/// body's sweep (which meets only those): the box sweepBody queries, made from the
/// step's start pose without the sweep's angles (makeMover's two atan2) and
/// grown by far more than the rounding that tells the two start poses apart
/// (a few 1e-7 of a rotation, of the coordinates). A body in the open (rain
/// above the ground, a swinging grid) is then not swept at all. (In a world
/// without static or kinematic shapes needsSweep has said no already.)
bool mayMeetFixed(const WorldState& w, const Body& body, const BodyState& s) {
    const DynamicTree& statics = w.broadPhase.staticTree;
    const SweepStart start = sweepStartOf(w, body, s);
    const Vec2 c0 = start.center;
    const Rot dq = start.turn;
    const Transform xf0{c0 - rotate(start.rotation, body.localCenter), start.rotation};
    const float scale = 1.0f + body.reach + std::abs(c0.x) + std::abs(c0.y) + std::abs(body.localCenter.x) +
                        std::abs(body.localCenter.y);
    const float grow = turnBoundOf(dq) * body.reach + 1e-5f * scale;
    bool found = false;
    for (int sh : bodyShapes(w.shapes, body)) {
        const Shape& shape = w.shapes[sh];
        if (shape.isSensor) continue;
        AABB box = unionOf(shapeAABB(shape, xf0), shapeAABB(shape, body.xf));
        box.lower -= Vec2{grow, grow};
        box.upper += Vec2{grow, grow};
        // (A kinematic body's box holds its whole step: broad_phase.cpp.)
        auto any = [&](int) {
            found = true;
            return false;
        };
        statics.query(box, any);
        if (!found) w.broadPhase.kinematicTree.query(box, any);
        if (found) return true;
    }
    return false;
}

}  // namespace

bool needsSweep(const WorldState& w, const Body& body, const BodyState& s) {
    // makeMover's test without its sweep (two atan2 per moving body, 2 % of a
    // swinging joint grid's step when asked of every body). A body that is
    // not a bullet is swept against static and kinematic shapes only: none,
    // no sweep.
    const BroadPhase& bp = w.broadPhase;
    if (!body.isBullet && bp.staticTree.proxyCount() == 0 && bp.kinematicTree.proxyCount() == 0) return false;
    return body.type == BodyType::dynamic_body && body.reach >= 0.0f && movedBeyondContacts(w, body, s);
}

namespace {

/// In a step with a deep overlap: the dynamic bodies with a deep contact
/// against a static or kinematic body are swept too (SolverArrays::sweeps
/// kPressedSweep), however little they moved. A body pressed into such a
/// shape by a load far heavier than itself sinks a little each step, never
/// further than the speculative distance, so it was never swept: a flat box
/// 15 cm thick under a box 800 times its mass went into a chain ground
/// until its centre crossed the chain, which then let it fall, and through
/// a two-sided segment, which pushed it out below. Swept, its centroid's
/// probe keeps the centre from crossing the surface (probeCentroid).
constexpr std::uint8_t kPressedSweep = 2;

void markPressedBodies(WorldState& w) {
    SolverArrays& s = w.solver;
    for (std::size_t k = 0; k < w.activeContacts.size(); ++k) {
        if ((w.activeLooks[k].rowFlags & kLookDeep) == 0) continue;
        const Contact& ct = w.contacts[w.activeContacts[k]];
        const Body& a = w.bodies[ct.bodyA];
        const Body& b = w.bodies[ct.bodyB];
        const bool aFixed = a.type != BodyType::dynamic_body, bFixed = b.type != BodyType::dynamic_body;
        if (aFixed == bFixed) continue;  // two dynamic bodies (or none)
        const int i = stateIndexOf(s, aFixed ? ct.bodyB : ct.bodyA);
        if (i == kNullIndex) continue;
        if (s.sweeps[static_cast<std::size_t>(i)] == 0) s.sweeps[static_cast<std::size_t>(i)] = kPressedSweep;
    }
}

}  // namespace

void solveContinuous(WorldState& w, float dt) {
    // Non-bullets first: the bullets then meet them where they ended the step.
    struct Bullet {
        int body;
        Mover m;
        Vec2 rewind;
    };
    std::vector<Bullet> bullets;  // allocates only in a step with a fast bullet
    if (w.solver.anyDeepOverlap) markPressedBodies(w);
    const std::vector<std::uint8_t>& sweeps = w.solver.sweeps;
    for (std::size_t i = 0; i < w.solver.stateBodies.size(); ++i) {
        if (sweeps[i] == 0) continue;  // needsSweep said no in the write-back
        Body& body = w.bodies[w.solver.stateBodies[i]];
        if (!body.isBullet && !mayMeetFixed(w, body, w.solver.states[i])) continue;
        Mover m;
        if (!makeMover(w, body, w.solver.states[i], m, sweeps[i] == kPressedSweep)) continue;
        // The velocity the free acceleration added over the whole step.
        const Vec2 rewind = dt * w.solver.integration[i].linearAcceleration;
        if (body.isBullet)
            bullets.push_back({w.solver.stateBodies[i], m, rewind});
        else
            sweepBody(w, body, m, rewind);
    }
    if (bullets.empty()) return;
    // The bullets find the dynamic bodies through their boxes in the tree,
    // which must hold where those bodies ended the step (a plank just hit
    // moves fast): the step's refresh of the proxies is made now, and after
    // the bullets only the bullets' own (sweepBody marks those it moves).
    // Refreshed here without the step's stretch ahead and then again with
    // it, every awake body's boxes were computed twice and most moved
    // proxies moved twice: one bullet far from everything cost a swinging
    // joint grid 14 % more instructions, rain1000 6 %.
    refreshProxies(w, dt);
    for (const Bullet& b : bullets) sweepBody(w, w.bodies[b.body], b.m, b.rewind);
}

}  // namespace i2d::detail
