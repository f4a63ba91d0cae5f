// Contacts: their lifetime (created when the broadphase finds a new pair,
// destroyed when the fattened boxes part, or with a shape, a body type change,
// a filter change or a joint) and the narrowphase update of their manifolds.
//
// Each step, every contact with an awake body recomputes its manifold.
// Manifold points keep the accumulated impulses of the previous step's point
// with the same feature id: the "contact caching" of Tamis and Maggiore
// (2015), Constraint based physics solver, the solver's warm start.
#include <algorithm>
#include <cmath>
#include <new>

#include "circle_manifold.hpp"
#include "contact_persistence.hpp"
#include "impact_look.hpp"
#include "lost_load.hpp"
#include "seams.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

// Order of the pair passed to the colliders: the manifold function table is
// written for (higher-rank type, lower-rank type) with rank
// polygon > capsule > circle, and segments always first.
int typeRank(ShapeType t) {
    switch (t) {
        case ShapeType::segment: return 3;
        case ShapeType::polygon: return 2;
        case ShapeType::capsule: return 1;
        case ShapeType::circle: return 0;
    }
    return 0;
}

// The radius a shape rolls on: a circle's or capsule's, a rounded polygon's.
float rollingRadius(const Shape& s) {
    switch (s.type) {
        case ShapeType::circle: return s.geometry.circle.radius;
        case ShapeType::capsule: return s.geometry.capsule.radius;
        case ShapeType::polygon: return s.geometry.polygon.radius;
        case ShapeType::segment: return 0.0f;
    }
    return 0.0f;
}

/// The manifold of two shapes ordered for the function table.
Manifold collideOrdered(const Shape& sa, const Transform& xa, const Shape& sb, const Transform& xb, float spec) {
    const ShapeGeometry& a = sa.geometry;
    const ShapeGeometry& b = sb.geometry;
    switch (sa.type) {
        case ShapeType::segment:
            switch (sb.type) {
                case ShapeType::circle: return collideSegmentAndCircle(a.segment, xa, b.circle, xb, spec);
                case ShapeType::capsule: return collideSegmentAndCapsule(a.segment, xa, b.capsule, xb, spec);
                case ShapeType::polygon: return collideSegmentAndPolygon(a.segment, xa, b.polygon, xb, spec);
                case ShapeType::segment: return {};  // two segments have no area to collide
            }
            break;
        case ShapeType::polygon:
            switch (sb.type) {
                case ShapeType::circle: return collidePolygonAndCircle(a.polygon, xa, b.circle, xb, spec);
                case ShapeType::capsule: return collidePolygonAndCapsule(a.polygon, xa, b.capsule, xb, spec);
                case ShapeType::polygon: return collidePolygons(a.polygon, xa, b.polygon, xb, spec);
                default: break;
            }
            break;
        case ShapeType::capsule:
            switch (sb.type) {
                case ShapeType::circle: return collideCapsuleAndCircle(a.capsule, xa, b.circle, xb, spec);
                case ShapeType::capsule: return collideCapsules(a.capsule, xa, b.capsule, xb, spec);
                default: break;
            }
            break;
        case ShapeType::circle:
            if (sb.type == ShapeType::circle) return collideCircles(a.circle, xa, b.circle, xb, spec);
            break;
    }
    return {};
}

// A hit event when the surfaces close faster than the threshold at one of
// the manifold points, measured with the bodies' velocities at the step's
// start (before the solver stops them).
void reportHit(WorldState& w, const Contact& ct) {
    const Body& bA = w.bodies[ct.bodyA];
    const Body& bB = w.bodies[ct.bodyB];
    const Manifold& m = ct.manifold;
    float fastest = 0.0f;
    int best = -1;
    for (int i = 0; i < m.pointCount; ++i) {
        const Vec2 p = m.points[i].point;
        const Vec2 dv = (bB.v + cross(bB.w, p - bB.center)) - (bA.v + cross(bA.w, p - bA.center));
        const float approach = -dot(dv, m.normal);
        if (approach > fastest) {
            fastest = approach;
            best = i;
        }
    }
    if (best < 0 || fastest <= w.settings.hitEventThreshold) return;
    w.events.contactHit.push_back(
        {w.shapeHandle(ct.shapeA), w.shapeHandle(ct.shapeB), m.points[best].point, m.normal, fastest});
}

/// Whether a flat side of either shape keeps the two further apart than
/// `margin` through the step of length dt, each body closing along that
/// side's normal at most as fast as at the step's start (its turn moving
/// its surface by up to |ω|·reach), as in computeManifold's bound: the
/// separating axis then holds for the whole step.
bool apartAlongASide(const Shape& sa, const Body& A, const Shape& sb, const Body& B, float dt, float margin) {
    const float turnA = std::abs(A.w) * std::max(A.reach, 0.0f);
    const float turnB = std::abs(B.w) * std::max(B.reach, 0.0f);
    auto apart = [&](Vec2 u) {  // u points from A towards B
        const float gap = -shapeSupport(sb, B.xf, -u) - shapeSupport(sa, A.xf, u);
        const float closing = std::max(dot(A.v, u), 0.0f) + turnA + std::max(-dot(B.v, u), 0.0f) + turnB;
        return gap - dt * closing > margin;
    };
    Vec2 normals[kMaxPolygonVertices];
    int count = shapeFaceNormals(sa, A.xf, normals);
    for (int i = 0; i < count; ++i)
        if (apart(normals[i])) return true;
    count = shapeFaceNormals(sb, B.xf, normals);
    for (int i = 0; i < count; ++i)
        if (apart(-normals[i])) return true;
    return false;
}

/// How far any point of body A or B can move within a step of dt, each at
/// its speed at the step's start (computeManifold's speculative bound).
inline float motionBound(const Body& A, const Body& B, float dt) {
    return dt * (length(A.v) + std::abs(A.w) * std::max(A.reach, 0.0f) + length(B.v) +
                 std::abs(B.w) * std::max(B.reach, 0.0f));
}

/// How fast A and B close at point p along n (A to B), each body taken to
/// move towards the other at most as fast as at the step's start
/// (computeManifold: the bound on a point beyond the fixed distance).
inline float closingAt(const Body& A, const Body& B, Vec2 p, Vec2 n) {
    const Vec2 vA = A.v + cross(A.w, p - A.center), vB = B.v + cross(B.w, p - B.center);
    return std::max(dot(vA, n), 0.0f) + std::max(-dot(vB, n), 0.0f);
}

// The speculative margin of a pair of moving bodies follows their motion. A
// point is kept while its gap is within the fixed speculative distance plus
// how far the two bodies can close at that point within this step: the solver's
// speculative row allows exactly the approach that closes the gap, and the
// impact stage resolves the hit at the moment the gap closes, so two fast
// bodies meet at their surfaces instead of a step's travel inside each other
// (speculative contacts: Catto (2013), "Continuous Collision"). Each body is
// taken to move towards the other at most as fast as it does at the step's
// start, while the other may be stopped within the step: the closing bound at
// a point is the sum of the two bodies' speeds towards each other there, not
// their relative speed. Two boxes falling one above the other at 13 m/s close
// at zero, but when the lower one lands in a step the upper one falls 22 cm
// onto it; with the relative speed (or the fixed distance alone) it ended that
// step up to 19 cm inside. The fixed distance covers what the step's start
// does not show: gravity's Δv·Δt, a turn's departure from the point's straight
// path. A point that no body moves towards keeps the fixed distance, so a
// body sliding fast past another's corner gets no row there. Pairs with a
// static body get the margin too: continuous collision (continuous.cpp) stops
// a fast body at a static surface only after the solve, so the bodies resting
// on it would otherwise keep going into it. A chain segment whose end judges
// the manifold's normal a ghost drops the whole manifold (seams.cpp), so the
// wider margin does not snag a body on the next segment's far end.
//
// Written into `m` in place: the narrowphase function constructs its result
// there (a prvalue into placement new is never copied). A manifold returned
// into a local and then copied into the contact was written in 4-byte pieces
// and read back in 16-byte ones at once, a store-forwarding stall per
// contact that was a quarter of the manifold update's time in rain1000.
// Inlined into both callers (the narrowphase's, for every contact, and
// refreshStruckContacts'): called, it made rain1000's step 2 % longer.
inline __attribute__((always_inline)) void computeManifold(const WorldState& w, const Contact& c, Manifold& m) {
    const Shape& sa = w.shapes[c.shapeA];
    const Shape& sb = w.shapes[c.shapeB];
    const Body& A = w.bodies[c.bodyA];
    const Body& B = w.bodies[c.bodyB];
    // Sensors report overlap only: no speculative margin.
    if (c.isSensor) {
        ::new (&m) Manifold(collideOrdered(sa, A.xf, sb, B.xf, 0.0f));
        return;
    }
    const float spec = w.settings.speculativeDistance;
    const float dt = w.stepDt;
    // No point of either body moves further than this within the step.
    const float bound = motionBound(A, B, dt);
    if (!(bound > 0.0f) || !std::isfinite(bound)) {
        ::new (&m) Manifold(collideOrdered(sa, A.xf, sb, B.xf, spec));
        return;
    }
    if (sa.type == ShapeType::circle && sb.type == ShapeType::circle)
        writeCircleManifold(sa.geometry.circle, A.xf, sb.geometry.circle, B.xf, spec + bound, m);
    else
        ::new (&m) Manifold(collideOrdered(sa, A.xf, sb, B.xf, spec + bound));
    const Vec2 n = m.normal;  // from A to B
    int kept = 0;
    bool keptByMotion = false;
    for (int i = 0; i < m.pointCount; ++i) {
        const ManifoldPoint& mp = m.points[i];
        if (mp.separation > spec) {
            if (mp.separation > spec + dt * closingAt(A, B, mp.point, n)) continue;
            keptByMotion = true;
        }
        // Moved only when a point before it was dropped: copying every point
        // onto itself wrote it in pieces that the copy of the whole manifold
        // then read back at once, a store-forwarding stall per contact.
        if (kept != i) m.points[kept] = mp;
        ++kept;
    }
    // The bound above is taken along the manifold's normal, which between two
    // corners (or a corner and a rounded end) is the direction from one to
    // the other, not a direction the gap closes in: two boxes falling side by
    // side 0.1 m apart, corner above corner, close along that diagonal at 0.7
    // times their fall speed, though their sides never meet. Such a point was
    // a row, and struck as an impact once the lower box landed: a 7 × 7 grid
    // of boxes 0.1 m apart dropped from 10 m threw boxes sideways along the
    // diagonals at 11 m/s and its top row up at 6.7 m/s (Box2D 2.4.1 lands it
    // standing). A flat side of either shape along whose normal the two stay
    // further apart than the fixed distance, however each body closes, proves
    // the points that motion alone kept will not be reached within the step.
    // (Two circles have no side: nothing to look at.)
    if (keptByMotion && (sa.type != ShapeType::circle || sb.type != ShapeType::circle) &&
        apartAlongASide(sa, A, sb, B, dt, spec)) {
        int still = 0;
        for (int i = 0; i < kept; ++i)
            if (m.points[i].separation <= spec) m.points[still++] = m.points[i];
        kept = still;
    }
    if (kept != m.pointCount) m.pointCount = kept;  // (as above: no write when nothing moved)
}

/// Contact::overlapFromStart for a contact whose new manifold has points:
/// set at its first touch when a point is deeper than deepOverlapOf and none
/// closes faster than the impact threshold (bodies created or moved inside
/// each other, not a collision, which the impact law must meet however deep
/// its first manifold: a fast body's first touch of a thin plank can be
/// deeper than the plank's deep-overlap depth), cleared once every point is
/// within the penetration slop. `deepest`: deepestSeparation of its manifold.
inline void markOverlapFromStart(const WorldState& w, Contact& ct, const Body& a, const Body& b, float deepest) {
    const Manifold& m = ct.manifold;
    if (ct.touching) {
        if (ct.overlapFromStart && deepest > -w.settings.penetrationSlop) ct.overlapFromStart = false;
        return;
    }
    bool overlap = deepest < -deepDepthOf(ct);  // (a first touch: as deep as the shapes' own depth)
    for (int i = 0; i < m.pointCount && overlap; ++i) {
        const Vec2 p = m.points[i].point;
        const Vec2 dv = (b.v + cross(b.w, p - b.center)) - (a.v + cross(a.w, p - a.center));
        overlap = !(dot(dv, m.normal) < -w.settings.impactThreshold);
    }
    ct.overlapFromStart = overlap;
}

/// Contact::stillDeep and overlapFromStart for a contact whose new manifold
/// has points. stillDeep is judged against the depth deepOverlapOf gives
/// with its last value: the depth a contact becomes deep from, or the
/// shallower one it stays deep to.
inline void markDepth(const WorldState& w, Contact& ct, const Body& a, const Body& b) {
    const float deepest = deepestSeparation(ct.manifold);
    const bool deep = deepest < -deepOverlapOf(ct);
    if (deep != ct.stillDeep) ct.stillDeep = deep;  // (written only when it changes, as most contacts keep it)
    markOverlapFromStart(w, ct, a, b, deepest);
}

/// What the narrowphase found for one contact (updateManifold).
/// `kept`: touching as before and no hit to report, so applyUpdate has
/// nothing to do (most contacts of a resting pile; it need not read them again).
enum class Update : std::uint8_t { parted, apart, touching, kept };

/// The contact's impulses (and rest loads, rest_load.hpp) carried over by feature id to the points of
/// manifold m, from those of the points it had (ids lastIds[0…lastCount));
/// a point with no match starts from zero.
void carryImpulses(Contact& ct, const std::uint16_t* lastIds, int lastCount, const Manifold& m) {
    // The same features in the same places (every reused manifold, most of a
    // resting pile's): each point keeps what it has (a point beyond the count
    // holds zero already: this function or the contact's creation left it so).
    if (m.pointCount == lastCount && (lastCount < 1 || lastIds[0] == m.points[0].id) &&
        (lastCount < 2 || (lastIds[1] == m.points[1].id && lastIds[0] != lastIds[1])))
        return;
    float ni[2] = {0.0f, 0.0f}, ti[2] = {0.0f, 0.0f};
    RestLoad rest[2] = {0, 0};
    for (int i = 0; i < m.pointCount; ++i) {
        for (int j = 0; j < lastCount; ++j) {
            if (lastIds[j] == m.points[i].id) {
                ni[i] = ct.normalImpulse[j];
                ti[i] = ct.tangentImpulse[j];
                rest[i] = ct.restLoad[j];
                break;
            }
        }
    }
    for (int i = 0; i < 2; ++i) {
        ct.normalImpulse[i] = ni[i];
        ct.tangentImpulse[i] = ti[i];
        ct.restLoad[i] = rest[i];
    }
}

/// updateManifold for two circles with neither a sensor, a seam rule nor a
/// pre-solve callback (every contact of a pile of balls): the same steps in
/// the same order and the same bits, without the questions two circles
/// answer already. Such a pair is never framed (canPersist: two round shapes
/// have no face to keep), the feature id of its one point is always 0 (so
/// the impulses carry over exactly when the point count stays), and its
/// motion-kept point needs no side test (computeManifold).
Update updateCirclePair(WorldState& w, Contact& ct) {
    const Body& A = w.bodies[ct.bodyA];
    const Body& B = w.bodies[ct.bodyB];
    const Circle& ca = w.shapes[ct.shapeA].geometry.circle;
    const Circle& cb = w.shapes[ct.shapeB].geometry.circle;
    ct.foundAfterStrike = false;
    const int lastCount = ct.manifold.pointCount;
    Manifold& m = ct.manifold;
    const float spec = w.settings.speculativeDistance;
    const float dt = w.stepDt;
    // computeManifold's bound and its kept point.
    const float bound = motionBound(A, B, dt);
    const bool bounded = bound > 0.0f && std::isfinite(bound);
    writeCircleManifold(ca, A.xf, cb, B.xf, bounded ? spec + bound : spec, m);
    if (bounded && m.pointCount == 1 && m.points[0].separation > spec &&
        m.points[0].separation > spec + dt * closingAt(A, B, m.points[0].point, m.normal))
        m.pointCount = 0;
    const bool touching = m.pointCount > 0;
    if (touching)
        markDepth(w, ct, A, B);
    else if (ct.stillDeep)
        ct.stillDeep = false;
    if (m.pointCount != lastCount) {  // carryImpulses: a new point starts from zero
        for (int i = 0; i < 2; ++i) {
            ct.normalImpulse[i] = 0.0f;
            ct.tangentImpulse[i] = 0.0f;
            ct.restLoad[i] = 0;
        }
    }
    ct.touchBegan = touching && !ct.touching;
    ct.framed = false;
    if (touching && ct.touching && !ct.enableHitEvents) return Update::kept;
    return touching ? Update::touching : Update::apart;
}

/// The manifold part of a contact's update: the new manifold (kept or
/// computed), seam ghosts dropped, the pre-solve callback, the impulses
/// carried over by feature id, the frame for reuse. Writes this contact
/// only and reads the world (the callback aside, which runs only on the
/// stepping thread), so contacts may be updated on any worker; what changes
/// the world — destroying, waking, events — is applyUpdate's.
Update updateManifold(WorldState& w, int c) {
    Contact& ct = w.contacts[c];
    if (!overlaps(w.broadPhase.fatBox(ct.shapeA), w.broadPhase.fatBox(ct.shapeB))) return Update::parted;
    if (ct.roundA && ct.roundB && !ct.isSensor && !ct.seamRule && !w.preSolve) return updateCirclePair(w, ct);
    const Body& bodyA = w.bodies[ct.bodyA];
    const Body& bodyB = w.bodies[ct.bodyB];
    // A touching flat pair that has barely moved keeps its manifold (same ids,
    // so the impulses carry over below; contact_persistence.hpp). The game's
    // callbacks see it like any other.
    const bool reused = ct.touching && reuseManifold(ct, bodyA, bodyB, w.settings.manifoldReuseDistance);
    // The last manifold's feature ids, for the impulses carried over below;
    // the new manifold is computed into the contact (computeManifold).
    ct.foundAfterStrike = false;
    const int lastCount = ct.manifold.pointCount;
    const std::uint16_t lastIds[2] = {ct.manifold.points[0].id, ct.manifold.points[1].id};
    Manifold& m = ct.manifold;
    // Seam ghosts were dropped when a kept manifold was computed.
    if (!reused) {
        computeManifold(w, ct, m);
        if (ct.seamRule) dropSeamGhosts(w, ct, m);
    }
    // The game's pre-solve callback may switch a touching contact off for
    // this step (a one-way platform): it then has no points, no row, and
    // counts as not touching.
    if (w.preSolve && !ct.isSensor && m.pointCount > 0 &&
        !w.preSolve(w.shapeHandle(ct.shapeA), w.shapeHandle(ct.shapeB), m))
        m.pointCount = 0;
    bool touching;
    if (ct.isSensor) {
        touching = false;
        for (int i = 0; i < m.pointCount; ++i) touching = touching || m.points[i].separation < 0.0f;
    } else {
        touching = m.pointCount > 0;
        if (touching)
            markDepth(w, ct, bodyA, bodyB);
        else if (ct.stillDeep)
            ct.stillDeep = false;
        carryImpulses(ct, lastIds, lastCount, m);  // the warm start
    }
    ct.touchBegan = touching && !ct.touching;
    if (!reused) {
        ct.framed = false;
        if (ct.persists && m.pointCount > 0) recordManifoldFrame(ct, bodyA, bodyB);  // (no points: not framed)
    } else if (m.pointCount == 0) {
        ct.framed = false;  // switched off by the pre-solve callback
    }
    if (touching && ct.touching && !ct.enableHitEvents) return Update::kept;
    return touching ? Update::touching : Update::apart;
}

/// A touching contact's look for the solver (ContactLook::rowFlags, but for
/// kLookHeavyOnLight, which the impact stage reads): whether it has a row,
/// of one point, with a deep overlap, on a rolling surface.
std::uint8_t rowLook(const WorldState& w, int c, const Contact& ct) {
    if (ct.isSensor || ct.manifold.pointCount == 0) return 0;
    std::uint8_t flags = kLookRow;
    if (ct.manifold.pointCount == 1) flags |= kLookOnePoint;
    const float deep = deepOverlapOf(ct);
    for (int j = 0; j < ct.manifold.pointCount; ++j)
        if (ct.manifold.points[j].separation < -deep) flags |= kLookDeep;
    const ContactSurface* surface = contactSurface(w, c);
    if (surface && surface->rollingResistance > 0.0f) flags |= kLookRollingSurface;
    return flags;
}

/// Whether the contact touches once `update` is applied (applyUpdate).
constexpr bool touchingAfter(Update update) { return update == Update::kept || update == Update::touching; }

/// The rest of a contact's update, on the stepping thread in slot order:
/// destroys a contact whose boxes parted (false), reports hits, begin and
/// end events, and wakes what a new touch reaches.
bool applyUpdate(WorldState& w, int c, Update update) {
    if (update == Update::kept) return true;
    if (update == Update::parted) {
        destroyContact(w, c, true);
        return false;
    }
    Contact& ct = w.contacts[c];
    const bool touching = update == Update::touching;
    const Manifold& m = ct.manifold;
    if (ct.enableHitEvents && touching) reportHit(w, ct);
    if (touching != ct.touching) {
        ct.touching = touching;
        if (touching) {
            // A touch wakes whatever sleeps on the other side.
            if (!w.bodies[ct.bodyA].awake) wakeBody(w, ct.bodyA);
            if (!w.bodies[ct.bodyB].awake) wakeBody(w, ct.bodyB);
        }
        if (ct.enableEvents) {
            if (ct.isSensor) {
                bool aSensor = w.shapes[ct.shapeA].isSensor;
                SensorBeginEvent ev{w.shapeHandle(aSensor ? ct.shapeA : ct.shapeB),
                                    w.shapeHandle(aSensor ? ct.shapeB : ct.shapeA)};
                if (touching)
                    w.events.sensorBegin.push_back(ev);
                else
                    w.events.sensorEnd.push_back({ev.sensor, ev.visitor});
            } else if (touching) {
                w.events.contactBegin.push_back({w.shapeHandle(ct.shapeA), w.shapeHandle(ct.shapeB), m});
            } else {
                w.events.contactEnd.push_back({w.shapeHandle(ct.shapeA), w.shapeHandle(ct.shapeB)});
            }
        }
    }
    return true;
}

/// Contacts per chunk of the parallel manifold stage.
constexpr int kCollideGrain = 64;
/// The gathered contacts are listed by reading every slot once they are at
/// least 1/kDenseGather of the slots (collide).
constexpr std::size_t kDenseGather = 4;

}  // namespace

namespace {

/// Whether `direction` (a unit vector, world) is the outward normal of a
/// flat side of shape sh at pose xf, within 0.8 degrees: the side of a
/// polygon, a capsule's or a segment's length (shapeFaceNormals). A circle
/// has none, nor has a rounded end or a corner (a normal between a corner
/// and the other shape).
bool isFaceNormal(const Shape& sh, const Transform& xf, Vec2 direction) {
    constexpr float kAligned = 0.9999f;
    Vec2 normals[kMaxPolygonVertices];
    const int count = shapeFaceNormals(sh, xf, normals);
    for (int i = 0; i < count; ++i)
        if (dot(normals[i], direction) > kAligned) return true;
    return false;
}

}  // namespace

/// kLookTurnA, kLookTurnB or 0: whether the contact's normal is a flat side
/// of A (or, reversed, of B) whose body turns further than
/// kTurningRowAngle in the step of dt, at its angular velocity now.
std::uint8_t turningLook(const WorldState& w, const Contact& ct, float dt) {
    const Body& a = w.bodies[ct.bodyA];
    const Body& b = w.bodies[ct.bodyB];
    const bool turnA = std::abs(a.w) * dt > kTurningRowAngle, turnB = std::abs(b.w) * dt > kTurningRowAngle;
    if (!turnA && !turnB) return 0;  // (NaN: neither)
    const Vec2 n = ct.manifold.normal;
    if (turnA && isFaceNormal(w.shapes[ct.shapeA], a.xf, n)) return kLookTurnA;
    if (turnB && isFaceNormal(w.shapes[ct.shapeB], b.xf, -n)) return kLookTurnB;
    return 0;
}

Manifold collideShapes(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                       float speculativeDistance) {
    if (typeRank(a.type) >= typeRank(b.type)) return collideOrdered(a, xa, b, xb, speculativeDistance);
    Manifold m = collideOrdered(b, xb, a, xa, speculativeDistance);
    m.normal = -m.normal;
    return m;
}

void updatePairs(WorldState& w) {
    w.broadPhase.findNewPairs(w.shapes, [&](int s, int other) {
        const Shape& sh = w.shapes[s];
        const Shape& o = w.shapes[other];
        const Body& b1 = w.bodies[sh.body];
        const Body& b2 = w.bodies[o.body];
        if (b1.type != BodyType::dynamic_body && b2.type != BodyType::dynamic_body) return;
        if (sh.isSensor && o.isSensor) return;
        if (!shouldCollide(sh.filter, o.filter)) return;
        if (jointPreventsCollision(w, sh.body, o.body)) return;
        if (w.customFilter && !w.customFilter(w.shapeHandle(s), w.shapeHandle(other))) return;
        createContact(w, s, other);
    });
}

void createContact(WorldState& w, int s1, int s2) {
    // Shape A's face is the reference of a face contact whenever the two
    // faces are within the classification tolerance (manifold.cpp). Of two
    // like shapes, the immovable body's is A: its face does not turn with the
    // moving body's tilt, so a frictionless row pushes along the surface only.
    // A falling or sliding box as A gave its floor a normal tilted with it: a
    // frictionless box of 0.2 m sliding over 1 m floor pieces gained 1.2 % of
    // its energy a minute (6.6 % at one substep), and boxes landing flat on a
    // ground 200 m wide left their first impact turning, the ground's face
    // reaching their frame from vertices 100 m away (docs/validation.md,
    // "The floor's face as the reference").
    const int rank1 = typeRank(w.shapes[s1].type), rank2 = typeRank(w.shapes[s2].type);
    const bool moves1 = w.bodies[w.shapes[s1].body].type == BodyType::dynamic_body;
    const bool moves2 = w.bodies[w.shapes[s2].body].type == BodyType::dynamic_body;
    if (rank1 < rank2 || (rank1 == rank2 && moves1 && !moves2)) std::swap(s1, s2);
    int c = w.contacts.allocate();
    Contact& ct = w.contacts[c];
    const Shape& a = w.shapes[s1];
    const Shape& b = w.shapes[s2];
    ct.shapeA = s1;
    ct.shapeB = s2;
    ct.bodyA = a.body;
    ct.bodyB = b.body;
    // Mixing rules: friction is the geometric mean (a slippery surface stays
    // slippery whatever touches it); restitution is the larger (a bouncy ball
    // bounces on anything). Both as in Box2D.
    ct.friction = std::sqrt(a.friction * b.friction);
    ct.restitution = std::max(a.restitution, b.restitution);
    ct.isSensor = a.isSensor || b.isSensor;
    ct.roundA = a.type == ShapeType::circle;
    ct.roundB = b.type == ShapeType::circle;
    ct.persists = canPersist(a, b);
    ct.seamRule = hasSeamRule(a, b, w.bodies[a.body].type == BodyType::static_body,
                              w.bodies[b.body].type == BodyType::static_body);
    const float thinner = std::min(shapeThickness(a), shapeThickness(b));
    if (kDeepFraction * thinner < kDeepOverlap)  // (a NaN thickness keeps kDeepOverlap)
        ct.deepScale = static_cast<std::uint8_t>(
            std::clamp(255.0f * std::max(kDeepFraction * thinner, kMinDeepOverlap) / kDeepOverlap, 1.0f, 254.0f));
    else
        ct.deepScale = kFullDeepScale;
    ct.enableHitEvents = !ct.isSensor && (a.enableHitEvents || b.enableHitEvents);
    ct.enableEvents = ct.isSensor ? ((a.isSensor ? a.enableSensorEvents : b.enableSensorEvents))
                                  : (a.enableContactEvents || b.enableContactEvents);
    setContactSurface(w, c, s1, s2);
    w.broadPhase.pairs.insert(pairKey(s1, s2));
    w.bodies[a.body].contacts.push_back(c);
    w.bodies[b.body].contacts.push_back(c);
}

const ContactSurface* contactSurface(const WorldState& w, int c) {
    return w.contactSurfaces.empty() ? nullptr : &w.contactSurfaces[static_cast<std::size_t>(c)];
}

void setContactSurface(WorldState& w, int c, int shapeA, int shapeB) {
    const Shape& a = w.shapes[shapeA];
    const Shape& b = w.shapes[shapeB];
    ContactSurface s;
    s.rollingResistance = std::max(a.rollingResistance, b.rollingResistance) *
                          std::max(rollingRadius(a), rollingRadius(b));
    s.tangentSpeed = a.tangentSpeed + b.tangentSpeed;
    std::vector<ContactSurface>& all = w.contactSurfaces;
    if (all.empty() && s.rollingResistance == 0.0f && s.tangentSpeed == 0.0f) return;
    if (all.size() < static_cast<std::size_t>(w.contacts.capacity()))
        all.resize(static_cast<std::size_t>(w.contacts.capacity()));
    all[static_cast<std::size_t>(c)] = s;
}

void destroyContact(WorldState& w, int c, bool emitEvents) {
    Contact& ct = w.contacts[c];
    if (ct.touching && emitEvents && ct.enableEvents) {
        if (ct.isSensor) {
            bool aSensor = w.shapes[ct.shapeA].isSensor;
            w.events.sensorEndList(w.stepping)
                .push_back(
                    {w.shapeHandle(aSensor ? ct.shapeA : ct.shapeB), w.shapeHandle(aSensor ? ct.shapeB : ct.shapeA)});
        } else {
            w.events.contactEndList(w.stepping).push_back({w.shapeHandle(ct.shapeA), w.shapeHandle(ct.shapeB)});
        }
    }
    w.broadPhase.pairs.erase(pairKey(ct.shapeA, ct.shapeB));
    for (int b : {ct.bodyA, ct.bodyB}) {
        auto& list = w.bodies[b].contacts;
        auto it = std::find(list.begin(), list.end(), c);
        if (it != list.end()) {
            *it = list.back();
            list.pop_back();
        }
    }
    w.contacts.release(c);
}

void destroyBodyContacts(WorldState& w, int body, int shape) {
    // A copy: destroyContact edits the body's list.
    const std::vector<int> list = w.bodies[body].contacts;
    // A touching contact the game takes away takes its load with it
    // (lost_load.hpp), taken out of the others once the contacts are gone.
    std::vector<LostLoad> lost;
    for (int c : list) {
        const Contact& ct = w.contacts[c];
        if (shape != kNullIndex && ct.shapeA != shape && ct.shapeB != shape) continue;
        addContactLoss(w, ct, lost);
        destroyContact(w, c, true);
    }
    releaseLostLoads(w, lost);
}

void collide(WorldState& w) {
    // Gather each contact with an awake body once (a sleeping or static
    // pair costs nothing here). A touch can wake a sleeping island; its
    // contacts are then gathered in a further round of the same loop so the
    // island is supported in this very step.
    ++w.stepStamp;
    w.activeContacts.clear();
    // At most every contact: one allocation when the lists were freed after the last step.
    w.activeContacts.reserve(static_cast<std::size_t>(w.contacts.count));
    std::vector<int>& scratch = w.gatherScratch;
    const std::vector<int>& awakeBodies = w.islands.awakeBodies;
    std::size_t bodyCursor = 0;
    std::size_t processed = 0;
    scratch.clear();
    scratch.reserve(static_cast<std::size_t>(w.contacts.count));
    std::vector<std::uint8_t>& updates = w.collideUpdates;
    updates.clear();
    // A narrowphase with enough contacts is shared with the task system's
    // workers, when the step has them (stage_runner.hpp); the result is the same.
    w.runner.share(w.contacts.count >= kParallelWork);
    // Each active contact's look (ContactLook), taken with its manifold: per
    // gathered contact, then per active one. Velocity-bias impacts have no
    // impact stage to look for.
    std::vector<ContactLook>& gatheredLooks = w.collideLooks;
    gatheredLooks.clear();
    w.activeLooks.clear();
    w.activeLooks.reserve(static_cast<std::size_t>(w.contacts.count));
    const bool lookForImpacts = w.settings.impactModel == ImpactModel::closed_form;
    // Written field by field into its place: returned as a whole, it was
    // written in 4-byte pieces and read back in 8-byte ones, a stall on store
    // forwarding per contact.
    auto look = [&](int c, Update update, ContactLook& out) {
        const Contact& ct = w.contacts[c];
        const bool touching = touchingAfter(update);
        out.bodyA = ct.bodyA;
        out.bodyB = ct.bodyB;
        const ImpactLook impacts = lookForImpacts ? lookAtImpacts(w, ct, touching) : ImpactLook{true, false};
        out.passOver = impacts.passOver;
        std::uint8_t flags = touching ? rowLook(w, c, ct) : 0;
        if (flags && impacts.heavyOnLight) flags |= kLookHeavyOnLight;
        out.rowFlags = flags;
    };
    auto keep = [&](int c, const ContactLook& first) {
        w.activeContacts.push_back(c);
        w.activeLooks.push_back(first);
    };
    // With no island asleep every contact has an awake body (a contact needs
    // a body that can move, and a disabled body keeps none): the round is
    // every live contact, in slot order, read off the slots without walking
    // the bodies' lists, and no touch can wake anything, so it is the only one.
    const bool noneAsleep = w.islands.sleepingIslands.size() == w.islands.freeIslands.size();
    bool firstRound = true;
    while (firstRound ? !awakeBodies.empty() : bodyCursor < awakeBodies.size()) {
        const std::size_t roundBegin = scratch.size();
        const int slots = w.contacts.capacity();
        if (firstRound && noneAsleep) {
            appendLiveSlots(w.contacts, w.gatherMarks, scratch);
            bodyCursor = awakeBodies.size();
        } else {
            for (; bodyCursor < awakeBodies.size(); ++bodyCursor) {
                for (int c : w.bodies[awakeBodies[bodyCursor]].contacts) {
                    Contact& ct = w.contacts[c];
                    if (ct.stamp == w.stepStamp) continue;
                    ct.stamp = w.stepStamp;
                    scratch.push_back(c);
                }
            }
            // Contact-slot order, so results do not depend on the awake list's
            // order. When the first round gathered a good part of all the slots
            // (a world mostly awake), marking the gathered slots in a byte
            // array and reading the marks in order gives that order for less
            // than sorting (many_pyramids' 44,000 contacts took a millisecond
            // and a half to sort) and without reading each contact's stamp
            // again (a cache miss per contact). Later rounds (islands a touch
            // woke) sort.
            const std::size_t gathered = scratch.size() - roundBegin;
            if (roundBegin == 0 && gathered * kDenseGather >= static_cast<std::size_t>(slots)) {
                std::vector<std::uint8_t>& marks = w.gatherMarks;
                marks.assign(static_cast<std::size_t>(slots), 0);
                for (const int c : scratch) marks[static_cast<std::size_t>(c)] = 1;
                scratch.clear();
                appendMarked(marks, scratch);
            } else {
                std::sort(scratch.begin() + static_cast<std::ptrdiff_t>(roundBegin), scratch.end());
            }
        }
        firstRound = false;
        if (w.preSolve) {
            // The game's callback runs on the stepping thread, contact by
            // contact in slot order, each seeing the updates before it.
            for (; processed < scratch.size(); ++processed) {
                const int c = scratch[processed];
                const Update update = updateManifold(w, c);
                ContactLook first;
                look(c, update, first);
                if (applyUpdate(w, c, update)) keep(c, first);
            }
            continue;
        }
        // The manifolds on every worker (each contact alone), then what
        // changes the world on this thread in slot order: the same updates,
        // events and wakes in the same order as one contact after the other.
        const std::size_t roundEnd = scratch.size();
        const int count = static_cast<int>(roundEnd - processed);
        updates.resize(roundEnd);
        gatheredLooks.resize(roundEnd);
        const int* round = scratch.data() + processed;
        std::uint8_t* results = updates.data() + processed;
        ContactLook* looks = gatheredLooks.data() + processed;
        auto manifolds = [&](int b, int e) {
            // The chunk's manifolds, then its looks: each pass a shorter chain
            // per contact, so more contacts overlap in the core (the chunk's
            // contacts stay in the first-level cache between the two). One
            // pass doing both took 3 % longer on a pile of 1,000 circles.
            for (int i = b; i < e; ++i) results[i] = static_cast<std::uint8_t>(updateManifold(w, round[i]));
            for (int i = b; i < e; ++i) look(round[i], static_cast<Update>(results[i]), looks[i]);
        };
        w.runner.run(count, kCollideGrain, manifolds);
        for (; processed < roundEnd; ++processed) {
            const int c = scratch[processed];
            if (applyUpdate(w, c, static_cast<Update>(updates[processed]))) keep(c, gatheredLooks[processed]);
        }
    }
}

void refreshStruckContacts(WorldState& w, const std::vector<int>& struckBodies) {
    // A struck body is awake, so collide gathered all its contacts: the
    // struck bodies' lists are walked, not every active contact.
    // A dynamic body asleep on the other side stays as collide left it
    // (waking it here would change the islands after they were gathered).
    auto asleep = [&](const Body& b) { return b.type == BodyType::dynamic_body && !b.awake; };
    for (const int s : struckBodies) {
        for (const int c : w.bodies[s].contacts) {
            Contact& ct = w.contacts[c];
            // A manifold already full: two points, or the one a round shape has.
            const int had = ct.manifold.pointCount;
            if (ct.isSensor || had >= 2 || (had == 1 && (ct.roundA || ct.roundB))) continue;
            Body& a = w.bodies[ct.bodyA];
            Body& b = w.bodies[ct.bodyB];
            if (asleep(a) || asleep(b)) continue;
            // At the poses the step began with (the rows measure from them,
            // impactShift adding what the stage moved), with the new velocities.
            struct Pose {
                Body& body;
                Vec2 center;
                Transform xf;
            };
            Pose saved[2] = {{a, a.center, a.xf}, {b, b.center, b.xf}};
            for (Pose& p : saved)
                if (const StepStart* start = w.shiftedStart(p.body)) {
                    p.body.center = start->center;
                    p.body.xf.q = start->q;
                    p.body.xf.p = start->center - rotate(start->q, p.body.localCenter);
                }
            auto restore = [&] {
                for (Pose& p : saved) {
                    p.body.center = p.center;
                    p.body.xf = p.xf;
                }
            };
            Manifold fresh;
            computeManifold(w, ct, fresh);
            if (ct.seamRule) dropSeamGhosts(w, ct, fresh);
            if (w.preSolve && fresh.pointCount > had &&
                !w.preSolve(w.shapeHandle(ct.shapeA), w.shapeHandle(ct.shapeB), fresh))
                fresh.pointCount = 0;
            // Only a manifold with more points than before is taken (what
            // the step's start showed stays).
            if (fresh.pointCount <= had) {
                restore();
                continue;
            }
            // Rare (a few contacts a step in a pile under a rain of bodies):
            // its place among the active contacts is looked up.
            const auto at = std::find(w.activeContacts.begin(), w.activeContacts.end(), c);
            if (at == w.activeContacts.end()) {  // (not gathered: cannot be, as said above)
                restore();
                continue;
            }
            const std::uint16_t lastIds[2] = {ct.manifold.points[0].id, ct.manifold.points[1].id};
            carryImpulses(ct, lastIds, had, fresh);
            ct.manifold = fresh;
            markDepth(w, ct, a, b);
            ct.foundAfterStrike = true;
            ct.framed = false;
            if (ct.persists) recordManifoldFrame(ct, a, b);
            restore();
            if (had == 0) {  // a new touch: its begin event, and its hit, as collide's
                ct.touchBegan = true;
                applyUpdate(w, c, Update::touching);
            }
            w.activeLooks[static_cast<std::size_t>(at - w.activeContacts.begin())].rowFlags = rowLook(w, c, ct);
        }
    }
}

}  // namespace i2d::detail
