// World::draw: hands every shape, joint and (optionally) AABB and contact to
// a DebugDraw implementation, in world coordinates.
#include <algorithm>

#include "impulse2d/world.hpp"
#include "world_state.hpp"

namespace i2d {

namespace {
Color bodyColor(const detail::Body& b) {
    if (b.type == BodyType::static_body) return {0.45f, 0.55f, 0.45f, 1.0f};
    if (b.type == BodyType::kinematic_body) return {0.45f, 0.45f, 0.8f, 1.0f};
    if (!b.awake) return {0.55f, 0.55f, 0.6f, 1.0f};
    return {0.9f, 0.7f, 0.45f, 1.0f};
}
}  // namespace

void World::draw(DebugDraw& dd) const {
    // A drawer that calls back into the world to create or destroy things
    // would edit the arrays iterated here: such calls are refused.
    bool& locked = state().locked;
    const bool wasLocked = locked;
    locked = true;
    struct Restore {
        bool& flag;
        bool value;
        ~Restore() { flag = value; }
    } restore{locked, wasLocked};
    const auto& w = state();
    if (dd.drawShapes) {
        for (int s = 0; s < w.shapes.capacity(); ++s) {
            const detail::Shape& sh = w.shapes[s];
            if (!sh.alive) continue;
            const detail::Body& b = w.bodies[sh.body];
            if (!b.enabled) continue;  // out of the world until enabled again
            Color c = bodyColor(b);
            if (sh.isSensor) c.a = 0.3f;
            switch (sh.type) {
                case ShapeType::circle: {
                    Vec2 center = transformPoint(b.xf, sh.geometry.circle.center);
                    dd.drawSolidCircle(center, sh.geometry.circle.radius, rotate(b.xf.q, {1.0f, 0.0f}), c);
                    break;
                }
                case ShapeType::capsule:
                    dd.drawSolidCapsule(transformPoint(b.xf, sh.geometry.capsule.center1),
                                        transformPoint(b.xf, sh.geometry.capsule.center2), sh.geometry.capsule.radius,
                                        c);
                    break;
                case ShapeType::polygon:
                    dd.drawSolidPolygon(b.xf, sh.geometry.polygon.vertices, sh.geometry.polygon.count,
                                        sh.geometry.polygon.radius, c);
                    break;
                case ShapeType::segment: {
                    const Vec2 p1 = transformPoint(b.xf, sh.geometry.segment.point1);
                    const Vec2 p2 = transformPoint(b.xf, sh.geometry.segment.point2);
                    dd.drawSegment(p1, p2, c);
                    if (sh.chainSegment) {
                        // A chain collides on its right side: a tick from the
                        // middle towards it, a fifth of the segment (≤ 0.2 m).
                        const Vec2 mid = 0.5f * (p1 + p2);
                        const float tick = std::min(0.2f * length(p2 - p1), 0.2f);
                        dd.drawSegment(mid, mid + tick * rightPerp(normalize(p2 - p1)), c);
                    }
                    break;
                }
            }
        }
    }
    if (dd.drawJoints) {
        const Color colour{0.3f, 0.8f, 0.8f, 1.0f};
        for (int j = 0; j < w.joints.capacity(); ++j) {
            const detail::Joint& jt = w.joints[j];
            if (!jt.alive) continue;
            const Transform& xfA = w.bodies[jt.bodyA].xf;
            const Transform& xfB = w.bodies[jt.bodyB].xf;
            const detail::JointAnchors an = detail::jointAnchors(w, jt);
            if (jt.type == JointType::pulley) {
                const PulleyJointDef& def = std::get<PulleyJointDef>(jt.def);
                dd.drawSegment(def.groundAnchorA, an.a, colour);
                dd.drawSegment(def.groundAnchorB, an.b, colour);
                dd.drawSegment(def.groundAnchorA, def.groundAnchorB, colour);
            } else {
                // From each body's origin to its anchor, and anchor to anchor.
                dd.drawSegment(xfA.p, an.a, colour);
                dd.drawSegment(an.a, an.b, colour);
                dd.drawSegment(xfB.p, an.b, colour);
            }
            dd.drawPoint(an.a, 4.0f, colour);
            dd.drawPoint(an.b, 4.0f, colour);
        }
    }
    if (dd.drawAABBs) {
        for (int s = 0; s < w.shapes.capacity(); ++s) {
            const detail::Shape& sh = w.shapes[s];
            if (!sh.alive || sh.proxy == detail::DynamicTree::kNull) continue;  // no box: not in a tree
            const AABB& a = w.broadPhase.fatBox(s);
            Color c{0.8f, 0.3f, 0.8f, 1.0f};
            dd.drawSegment(a.lower, {a.upper.x, a.lower.y}, c);
            dd.drawSegment({a.upper.x, a.lower.y}, a.upper, c);
            dd.drawSegment(a.upper, {a.lower.x, a.upper.y}, c);
            dd.drawSegment({a.lower.x, a.upper.y}, a.lower, c);
        }
    }
    if (dd.drawContacts || dd.drawContactNormals) {
        for (int c = 0; c < w.contacts.capacity(); ++c) {
            const detail::Contact& ct = w.contacts[c];
            if (!ct.alive || !ct.touching || ct.isSensor) continue;
            for (int j = 0; j < ct.manifold.pointCount; ++j) {
                const ManifoldPoint& mp = ct.manifold.points[j];
                if (dd.drawContacts)
                    dd.drawPoint(mp.point, 5.0f,
                                 mp.separation < 0.0f ? Color{0.9f, 0.2f, 0.2f, 1.0f} : Color{0.2f, 0.6f, 0.9f, 1.0f});
                if (dd.drawContactNormals)
                    dd.drawSegment(mp.point, mp.point + 0.3f * ct.manifold.normal, {0.9f, 0.9f, 0.3f, 1.0f});
            }
        }
    }
}

}  // namespace i2d
