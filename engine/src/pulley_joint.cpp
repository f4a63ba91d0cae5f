// The pulley joint: two bodies hung from two fixed ground points by one rope:
// C = L_A + r·L_B − (lengthA + r·lengthB), with L_X = |p_X − g_X| and unit
// directions u_X = (p_X − g_X)/L_X. J v = u_A·(v_A + ω_A × r_A) + r·u_B·(v_B + ω_B × r_B),
// m_eff = 1/(m_A⁻¹ + I_A⁻¹ (r_A × u_A)² + r²(m_B⁻¹ + I_B⁻¹ (r_B × u_B)²)). A
// bilateral row, softened like every rigid row.
// Impulses: axial.
#include "joint_rows.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

struct PulleyFrame {
    Vec2 rA, rB, uA, uB;
    float lengthA, lengthB;
};

PulleyFrame pulleyFrame(const JointConstraint& jc, const BodyState& sA, const BodyState& sB) {
    const PulleyRow& row = jc.row.pulley;
    PulleyFrame f;
    f.rA = rotate(sA.dq, jc.rA);
    f.rB = rotate(sB.dq, jc.rB);
    f.uA = normalize(sA.dp + f.rA - row.groundFromCenterA, f.lengthA);
    f.uB = normalize(sB.dp + f.rB - row.groundFromCenterB, f.lengthB);
    return f;
}

void applyPulley(const JointConstraint& jc, const PulleyFrame& f, float impulse, BodyState& sA, BodyState& sB) {
    const float ratio = jc.row.pulley.ratio;
    sA.v = mulAdd(sA.v, jc.invMassA * impulse, f.uA);
    sA.w += jc.invIA * impulse * cross(f.rA, f.uA);
    sB.v = mulAdd(sB.v, jc.invMassB * ratio * impulse, f.uB);
    sB.w += jc.invIB * ratio * impulse * cross(f.rB, f.uB);
}

}  // namespace

void preparePulleyJoint(const WorldState& w, const Joint& joint, JointConstraint& jc) {
    const PulleyJointDef& def = std::get<PulleyJointDef>(joint.def);
    const Body& bA = w.bodies[joint.bodyA];
    const Body& bB = w.bodies[joint.bodyB];
    setAnchors(bA, bB, def.localAnchorA, def.localAnchorB, jc);
    PulleyRow& row = jc.row.pulley;
    row.groundFromCenterA = def.groundAnchorA - bA.center;
    row.groundFromCenterB = def.groundAnchorB - bB.center;
    row.ratio = def.ratio;
    row.constant = def.lengthA + def.ratio * def.lengthB;
}

void warmStartPulleyJoint(const JointConstraint& jc, BodyState& sA, BodyState& sB) {
    applyPulley(jc, pulleyFrame(jc, sA, sB), jc.impulses.axial, sA, sB);
}

void solvePulleyJoint(JointConstraint& jc, const JointContext& ctx, BodyState& sA, BodyState& sB) {
    const PulleyRow& row = jc.row.pulley;
    const PulleyFrame f = pulleyFrame(jc, sA, sB);
    const float ruA = cross(f.rA, f.uA), ruB = cross(f.rB, f.uB);
    const float k = jc.invMassA + jc.invIA * ruA * ruA + row.ratio * row.ratio * (jc.invMassB + jc.invIB * ruB * ruB);
    const float mass = k > 0.0f ? 1.0f / k : 0.0f;
    const float cdot = dot(f.uA, sA.v + cross(sA.w, f.rA)) + row.ratio * dot(f.uB, sB.v + cross(sB.w, f.rB));
    const RowBias rb = rigidBias(ctx, f.lengthA + row.ratio * f.lengthB - row.constant);
    const float impulse = -rb.massScale * mass * (cdot + rb.bias) - rb.impulseScale * jc.impulses.axial;
    jc.impulses.axial += impulse;
    applyPulley(jc, f, impulse, sA, sB);
}

}  // namespace i2d::detail
