// Broadphase proxies: inserting, removing and moving shapes' fat boxes.
#include <algorithm>

#include "world_state.hpp"

namespace i2d::detail {

namespace {
AABB fatten(const AABB& box, float margin) {
    return {{box.lower.x - margin, box.lower.y - margin}, {box.upper.x + margin, box.upper.y + margin}};
}

// The box a moving shape's fat box must contain: its shape's box grown by the
// speculative distance. Two shapes closer than that then always have
// overlapping fat boxes, hence a contact whose manifold can catch them. With
// the bare box, a ball whose fat box ended just above the ground reached it
// with no contact at all: continuous collision put it back 5 mm above the
// floor, the next step found no pair, and it sank 3.8 cm before bouncing
// (a third bounce 39 % too low). Box2D v3 grows its shape boxes the same way.
AABB speculativeBox(const WorldState& w, const Shape& sh, const Body& body, const Transform& xf) {
    return fatten(shapeAABB(sh, xf), body.type == BodyType::static_body ? 0.0f : w.settings.speculativeDistance);
}
AABB speculativeBox(const WorldState& w, const Shape& sh, const Body& body) {
    return speculativeBox(w, sh, body, body.xf);
}

/// How far any point of the body can move within a step of dt (|v| plus |ω|
/// times the farthest core point's distance from the centre of mass), or
/// infinity when the body has no reach (sensors only): measure it.
float comingMotion(const Body& body, float dt) {
    if (body.reach < 0.0f) return INFINITY;
    return dt * (length(body.v) + std::abs(body.w) * (body.reach + length(body.localCenter)));
}

// The box a moving shape's fat box must hold for the next step of dt: its
// speculative box now and where the body's velocity takes it by the step's
// end. A pair is found only at a step's start, from the fat boxes, and the
// narrowphase's margin (contact.cpp) covers how far two bodies close within
// the step only for pairs that exist: a fat box checked against the shape's
// box alone let a body leave it within the step with no pair ahead of it. A
// kinematic wall moving 1 m a step went into a box up to 0.5 m with no
// contact at all in its first step, and in a step whose end carried its box
// past its fat box (docs/robustness.md, "Fast kinematic bodies"). A turn
// moves a point along an arc, which leaves the chord between the arc's ends
// by at most r·(1 − cos(θ/2)) (r its distance from the centre of mass, θ the
// turn), so the two boxes are grown by that for the shape's farthest corner
// (a circle's centre).
// Without velocity, or with dt 0 (a body moved by the game), the box now.
// Nor when no point moves further than the speculative distance within the
// step: the box grown by it holds every shape the body can then reach
// within that distance of (which it could not overlap), and the next step's
// pairs have them.
AABB comingBox(const WorldState& w, const Shape& sh, const Body& body, float dt) {
    AABB box = speculativeBox(w, sh, body);
    if (!(dt > 0.0f) || body.type == BodyType::static_body) return box;
    const float turn = body.w * dt;
    const Vec2 move = dt * body.v;
    if (!(comingMotion(body, dt) > w.settings.speculativeDistance)) return box;
    Transform next;
    next.q = mulRot(body.xf.q, makeRot(turn));
    next.p = (body.center + move) - rotate(next.q, body.localCenter);
    box = unionOf(box, speculativeBox(w, sh, body, next));
    if (turn != 0.0f) {
        // A circle's box follows its centre alone: r is the centre's
        // distance from the centre of mass (none for a circle around it).
        float r = 0.0f;
        if (sh.type == ShapeType::circle) {
            r = length(transformPoint(body.xf, sh.geometry.circle.center) - body.center);
        } else {
            for (const Vec2 corner :
                 {box.lower, box.upper, Vec2{box.lower.x, box.upper.y}, Vec2{box.upper.x, box.lower.y}})
                r = std::max(r, length(corner - body.center));
        }
        const float half = 0.5f * std::abs(turn);
        if (r > 0.0f) box = fatten(box, half >= 1.5707964f ? 2.0f * r : r * (1.0f - std::cos(half)));
    }
    return box;
}
}  // namespace

void createProxy(WorldState& w, int s) {
    Shape& sh = w.shapes[s];
    const Body& body = w.bodies[sh.body];
    BroadPhase& bp = w.broadPhase;
    if (!body.enabled) return;  // a disabled body's shapes stay out of the trees
    // Static boxes are exact: they never move, so a margin would only make
    // more pairs.
    if (bp.fatBoxes.size() < static_cast<std::size_t>(w.shapes.capacity())) {
        bp.fatBoxes.reserve(w.shapes.items.capacity());  // grown as the shapes are (grownCapacity)
        bp.fatBoxes.resize(static_cast<std::size_t>(w.shapes.capacity()));
    }
    AABB& fat = bp.fatBox(s);
    fat = fatten(speculativeBox(w, sh, body), body.type == BodyType::static_body ? 0.0f : w.settings.aabbMargin);
    w.bodies[sh.body].boxSlack = 0.0f;  // a new box: measure again
    sh.treeType = body.type;
    sh.proxy = bp.tree(sh.treeType).createProxy(fat, s);
    if (!sh.inStaticTree()) {
        sh.moved = true;
        bp.moveBuffer.push_back(s);
    } else {
        // A new static shape: let the dynamic shapes around it look again.
        bp.dynamicTree.query(fat, [&](int other) {
            Shape& o = w.shapes[other];
            if (!o.moved) {
                o.moved = true;
                bp.moveBuffer.push_back(other);
            }
            return true;
        });
    }
}

void destroyProxy(WorldState& w, int s) {
    Shape& sh = w.shapes[s];
    BroadPhase& bp = w.broadPhase;
    if (sh.proxy == DynamicTree::kNull) return;
    w.bodies[sh.body].boxSlack = 0.0f;
    bp.tree(sh.treeType).destroyProxy(sh.proxy);
    sh.proxy = DynamicTree::kNull;
    if (sh.moved) {
        bp.moveBuffer.erase(std::remove(bp.moveBuffer.begin(), bp.moveBuffer.end(), s), bp.moveBuffer.end());
        sh.moved = false;
    }
}

void synchronizeProxies(WorldState& w, int b, float dt) {
    const Body& body = w.bodies[b];
    BroadPhase& bp = w.broadPhase;
    if (!body.enabled) return;
    // A box that must move is stretched ahead along the body's motion, by
    // kMotionAhead steps of it beyond the coming step comingBox holds, so
    // that a moving body re-inserts its proxy (and queries the tree for new
    // pairs) every few steps rather than every step (Box2D 2.4.1's
    // b2_aabbMultiplier). joint_grid's swinging grid spent a fifth of its
    // first 5 s moving proxies. Four steps in all before the coming step
    // was held; three now: with four, the boxes met more pairs ahead and
    // rain1000's narrowphase took 17 % longer (its step 6 %); with three its
    // step takes 0.96 to 0.99 of its time before the coming step was held,
    // circle_pile1000's 0.99, pyramid100's the same within the noise, and
    // joint_grid's 1.08 to 1.10: its swinging bodies now leave their fat
    // boxes sooner, so their proxies move and query more often (the engine
    // alone, medians over 200 to 600 steps, three rounds interleaved).
    constexpr float kMotionAhead = 2.0f;
    const Vec2 ahead = (kMotionAhead * dt) * body.v;
    for (int s : bodyShapes(w.shapes, body)) {
        Shape& sh = w.shapes[s];
        AABB box = comingBox(w, sh, body, dt);
        AABB& fat = bp.fatBox(s);
        if (contains(fat, box)) continue;
        w.bodies[b].boxSlack = 0.0f;  // measured against the old box
        fat = fatten(box, body.type == BodyType::static_body ? 0.0f : w.settings.aabbMargin);
        if (body.type != BodyType::static_body && isFinite(ahead.x + ahead.y)) {
            (ahead.x < 0.0f ? fat.lower.x : fat.upper.x) += ahead.x;
            (ahead.y < 0.0f ? fat.lower.y : fat.upper.y) += ahead.y;
        }
        bp.tree(sh.treeType).moveProxy(sh.proxy, fat);
        bp.markMoved(sh, s);
    }
}

// A shape's box moves by at most how far its farthest core point can move:
// |Δp| of the body's origin plus that point's distance from the origin,
// at most reach + |localCenter| (Body::reach is from the centre of mass),
// times the turn (a chord is shorter than its arc). A rounded shape's box is
// its core's grown by the radius, which no turn changes. So while that bound
// stays below the room the boxes had when last measured (Body::boxSlack),
// every box still lies inside its fat box, and none is computed: resting
// bodies, which are most, cost a rotation product and a square root instead
// of a box per shape (a box's four corners turned: 2.3 % of pyramid100's
// instructions). The room is taken a little short of what was measured, for
// the rounding of the two boxes' coordinates.
namespace {
/// Whether the body's shapes may have moved as far as the room its boxes had
/// when last measured (the comment above), by the rotation product and the
/// square roots alone.
inline bool mayHaveLeft(const Body& body, float dt, float speculative) {
    if (!(body.boxSlack > 0.0f)) return true;
    const float angle = turnBoundOf(invMulRot(body.boxRotation, body.xf.q));
    const float arm = body.reach + length(body.localCenter);
    // How far it may have moved since, and may move in the next step (comingBox).
    const float moved = length(body.xf.p - body.boxOrigin) + angle * arm;
    const float coming = comingMotion(body, dt);
    return !(moved + (coming > speculative ? coming : 0.0f) < body.boxSlack);
}

/// leftFatBoxes past the bound: each shape's coming box against its fat box,
/// and the room measured again.
bool measureFatBoxes(const WorldState& w, Body& body) {
    const float dt = w.stepDt;
    float room = INFINITY, extent = 0.0f;
    bool measurable = body.reach >= 0.0f;  // reach bounds solid shapes only
    for (int s : bodyShapes(w.shapes, body)) {
        const AABB box = comingBox(w, w.shapes[s], body, dt);
        const AABB& fat = w.broadPhase.fatBox(s);
        if (!contains(fat, box)) {
            body.boxSlack = 0.0f;
            return true;
        }
        room = std::min({room, box.lower.x - fat.lower.x, box.lower.y - fat.lower.y, fat.upper.x - box.upper.x,
                         fat.upper.y - box.upper.y});
        extent = std::max(
            {extent, std::abs(box.lower.x), std::abs(box.lower.y), std::abs(box.upper.x), std::abs(box.upper.y)});
        measurable = measurable && !w.shapes[s].isSensor;
    }
    // Eight units in the last place of the largest coordinate, for rounding.
    const float rounding = 1.0e-6f * (1.0f + extent);
    body.boxSlack = measurable && room > rounding ? room - rounding : 0.0f;
    body.boxOrigin = body.xf.p;
    body.boxRotation = body.xf.q;
    return false;
}
}  // namespace

void leftFatBoxes(WorldState& w, const int* bodies, std::size_t count, std::uint8_t* leaves) {
    // Two passes: the bound for every body first, a short loop without calls
    // whose square roots the CPU works on for several bodies at once, then
    // the measuring for the bodies the bound leaves in doubt. Asked body by
    // body, each bound waited on its square roots before the next body's
    // began: a swinging hinge grid spent 7 % of its step here.
    const float dt = w.stepDt, speculative = w.settings.speculativeDistance;
    for (std::size_t i = 0; i < count; ++i) {
        const Body& body = w.bodies[bodies[i]];
        leaves[i] = body.enabled && mayHaveLeft(body, dt, speculative) ? 1 : 0;
    }
    for (std::size_t i = 0; i < count; ++i)
        if (leaves[i]) leaves[i] = measureFatBoxes(w, w.bodies[bodies[i]]) ? 1 : 0;
}

void noteMotionSet(WorldState& w, int b) {
    Body& body = w.bodies[b];
    if (body.motionSet || body.type == BodyType::static_body) return;
    body.motionSet = true;
    w.broadPhase.motionSet.push_back(b);
}

void coverSetMotions(WorldState& w, float dt) {
    std::vector<int>& bodies = w.broadPhase.motionSet;
    for (const int b : bodies) {
        Body& body = w.bodies[b];
        if (!body.motionSet) continue;  // destroyed since (its slot may be another body's)
        body.motionSet = false;
        if (body.alive && body.awake) synchronizeProxies(w, b, dt);
    }
    bodies.clear();
}

void refreshProxies(WorldState& w, float dt) {
    const std::vector<int>& awake = w.islands.awakeBodies;
    std::vector<std::uint8_t>& leaves = w.broadPhase.proxyLeaves;
    for (std::size_t i = 0; i < awake.size(); ++i)
        if (leaves[i]) {
            synchronizeProxies(w, awake[i], dt);
            leaves[i] = 0;
        }
}

void wakeShapesAround(WorldState& w, int b) {
    BroadPhase& bp = w.broadPhase;
    if (!w.bodies[b].enabled) return;
    // Only the dynamic shapes can touch it; kinematic ones are woken too, as
    // a static body's move wakes whatever lies against it.
    auto wake = [&](int other) {
        Shape& o = w.shapes[other];
        wakeBody(w, o.body);
        bp.markMoved(o, other);
        return true;
    };
    for (int s : bodyShapes(w.shapes, w.bodies[b])) {
        const AABB box = bp.fatBox(s);
        bp.kinematicTree.query(box, wake);
        bp.dynamicTree.query(box, wake);
    }
}

}  // namespace i2d::detail
