// The exact solve of joint trees: Baraff (1996), Linear-Time Dynamics using
// Lagrange Multipliers, §4–§6.
//
// Why. A chain of joints carrying a heavy body is badly conditioned: a
// Gauss-Seidel sweep moves each link by its own small mass, so the load of a
// body 100× a link's mass reaches the top of a 20-link chain only over many
// sweeps, and what is not resolved stretches the joints (chain_swing: 7.2 cm).
// The equality rows of joints whose bodies form a tree can instead be solved
// exactly, in time linear in their number.
//
// The system. With unknowns Δv (every body of the tree) and Δλ (every row of
// its joints), the rows' velocity targets J(v + Δv) + b + Γ(λ + Δλ) = 0 and
// Newton's law M Δv = Jᵀ Δλ form the symmetric system
//   [ M   Jᵀ ] [  Δv ]   [ 0 ]
//   [ J  −Γ  ] [ −Δλ ] = [ r ],   r = −(J v + b + Γ λ).
// Γ is the soft step's compliance: a row whose impulse is
// −massScale·K⁻¹(Jv + b) − impulseScale·λ (joint_rows.hpp) satisfies
// Jv + b + Γλ = 0 with Γ = K·impulseScale/massScale, K the joint's own block;
// Γ = 0 in the relax and baumgarte passes, and in the biased pass of a pushed
// tree (no loop closes it and its joints are hinges or rigid welds, or it
// holds a stretched joint), whose error is closed on pseudo-velocities
// instead (pushJointTrees), its bodies' inertia raised by the tension's
// geometric stiffness where the substep does not resolve it (stiffenTree).
//
// The graph of this matrix has a node per body and per joint, and an edge
// where a joint acts on a body: a tree when the joints form one. Eliminating
// the nodes leaves first, each node's block becomes D_i = H_ii − Σ_c B_cᵀ D_c⁻¹ B_c
// over its children c (B_c = H_c,parent), with no fill-in (Baraff's §5).
// Bodies that do not move (static, kinematic, sleeping) are not nodes; the
// forest is spanned with all of them as one node, so a tree holds at most one
// joint to them and that joint is its root. Every other joint node then has a
// body child, so its block never is the bare −Γ (zero when rigid).
#include "joint_tree.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "world_state.hpp"

namespace i2d::detail {

// ---------------------------------------------------------------------------
// The rows each joint type hands over (their maths is in each type's file).

bool rowsOnlyAtLimit(const Joint& joint) {
    return joint.type == JointType::distance && !isRigidDistance(std::get<DistanceJointDef>(joint.def));
}

int equalityRowCount(const Joint& joint) {
    switch (joint.type) {
        case JointType::revolute: return 2;
        case JointType::weld: {
            // Its rigid parts: the point and the angle, the point alone (an
            // angular spring, swept), the angle alone (a linear spring, swept).
            const WeldJointDef& def = std::get<WeldJointDef>(joint.def);
            if (def.linearHertz == 0.0f) return def.angularHertz == 0.0f ? 3 : 2;
            return def.angularHertz == 0.0f ? 1 : 0;
        }
        case JointType::distance: {
            // A rope or a spring with limits hands over a limit while it
            // holds it (rowsOnlyAtLimit).
            const DistanceJointDef& def = std::get<DistanceJointDef>(joint.def);
            return isRigidDistance(def) || (def.enableLimit && def.minLength < def.maxLength) ? 1 : 0;
        }
        case JointType::prismatic: return 2;
        case JointType::wheel: return 1;
        default: return 0;
    }
}

void equalityRows(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, EqualityRows& rows) {
    switch (jc.type) {
        case JointType::revolute: revoluteEqualityRows(jc, sA, sB, rows); break;
        case JointType::weld: weldEqualityRows(jc, sA, sB, rows); break;
        case JointType::distance: distanceEqualityRows(jc, sA, sB, rows); break;
        case JointType::prismatic: prismaticEqualityRows(jc, sA, sB, rows); break;
        case JointType::wheel: wheelEqualityRows(jc, sA, sB, rows); break;
        default: rows.count = 0; break;
    }
}

bool hasSpringRow(const Joint& joint) {
    switch (joint.type) {
        case JointType::revolute: {
            const RevoluteJointDef& def = std::get<RevoluteJointDef>(joint.def);
            return def.enableSpring && def.hertz > 0.0f;
        }
        case JointType::prismatic: {
            const PrismaticJointDef& def = std::get<PrismaticJointDef>(joint.def);
            return def.enableSpring && def.hertz > 0.0f;
        }
        case JointType::wheel: {
            const WheelJointDef& def = std::get<WheelJointDef>(joint.def);
            return def.enableSpring && def.hertz > 0.0f;
        }
        case JointType::distance: {
            const DistanceJointDef& def = std::get<DistanceJointDef>(joint.def);
            return !isRigidDistance(def) && def.hertz > 0.0f;
        }
        case JointType::weld: return std::get<WeldJointDef>(joint.def).angularHertz > 0.0f;
        default: return false;
    }
}

void springRow(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, float h, EqualityRows& rows,
               Softness& soft) {
    switch (jc.type) {
        case JointType::revolute: {
            const RevoluteRow& row = jc.row.revolute;
            angularSpringRow(jc, sA, sB, row.referenceAngle, row.hertz, row.dampingRatio, h, rows, soft);
            break;
        }
        case JointType::prismatic: {
            const PrismaticRow& row = jc.row.prismatic;
            sliderSpringRow(jc, sliderFrame(jc, row.axisA, sA, sB), row.hertz, row.dampingRatio, h, rows, soft);
            break;
        }
        case JointType::wheel: {
            const WheelRow& row = jc.row.wheel;
            sliderSpringRow(jc, sliderFrame(jc, row.axisA, sA, sB), row.hertz, row.dampingRatio, h, rows, soft);
            break;
        }
        case JointType::distance: distanceSpringRow(jc, sA, sB, h, rows, soft); break;
        case JointType::weld: {
            const WeldRow& row = jc.row.weld;
            angularSpringRow(jc, sA, sB, row.referenceAngle, row.angularHertz, row.angularDampingRatio, h, rows, soft);
            break;
        }
        default: rows.count = 0; break;
    }
}

namespace {

/// Whether a joint has a limit its tree may hold (limitCoordinate can be true).
bool hasLimit(const JointConstraint& jc) {
    switch (jc.type) {
        case JointType::revolute: return jc.row.revolute.enableLimit;
        case JointType::prismatic: return jc.row.prismatic.enableLimit;
        case JointType::wheel: return jc.row.wheel.enableLimit;
        case JointType::distance: return !jc.row.distance.rigid && jc.row.distance.enableLimit;
        default: return false;
    }
}

}  // namespace

bool limitCoordinate(const JointConstraint& jc, const BodyState& sA, const BodyState& sB, LimitCoordinate& out) {
    auto slider = [&](Vec2 axisA, bool enabled, float lower, float upper) {
        if (!enabled) return false;
        out = {sliderFrame(jc, axisA, sA, sB).translation, lower, upper};
        return true;
    };
    switch (jc.type) {
        case JointType::revolute: return revoluteLimitCoordinate(jc, sA, sB, out);
        case JointType::prismatic: {
            const PrismaticRow& row = jc.row.prismatic;
            return slider(row.axisA, row.enableLimit, row.lower, row.upper);
        }
        case JointType::wheel: {
            const WheelRow& row = jc.row.wheel;
            return slider(row.axisA, row.enableLimit, row.lower, row.upper);
        }
        case JointType::distance: return distanceLimitCoordinate(jc, sA, sB, out);
        default: return false;
    }
}

namespace {

/// How close to a revolute joint's angle limit the tree starts to hold it
/// (2°, Box2D's angular slop); sliders' and distance joints' limits use
/// kLinearSlop.
constexpr float kAngularLimitSlop = 2.0f / 180.0f * 3.14159265f;

/// The row a limit the tree holds takes (JointConstraint::treeLimit): after
/// the joint's equality rows; −1 when none is held.
int heldLimitRow(const JointConstraint& jc) {
    if (jc.treeLimit == 0) return -1;
    switch (jc.type) {
        case JointType::distance: return 0;  // (a rigid one holds no limit)
        case JointType::wheel: return 1;
        default: return 2;
    }
}

/// A weld whose only rigid part, the one its tree holds, is its angle (a
/// linear spring): its one equality row is the angle's.
bool weldAngleOnly(const JointConstraint& jc) {
    return jc.type == JointType::weld && jc.row.weld.linearHertz != 0.0f && jc.row.weld.angularHertz == 0.0f;
}

void readImpulse(const JointConstraint& jc, double out[3]) {
    const JointImpulses& acc = jc.impulses;
    out[0] = out[1] = out[2] = 0.0;
    switch (jc.type) {
        case JointType::distance: out[0] = jc.row.distance.rigid ? acc.axial : 0.0f; break;
        case JointType::revolute:
        case JointType::weld:
            if (weldAngleOnly(jc)) {
                out[0] = acc.angular;
                break;
            }
            out[0] = acc.linear.x;
            out[1] = acc.linear.y;
            out[2] = jc.type == JointType::weld && jc.row.weld.angularHertz == 0.0f ? acc.angular : 0.0f;
            break;
        case JointType::prismatic:  // the perpendicular and the angle
            out[0] = acc.axial;
            out[1] = acc.angular;
            break;
        case JointType::wheel: out[0] = acc.axial; break;  // the perpendicular
        default: break;
    }
    // A limit the tree holds, along its joint's free direction (ω_B − ω_A,
    // B's motion along the axis or along the rope): the lower pushes that
    // way, the upper against.
    if (const int r = heldLimitRow(jc); r >= 0) out[r] = acc.lower - acc.upper;
}

void addImpulse(JointConstraint& jc, const double delta[3]) {
    JointImpulses& acc = jc.impulses;
    switch (jc.type) {
        case JointType::distance:
            if (jc.row.distance.rigid) acc.axial += static_cast<float>(delta[0]);
            break;
        case JointType::revolute:
        case JointType::weld:
            if (weldAngleOnly(jc)) {
                acc.angular += static_cast<float>(delta[0]);
                break;
            }
            acc.linear.x += static_cast<float>(delta[0]);
            acc.linear.y += static_cast<float>(delta[1]);
            if (jc.type == JointType::weld && jc.row.weld.angularHertz == 0.0f)
                acc.angular += static_cast<float>(delta[2]);
            break;
        case JointType::prismatic:
            acc.axial += static_cast<float>(delta[0]);
            acc.angular += static_cast<float>(delta[1]);
            break;
        case JointType::wheel: acc.axial += static_cast<float>(delta[0]); break;
        default: break;
    }
    if (const int r = heldLimitRow(jc); r >= 0) {
        if (jc.treeLimit < 0) acc.lower += static_cast<float>(delta[r]);
        if (jc.treeLimit > 0) acc.upper -= static_cast<float>(delta[r]);
    }
}

using Block = double[3][3];

void setZero(Block m) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m[i][j] = 0.0;
}

/// m ← m⁻¹ for a symmetric 3×3 block (cofactors); a singular block becomes
/// zero, which drops what it couples instead of spreading infinities.
void invertSymmetric(Block m) {
    const double a = m[0][0], b = m[0][1], c = m[0][2], d = m[1][1], e = m[1][2], f = m[2][2];
    const double c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
    const double det = a * c00 + b * c01 + c * c02;
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) {
        setZero(m);
        return;
    }
    const double inv = 1.0 / det;
    const double c11 = a * f - c * c, c12 = b * c - a * e, c22 = a * d - b * b;
    m[0][0] = c00 * inv, m[0][1] = m[1][0] = c01 * inv, m[0][2] = m[2][0] = c02 * inv;
    m[1][1] = c11 * inv, m[1][2] = m[2][1] = c12 * inv, m[2][2] = c22 * inv;
}

/// Union-find root with path halving.
int findRoot(std::vector<int>& parent, int i) {
    while (parent[static_cast<std::size_t>(i)] != i) {
        int& p = parent[static_cast<std::size_t>(i)];
        p = parent[static_cast<std::size_t>(p)];
        i = p;
    }
    return i;
}

/// A weld whose three rows all hold (no spring on either part): with a
/// hinge, the joints that carry their load at a point (holdsLoadAtPoint).
bool isRigidWeld(const JointSlot& jc) { return jc.pointLoad && jc.equalityRows == 3; }

/// The reach of the body of state `index` (Body::reach); a body without a
/// solid shape has none to tear from (infinity).
float reachOf(const WorldState& w, int index) {
    const float reach = w.bodies[w.solver.stateBodies[static_cast<std::size_t>(index)]].reach;
    return reach > 0.0f ? reach : INFINITY;
}

/// The state index of a joint side that moves, or `ground` for one that does not.
int movingSide(int index, float invMass, float invI, int ground) {
    return index >= 0 && (invMass != 0.0f || invI != 0.0f) ? index : ground;
}

}  // namespace

float jointOmega(const WorldSettings& settings, float h) { return 2.0f * 3.14159265f * jointHertzOver(settings, h); }

void selectTreeJoints(WorldState& w, std::vector<JointSlot>& slots, float h) {
    SolverArrays& s = w.solver;
    JointTrees& t = s.trees;
    const int ground = static_cast<int>(s.stateBodies.size());
    const std::size_t bodySlots = static_cast<std::size_t>(ground) + 1;

    // No tree can qualify when the jointed bodies' masses, and the masses at
    // their anchors, are alike overall, no joint is stretched and no body is
    // welded to two others: the common case (a grid, a bridge, a ragdoll of
    // alike parts) stops here.
    const bool anyStretched = std::any_of(slots.begin(), slots.end(), [](const JointSlot& jc) { return jc.stretched; });
    const float massRatio = w.settings.exactJointMassRatio;
    // The movable bodies' inverse masses, those the rows see at the anchors
    // (JointSlot::anchorInvMassA), and whether a body is rigidly welded to two
    // others or more (below).
    float leastInverseMass = INFINITY, mostInverseMass = 0.0f;
    float leastAnchor = INFINITY, mostAnchor = 0.0f;
    // The load a tree's soft rows hold: the weight of the bodies beyond a
    // joint, at most the whole tree's. Under a load of L times its own
    // body's weight a soft row (stiffness m·ω², ω = jointOmega) stretches
    // L·g/ω². Swept one pass a substep, a chain of many light alike links
    // whose joints so stretch by a sizeable part of a link tears and gains
    // energy without bound: 30 capsules 0.1 m long (reach 0.06 m) released
    // level at one substep, ω = 94 rad/s, stretch at the top 30·g/ω² = 3.4
    // cm, had its joints 0.24 m open after a second and 150 times its
    // releasable energy after 20 s (docs/joints.md, "Chains of many light
    // links"). Solved exactly such a tree holds its length. The criterion:
    // L·g/ω² at least kLoadStretch times the least reach of the tree's
    // bodies, L its mass over its lightest body's. Over chains of 20 to 60
    // alike links 0.05 to 0.25 m long at 1, 2 and 4 substeps, those that
    // tore lay at 0.30 of the reach and above, those that held at 0.28 and
    // below, and 100 links of 0.05 m at 4 substeps tore at 0.235: at a
    // tenth, every torn chain is solved exactly, and a chain of 0.5 m links
    // at 4 substeps only from 400 links. The load must also be
    // massRatio times the lightest body's mass, as the other ratios must.
    // The sum of the jointed bodies' masses, joint by joint, bounds every
    // tree's (a body counts once per joint it holds), and their least reach
    // every tree's.
    const float omega = jointOmega(w.settings, h);
    const float loadStretch = length(w.settings.gravity) / (omega * omega);  // per body weight carried (m)
    float jointedMass = 0.0f, leastReach = INFINITY;
    bool anyWeldCluster = false;
    t.welds.assign(bodySlots, 0);
    for (const JointSlot& jc : slots) {
        for (float inverse : {jc.invMassA, jc.invMassB})
            if (inverse > 0.0f) {
                leastInverseMass = std::min(leastInverseMass, inverse);
                mostInverseMass = std::max(mostInverseMass, inverse);
                jointedMass += 1.0f / inverse;
            }
        for (int index : {jc.a, jc.b})
            if (index >= 0) leastReach = std::min(leastReach, reachOf(w, index));
        for (float inverse : {jc.anchorInvMassA, jc.anchorInvMassB})
            if (inverse > 0.0f) {
                leastAnchor = std::min(leastAnchor, inverse);
                mostAnchor = std::max(mostAnchor, inverse);
            }
        if (!isRigidWeld(jc)) continue;
        for (int index : {jc.a, jc.b})
            if (index >= 0 && t.welds[static_cast<std::size_t>(index)] < 2 &&
                ++t.welds[static_cast<std::size_t>(index)] == 2)
                anyWeldCluster = true;
    }
    // The load is a ratio of masses as the others are, held to massRatio too
    // (1e30: no tree is solved exactly for its load either).
    auto tornByLoad = [&](float load, float reach) {
        return load >= massRatio && load * loadStretch >= kLoadStretch * reach;
    };
    if (!(mostInverseMass >= massRatio * leastInverseMass) && !(mostAnchor >= massRatio * leastAnchor) &&
        !tornByLoad(jointedMass * leastInverseMass, leastReach) && !anyStretched && !anyWeldCluster)
        return;

    // The spanning forest, all immovable bodies one node, in row order.
    t.unionParent.resize(bodySlots);
    std::iota(t.unionParent.begin(), t.unionParent.end(), 0);
    // Joints whose rows always hold first, then those that hand over a limit
    // only while they hold it (a rope beside a hinge of the same bodies
    // leaves the hinge in the tree).
    int treeJoints = 0;
    for (const bool limitsOnly : {false, true})
        for (JointSlot& jc : slots) {
            if (jc.equalityRows == 0 || jc.rowsOnlyAtLimit != limitsOnly) continue;
            const int a = movingSide(jc.a, jc.invMassA, jc.invIA, ground);
            const int b = movingSide(jc.b, jc.invMassB, jc.invIB, ground);
            const int ra = findRoot(t.unionParent, a), rb = findRoot(t.unionParent, b);
            if (ra == rb) continue;  // closes a loop (or joins two immovable bodies): stays in the sweep
            t.unionParent[static_cast<std::size_t>(ra)] = rb;
            jc.inTree = true;
            ++treeJoints;
        }
    if (treeJoints == 0) return;

    // Which trees are worth solving exactly: those whose heaviest body is
    // massRatio times their lightest. A tree is a component of the forest
    // without the immovable node (each holds at most one joint to it: two
    // would close a loop through it), so the trees are joined again without
    // that node. Judged over the component joined through the immovable node,
    // one heavy-ended chain made every chain hung beside it from the same
    // ground leave the wide path for scalar rows.
    std::iota(t.unionParent.begin(), t.unionParent.end(), 0);
    for (const JointSlot& jc : slots) {
        if (!jc.inTree) continue;
        const int a = movingSide(jc.a, jc.invMassA, jc.invIA, ground);
        const int b = movingSide(jc.b, jc.invMassB, jc.invIB, ground);
        if (a == ground || b == ground) continue;
        t.unionParent[static_cast<std::size_t>(findRoot(t.unionParent, a))] = findRoot(t.unionParent, b);
    }
    t.lightest.assign(bodySlots, INFINITY);
    t.heaviest.assign(bodySlots, 0.0f);
    t.treeMass.assign(bodySlots, 0.0f);
    t.leastReach.assign(bodySlots, INFINITY);
    t.lightestAnchor.assign(bodySlots, INFINITY);
    t.heaviestAnchor.assign(bodySlots, 0.0f);
    t.stretched.assign(bodySlots, 0);
    for (int body = 0; body < ground; ++body) {
        const float invMass = w.bodies[s.stateBodies[static_cast<std::size_t>(body)]].invMass;
        const float mass = invMass > 0.0f ? 1.0f / invMass : INFINITY;
        const std::size_t root = static_cast<std::size_t>(findRoot(t.unionParent, body));
        t.lightest[root] = std::min(t.lightest[root], mass);
        t.heaviest[root] = std::max(t.heaviest[root], mass);
        t.treeMass[root] += mass;
        t.leastReach[root] = std::min(t.leastReach[root], reachOf(w, body));
    }
    // A tree in which a body is rigidly welded to two others or more: welds
    // leave no motion between their bodies, so the structure is rigid, and
    // the sweep holds it only as fast as it converges (a cantilever of eight
    // alike capsules welded end to end sagged 1.54 m) and can gain energy
    // doing it: of 1,000 random trees of hinges and welds, two such stars of
    // bodies within exactJointMassRatio of each other's mass, swept at 4
    // substeps, gained 14 and 21 times their potential energy (docs/joints.md,
    // "The masses at the anchors").
    t.weldCluster.assign(bodySlots, 0);
    if (anyWeldCluster) {
        t.welds.assign(bodySlots, 0);
        for (const JointSlot& jc : slots) {
            if (!jc.inTree || !isRigidWeld(jc)) continue;
            for (int index : {jc.a, jc.b})
                if (index >= 0 && t.welds[static_cast<std::size_t>(index)] < 2 &&
                    ++t.welds[static_cast<std::size_t>(index)] == 2)
                    t.weldCluster[static_cast<std::size_t>(findRoot(t.unionParent, index))] = 1;
        }
    }
    // The masses at the anchors, per tree: a body driven at an anchor far
    // outside itself gives there as a much lighter body would, and the sweep
    // converges as slowly on the rows around it. Of the same random trees,
    // those whose bodies' masses were within the ratio but whose masses at
    // the anchors were exactJointMassRatio apart gained up to 475 times their
    // potential energy at 2 substeps; solved exactly, none of the 1,000 more
    // than 11 % at any substep count.
    for (const JointSlot& jc : slots) {
        if (!jc.inTree) continue;
        for (const auto& [index, inverse] : {std::pair{jc.a, jc.anchorInvMassA}, std::pair{jc.b, jc.anchorInvMassB}}) {
            if (!(inverse > 0.0f) || index < 0) continue;  // a side that does not move
            const std::size_t root = static_cast<std::size_t>(findRoot(t.unionParent, index));
            t.lightestAnchor[root] = std::min(t.lightestAnchor[root], 1.0f / inverse);
            t.heaviestAnchor[root] = std::max(t.heaviestAnchor[root], 1.0f / inverse);
        }
    }
    // A tree through which a joint outside it closes a loop (a net, a
    // bridge's deck) keeps soft rows; one alone, of hinges and rigid welds,
    // may be pushed: rigid in the biased pass, its error closed by
    // pushJointTrees (JointSlot::treePushed; buildJointTrees decides).
    auto rootOf = [&](const JointSlot& jc) {
        const int a = movingSide(jc.a, jc.invMassA, jc.invIA, ground);
        const int side = a != ground ? a : movingSide(jc.b, jc.invMassB, jc.invIB, ground);
        return static_cast<std::size_t>(findRoot(t.unionParent, side));
    };
    t.closed.assign(bodySlots, 0);
    t.pointsOnly.assign(bodySlots, 1);
    for (const JointSlot& jc : slots) {
        if (!jc.inTree && jc.equalityRows > 0 && !jc.rowsOnlyAtLimit &&
            movingSide(jc.a, jc.invMassA, jc.invIA, ground) != movingSide(jc.b, jc.invMassB, jc.invIB, ground))
            t.closed[rootOf(jc)] = 1;
        if (jc.inTree && !jc.pointLoad) t.pointsOnly[rootOf(jc)] = 0;
    }
    // And those holding a stretched joint, whatever their masses
    // (Joint::stretched), unless a loop closes through them: a net of loops
    // created with its joints 1 m open, its spanning tree solved rigid and
    // pushed while the loops' joints kept their soft rows, gained 1.4 times
    // what it did with soft rows alone.
    if (anyStretched)
        for (const JointSlot& jc : slots)
            if (jc.inTree && jc.stretched && !t.closed[rootOf(jc)]) t.stretched[rootOf(jc)] = 1;
    auto exact = [&](std::size_t root) {
        return t.heaviest[root] >= massRatio * t.lightest[root] ||
               t.heaviestAnchor[root] >= massRatio * t.lightestAnchor[root] ||
               (!t.closed[root] && tornByLoad(t.treeMass[root] / t.lightest[root], t.leastReach[root])) ||
               t.stretched[root] || t.weldCluster[root];
    };
    auto pushable = [&](std::size_t root) { return !t.closed[root] && (t.stretched[root] || t.pointsOnly[root]); };
    for (JointSlot& jc : slots) {
        if (!jc.inTree) continue;
        const std::size_t root = rootOf(jc);
        jc.inTree = exact(root);
        jc.treePushed = jc.inTree && pushable(root);
    }
    // The joints that close loops through exact trees: each of their moving
    // sides in a tree solved exactly (a side that does not move closes the
    // loop through the ground) and not pushed (a loop between two trees hung
    // from the ground closes only the first, rootOf's, above; one through a
    // pushed tree is left to the sweep). Swept beside the trees, such a
    // joint's rows move each body by its own mass while the tree moves it as
    // part of the whole: of 1,000 random hinge trees with loops, a quarter of
    // their bodies 10 to 1,000 times as dense, 26, 15 and 10 gained more
    // than 1 % of their energy at 4, 2 and 1 substeps, the worst 938 times
    // (docs/validation.md, energy audit). Their equality rows are solved with
    // the trees instead, as auxiliary rows (Baraff (1996), §8): at most
    // kMaxLoopRows of them in a step, taken in slot order; the rest stay in
    // the sweep.
    int loopRows = 0;
    for (JointSlot& jc : slots) {
        if (jc.inTree || jc.equalityRows == 0 || jc.rowsOnlyAtLimit) continue;
        const int a = movingSide(jc.a, jc.invMassA, jc.invIA, ground);
        const int b = movingSide(jc.b, jc.invMassB, jc.invIB, ground);
        if (a == b) continue;
        bool exactSides = true;
        for (int side : {a, b}) {
            if (side == ground) continue;
            const std::size_t root = static_cast<std::size_t>(findRoot(t.unionParent, side));
            exactSides = exactSides && exact(root) && !pushable(root);
        }
        if (!exactSides || loopRows + jc.equalityRows > kMaxLoopRows) continue;
        loopRows += jc.equalityRows;
        jc.inTree = jc.treeLoop = true;
    }
    // The springs of the exact trees' joints, of the loops' and of joints
    // that are only a spring between the trees' bodies: swept beside
    // the trees, a spring's row moves its two bodies by their own masses, not
    // by the mass the tree gives that row, and it is not the implicit spring
    // it is meant to be. Of 1,000 random trees of hinges and sliders (a
    // quarter of their bodies 10 to 1,000 times as dense), 20 and 39 gained
    // more than 1 % of their energy at 4 and 1 substeps, 7 and 13 with the
    // sliders' springs left out (docs/validation.md, energy audit). Each is
    // solved with the trees as an auxiliary row of its own compliance (the
    // spring's, in every pass), within kMaxLoopRows with the loops, in slot
    // order; the rest stay in the sweep.
    for (JointSlot& jc : slots) {
        if (!jc.spring || loopRows >= kMaxLoopRows) continue;
        if (!jc.inTree) {  // (a spring alone, a distance joint's: both its moving sides in exact trees)
            // A distance spring whose limits stay in the sweep (it closes a
            // loop) keeps its spring there too, on the same axis: solved with
            // the trees while its rope was swept by its bodies' own masses,
            // the rope let a 1,000:1 tree stretch it 0.7 m past its length and
            // the tree gained 39 % of its energy.
            if (jc.rowsOnlyAtLimit && jc.equalityRows > 0) continue;
            const int a = movingSide(jc.a, jc.invMassA, jc.invIA, ground);
            const int b = movingSide(jc.b, jc.invMassB, jc.invIB, ground);
            bool exactSides = a != b;
            for (int side : {a, b})
                if (side != ground)
                    exactSides = exactSides && exact(static_cast<std::size_t>(findRoot(t.unionParent, side)));
            if (!exactSides) continue;
        }
        ++loopRows;
        jc.treeSpring = true;
    }
}

bool holdsLoadAtPoint(const Joint& joint) {
    if (joint.type == JointType::revolute) return true;
    // A weld whose point is rigid (its angle rigid too, or a spring: a hinge
    // with an angular spring, as a revolute joint's).
    return joint.type == JointType::weld && equalityRowCount(joint) >= 2;
}

namespace {

/// The inverse of the inertia 1/invI + extra (0 stays 0: a body that does
/// not turn).
float raisedInverseInertia(float invI, float extra) { return invI > 0.0f ? 1.0f / (1.0f / invI + extra) : 0.0f; }

/// The tension's geometric stiffness (Andrews, Teichmann and Kry (2017),
/// Geometric Stiffness for Real-time Constrained Multibody Dynamics): a body
/// pulled by a load F at an anchor r from its centre turns as if on a spring
/// of stiffness |F|·|r| (the load's moment changes as the anchor turns), and
/// a link pulled at both ends by T turns at ω² ≈ T·L/I. One position update
/// a substep holds that turn only while ωh < 2; a chain under a heavy end
/// passes it (120 kN on a 6 kg, 1 m capsule link: ωh ≈ 1.9 at 4 substeps),
/// its links then whip and the chain gains energy. Raising the body's inertia
/// to h²·Σ|F|·|r| in the step's solve, where the substep does not resolve the
/// turn (h²·Σ|F|·|r| > I), keeps ωh ≤ 1 there; it changes nothing where the
/// substep resolves it. The load is the joint's accumulated point impulse
/// (|F|·h, the warm start). Only in a pushed tree none of whose bodies
/// touches anything (a manifold, speculative points included): a contact's
/// rows turn a body with its own inertia, and the two metrics side by side
/// gained energy (a free hinge tree with a 1000:1 body landing on the ground,
/// its light links whirled by the stopped heavy body: 7.5 times what its fall
/// releases). The caller (buildJointTrees) looks.
void stiffenTree(WorldState& w, std::size_t head, float h) {
    SolverArrays& s = w.solver;
    JointTrees& t = s.trees;
    std::vector<TreeNode>& nodes = t.nodes;
    std::vector<float>& extra = t.extraInertia;
    if (extra.empty()) extra.assign(s.stateBodies.size(), 0.0f);
    bool any = false;
    for (std::size_t k = head; k < nodes.size(); ++k) {
        if (nodes[k].row < 0) continue;
        const JointConstraint& jc = s.joints[static_cast<std::size_t>(nodes[k].row)];
        if (jc.type != JointType::revolute && jc.type != JointType::weld) continue;
        const float load = length(jc.impulses.linear);
        if (jc.a >= 0 && jc.invIA > 0.0f) extra[static_cast<std::size_t>(jc.a)] += h * load * length(jc.rA);
        if (jc.b >= 0 && jc.invIB > 0.0f) extra[static_cast<std::size_t>(jc.b)] += h * load * length(jc.rB);
        any = true;
    }
    if (!any) return;
    for (std::size_t k = head; k < nodes.size(); ++k) {
        if (nodes[k].row >= 0) continue;
        const std::size_t b = static_cast<std::size_t>(nodes[k].body);
        const float invI = w.bodies[s.stateBodies[b]].invInertia;
        extra[b] = invI > 0.0f ? std::max(0.0f, extra[b] - 1.0f / invI) : 0.0f;
    }
}

}  // namespace

void buildJointTrees(WorldState& w, float h) {
    SolverArrays& s = w.solver;
    JointTrees& t = s.trees;
    t.nodes.clear();
    t.loops.clear();
    t.loopRows = 0;
    t.extraInertia.clear();
    t.factoredPositions = -1;
    t.limitsDecidedAt = -1;
    t.anyLimit = false;
    const int ground = static_cast<int>(s.stateBodies.size());
    const std::size_t bodySlots = static_cast<std::size_t>(ground) + 1;
    // A joint closing a loop (treeLoop) is no edge of its tree.
    auto isEdge = [](const JointConstraint& jc) { return jc.inTree && !jc.treeLoop; };
    int treeJoints = 0;
    for (const JointConstraint& jc : s.joints) treeJoints += isEdge(jc);
    if (treeJoints == 0) return;
    t.unionParent.resize(bodySlots);

    // Each body's tree joints (compressed rows).
    t.adjacencyStart.assign(bodySlots + 1, 0);
    for (const JointConstraint& jc : s.joints) {
        if (!isEdge(jc)) continue;
        ++t.adjacencyStart[static_cast<std::size_t>(movingSide(jc.a, jc.invMassA, jc.invIA, ground)) + 1];
        ++t.adjacencyStart[static_cast<std::size_t>(movingSide(jc.b, jc.invMassB, jc.invIB, ground)) + 1];
    }
    std::partial_sum(t.adjacencyStart.begin(), t.adjacencyStart.end(), t.adjacencyStart.begin());
    t.adjacency.resize(static_cast<std::size_t>(t.adjacencyStart.back()));
    {
        std::vector<int>& fill = t.unionParent;  // reused as write cursors
        std::copy(t.adjacencyStart.begin(), t.adjacencyStart.end() - 1, fill.begin());
        for (std::size_t r = 0; r < s.joints.size(); ++r) {
            const JointConstraint& jc = s.joints[r];
            if (!isEdge(jc)) continue;
            for (int side :
                 {movingSide(jc.a, jc.invMassA, jc.invIA, ground), movingSide(jc.b, jc.invMassB, jc.invIB, ground)})
                t.adjacency[static_cast<std::size_t>(fill[static_cast<std::size_t>(side)]++)] = static_cast<int>(r);
        }
    }

    // Breadth-first from the roots: first the joints to immovable bodies,
    // then a body of each tree that has none. Parents come before children.
    std::vector<TreeNode>& nodes = t.nodes;
    nodes.reserve(static_cast<std::size_t>(2 * treeJoints + 1));
    constexpr int kUnvisited = -1;
    t.nodeOfBody.assign(bodySlots, kUnvisited);
    std::vector<char> rowTaken(s.joints.size(), 0);
    auto addBody = [&](int body, int parent) {
        t.nodeOfBody[static_cast<std::size_t>(body)] = static_cast<int>(nodes.size());
        TreeNode& node = nodes.emplace_back();
        node.body = body;
        node.parent = parent;
        node.pushed = false;
    };
    auto addJoint = [&](int row, int parent) {
        rowTaken[static_cast<std::size_t>(row)] = 1;
        TreeNode& node = nodes.emplace_back();
        node.row = row;
        node.parent = parent;
        node.pushed = false;
        node.speculative = false;
        t.anyLimit = t.anyLimit || hasLimit(s.joints[static_cast<std::size_t>(row)]);
    };
    // A tree (the nodes from `head` on) is pushed whole (selectTreeJoints: its
    // joints are all or none JointConstraint::treePushed), unless a body of it
    // touches something and it holds no stretched joint. Beside its contacts
    // and its held limits, rigid with nothing to damp them, a ragdoll whose
    // torso is 10 times as dense as its limbs kept jiggling on the ground
    // (JointTree.RagdollsWithAHeavyTorsoComeToRestOnTheGround); its soft rows
    // damp that.
    auto markPushed = [&](std::size_t head) {
        bool pushed = false, stretched = false, touches = false;
        for (std::size_t k = head; k < nodes.size(); ++k) {
            if (nodes[k].row >= 0) {
                const JointConstraint& jc = s.joints[static_cast<std::size_t>(nodes[k].row)];
                pushed = pushed || jc.treePushed;
                stretched = stretched || w.joints[jc.joint].stretched;
            } else {
                touches = touches || touchesThroughContact(w, s.stateBodies[static_cast<std::size_t>(nodes[k].body)]);
            }
        }
        if (!pushed || (touches && !stretched)) return;
        for (std::size_t k = head; k < nodes.size(); ++k) nodes[k].pushed = true;
        if (!touches) stiffenTree(w, head, h);
        s.pushTrees = true;
    };
    auto expand = [&](std::size_t head) {
        for (; head < nodes.size(); ++head) {
            const int self = static_cast<int>(head);
            if (nodes[head].row >= 0) {
                const JointConstraint& jc = s.joints[static_cast<std::size_t>(nodes[head].row)];
                for (int side :
                     {movingSide(jc.a, jc.invMassA, jc.invIA, ground), movingSide(jc.b, jc.invMassB, jc.invIB, ground)})
                    if (side != ground && t.nodeOfBody[static_cast<std::size_t>(side)] == kUnvisited)
                        addBody(side, self);
            } else {
                const std::size_t body = static_cast<std::size_t>(nodes[head].body);
                for (int k = t.adjacencyStart[body]; k < t.adjacencyStart[body + 1]; ++k) {
                    const int row = t.adjacency[static_cast<std::size_t>(k)];
                    if (!rowTaken[static_cast<std::size_t>(row)]) addJoint(row, self);
                }
            }
        }
    };
    for (int k = t.adjacencyStart[static_cast<std::size_t>(ground)]; k < t.adjacencyStart[bodySlots]; ++k) {
        const std::size_t head = nodes.size();
        addJoint(t.adjacency[static_cast<std::size_t>(k)], -1);
        expand(head);
        markPushed(head);
    }
    for (int body = 0; body < ground; ++body) {
        const std::size_t b = static_cast<std::size_t>(body);
        if (t.nodeOfBody[b] != kUnvisited || t.adjacencyStart[b] == t.adjacencyStart[b + 1]) continue;
        const std::size_t head = nodes.size();
        addBody(body, -1);
        expand(head);
        markPushed(head);
    }
    if (nodes.empty()) return;
    // The joints' rows turn the stiffened bodies with their raised inertia
    // too (warm start, limits, motors), so that every impulse on them this
    // step sees the same body.
    if (!t.extraInertia.empty())
        for (JointConstraint& jc : s.joints) {
            if (jc.a >= 0) jc.invIA = raisedInverseInertia(jc.invIA, t.extraInertia[static_cast<std::size_t>(jc.a)]);
            if (jc.b >= 0) jc.invIB = raisedInverseInertia(jc.invIB, t.extraInertia[static_cast<std::size_t>(jc.b)]);
        }

    // Children before parents: reverse the order.
    const int last = static_cast<int>(nodes.size()) - 1;
    std::reverse(nodes.begin(), nodes.end());
    for (TreeNode& node : nodes)
        if (node.parent >= 0) node.parent = last - node.parent;
    for (int& node : t.nodeOfBody)
        if (node >= 0) node = last - node;
    for (TreeNode& node : nodes) {
        if (node.row < 0) continue;
        const JointConstraint& jc = s.joints[static_cast<std::size_t>(node.row)];
        const int a = movingSide(jc.a, jc.invMassA, jc.invIA, ground);
        const int b = movingSide(jc.b, jc.invMassB, jc.invIB, ground);
        node.nodeA = a == ground ? -1 : t.nodeOfBody[static_cast<std::size_t>(a)];
        node.nodeB = b == ground ? -1 : t.nodeOfBody[static_cast<std::size_t>(b)];
    }
    // The auxiliary rows (selectTreeJoints took at most kMaxLoopRows), on the
    // nodes of their bodies: the loops' joints, then the springs. One with a
    // side outside the trees is left to the sweep.
    auto addAuxiliary = [&](std::size_t r, bool spring) {
        const JointConstraint& jc = s.joints[r];
        const int a = movingSide(jc.a, jc.invMassA, jc.invIA, ground);
        const int b = movingSide(jc.b, jc.invMassB, jc.invIB, ground);
        const int nodeA = a == ground ? -1 : t.nodeOfBody[static_cast<std::size_t>(a)];
        const int nodeB = b == ground ? -1 : t.nodeOfBody[static_cast<std::size_t>(b)];
        if ((a != ground && nodeA < 0) || (b != ground && nodeB < 0)) return false;
        TreeLoop& loop = t.loops.emplace_back();
        loop.row = static_cast<int>(r);
        loop.nodeA = nodeA;
        loop.nodeB = nodeB;
        loop.first = t.loopRows;
        loop.spring = spring;
        t.loopRows += spring ? 1 : equalityRowCount(w.joints[jc.joint]);
        return true;
    };
    for (std::size_t r = 0; r < s.joints.size(); ++r) {
        JointConstraint& jc = s.joints[r];
        if (jc.treeLoop && !addAuxiliary(r, false)) jc.inTree = jc.treeLoop = false;
    }
    for (std::size_t r = 0; r < s.joints.size(); ++r) {
        JointConstraint& jc = s.joints[r];
        if (jc.treeSpring && !addAuxiliary(r, true)) jc.treeSpring = false;
    }
}

namespace {

/// The solver state of a joint side, or the zero state kept after the awake
/// bodies for a side without one (static, kinematic without a state, asleep).
BodyState& sideState(SolverArrays& s, int index) {
    return index >= 0 ? s.states[static_cast<std::size_t>(index)] : s.states.back();
}

/// Solves the factored system for the right-hand sides in the nodes' rhs
/// (leaving the solution there): forward, y_i = D_i⁻¹ r̂_i with
/// r̂_parent −= B_iᵀ y_i; then backward, roots first, x_i = y_i − D_i⁻¹ B_i x_parent.
void substitute(std::vector<TreeNode>& nodes) {
    for (TreeNode& node : nodes) {
        const double r0 = node.rhs[0], r1 = node.rhs[1], r2 = node.rhs[2];
        for (int r = 0; r < 3; ++r) node.rhs[r] = node.diag[r][0] * r0 + node.diag[r][1] * r1 + node.diag[r][2] * r2;
        if (node.parent < 0) continue;
        TreeNode& parent = nodes[static_cast<std::size_t>(node.parent)];
        for (int c = 0; c < 3; ++c)
            parent.rhs[c] -= node.link[0][c] * node.rhs[0] + node.link[1][c] * node.rhs[1] +
                             node.link[2][c] * node.rhs[2];
    }
    for (std::size_t k = nodes.size(); k-- > 0;) {
        TreeNode& node = nodes[k];
        if (node.parent < 0) continue;
        const TreeNode& parent = nodes[static_cast<std::size_t>(node.parent)];
        double bx[3];
        for (int r = 0; r < 3; ++r)
            bx[r] = node.link[r][0] * parent.rhs[0] + node.link[r][1] * parent.rhs[1] + node.link[r][2] * parent.rhs[2];
        for (int r = 0; r < 3; ++r)
            node.rhs[r] -= node.diag[r][0] * bx[0] + node.diag[r][1] * bx[1] + node.diag[r][2] * bx[2];
    }
}

/// The accumulated impulses of a loop's rows: its joint's equality rows', or its spring's.
/// A joint's accumulated spring impulse (a distance joint keeps its spring's
/// in its axial impulse, a weld its angular spring's in its angular one).
template <class Constraint>
auto& springImpulse(Constraint& jc) {
    if (jc.type == JointType::distance) return jc.impulses.axial;
    return jc.type == JointType::weld ? jc.impulses.angular : jc.impulses.spring;
}

void readLoopImpulse(const TreeLoop& loop, const JointConstraint& jc, double out[3]) {
    if (!loop.spring) return readImpulse(jc, out);
    out[0] = springImpulse(jc);
    out[1] = out[2] = 0.0;
}

/// Adds `delta` to the accumulated impulses of a loop's rows.
void accumulateLoopImpulse(const TreeLoop& loop, JointConstraint& jc, const double delta[3]) {
    if (!loop.spring) return addImpulse(jc, delta);
    springImpulse(jc) += static_cast<float>(delta[0]);
}

/// Adds scale · (a row's Jacobian jA, jB)ᵀ to the right-hand sides of its
/// body nodes (an impulse on the bodies, in the degrees of freedom they have).
void addRowImpulse(std::vector<TreeNode>& nodes, int nodeA, int nodeB, const float (&jA)[3], const float (&jB)[3],
                   double scale) {
    for (int side = 0; side < 2; ++side) {
        const int n = side == 0 ? nodeA : nodeB;
        if (n < 0) continue;
        TreeNode& body = nodes[static_cast<std::size_t>(n)];
        const float(&j)[3] = side == 0 ? jA : jB;
        for (int d = 0; d < 3; ++d) body.rhs[d] += scale * double(j[d]) * body.mask[d];
    }
}

/// Adds scale · (row r of a loop's Jacobian)ᵀ to the right-hand sides of its body nodes.
void addLoopImpulse(std::vector<TreeNode>& nodes, const TreeLoop& loop, int r, double scale) {
    addRowImpulse(nodes, loop.nodeA, loop.nodeB, loop.rows.jA[r], loop.rows.jB[r], scale);
}

/// Row r of a loop's Jacobian times the velocity changes in its body nodes' rhs.
double loopRowOfChange(const std::vector<TreeNode>& nodes, const TreeLoop& loop, int r) {
    double sum = 0.0;
    for (int side = 0; side < 2; ++side) {
        const int n = side == 0 ? loop.nodeA : loop.nodeB;
        if (n < 0) continue;
        const TreeNode& body = nodes[static_cast<std::size_t>(n)];
        const float* j = side == 0 ? loop.rows.jA[r] : loop.rows.jB[r];
        for (int d = 0; d < 3; ++d) sum += double(j[d]) * body.mask[d] * body.rhs[d];
    }
    return sum;
}

/// A loop row whose pivot is below this fraction of what it would be with no
/// tree and no other loop row (the row's own J M⁻¹ Jᵀ, with its compliance)
/// is dropped: the trees and the rows before it already hold it (a hinge
/// doubling another, a slider closing a welded frame), and solving for what
/// is left, rounding and near-locked geometry, takes impulses that many times
/// the row's own scale. Relative to the pivot's own diagonal instead, a
/// slider closing a frame of hinges and a weld (alike bodies) kept a pivot
/// 10⁻¹¹ of its free mobility in the relax pass, was solved, and the frame
/// gained 176 times its energy in one step.
constexpr double kLoopPivot = 1e-6;

/// The loops' rows at the current positions and their system through the
/// factored trees (Baraff (1996), §8): column k of J_L P J_Lᵀ is what a unit
/// impulse on loop row k does to every loop row once the trees' rows have
/// answered it, one substitution per row. Then S = L Lᵀ (Cholesky), the rows
/// that add nothing independent dropped (kLoopPivot).
void factorLoops(SolverArrays& s, JointTrees& t, double gammaScale, float h) {
    if (t.loops.empty()) return;
    const int m = t.loopRows;
    double(&S)[kMaxLoopRows][kMaxLoopRows] = t.loopMatrix;
    // A row its joint does not hand over (none should) stays zero: dropped.
    for (int i = 0; i < m; ++i) {
        t.loopPivotFloor[i] = INFINITY;
        for (int j = 0; j < m; ++j) S[i][j] = 0.0;
    }
    for (std::size_t l = 0; l < t.loops.size(); ++l) {
        TreeLoop& loop = t.loops[l];
        JointConstraint& jc = s.joints[static_cast<std::size_t>(loop.row)];
        const BodyState& sA = sideState(s, jc.a);
        const BodyState& sB = sideState(s, jc.b);
        EqualityRows& rows = loop.rows;
        // Γ = γ·K of the joint's own block, as a tree joint's (factor), with
        // the pass's γ; a spring's with its own, γ = impulseScale/massScale
        // of its softness: (K + Γ)Δλ = −(Jv + rate·C + Γλ) is then its sweep's
        // impulse, −massScale·K⁻¹(Jv + rate·C) − impulseScale·λ.
        double g = gammaScale;
        if (loop.spring) {
            Softness soft;
            springRow(jc, sA, sB, h, rows, soft);
            loop.springRate = soft.biasRate;
            g = soft.massScale > 0.0f ? double(soft.impulseScale) / soft.massScale : INFINITY;
        } else {
            equalityRows(jc, sA, sB, rows);
        }
        const int allotted = (l + 1 < t.loops.size() ? t.loops[l + 1].first : m) - loop.first;
        rows.count = std::min(rows.count, allotted);
        const double invA[3] = {jc.invMassA, jc.invMassA, jc.invIA}, invB[3] = {jc.invMassB, jc.invMassB, jc.invIB};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                double k = 0.0;
                if (r < rows.count && c < rows.count)
                    for (int d = 0; d < 3; ++d)
                        k += double(rows.jA[r][d]) * invA[d] * rows.jA[c][d] +
                             double(rows.jB[r][d]) * invB[d] * rows.jB[c][d];
                loop.compliance[r][c] = std::isfinite(g) ? g * k : 0.0;
                if (r == c && r < rows.count) t.loopPivotFloor[loop.first + r] = kLoopPivot * (1.0 + g) * k;
            }
    }
    for (const TreeLoop& source : t.loops)
        for (int r = 0; r < source.rows.count; ++r) {
            for (TreeNode& node : t.nodes) node.rhs[0] = node.rhs[1] = node.rhs[2] = 0.0;
            addLoopImpulse(t.nodes, source, r, 1.0);
            substitute(t.nodes);
            const int k = source.first + r;
            for (const TreeLoop& loop : t.loops)
                for (int q = 0; q < loop.rows.count; ++q) S[loop.first + q][k] = loopRowOfChange(t.nodes, loop, q);
            for (int q = 0; q < source.rows.count; ++q) S[source.first + q][k] += source.compliance[q][r];
        }
    // Symmetrised (the two halves differ by rounding) and factored in place,
    // the lower triangle holding L.
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < i; ++j) S[i][j] = S[j][i] = 0.5 * (S[i][j] + S[j][i]);
    for (int k = 0; k < m; ++k) {
        double pivot = S[k][k];
        for (int j = 0; j < k; ++j) pivot -= S[k][j] * S[k][j];
        t.loopDropped[k] = !(pivot > t.loopPivotFloor[k]) || !std::isfinite(pivot);
        if (t.loopDropped[k]) {
            for (int i = k; i < m; ++i) S[i][k] = 0.0;
            continue;
        }
        S[k][k] = std::sqrt(pivot);
        for (int i = k + 1; i < m; ++i) {
            double v = S[i][k];
            for (int j = 0; j < k; ++j) v -= S[i][j] * S[k][j];
            S[i][k] = v / S[k][k];
        }
    }
}

/// Which limit each tree joint's node holds at the positions now
/// (JointConstraint::treeLimit, TreeNode::speculative, JointTrees::holdsLimits);
/// `newPositions` first forgets the limits let go of at the last positions.
void decideHeldLimits(const WorldState& w, SolverArrays& s, JointTrees& t, bool newPositions) {
    t.holdsLimits = false;
    if (!t.anyLimit) return;  // (no tree joint has a limit: none is ever held)
    for (TreeNode& node : t.nodes) {
        if (node.row < 0) continue;
        JointConstraint& jc = s.joints[static_cast<std::size_t>(node.row)];
        const BodyState& sA = sideState(s, jc.a);
        const BodyState& sB = sideState(s, jc.b);
        // A limit reached is held with the tree (an active set: a limit that
        // pulls is let go until the positions change, solveJointTrees), and
        // so is one within a slop of it, with the gap as the row's
        // speculative target, J v = −C/h: the approach that closes it within
        // the substep, as the limit's own sweep row allows. Held only once
        // reached, a limit was passed by up to a substep's travel first
        // (0.004 rad in the 90:1 pair of test_joint_tree.cpp, 0.042 at one
        // substep; a rope 9 mm) and pushed back from there. Judged by the
        // rate now instead, the hold came too late: by the time the tree is
        // factored, the joint's own limit row has stopped the light body
        // and the rate reads zero.
        if (newPositions) jc.limitReleased = false;
        jc.treeLimit = 0;
        node.speculative = false;
        if (LimitCoordinate c; !jc.limitReleased && limitCoordinate(jc, sA, sB, c)) {
            int side = limitSide(c.value, c.lower, c.upper);
            if (side == 0) {  // (then lower < value < upper) the nearer bound, if within the slop
                const float slop = jc.type == JointType::revolute ? kAngularLimitSlop : kLinearSlop;
                const float toLower = c.value - c.lower, toUpper = c.upper - c.value;
                if (std::min(toLower, toUpper) <= slop) side = toLower <= toUpper ? -1 : 1;
                node.speculative = side != 0;
            }
            jc.treeLimit = static_cast<std::int8_t>(side);
        }
        // A slider's or a rope's limit is left to its sweep row while a body
        // of the joint touches something: held rigid by the tree, a light
        // body between a heavy one and the ground was pressed 6.5 cm into
        // the ground (the contact's sweep moves it by its own mass alone),
        // and the push out of it went through the rigid limit to the heavy
        // body, thrown back up with 14 % more energy than it fell with. (A
        // revolute joint's limit, held beside contacts, did better held.)
        if (jc.treeLimit != 0 && jc.type != JointType::revolute) {
            const Joint& joint = w.joints[jc.joint];
            if (touchesThroughContact(w, joint.bodyA) || touchesThroughContact(w, joint.bodyB)) jc.treeLimit = 0;
        }
        node.speculative = node.speculative && jc.treeLimit != 0;
        t.holdsLimits = t.holdsLimits || jc.treeLimit != 0;
    }
}

/// The blocks of every node at the current positions (H_ii and the links),
/// then their elimination, leaves first.
void factor(const WorldState& w, SolverArrays& s, JointTrees& t, double gammaScale, float h, bool newPositions,
            bool limitsDecided, bool push = false) {
    std::vector<TreeNode>& nodes = t.nodes;
    if (!limitsDecided) decideHeldLimits(w, s, t, newPositions);
    for (TreeNode& node : nodes) {
        if (node.row >= 0) continue;
        const Body& b = w.bodies[s.stateBodies[static_cast<std::size_t>(node.body)]];
        setZero(node.diag);
        setZero(node.link);
        // M = diag(m, m, I); a degree of freedom the body lacks (zero inverse)
        // gets 1 and zero coupling, so its velocity change is zero.
        const float extra = node.body < static_cast<int>(t.extraInertia.size())
                                ? t.extraInertia[static_cast<std::size_t>(node.body)]
                                : 0.0f;
        const float invMass = b.invMass, invI = raisedInverseInertia(b.invInertia, extra);
        node.mask[0] = node.mask[1] = invMass != 0.0f ? 1.0f : 0.0f;
        node.mask[2] = invI != 0.0f ? 1.0f : 0.0f;
        node.diag[0][0] = node.diag[1][1] = invMass != 0.0f ? 1.0 / invMass : 1.0;
        node.diag[2][2] = invI != 0.0f ? 1.0 / invI : 1.0;
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        TreeNode& node = nodes[i];
        if (node.row < 0) continue;
        JointConstraint& jc = s.joints[static_cast<std::size_t>(node.row)];
        BodyState& sA = sideState(s, jc.a);
        BodyState& sB = sideState(s, jc.b);
        EqualityRows& rows = node.rows;
        equalityRows(jc, sA, sB, rows);
        // In a push, a row that holds a point or a line moves its bodies
        // without turning them, and a row that holds an angle only turns
        // them (pushJointTrees).
        if (push)
            for (int r = 0; r < rows.count; ++r)
                if (rows.jA[r][0] != 0.0f || rows.jA[r][1] != 0.0f || rows.jB[r][0] != 0.0f || rows.jB[r][1] != 0.0f)
                    rows.jA[r][2] = rows.jB[r][2] = 0.0f;
        const int n = rows.count;
        const int limitRow = heldLimitRow(jc);
        // Γ = γ·K with K = J_A M_A⁻¹ J_Aᵀ + J_B M_B⁻¹ J_Bᵀ, the joint's own block.
        const double invA[3] = {jc.invMassA, jc.invMassA, jc.invIA}, invB[3] = {jc.invMassB, jc.invMassB, jc.invIB};
        // A row no body can act on (an angle row between bodies that do not
        // turn): moot, as in the joint's own sweep. Left in, its zero pivot
        // made the whole joint's block singular and dropped every row of it.
        bool moot[3] = {false, false, false};
        for (int r = 0; r < n; ++r) {
            double k = 0.0;
            for (int d = 0; d < 3; ++d)
                k += double(rows.jA[r][d]) * invA[d] * rows.jA[r][d] + double(rows.jB[r][d]) * invB[d] * rows.jB[r][d];
            if (k > 0.0) continue;
            moot[r] = true;
            for (int d = 0; d < 3; ++d) rows.jA[r][d] = rows.jB[r][d] = 0.0f;
            rows.error[r] = 0.0f;
        }
        setZero(node.compliance);
        setZero(node.link);
        setZero(node.diag);
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                double k = 0.0;
                for (int d = 0; d < 3; ++d)
                    k += double(rows.jA[r][d]) * invA[d] * rows.jA[c][d] +
                         double(rows.jB[r][d]) * invB[d] * rows.jB[c][d];
                // A limit the tree holds is rigid: soft relative to its own
                // row's mass, the light body's, it yielded to the load beyond
                // (a 0.2 kg disc held at its limit under an 18 kg box crept
                // 0.12 rad past it in 10 s; rigid, it stays at it).
                const double g = r == limitRow || c == limitRow || node.pushed ? 0.0 : gammaScale;
                node.compliance[r][c] = g * k;
                node.diag[r][c] = -g * k;
            }
        for (int r = 0; r < 3; ++r)  // unused and moot rows: x = 0
            if (r >= n || moot[r]) node.diag[r][r] = -1.0;
        // The links: this joint's to its parent body, and each child body's to this joint.
        for (int side = 0; side < 2; ++side) {
            const int bodyNode = side == 0 ? node.nodeA : node.nodeB;
            if (bodyNode < 0) continue;
            const float(*j)[3] = side == 0 ? rows.jA : rows.jB;
            TreeNode& body = nodes[static_cast<std::size_t>(bodyNode)];
            if (bodyNode == node.parent) {
                for (int r = 0; r < n; ++r)
                    for (int d = 0; d < 3; ++d) node.link[r][d] = double(j[r][d]) * body.mask[d];
            } else {
                for (int r = 0; r < n; ++r)
                    for (int d = 0; d < 3; ++d) body.link[d][r] = double(j[r][d]) * body.mask[d];
            }
        }
    }
    // Elimination: D_i⁻¹, and D_parent −= B_iᵀ D_i⁻¹ B_i.
    for (TreeNode& node : nodes) {
        invertSymmetric(node.diag);
        if (node.parent < 0) continue;
        TreeNode& parent = nodes[static_cast<std::size_t>(node.parent)];
        double db[3][3];  // D⁻¹ B
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                db[r][c] = node.diag[r][0] * node.link[0][c] + node.diag[r][1] * node.link[1][c] +
                           node.diag[r][2] * node.link[2][c];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                parent.diag[r][c] -= node.link[0][r] * db[0][c] + node.link[1][r] * db[1][c] +
                                     node.link[2][r] * db[2][c];
    }
    if (!push) factorLoops(s, t, gammaScale, h);
}

}  // namespace

namespace {

/// Row r of `rows` times the two bodies' velocities, J_r v.
double rowSpeed(const EqualityRows& rows, int r, const BodyState& sA, const BodyState& sB) {
    return double(rows.jA[r][0]) * sA.v.x + double(rows.jA[r][1]) * sA.v.y + double(rows.jA[r][2]) * sA.w +
           double(rows.jB[r][0]) * sB.v.x + double(rows.jB[r][1]) * sB.v.y + double(rows.jB[r][2]) * sB.w;
}

/// Row r of Γ λ.
double compliantImpulse(const double (&compliance)[3][3], int r, const double lambda[3]) {
    return compliance[r][0] * lambda[0] + compliance[r][1] * lambda[1] + compliance[r][2] * lambda[2];
}

/// The trees' joints' right-hand sides r = −(J v + b·C + Γ λ), 0 for the bodies.
void treeRightHandSides(SolverArrays& s, JointTrees& t, const RowBias& rb, float invH, bool push) {
    for (TreeNode& node : t.nodes) {
        node.rhs[0] = node.rhs[1] = node.rhs[2] = 0.0;
        if (node.row < 0 || (push && !node.pushed)) continue;  // (a tree not pushed: no change)
        const JointConstraint& jc = s.joints[static_cast<std::size_t>(node.row)];
        const BodyState& sA = sideState(s, jc.a);
        const BodyState& sB = sideState(s, jc.b);
        const EqualityRows& rows = node.rows;
        double lambda[3];
        readImpulse(jc, lambda);
        for (int r = 0; r < rows.count; ++r) {
            const double jv = rowSpeed(rows, r, sA, sB);
            const double gl = compliantImpulse(node.compliance, r, lambda);
            // A held limit not reached yet closes its gap within the substep
            // (a push does not: the gap is no error).
            // A pushed tree's rows are rigid in the soft pass (its error is the push's).
            const bool gap = node.speculative && r == heldLimitRow(jc);
            const bool rigid = node.pushed && !push && rb.impulseScale != 0.0f;
            const double bias = gap ? (push ? 0.0 : double(invH)) : rigid ? 0.0 : double(rb.bias);
            node.rhs[r] = -(jv + bias * rows.error[r] + gl);
        }
    }
}

/// The loops' impulses Δλ_L (Baraff (1996), §8): with Δv₀ the trees' answer
/// to their own rows (in the nodes' rhs), S Δλ_L = −(J_L (v + Δv₀) + b·C + Γ λ),
/// solved with the factors of factorLoops (a dropped row takes none).
void solveLoops(SolverArrays& s, const JointTrees& t, const RowBias& rb, double out[kMaxLoopRows]) {
    const int m = t.loopRows;
    double y[kMaxLoopRows];
    for (const TreeLoop& loop : t.loops) {
        const JointConstraint& jc = s.joints[static_cast<std::size_t>(loop.row)];
        const BodyState& sA = sideState(s, jc.a);
        const BodyState& sB = sideState(s, jc.b);
        const EqualityRows& rows = loop.rows;
        double lambda[3];
        readLoopImpulse(loop, jc, lambda);
        const double rate = loop.spring ? double(loop.springRate) : double(rb.bias);
        for (int r = 0; r < rows.count; ++r) {
            // With Δv₀: the velocities the trees' rows leave.
            const double jv = rowSpeed(rows, r, sA, sB) + loopRowOfChange(t.nodes, loop, r);
            const double gl = compliantImpulse(loop.compliance, r, lambda);
            y[loop.first + r] = -(jv + rate * rows.error[r] + gl);
        }
    }
    const double(&L)[kMaxLoopRows][kMaxLoopRows] = t.loopMatrix;
    for (int i = 0; i < m; ++i) {  // L y = r
        if (t.loopDropped[i]) {
            y[i] = 0.0;
            continue;
        }
        for (int j = 0; j < i; ++j) y[i] -= L[i][j] * y[j];
        y[i] /= L[i][i];
    }
    for (int i = m; i-- > 0;) {  // Lᵀ x = y
        if (t.loopDropped[i]) {
            out[i] = 0.0;
            continue;
        }
        double v = y[i];
        for (int j = i + 1; j < m; ++j) v -= L[j][i] * out[j];
        out[i] = v / L[i][i];
    }
}

/// The impulses of the limits let go of in this solve (releaseLimits), taken
/// off through the trees: their opposite on the bodies' right-hand sides.
void undoReleasedLimits(JointTrees& t) {
    for (const ReleasedLimit& released : t.releasedLimits)
        addRowImpulse(t.nodes, released.nodeA, released.nodeB, released.jA, released.jB, -released.impulse);
}

/// One exact solve of the trees with the factorization in `t`.
void solveFactored(SolverArrays& s, JointTrees& t, const RowBias& rb, float invH, bool push = false) {
    std::vector<TreeNode>& nodes = t.nodes;
    treeRightHandSides(s, t, rb, invH, push);
    undoReleasedLimits(t);
    substitute(nodes);
    if (!push && !t.loops.empty()) {
        // With the loops: their impulses from the trees' answer, then the
        // trees solved again with those impulses on their bodies.
        double loopImpulse[kMaxLoopRows];
        solveLoops(s, t, rb, loopImpulse);
        treeRightHandSides(s, t, rb, invH, push);
        undoReleasedLimits(t);
        for (const TreeLoop& loop : t.loops) {
            double delta[3] = {0.0, 0.0, 0.0};
            for (int r = 0; r < loop.rows.count; ++r) {
                delta[r] = loopImpulse[loop.first + r];
                addLoopImpulse(nodes, loop, r, delta[r]);
            }
            accumulateLoopImpulse(loop, s.joints[static_cast<std::size_t>(loop.row)], delta);
        }
        substitute(nodes);
    }
    // Apply: Δv to the bodies, Δλ = −x to the joints.
    for (TreeNode& node : nodes) {
        if (node.row >= 0) {
            const double delta[3] = {-node.rhs[0], -node.rhs[1], -node.rhs[2]};
            addImpulse(s.joints[static_cast<std::size_t>(node.row)], delta);
        } else {
            BodyState& st = s.states[static_cast<std::size_t>(node.body)];
            st.v.x += static_cast<float>(node.rhs[0]) * node.mask[0];
            st.v.y += static_cast<float>(node.rhs[1]) * node.mask[1];
            st.w += static_cast<float>(node.rhs[2]) * node.mask[2];
        }
    }
}

/// Takes the limits the trees let go of (releasePullingLimits) off the
/// bodies: each one's accumulated impulse, warm started and solved with the
/// tree, pulled, and a limit that is let go carries none. The solves that
/// follow apply its opposite through the trees (releasedLimits), so that the
/// trees answer it as they would any impulse on their bodies. Left to the
/// limit's sweep row, which moves a body by its own mass alone, the impulse
/// was taken back a few percent a pass: a hinge let go at its limit with a
/// spring pushing it off kept 130 N·m of its limit's torque for five steps,
/// and its tree of five light bodies gained 12 % of its energy. Undone with
/// the bodies' own masses instead, and the soft rows left to turn that into
/// the trees' answer, a light body took the whole impulse first and a tree
/// of 1,000:1 bodies gained 90 times its energy.
void releaseLimits(SolverArrays& s, JointTrees& t) {
    for (const TreeNode& node : t.nodes) {
        if (node.row < 0) continue;
        JointConstraint& jc = s.joints[static_cast<std::size_t>(node.row)];
        const int r = heldLimitRow(jc);
        if (!jc.limitReleased || r < 0 || r >= node.rows.count) continue;
        ReleasedLimit& released = t.releasedLimits.emplace_back();
        released.row = node.row;
        released.lower = jc.treeLimit < 0;
        released.nodeA = node.nodeA;
        released.nodeB = node.nodeB;
        for (int d = 0; d < 3; ++d) {
            released.jA[d] = node.rows.jA[r][d];
            released.jB[d] = node.rows.jB[r][d];
        }
        // Along +J: the lower pushes that way, the upper against.
        released.impulse = released.lower ? jc.impulses.lower : -jc.impulses.upper;
    }
    for (const ReleasedLimit& released : t.releasedLimits) {
        JointImpulses& acc = s.joints[static_cast<std::size_t>(released.row)].impulses;
        (released.lower ? acc.lower : acc.upper) = 0.0f;
    }
}

/// Whether a limit the trees hold pulled in the last solve; such limits are
/// let go (JointConstraint::limitReleased).
bool releasePullingLimits(SolverArrays& s, JointTrees& t) {
    bool any = false;
    for (const TreeNode& node : t.nodes) {
        if (node.row < 0) continue;
        JointConstraint& jc = s.joints[static_cast<std::size_t>(node.row)];
        if (jc.treeLimit == 0) continue;
        const float held = jc.treeLimit < 0 ? jc.impulses.lower : jc.impulses.upper;
        if (held >= 0.0f) continue;
        jc.limitReleased = true;
        any = true;
    }
    return any;
}

}  // namespace

void holdTreeLimits(WorldState& w, int positions) {
    JointTrees& t = w.solver.trees;
    if (t.nodes.empty() || t.limitsDecidedAt == positions) return;
    decideHeldLimits(w, w.solver, t, true);
    t.limitsDecidedAt = positions;
}

void solveJointTrees(WorldState& w, const JointContext& ctx, int positions) {
    SolverArrays& s = w.solver;
    JointTrees& t = s.trees;
    if (t.nodes.empty()) return;
    const RowBias rb = rigidBias(ctx, 1.0f);  // the rates, applied to each row's error
    const bool soft = rb.impulseScale != 0.0f;
    const double gammaScale = soft && rb.massScale > 0.0f ? double(rb.impulseScale) / rb.massScale : 0.0;
    if (t.factoredPositions != positions || t.factoredSoft != soft) {
        // At new positions the held limits were decided before the sweep
        // (holdTreeLimits); again after a limit was let go of.
        const bool newPositions = t.factoredPositions != positions;
        factor(w, s, t, gammaScale, ctx.h, newPositions, newPositions && t.limitsDecidedAt == positions);
        t.factoredPositions = positions;
        t.factoredSoft = soft;
    }
    if (!t.holdsLimits) {
        solveFactored(s, t, rb, ctx.invH);
        return;
    }
    // An active set: a limit held as an equality may come out pulling (the
    // joint leaving it); then the solve is made again from the same start
    // without that limit, which the sweep then treats as before.
    // What a solve changes: the trees' bodies' velocities, their joints' impulses.
    std::vector<BodyState>& saved = t.savedStates;
    std::vector<JointImpulses>& savedImpulses = t.savedImpulses;
    saved.clear();
    savedImpulses.clear();
    for (const TreeNode& node : t.nodes) {
        if (node.row >= 0)
            savedImpulses.push_back(s.joints[static_cast<std::size_t>(node.row)].impulses);
        else
            saved.push_back(s.states[static_cast<std::size_t>(node.body)]);
    }
    for (const TreeLoop& loop : t.loops) savedImpulses.push_back(s.joints[static_cast<std::size_t>(loop.row)].impulses);
    for (int attempt = 0;; ++attempt) {
        solveFactored(s, t, rb, ctx.invH);
        if (attempt == 2 || !releasePullingLimits(s, t)) break;
        std::size_t body = 0, joint = 0;
        for (const TreeNode& node : t.nodes) {
            if (node.row >= 0)
                s.joints[static_cast<std::size_t>(node.row)].impulses = savedImpulses[joint++];
            else
                s.states[static_cast<std::size_t>(node.body)] = saved[body++];
        }
        for (const TreeLoop& loop : t.loops)
            s.joints[static_cast<std::size_t>(loop.row)].impulses = savedImpulses[joint++];
        releaseLimits(s, t);
        factor(w, s, t, gammaScale, ctx.h, false, false);
    }
    t.releasedLimits.clear();
    // A limit that still pulls after the third solve keeps no pull.
    for (const TreeNode& node : t.nodes) {
        if (node.row < 0) continue;
        JointConstraint& jc = s.joints[static_cast<std::size_t>(node.row)];
        if (jc.treeLimit == 0) continue;
        jc.impulses.lower = std::max(jc.impulses.lower, 0.0f);
        jc.impulses.upper = std::max(jc.impulses.upper, 0.0f);
    }
}

// A push closes a point's error by moving the bodies, not turning them.
// Turning moves an anchor linearly in the angle only for small angles, and the
// least correction in the bodies' masses turns a body light in rotation: a
// disc of radius 0.2 m hinged 0.5 m from its centre turns 12 times as readily
// as it moves (I⁻¹r² against m⁻¹), so a joint 1 m open was to be closed by
// turning discs some 2 rad, which moved their anchors elsewhere; pushes so
// made left a 40-disc chain 31 m open after 2 s. With its point rows moving
// the bodies only, the same chain closes within half a second (docs/joints.md,
// "Stretched joints"). An angle's row (a weld's) turns them, which is exact
// in the angle; what the turn does to the anchors the next substep's push
// closes.
void pushJointTrees(WorldState& w, const JointContext& ctx) {
    SolverArrays& s = w.solver;
    JointTrees& t = s.trees;
    if (t.nodes.empty()) return;
    // The pseudo-velocities take the real ones' place for the solve.
    std::vector<BodyState>& saved = t.savedStates;
    std::vector<JointImpulses>& savedImpulses = t.savedImpulses;
    saved.clear();
    savedImpulses.clear();
    for (const TreeNode& node : t.nodes) {
        if (node.row >= 0) {
            savedImpulses.push_back(s.joints[static_cast<std::size_t>(node.row)].impulses);
            continue;
        }
        const std::size_t b = static_cast<std::size_t>(node.body);
        saved.push_back(s.states[b]);
        s.states[b].v = s.biasV[b];
        s.states[b].w = s.biasW[b];
    }
    factor(w, s, t, 0.0, ctx.h, false, false, /*push=*/true);
    solveFactored(s, t, {ctx.pushFactor * ctx.invH, 1.0f, 0.0f}, ctx.invH, true);
    t.factoredPositions = -1;  // the next solve factors the bodies as they are
    std::size_t body = 0, joint = 0;
    for (const TreeNode& node : t.nodes) {
        if (node.row >= 0) {
            s.joints[static_cast<std::size_t>(node.row)].impulses = savedImpulses[joint++];
            continue;
        }
        const std::size_t b = static_cast<std::size_t>(node.body);
        s.biasV[b] = s.states[b].v;
        s.biasW[b] = s.states[b].w;
        s.states[b].v = saved[body].v;
        s.states[b].w = saved[body].w;
        ++body;
    }
}

}  // namespace i2d::detail
