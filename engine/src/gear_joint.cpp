// The gear joint: couples two revolute or prismatic joints so that
// coordinate1 + ratio·coordinate2 stays constant (angles in rad, translations
// in m). Joint 1 moves body A relative to its frame C, joint 2 body B relative
// to D; the gear's row acts on all four bodies.
//
// Coordinates and their Jacobians, for a body X moved relative to a frame F:
//   revolute:  q = θ_X − θ_F,            J v = ω_X − ω_F;
//   prismatic: q = u·d, d = p_X − p_F,   J v = u·(v_X − v_F) + (r_X × u) ω_X − ((d + r_F) × u) ω_F,
//              u the joint's axis turning with F.
// C = q1 + r·q2 − constant, J = J1 + r·J2, m_eff = 1/Σ(m⁻¹|J_v|² + I⁻¹ J_ω²) over
// the four bodies; a bilateral row softened like every rigid row. Angles are
// not wrapped: the gear keeps the error C at the end of each step
// (Joint::gearError) and adds the change of each coordinate within the step,
// so it follows any number of turns.
// Impulses: axial.
#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// One coupled joint's contribution now: its coordinate's change since the
/// step began and its Jacobian on the moving body X and the frame F.
struct GearPart {
    float delta = 0.0f;
    Vec2 jvX{}, jvF{};
    float jwX = 0.0f, jwF = 0.0f;
};

GearPart gearPart(bool prismatic, Vec2 axisF0, Vec2 rF0, Vec2 rX0, Vec2 deltaCenterFX, float start, const BodyState& sX,
                  const BodyState& sF) {
    GearPart p;
    if (!prismatic) {
        p.delta = angleOf(invMulRot(sF.dq, sX.dq));
        p.jwX = 1.0f;
        p.jwF = -1.0f;
        return p;
    }
    const Vec2 u = rotate(sF.dq, axisF0);
    const Vec2 rF = rotate(sF.dq, rF0), rX = rotate(sX.dq, rX0);
    const Vec2 d = (sX.dp - sF.dp) + deltaCenterFX + rX - rF;
    p.delta = dot(u, d) - start;
    p.jvX = u;
    p.jvF = -1.0f * u;
    p.jwX = cross(rX, u);
    p.jwF = -cross(d + rF, u);
    return p;
}

struct GearNow {
    GearPart p1, p2;
    float C;
};

GearNow gearNow(const JointConstraint& jc, const GearStates& s) {
    const GearRow& row = jc.row.gear;
    GearNow g;
    g.p1 = gearPart(row.prismatic1, row.axisC, row.rCAnchor, row.rAAnchor, row.deltaCenterCA, row.reference1, s.a, s.c);
    g.p2 = gearPart(row.prismatic2, row.axisD, row.rDAnchor, row.rBAnchor, row.deltaCenterDB, row.reference2, s.b, s.d);
    g.C = row.errorAtStart + g.p1.delta + row.ratio * g.p2.delta;
    return g;
}

void applyGear(const JointConstraint& jc, const GearNow& g, float impulse, GearStates s) {
    const float r = jc.row.gear.ratio;
    s.a.v = mulAdd(s.a.v, jc.invMassA * impulse, g.p1.jvX);
    s.a.w += jc.invIA * impulse * g.p1.jwX;
    s.c.v = mulAdd(s.c.v, jc.invMassC * impulse, g.p1.jvF);
    s.c.w += jc.invIC * impulse * g.p1.jwF;
    s.b.v = mulAdd(s.b.v, jc.invMassB * r * impulse, g.p2.jvX);
    s.b.w += jc.invIB * r * impulse * g.p2.jwX;
    s.d.v = mulAdd(s.d.v, jc.invMassD * r * impulse, g.p2.jvF);
    s.d.w += jc.invID * r * impulse * g.p2.jwF;
}

/// For a prismatic joint: its axis in world, anchors relative to the centres,
/// the centre of the moving body from the frame's, and the translation.
struct SliderStart {
    Vec2 axis, rF, rX, deltaCenter;
    float translation;
};

SliderStart sliderStart(const WorldState& w, const Joint& joint) {
    const PrismaticJointDef& def = std::get<PrismaticJointDef>(joint.def);
    const Body& f = w.bodies[joint.bodyA];
    const Body& x = w.bodies[joint.bodyB];
    SliderStart s;
    s.axis = rotate(f.xf.q, normalize(def.localAxisA));
    s.rF = rotate(f.xf.q, def.localAnchorA - f.localCenter);
    s.rX = rotate(x.xf.q, def.localAnchorB - x.localCenter);
    s.deltaCenter = x.center - f.center;
    s.translation = dot(s.axis, s.deltaCenter + s.rX - s.rF);
    return s;
}

}  // namespace

void prepareGearJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const GearJointDef& def = std::get<GearJointDef>(joint.def);
    const Joint& j1 = w.joints[joint.joint1];
    const Joint& j2 = w.joints[joint.joint2];
    GearRow& row = jc.row.gear;
    row = GearRow{};
    row.ratio = def.ratio;
    row.errorAtStart = joint.gearError;
    row.prismatic1 = j1.type == JointType::prismatic;
    row.prismatic2 = j2.type == JointType::prismatic;
    if (row.prismatic1) {
        const SliderStart s = sliderStart(w, j1);
        row.axisC = s.axis;
        row.rCAnchor = s.rF;
        row.rAAnchor = s.rX;
        row.deltaCenterCA = s.deltaCenter;
        row.reference1 = s.translation;
    }
    if (row.prismatic2) {
        const SliderStart s = sliderStart(w, j2);
        row.axisD = s.axis;
        row.rDAnchor = s.rF;
        row.rBAnchor = s.rX;
        row.deltaCenterDB = s.deltaCenter;
        row.reference2 = s.translation;
    }
}

void warmStartGearJoint(const JointConstraint& jc, GearStates s) {
    applyGear(jc, gearNow(jc, s), jc.impulses.axial, s);
}

void solveGearJoint(JointConstraint& jc, const JointContext& ctx, GearStates s) {
    const GearNow g = gearNow(jc, s);
    const float r = jc.row.gear.ratio;
    auto term = [](float m, float i, Vec2 jv, float jw) { return m * dot(jv, jv) + i * jw * jw; };
    const float k = term(jc.invMassA, jc.invIA, g.p1.jvX, g.p1.jwX) + term(jc.invMassC, jc.invIC, g.p1.jvF, g.p1.jwF) +
                    r * r *
                        (term(jc.invMassB, jc.invIB, g.p2.jvX, g.p2.jwX) +
                         term(jc.invMassD, jc.invID, g.p2.jvF, g.p2.jwF));
    const float mass = k > 0.0f ? 1.0f / k : 0.0f;
    const float cdot = dot(g.p1.jvX, s.a.v) + g.p1.jwX * s.a.w + dot(g.p1.jvF, s.c.v) + g.p1.jwF * s.c.w +
                       r * (dot(g.p2.jvX, s.b.v) + g.p2.jwX * s.b.w + dot(g.p2.jvF, s.d.v) + g.p2.jwF * s.d.w);
    const RowBias rb = rigidBias(ctx, g.C);
    const float impulse = -rb.massScale * mass * (cdot + rb.bias) - rb.impulseScale * jc.impulses.axial;
    jc.impulses.axial += impulse;
    applyGear(jc, g, impulse, s);
}

float gearCoordinateError(const JointConstraint& jc, GearStates s) { return gearNow(jc, s).C; }

float gearCoordinate(const WorldState& w, const Joint& gear) {
    const GearJointDef& def = std::get<GearJointDef>(gear.def);
    auto coordinate = [&](const Joint& j) {
        if (j.type == JointType::prismatic) return sliderStart(w, j).translation;
        return angleOf(invMulRot(w.bodies[j.bodyA].xf.q, w.bodies[j.bodyB].xf.q));
    };
    return coordinate(w.joints[gear.joint1]) + def.ratio * coordinate(w.joints[gear.joint2]);
}

}  // namespace i2d::detail
