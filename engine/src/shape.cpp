// Shapes: creating one on a body, destroying it with its contacts, and
// re-pairing it under a new filter.
#include <algorithm>

#include "world_state.hpp"

namespace i2d::detail {

int createShape(WorldState& w, int b, const ShapeDef& def, ShapeType type, const ShapeGeometry& geometry,
                bool updateBodyMass) {
    int s = w.shapes.allocate();
    Shape& sh = w.shapes[s];
    sh.type = type;
    sh.geometry = geometry;
    sh.body = b;
    sh.density = def.density;
    sh.friction = def.friction;
    sh.restitution = def.restitution;
    sh.filter = def.filter;
    sh.isSensor = def.isSensor;
    sh.enableContactEvents = def.enableContactEvents;
    sh.enableSensorEvents = def.enableSensorEvents;
    sh.enableHitEvents = def.enableHitEvents;
    sh.rollingResistance = def.rollingResistance;
    sh.tangentSpeed = def.tangentSpeed;
    sh.userData = def.userData;
    // Appended: a body's shapes stay in creation order (its mass sums and
    // proxy updates visit them in that order).
    Body& body = w.bodies[b];
    sh.prevShape = body.lastShape;
    if (body.lastShape != kNullIndex)
        w.shapes[body.lastShape].nextShape = s;
    else
        body.firstShape = s;
    body.lastShape = s;
    createProxy(w, s);
    // A static or kinematic body has no mass to update, only its reach.
    if (body.type != BodyType::dynamic_body) body.reach = std::max(body.reach, shapeReach(sh, body.localCenter));
    // A sleeping body stays asleep (a level built asleep stays asleep, as in
    // Box2D): its new shape's contacts wake it when one begins to touch an
    // awake body.
    if (updateBodyMass) updateMass(w, b);
    return s;
}

void destroyShape(WorldState& w, int s) {
    const int b = w.shapes[s].body;
    destroyBodyContacts(w, b, s);
    destroyProxy(w, s);
    Body& body = w.bodies[b];
    const Shape& sh = w.shapes[s];
    if (sh.prevShape != kNullIndex)
        w.shapes[sh.prevShape].nextShape = sh.nextShape;
    else
        body.firstShape = sh.nextShape;
    if (sh.nextShape != kNullIndex)
        w.shapes[sh.nextShape].prevShape = sh.prevShape;
    else
        body.lastShape = sh.prevShape;
    w.shapes.release(s);
}

void refilterShape(WorldState& w, int s) {
    destroyBodyContacts(w, w.shapes[s].body, s);
    destroyProxy(w, s);
    createProxy(w, s);
}

}  // namespace i2d::detail
