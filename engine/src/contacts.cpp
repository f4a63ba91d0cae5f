// Broadphase pair finding and the narrowphase update of contacts.
//
// Pairs: shapes whose proxies moved (left their fattened box) or were
// created are queried against both trees; a pair that passes the filters and
// is not yet known becomes a contact. Only new pairs are reported, so the
// cost per step follows how much moved, not how much exists.
//
// Contacts: each step, every contact with an awake body recomputes its
// manifold. A contact whose fattened boxes no longer overlap is destroyed.
// Manifold points keep the accumulated impulses of the previous step's point
// with the same feature id: seed 001's "contact caching", the warm start.
#include <algorithm>
#include <cmath>

#include "world_impl.hpp"

namespace i2d::detail {

namespace {

std::uint64_t pairKey(int a, int b) {
    auto lo = static_cast<std::uint64_t>(std::min(a, b));
    auto hi = static_cast<std::uint64_t>(std::max(a, b));
    return (hi << 32) | lo;
}

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

}  // namespace

void WorldImpl::createProxy(int s) {
    Shape& sh = shapes[s];
    const Body& body = bodies[sh.body];
    AABB box = computeShapeAABB(sh, body.xf);
    float m = body.type == BodyType::static_body ? 0.0f : settings.aabbMargin;
    sh.fatAABB = {{box.lower.x - m, box.lower.y - m}, {box.upper.x + m, box.upper.y + m}};
    sh.inStaticTree = body.type == BodyType::static_body;
    DynamicTree& tree = sh.inStaticTree ? staticTree : movingTree;
    sh.proxy = tree.createProxy(sh.fatAABB, s);
    if (!sh.inStaticTree) {
        sh.moved = true;
        moveBuffer.push_back(s);
    } else {
        // A new static shape: let the moving shapes around it look again.
        movingTree.query(sh.fatAABB, [&](int other) {
            Shape& o = shapes[other];
            if (!o.moved) {
                o.moved = true;
                moveBuffer.push_back(other);
            }
            return true;
        });
    }
}

void WorldImpl::destroyProxy(int s) {
    Shape& sh = shapes[s];
    if (sh.proxy == DynamicTree::kNull) return;
    (sh.inStaticTree ? staticTree : movingTree).destroyProxy(sh.proxy);
    sh.proxy = DynamicTree::kNull;
    if (sh.moved) {
        moveBuffer.erase(std::remove(moveBuffer.begin(), moveBuffer.end(), s), moveBuffer.end());
        sh.moved = false;
    }
}

bool WorldImpl::jointPreventsCollision(int a, int b) const {
    const Body& ba = bodies[a];
    const Body& bb = bodies[b];
    const Body& fewer = ba.joints.size() <= bb.joints.size() ? ba : bb;
    for (int j : fewer.joints) {
        const DistanceJoint& jt = joints[j];
        if (!jt.def.collideConnected && ((jt.bodyA == a && jt.bodyB == b) || (jt.bodyA == b && jt.bodyB == a)))
            return true;
    }
    return false;
}

void WorldImpl::updatePairs() {
    // Deterministic: the move buffer is in the order proxies moved, queries
    // visit the trees in a fixed order, and contacts are created as found.
    for (int s : moveBuffer) {
        const Shape& sh = shapes[s];
        const AABB box = sh.fatAABB;
        auto visit = [&](int other) {
            if (other == s) return true;
            const Shape& o = shapes[other];
            // Both moved: the pair is handled once, from the lower index.
            if (o.moved && other < s && !o.inStaticTree) return true;
            if (o.body == sh.body) return true;
            const Body& b1 = bodies[sh.body];
            const Body& b2 = bodies[o.body];
            if (b1.type != BodyType::dynamic_body && b2.type != BodyType::dynamic_body) return true;
            if (sh.isSensor && o.isSensor) return true;
            if (!shouldCollide(sh.filter, o.filter)) return true;
            if (pairs.find(pairKey(s, other)) != pairs.end()) return true;
            if (jointPreventsCollision(sh.body, o.body)) return true;
            createContact(s, other);
            return true;
        };
        movingTree.query(box, visit);
        if (!sh.inStaticTree) staticTree.query(box, visit);
    }
    for (int s : moveBuffer) shapes[s].moved = false;
    moveBuffer.clear();
}

void WorldImpl::createContact(int s1, int s2) {
    if (typeRank(shapes[s1].type) < typeRank(shapes[s2].type)) std::swap(s1, s2);
    int c = contacts.allocate();
    Contact& ct = contacts[c];
    const Shape& a = shapes[s1];
    const Shape& b = shapes[s2];
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
    ct.enableEvents = ct.isSensor ? ((a.isSensor ? a.enableSensorEvents : b.enableSensorEvents))
                                  : (a.enableContactEvents || b.enableContactEvents);
    ct.key = pairKey(s1, s2);
    pairs.emplace(ct.key, c);
    bodies[a.body].contacts.push_back(c);
    bodies[b.body].contacts.push_back(c);
}

void WorldImpl::destroyContact(int c, bool emitEvents) {
    Contact& ct = contacts[c];
    if (ct.touching && emitEvents && ct.enableEvents) {
        if (ct.isSensor) {
            bool aSensor = shapes[ct.shapeA].isSensor;
            sensorEndEvents.push_back({shapeHandle(aSensor ? ct.shapeA : ct.shapeB), shapeHandle(aSensor ? ct.shapeB : ct.shapeA)});
        } else {
            endEvents.push_back({shapeHandle(ct.shapeA), shapeHandle(ct.shapeB)});
        }
    }
    pairs.erase(ct.key);
    for (int b : {ct.bodyA, ct.bodyB}) {
        auto& list = bodies[b].contacts;
        auto it = std::find(list.begin(), list.end(), c);
        if (it != list.end()) {
            *it = list.back();
            list.pop_back();
        }
    }
    contacts.release(c);
}

Manifold WorldImpl::computeManifold(const Contact& c) const {
    const Shape& a = shapes[c.shapeA];
    const Shape& b = shapes[c.shapeB];
    const Transform& xa = bodies[c.bodyA].xf;
    const Transform& xb = bodies[c.bodyB].xf;
    // Sensors report overlap only: no speculative margin.
    const float spec = c.isSensor ? 0.0f : settings.speculativeDistance;
    switch (a.type) {
        case ShapeType::segment:
            switch (b.type) {
                case ShapeType::circle: return collideSegmentAndCircle(a.segment, xa, b.circle, xb, spec);
                case ShapeType::capsule: return collideSegmentAndCapsule(a.segment, xa, b.capsule, xb, spec);
                case ShapeType::polygon: return collideSegmentAndPolygon(a.segment, xa, b.polygon, xb, spec);
                case ShapeType::segment: return {};  // two segments have no area to collide
            }
            break;
        case ShapeType::polygon:
            switch (b.type) {
                case ShapeType::circle: return collidePolygonAndCircle(a.polygon, xa, b.circle, xb, spec);
                case ShapeType::capsule: return collidePolygonAndCapsule(a.polygon, xa, b.capsule, xb, spec);
                case ShapeType::polygon: return collidePolygons(a.polygon, xa, b.polygon, xb, spec);
                default: break;
            }
            break;
        case ShapeType::capsule:
            switch (b.type) {
                case ShapeType::circle: return collideCapsuleAndCircle(a.capsule, xa, b.circle, xb, spec);
                case ShapeType::capsule: return collideCapsules(a.capsule, xa, b.capsule, xb, spec);
                default: break;
            }
            break;
        case ShapeType::circle:
            if (b.type == ShapeType::circle) return collideCircles(a.circle, xa, b.circle, xb, spec);
            break;
    }
    return {};
}

void WorldImpl::collide() {
    // Gather each contact with an awake body once (a sleeping or static
    // pair costs nothing here). A touch can wake a sleeping island; its
    // contacts are then gathered in a further round of the same loop so the
    // island is supported in this very step.
    ++stepStamp;
    activeContacts.clear();
    std::size_t bodyCursor = 0;
    std::size_t processed = 0;
    scratch.clear();
    while (bodyCursor < awakeBodies.size()) {
        std::size_t roundBegin = scratch.size();
        for (; bodyCursor < awakeBodies.size(); ++bodyCursor) {
            for (int c : bodies[awakeBodies[bodyCursor]].contacts) {
                Contact& ct = contacts[c];
                if (ct.stamp == stepStamp) continue;
                ct.stamp = stepStamp;
                scratch.push_back(c);
            }
        }
        // Contact-slot order, so results do not depend on the awake list's order.
        std::sort(scratch.begin() + static_cast<std::ptrdiff_t>(roundBegin), scratch.end());
        for (; processed < scratch.size(); ++processed) {
            int c = scratch[processed];
            if (updateContact(c)) activeContacts.push_back(c);
        }
    }
}

bool WorldImpl::updateContact(int c) {
    Contact& ct = contacts[c];
    const Shape& a = shapes[ct.shapeA];
    const Shape& b = shapes[ct.shapeB];
    if (!overlaps(a.fatAABB, b.fatAABB)) {
        destroyContact(c, true);
        return false;
    }
    Manifold m = computeManifold(ct);
    bool touching;
    if (ct.isSensor) {
        touching = false;
        for (int i = 0; i < m.pointCount; ++i) touching = touching || m.points[i].separation < 0.0f;
    } else {
        touching = m.pointCount > 0;
        // Warm start: carry impulses over by feature id.
        float ni[2] = {0.0f, 0.0f}, ti[2] = {0.0f, 0.0f};
        for (int i = 0; i < m.pointCount; ++i) {
            for (int j = 0; j < ct.manifold.pointCount; ++j) {
                if (ct.manifold.points[j].id == m.points[i].id) {
                    ni[i] = ct.normalImpulse[j];
                    ti[i] = ct.tangentImpulse[j];
                    break;
                }
            }
        }
        for (int i = 0; i < 2; ++i) {
            ct.normalImpulse[i] = ni[i];
            ct.tangentImpulse[i] = ti[i];
        }
    }
    ct.manifold = m;
    if (touching != ct.touching) {
        ct.touching = touching;
        if (touching) {
            // A touch wakes whatever sleeps on the other side.
            if (!bodies[ct.bodyA].awake) wakeBody(ct.bodyA);
            if (!bodies[ct.bodyB].awake) wakeBody(ct.bodyB);
        }
        if (ct.enableEvents) {
            if (ct.isSensor) {
                bool aSensor = a.isSensor;
                SensorBeginEvent ev{shapeHandle(aSensor ? ct.shapeA : ct.shapeB), shapeHandle(aSensor ? ct.shapeB : ct.shapeA)};
                if (touching)
                    sensorBeginEvents.push_back(ev);
                else
                    sensorEndEvents.push_back({ev.sensor, ev.visitor});
            } else if (touching) {
                beginEvents.push_back({shapeHandle(ct.shapeA), shapeHandle(ct.shapeB), m});
            } else {
                endEvents.push_back({shapeHandle(ct.shapeA), shapeHandle(ct.shapeB)});
            }
        }
    }
    return true;
}

}  // namespace i2d::detail
