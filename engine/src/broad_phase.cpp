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
AABB speculativeBox(const WorldState& w, const Shape& sh, const Body& body) {
    return fatten(shapeAABB(sh, body.xf), body.type == BodyType::static_body ? 0.0f : w.settings.speculativeDistance);
}
}  // namespace

void createProxy(WorldState& w, int s) {
    Shape& sh = w.shapes[s];
    const Body& body = w.bodies[sh.body];
    BroadPhase& bp = w.broadPhase;
    if (!body.enabled) return;  // a disabled body's shapes stay out of the trees
    // Static boxes are exact: they never move, so a margin would only make
    // more pairs.
    if (bp.fatBoxes.size() < static_cast<std::size_t>(w.shapes.capacity()))
        bp.fatBoxes.resize(static_cast<std::size_t>(w.shapes.capacity()));
    AABB& fat = bp.fatBox(s);
    fat = fatten(speculativeBox(w, sh, body), body.type == BodyType::static_body ? 0.0f : w.settings.aabbMargin);
    sh.inStaticTree = body.type == BodyType::static_body;
    DynamicTree& tree = sh.inStaticTree ? bp.staticTree : bp.movingTree;
    sh.proxy = tree.createProxy(fat, s);
    if (!sh.inStaticTree) {
        sh.moved = true;
        bp.moveBuffer.push_back(s);
    } else {
        // A new static shape: let the moving shapes around it look again.
        bp.movingTree.query(fat, [&](int other) {
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
    (sh.inStaticTree ? bp.staticTree : bp.movingTree).destroyProxy(sh.proxy);
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
    // kMotionAhead steps of it, so that a moving body re-inserts its proxy
    // (and queries the tree for new pairs) every few steps rather than every
    // step (Box2D 2.4.1's b2_aabbMultiplier). joint_grid's swinging grid
    // spent a fifth of its first 5 s moving proxies.
    constexpr float kMotionAhead = 4.0f;
    const Vec2 ahead = (kMotionAhead * dt) * body.v;
    for (int s : bodyShapes(w.shapes, body)) {
        Shape& sh = w.shapes[s];
        AABB box = speculativeBox(w, sh, body);
        AABB& fat = bp.fatBox(s);
        if (contains(fat, box)) continue;
        fat = fatten(box, body.type == BodyType::static_body ? 0.0f : w.settings.aabbMargin);
        if (body.type != BodyType::static_body && isFinite(ahead.x + ahead.y)) {
            (ahead.x < 0.0f ? fat.lower.x : fat.upper.x) += ahead.x;
            (ahead.y < 0.0f ? fat.lower.y : fat.upper.y) += ahead.y;
        }
        DynamicTree& tree = sh.inStaticTree ? bp.staticTree : bp.movingTree;
        tree.moveProxy(sh.proxy, fat);
        bp.markMoved(sh, s);
    }
}

bool leftFatBox(const WorldState& w, const Body& body) {
    if (!body.enabled) return false;
    for (int s : bodyShapes(w.shapes, body))
        if (!contains(w.broadPhase.fatBox(s), speculativeBox(w, w.shapes[s], body))) return true;
    return false;
}

void refreshProxies(WorldState& w, float dt) {
    const std::vector<int>& awake = w.islands.awakeBodies;
    const std::vector<std::uint8_t>& leaves = w.broadPhase.proxyLeaves;
    for (std::size_t i = 0; i < awake.size(); ++i)
        if (leaves[i]) synchronizeProxies(w, awake[i], dt);
}

void wakeShapesAround(WorldState& w, int b) {
    BroadPhase& bp = w.broadPhase;
    if (!w.bodies[b].enabled) return;
    for (int s : bodyShapes(w.shapes, w.bodies[b])) {
        const AABB box = bp.fatBox(s);
        bp.staticTree.query(box, [&](int other) {
            Shape& o = w.shapes[other];
            if (w.bodies[o.body].type != BodyType::static_body) wakeBody(w, o.body);
            bp.markMoved(o, other);
            return true;
        });
        bp.movingTree.query(box, [&](int other) {
            Shape& o = w.shapes[other];
            wakeBody(w, o.body);
            if (!o.moved) {
                o.moved = true;
                bp.moveBuffer.push_back(other);
            }
            return true;
        });
    }
}

}  // namespace i2d::detail
