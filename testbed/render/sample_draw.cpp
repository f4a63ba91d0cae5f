// Testbed renderer — drawing a Simulation (see sample_draw.hpp).
#include "render/sample_draw.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

namespace tb {

namespace {

i2d::Color bodyColour(const BodyDesc& body, const BodySample& s) {
    if (body.def.type == i2d::BodyType::static_body) return {0.45f, 0.55f, 0.45f, 1.0f};
    if (body.def.type == i2d::BodyType::kinematic_body) return {0.45f, 0.45f, 0.8f, 1.0f};
    if (!s.awake) return {0.55f, 0.55f, 0.6f, 1.0f};
    return {0.9f, 0.7f, 0.45f, 1.0f};
}

i2d::Transform poseOf(const BodySample& s) {
    i2d::Transform xf;
    xf.p = {s.x, s.y};
    xf.q = i2d::makeRot(s.angle);
    return xf;
}

bool finitePose(const BodySample& s) { return std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.angle); }

}  // namespace

void drawSimulation(i2d::DebugDraw& dd, const SceneDesc& desc, const Simulation& sim,
                    std::optional<i2d::Color> colour) {
    const int n = std::min(sim.bodyCount(), static_cast<int>(desc.bodies.size()));
    for (int i = 0; i < n; ++i) {
        const BodyDesc& body = desc.bodies[static_cast<std::size_t>(i)];
        const BodySample s = sim.sample(i);
        if (!finitePose(s)) continue;
        const i2d::Transform xf = poseOf(s);
        for (const ShapeDesc& shape : body.shapes) {
            i2d::Color c = colour ? *colour : bodyColour(body, s);
            if (shape.def.isSensor) c.a = 0.3f;
            if (shape.chain) {
                const std::size_t n = shape.chainPoints.size();
                for (std::size_t k = 0; k + 1 < n + (shape.chainLoop ? 1 : 0); ++k) {
                    const i2d::Vec2 p1 = i2d::transformPoint(xf, shape.chainPoints[k]);
                    const i2d::Vec2 p2 = i2d::transformPoint(xf, shape.chainPoints[(k + 1) % n]);
                    dd.drawSegment(p1, p2, c);
                    // The colliding (right) side, as the engine's debug draw shows it.
                    const i2d::Vec2 mid = 0.5f * (p1 + p2);
                    const float tick = std::min(0.2f * i2d::length(p2 - p1), 0.2f);
                    dd.drawSegment(mid, mid + tick * i2d::rightPerp(i2d::normalize(p2 - p1)), c);
                }
                continue;
            }
            switch (shape.type) {
                case i2d::ShapeType::circle:
                    dd.drawSolidCircle(i2d::transformPoint(xf, shape.circle.center), shape.circle.radius,
                                       i2d::rotate(xf.q, {1.0f, 0.0f}), c);
                    break;
                case i2d::ShapeType::capsule:
                    dd.drawSolidCapsule(i2d::transformPoint(xf, shape.capsule.center1),
                                        i2d::transformPoint(xf, shape.capsule.center2), shape.capsule.radius, c);
                    break;
                case i2d::ShapeType::polygon:
                    dd.drawSolidPolygon(xf, shape.polygon.vertices, shape.polygon.count, shape.polygon.radius, c);
                    break;
                case i2d::ShapeType::segment:
                    dd.drawSegment(i2d::transformPoint(xf, shape.segment.point1),
                                   i2d::transformPoint(xf, shape.segment.point2), c);
                    break;
            }
        }
    }
    if (!dd.drawJoints) return;
    const i2d::Color c = colour ? *colour : i2d::Color{0.8f, 0.3f, 0.8f, 1.0f};
    for (const JointDesc& j : desc.joints) {
        if (j.bodyA < 0 || j.bodyB < 0 || j.bodyA >= n || j.bodyB >= n) continue;
        const BodySample a = sim.sample(j.bodyA), b = sim.sample(j.bodyB);
        if (!finitePose(a) || !finitePose(b)) continue;
        const i2d::Transform xa = poseOf(a), xb = poseOf(b);
        std::visit(
            [&](const auto& d) {
                using D = std::decay_t<decltype(d)>;
                if constexpr (std::is_same_v<D, i2d::PulleyJointDef>) {
                    // The rope: anchor A, over both pulleys, to anchor B.
                    dd.drawSegment(i2d::transformPoint(xa, d.localAnchorA), d.groundAnchorA, c);
                    dd.drawSegment(d.groundAnchorA, d.groundAnchorB, c);
                    dd.drawSegment(d.groundAnchorB, i2d::transformPoint(xb, d.localAnchorB), c);
                } else if constexpr (std::is_same_v<D, i2d::MouseJointDef>) {
                    dd.drawSegment(d.target, {b.cx, b.cy}, c);
                } else if constexpr (requires { d.localAnchorA; }) {
                    dd.drawSegment(i2d::transformPoint(xa, d.localAnchorA), i2d::transformPoint(xb, d.localAnchorB), c);
                } else {
                    dd.drawSegment({a.cx, a.cy}, {b.cx, b.cy}, c);  // motor and gear joints: centre to centre
                }
            },
            j.def);
    }
}

}  // namespace tb
