// Bodies: mass properties from the shapes, the reach of a body's surface,
// and whether a joint keeps two bodies from colliding.
#include <algorithm>

#include "world_state.hpp"

namespace i2d::detail {

void updateMass(WorldState& w, int b) {
    w.solver.jointPlanStale = true;  // the joints' rows read the masses
    Body& body = w.bodies[b];
    body.mass = body.invMass = body.inertia = body.invInertia = 0.0f;
    body.localCenter = {};
    if (body.type != BodyType::dynamic_body) {
        // Its reach is kept as it is: grown as shapes are added (createShape),
        // so a level of many shapes on one static body is built in linear time.
        body.center = transformPoint(body.xf, body.localCenter);
        return;
    }
    // Parallel-axis sum: I_origin = Σ (I_i + m_i |c_i|²); I_com = I_origin − M |c|².
    float inertiaAtOrigin = 0.0f;
    Vec2 weighted{};
    for (int s : bodyShapes(w.shapes, body)) {
        const Shape& sh = w.shapes[s];
        if (sh.density == 0.0f) continue;
        const std::optional<MassData> md = shapeMass(sh);
        if (!md) continue;
        body.mass += md->mass;
        weighted += md->mass * md->center;
        inertiaAtOrigin += md->rotationalInertia + md->mass * dot(md->center, md->center);
    }
    // A positive mass too small to invert (denormal densities) counts as no
    // mass: 1/m would be infinite and the centre of mass 0·∞ = NaN.
    if (body.mass > 0.0f && isFinite(1.0f / body.mass)) {
        body.invMass = 1.0f / body.mass;
        body.localCenter = body.invMass * weighted;
        body.inertia = inertiaAtOrigin - body.mass * dot(body.localCenter, body.localCenter);
    } else {
        // A dynamic body without mass still needs one to move: 1 kg, no rotation.
        body.mass = 1.0f;
        body.invMass = 1.0f;
        body.inertia = 0.0f;
    }
    body.reach = solidReach(w, body);
    if (body.inertia > 0.0f && isFinite(1.0f / body.inertia) && !body.fixedRotation) {
        body.invInertia = 1.0f / body.inertia;
    } else {
        body.invInertia = 0.0f;
    }
    // Keep the velocity of the centre of mass consistent when it shifts.
    Vec2 oldCenter = body.center;
    body.center = transformPoint(body.xf, body.localCenter);
    body.v += cross(body.w, body.center - oldCenter);
}

float shapeReach(const Shape& shape, Vec2 from) {
    if (shape.isSensor) return -1.0f;
    float reach = -1.0f;
    const ShapeCore core = shapeCore(shape);
    for (int k = 0; k < core.count; ++k) reach = std::max(reach, length(core.points[k] - from));
    return reach;
}

float solidReach(const WorldState& w, const Body& body) {
    float reach = -1.0f;
    for (int s : bodyShapes(w.shapes, body)) reach = std::max(reach, shapeReach(w.shapes[s], body.localCenter));
    return reach;
}

bool jointPreventsCollision(const WorldState& w, int a, int b) {
    const Body& ba = w.bodies[a];
    const Body& bb = w.bodies[b];
    const int fewer = ba.jointCount <= bb.jointCount ? a : b;
    for (int j : bodyJoints(w.joints, w.bodies[fewer], fewer)) {
        const Joint& jt = w.joints[j];
        if (!jt.collideConnected && ((jt.bodyA == a && jt.bodyB == b) || (jt.bodyA == b && jt.bodyB == a))) return true;
    }
    return false;
}

}  // namespace i2d::detail
