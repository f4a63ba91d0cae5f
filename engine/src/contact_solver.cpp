// The contact rows: preparation, warm start, the Gauss-Seidel sweeps of each
// solver pass, split mode's push, the restitution pass, and storing the
// impulses for the next step (contact_solver.hpp describes the layout).
//
// Each row is solved on its own against the current velocities and its
// accumulated impulse is clamped (normal ≥ 0, |friction| ≤ μ·normal): the
// projected Gauss-Seidel of Tamis and Maggiore (2015), Constraint based
// physics solver, §7.2, without ever forming the matrix A = J M⁻¹ Jᵀ, since a
// row's update λ += −(J v − v_target)/(J M⁻¹ Jᵀ) is the same computation.
#include <algorithm>
#include <cmath>

#include "contact_persistence.hpp"
#include "contact_row.hpp"
#include "contact_solver.hpp"
#include "rest_load.hpp"
#include "wide_contact.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// The approach speed from which the last relax leaves a gap to the impact
/// law (soft_relax_last with the closed-form model). The law strikes what
/// meets faster than impactThreshold at the moment of impact, and along its
/// fall within the next step a pair can close faster than it does now by up
/// to g·Δt: judged by its speed now, a ball with e = 0.75 falling 5.3 cm
/// (1.03 m/s at impact) was slowed here to 0.45 m/s a step before it met the
/// ground, and never bounced. Left alone from the threshold less g·Δt, such a
/// gap's approach reaches the next step's impact stage, which judges it at
/// the moment of impact; those it passes over the rows then stop.
float leftApproachSpeed(const WorldState& w) {
    return std::max(w.settings.impactThreshold - length(w.settings.gravity) * w.stepDt, 0.0f);
}

// Baumgarte mode keeps its push in the bodies' velocities. A body
// overlapping many others deeply (boxes created on top of each other) would
// otherwise collect one capped push per contact and fly off at many times
// maxPushSpeed. There a body's deep contacts therefore share the cap, each
// getting maxPushSpeed / n (n the larger count of its two bodies); split
// mode's rows keep the shared cap too (it decides which pairs of points are
// solved together). The soft step pushes deep overlaps on pseudo-velocities
// instead (deep_overlap.cpp) and does not share.

// Divides the push cap of each deep contact by the larger deep-contact count
// of its two bodies (counted in prepareContacts).
void sharePushAmongDeepContacts(WorldState& w) {
    std::vector<int>& count = w.solver.deepContactCount;
    count.back() = 1;  // the immovable stand-in never shares
    for (ContactConstraint& cc : w.solver.constraints) {
        if (!cc.deepOverlap) continue;
        const int n = std::max(count[static_cast<std::size_t>(cc.a)], count[static_cast<std::size_t>(cc.b)]);
        if (n > 1) cc.maxPush /= static_cast<float>(n);
    }
}

}  // namespace

RowContext makeRowContext(const WorldState& w, float h, bool soft) {
    const WorldSettings& set = w.settings;
    RowContext x;
    x.zeroState = static_cast<int>(w.solver.states.size()) - 1;
    const float rate = 1.0f / h;
    // Capped at a quarter of the substep rate, as the joints are: 60 Hz at
    // the default 240 Hz substeps, 15 Hz at one substep of 60 Hz. (It was an
    // eighth while the sweep ran in one direction: then 15 Hz contacts let a
    // sagging 100-row pyramid go and threw its top 2 m up, +2 % energy;
    // tests/testbed/test_energy_audit.cpp runs it.) A row stiffer than about
    // 50 Hz at 240 Hz substeps rocks a pyramid: docs/validation.md, "The
    // pyramid's compliance".
    const float hertz = std::min(set.contactHertz, 0.25f * rate);
    x.dynamicSoft = makeSoft(hertz, set.contactDampingRatio, h);
    // Against an immovable body only one side gives: stiffen (Solver2D doubles the hertz).
    x.staticSoft = makeSoft(2.0f * hertz, set.contactDampingRatio, h);
    x.dynamicRestCompliance = soft ? restCompliance(hertz) : 0.0f;
    x.staticRestCompliance = soft ? restCompliance(2.0f * hertz) : 0.0f;
    x.biasRestitution = set.impactModel == ImpactModel::velocity_bias && !soft;
    x.fullDt = soft ? h * static_cast<float>(set.substeps) : h;
    x.warm = set.enableWarmStarting ? 1.0f : 0.0f;
    // The push a point would ask for at its overlap: the soft step's bias
    // rate, or Baumgarte's β/Δt past the slop.
    x.pushRate = soft ? 0.0f : set.pushFactor * rate;
    x.soft = soft;
    x.restingSpeed = soft && set.enableWarmStarting ? length(set.gravity) * x.fullDt : -1.0f;
    x.restingDepth = set.penetrationSlop;
    return x;
}

void prepareContacts(WorldState& w, float h, bool soft) {
    const RowContext x = makeRowContext(w, h, soft);
    SolverArrays& s = w.solver;
    s.deepContactCount.assign(s.states.size(), 0);
    s.rolling.clear();
    s.deepRows.clear();
    bool anyDeep = false, anyTurning = false;
    // Each row goes straight to its place in colour order (solver.cpp coloured
    // the contacts and left each colour's first slot in colourOffsets).
    s.constraints.resizeForOverwrite(static_cast<std::size_t>(s.rowCount));
    const std::size_t activeCount = w.activeContacts.size();

    for (std::size_t k = 0; k < activeCount; ++k) {
        const std::uint8_t colour = s.contactColours[k];
        if (colour == kNoRow) continue;
        const int c = w.activeContacts[k];
        const int row = s.colourOffsets[colour]++;
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(row)];
        const bool deep = prepareContactRow(w, x, c, cc);
        setTurning(cc, w.activeLooks[k].rowFlags);
        anyTurning = anyTurning || cc.turnA || cc.turnB;
        if (deep) {
            s.deepRows.push_back(row);
            ++s.deepContactCount[static_cast<std::size_t>(cc.a)];
            ++s.deepContactCount[static_cast<std::size_t>(cc.b)];
            anyDeep = true;
        }
        const ContactSurface* surface = contactSurface(w, c);
        if (surface && surface->rollingResistance > 0.0f) prepareRollingResistance(w, row, *surface);
    }
    s.anyDeepOverlap = anyDeep;
    s.anyTurningRow = anyTurning;
    std::sort(s.deepRows.begin(), s.deepRows.end());  // the push sweeps them in row order
    if (anyDeep && !soft) sharePushAmongDeepContacts(w);
    for (ContactConstraint& cc : s.constraints) finishContactRow(x, w.settings.penetrationSlop, cc);
}

namespace {

/// The wide blocks colour by colour, each colour's blocks shared among the
/// workers (WorldState::runner): they touch no movable body twice. A colour's
/// blocks are its two row groups (kWideGroupsPerColour) one after the other;
/// `blocks(b, e, points)` gets each chunk split where the one-point group starts.
/// `backward`: the colours last to first (SolverArrays::sweepBackward).
template <class F>
void forEachWideColour(WorldState& w, bool backward, F&& blocks) {
    // Blocks per chunk a worker claims. Each worker takes its own share of a
    // colour first (stage_runner.hpp), so only chunks taken from another's
    // share write bodies that other worker also writes; 32 balanced the
    // shares' ends better than 64 or 128 on pyramid100 (2.86 against 2.92 ms
    // per step on two workers). Claimed in turn from one counter, 16 ran
    // slower than 64 (3.4 against 2.7 ms of solve).
    constexpr int kBlockGrain = 32;
    const std::vector<int>& start = w.solver.wideContactColourStart;
    const std::size_t colours = start.empty() ? 0 : (start.size() - 1) / kWideGroupsPerColour;
    for (std::size_t c = 0; c < colours; ++c) {
        const std::size_t g = (backward ? colours - 1 - c : c) * kWideGroupsPerColour;
        const int first = start[g], single = start[g + 1], count = start[g + 2] - first;
        if (count == 0) continue;
        auto range = [&](int b, int e) {
            const int lo = first + b, hi = first + e;
            if (lo < single) blocks(lo, std::min(hi, single), 2);
            if (hi > single) blocks(std::max(lo, single), hi, 1);
        };
        w.runner.run(count, kBlockGrain, range);
    }
}

}  // namespace

// The warm start of deep rows (carryDeepLoads). The warm start carries each
// row's accumulated impulse into the next substep because a load (a body's
// weight, a stack's pressure) is steady: re-applied, it is what the row
// needs again, and one Gauss-Seidel sweep need only correct it. The rigid
// deep rows between bodies created overlapping also take impulses that are
// not loads: the substep a pile lands as one lump, they stop every body above
// the lowest within that substep, and the sweep squeezes bodies between
// opposing rows. Re-applied, such an impulse drives the bodies apart before
// the sweep runs, and one sweep cannot take back what a chain of rows gave:
// 50 capsules landing as one lump held 150 N·s in about 300 deep rows (a
// hundred times the pile's weight per substep), did 30 to 40 J of positive
// work per substep and bounced back almost elastically.
//
// A load is what a row carries substep after substep; an impact lasts one.
// So a deep point being pushed apart, its depth d more than its load
// explains (biasRate·d > loadPush: the points deep_overlap.cpp pushes), is
// warm-started with the smaller of its impulses at the end of the last two
// substeps, min(λ[i−1], λ[i−2]): a steady load is carried in full, a rising
// one a substep late (the sweep adds the rest, as for a new contact), a
// one-substep spike never. The load judged is that smaller impulse, so that
// a spike does not make its own depth look explained. A point whose depth
// its load does explain is the sag under a heavy load (the contact under a
// box 100 times heavier than the 5-box stack below it sinks 7 cm), not an
// overlap, and keeps its impulse in full: with the rigid rows, that stack's
// loads rise and fall by several per cent per substep as it breathes, and
// cutting every rise while following every fall pumped the breathing until
// the stacks 200 and 300 times heavier on top fell (as they did when deep
// rows were not warm-started at all, or were soft). Each point's friction
// stays within μ times the normal impulse carried. The rule runs at the
// step's end as well, so the stored impulses are what the next step's first
// substep carries. A step without deep rows does none of this; one with them
// keeps per deep row its block, lane and two floats, and makes one pass over
// its deep rows per substep.
void beginDeepCarry(SolverArrays& s) {
    s.deepCarry.resize(s.deepRows.size());
    // The blocks hold the coloured rows in ascending order, each from its
    // first row (wideBlockRows); the deep rows ascend too.
    const std::vector<int>& blockRows = s.wideBlockRows;
    const std::size_t blocks = s.wideContactsActive ? blockRows.size() / 2 : 0;
    const int wideEnd = s.wideContactsActive ? s.contactOverflowStart : 0;
    std::size_t block = 0;
    for (std::size_t d = 0; d < s.deepRows.size(); ++d) {
        const int r = s.deepRows[d];
        DeepCarry& dc = s.deepCarry[d];
        dc.block = -1;
        dc.lane = 0;
        if (r < wideEnd) {
            while (block + 1 < blocks && blockRows[2 * (block + 1)] <= r) ++block;
            dc.block = static_cast<int>(block);
            dc.lane = r - blockRows[2 * block];
        }
        const ContactConstraint& cc = s.constraints[static_cast<std::size_t>(r)];
        for (int j = 0; j < 2; ++j) dc.previous[j] = j < cc.pointCount ? cc.points[j].normalImpulse : 0.0f;
    }
}

void carryDeepLoads(SolverArrays& s, bool inRows) {
    const BodyState* states = s.states.data();
    for (std::size_t d = 0; d < s.deepRows.size(); ++d) {
        DeepCarry& dc = s.deepCarry[d];
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(s.deepRows[d])];
        WideContactBlock* k = dc.block >= 0 && !inRows ? &s.wideContacts[static_cast<std::size_t>(dc.block)] : nullptr;
        const BodyState& sA = states[cc.a];
        const BodyState& sB = states[cc.b];
        const Rot qA = cc.roundA ? Rot{} : sA.dq, qB = cc.roundB ? Rot{} : sB.dq;
        const Vec2 dp = sB.dp - sA.dp;
        for (int j = 0; j < cc.pointCount; ++j) {
            const ContactPointConstraint& cp = cc.points[j];
            float& normal = k ? k->points[j].normalImpulse[dc.lane] : cc.points[j].normalImpulse;
            float& tangent = k ? k->points[j].tangentImpulse[dc.lane] : cc.points[j].tangentImpulse;
            const float steady = std::min(normal, dc.previous[j]);
            dc.previous[j] = normal;
            const float sep = currentSeparation(cp, cc.normal, dp, qA, qB);
            if (-cc.biasRate * sep <= loadPush(cc, cp, steady)) continue;  // a sag its load explains
            normal = steady;
            const float maxFriction = cc.friction * steady;
            tangent = clamp(tangent, -maxFriction, maxFriction);
        }
    }
}

namespace {
void warmStartTurningRow(const ContactConstraint& cc, BodyState& sA, BodyState& sB);
}  // namespace

void warmStartContacts(WorldState& w) {
    SolverArrays& s = w.solver;
    if (!s.rolling.empty()) warmStartRollingResistance(w);
    // The coloured groups four at a time (wide_contact.cpp), then the rows
    // left to the scalar sweep.
    int first = 0;
    if (s.wideContactsActive) {
        forEachWideColour(w, false, [&](int b, int e, int points) { warmStartWideContacts(s, b, e, points); });
        first = s.contactOverflowStart;
    }
    BodyState* states = s.states.data();
    for (std::size_t r = static_cast<std::size_t>(first); r < s.constraints.size(); ++r) {
        ContactConstraint& cc = s.constraints[r];
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        if (cc.turnA || cc.turnB) {
            warmStartTurningRow(cc, sA, sB);
            continue;
        }
        Vec2 vA = sA.v, vB = sB.v;
        float wA = sA.w, wB = sB.w;
        const Vec2 n = cc.normal, t = rightPerp(n);
        for (int j = 0; j < cc.pointCount; ++j) {
            const ContactPointConstraint& cp = cc.points[j];
            Vec2 P = cp.normalImpulse * n + cp.tangentImpulse * t;
            vA = mulSub(vA, cc.invMassA, P);
            wA -= cc.invIA * cross(cp.rA, P);
            vB = mulAdd(vB, cc.invMassB, P);
            wB += cc.invIB * cross(cp.rB, P);
        }
        sA.v = vA;
        sA.w = wA;
        sB.v = vB;
        sB.w = wB;
    }
}

namespace {

/// The velocity target of one normal point in one pass.
struct PointTarget {
    float bias = 0.0f, massScale = 1.0f, impulseScale = 0.0f;
};

struct BodyVelocities {
    Vec2 vA;
    float wA;
    Vec2 vB;
    float wB;
};

struct RowMasses {
    float mA, iA, mB, iB;
};

float normalSpeed(const ContactPointConstraint& cp, Vec2 n, const BodyVelocities& v) {
    return dot((v.vB + cross(v.wB, cp.rB)) - (v.vA + cross(v.wA, cp.rA)), n);
}

void applyNormalImpulse(ContactPointConstraint& cp, Vec2 n, const RowMasses& m, float impulse, BodyVelocities& v) {
    cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, impulse);
    const Vec2 P = impulse * n;
    v.vA = mulSub(v.vA, m.mA, P);
    v.wA -= m.iA * cross(cp.rA, P);
    v.vB = mulAdd(v.vB, m.mB, P);
    v.wB += m.iB * cross(cp.rB, P);
}

/// One point on its own: the clamped increment of its accumulated impulse.
float pointImpulse(ContactPointConstraint& cp, Vec2 n, const PointTarget& t, const BodyVelocities& v) {
    const float vn = normalSpeed(cp, n, v);
    const float impulse = -cp.normalMass * t.massScale * (vn + t.bias) - t.impulseScale * cp.normalImpulse;
    const float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
    const float applied = newImpulse - cp.normalImpulse;
    cp.normalImpulse = newImpulse;
    return applied;
}

// The two points of a manifold are solved together. Each point's increment
// alone, u_j = −m_j·ms_j·(v_n,j + bias_j) − is_j·λ_j (the soft step's row,
// m_j = 1/K_jj), is the velocity change D·u (D = diag(K11, K22)) it asks
// for; the two impulses that give both changes at once solve K·Δλ = D·u,
// with K the rows' 2×2 effective-mass matrix. For rigid rows that is the
// block solve of Box2D 2.4.1's contact solver (Catto, 2009, b2ContactSolver,
// after Murty's direct enumeration); for soft rows a row at rest (u = 0)
// holds the load each point's own softness gives it, as when solved alone.
// Of the block solver's four cases only the first, both points pressing, is
// taken; where it would give a point a negative impulse (one point lifting:
// a box rocking onto a corner) the two are solved one after the other. A
// negative K12 (a unit box on another: ρ = −0.2) is taken as 0, which makes
// the solve side by side, each point clamped on its own: that converges by
// |ρ| a pass, and the pair's solve is as it was before the block solve. Why
// together:
// - Solved one after the other, the first point took an impulse the second
//   then corrected: a torque whose sign depends only on the points' order
//   in the manifold. It tilted every box of a column the same way in its
//   first steps (a column of 20 swayed 1.25 cm, and tall_stack20 0.27 m).
//   Solved together, a symmetric column gets symmetric impulses.
// - Solved side by side (each against the velocities before either acted,
//   both scaled by 1/(1 + ρ) where ρ = K12/√(K11·K22) > 0), the difference
//   of the rows, a box rocking on its two corners, converged by only
//   (1 − ρ)/(1 + ρ) a pass. For a post four times as tall as wide (ρ = 0.7)
//   that is 18 %: the rocking lagged behind its rows, and at 50 Hz contacts
//   and 4 substeps two such posts on each other rocked for good, corner to
//   corner, and walked (a column of 20 fell within 42 s).
// The block solve of all four cases, on the rows of deep overlaps too, threw
// a pile of 100 boxes created at one point at 26 m/s instead of 18; deep
// overlaps are not solved together (pointsTogether), nor are rows so nearly
// parallel that K is near singular (kLeastBlockDeterminant).
inline void solvePointPair(ContactConstraint& cc, const RowMasses& m, const PointTarget* t, BodyVelocities& v) {
    ContactPointConstraint& c1 = cc.points[0];
    ContactPointConstraint& c2 = cc.points[1];
    const Vec2 n = cc.normal;
    // Δλ = K⁻¹·D·u: Δλ1 = u1 − c1·Δλ2 and Δλ2 = u2 − c2·Δλ1, c_j = K12/K_jj.
    const float u1 = -c1.normalMass * t[0].massScale * (normalSpeed(c1, n, v) + t[0].bias) -
                     t[0].impulseScale * c1.normalImpulse;
    const float u2 = -c2.normalMass * t[1].massScale * (normalSpeed(c2, n, v) + t[1].bias) -
                     t[1].impulseScale * c2.normalImpulse;
    const float k1 = c1.normalMass * cc.pairCoupling, k2 = c2.normalMass * cc.pairCoupling;
    const float det = 1.0f - k1 * k2;
    const float next1 = c1.normalImpulse + (u1 - k1 * u2) / det;
    const float next2 = c2.normalImpulse + (u2 - k2 * u1) / det;
    auto take = [&](float total1, float total2) {
        const float increment1 = total1 - c1.normalImpulse, increment2 = total2 - c2.normalImpulse;
        c1.normalImpulse = total1;
        c2.normalImpulse = total2;
        applyNormalImpulse(c1, n, m, increment1, v);
        applyNormalImpulse(c2, n, m, increment2, v);
    };
    if (!(next1 < 0.0f || next2 < 0.0f)) {
        take(next1, next2);
    } else if (!(cc.pairCoupling > 0.0f)) {
        // Uncoupled (a negative K12 is taken as 0): each point clamped on its own.
        take(std::max(c1.normalImpulse + u1, 0.0f), std::max(c2.normalImpulse + u2, 0.0f));
    } else {
        applyNormalImpulse(c1, n, m, pointImpulse(c1, n, t[0], v), v);
        applyNormalImpulse(c2, n, m, pointImpulse(c2, n, t[1], v), v);
    }
}

/// A point's target in a pass, from its separation s now: Δλ = −m·ms·(vn +
/// bias) − is·λ, with the coefficients of its regime (speculative, soft
/// push, Baumgarte, none).
template <SolvePass passKind>
PointTarget pointTarget(const ContactConstraint& cc, const ContactPointConstraint& cp, float s, float invH, float beta,
                        float slop) {
    PointTarget t;
    if (s > 0.0f) {
        // Speculative: allow exactly the approach that closes the gap this (sub)step.
        t.bias = s * invH;
    } else if constexpr (passKind == SolvePass::soft_bias) {
        // A deep overlap is pushed apart on pseudo-velocities
        // (deep_overlap.cpp); its row here is rigid: it stops the
        // approach and carries the load.
        if (!cc.deepOverlap) {
            t.bias = std::max(cc.biasRate * s, -cc.maxPush);
            t.massScale = cc.massScale;
            t.impulseScale = cc.impulseScale;
        }
    } else if constexpr (passKind == SolvePass::baumgarte) {
        // Tamis and Maggiore (2015) eq. 5.3.1 with slop: push β·d/Δt, capped.
        t.bias = std::max(beta * invH * std::min(s + slop, 0.0f), -cc.maxPush);
    }
    if constexpr (passKind == SolvePass::baumgarte || passKind == SolvePass::no_push) {
        // Tamis and Maggiore (2015) §8.2: restitution target added to the push (classic modes).
        if (cp.restitutionBias > 0.0f) t.bias = std::min(t.bias, -cp.restitutionBias);
    }
    return t;
}

// Turning rows. A row keeps the normal n₀ its manifold had when the step
// began, and measures the gap between the two bodies' material points along
// it. While the face that n₀ belongs to turns little in the step that is
// the face's gap; a face turning by θ within the step moves, at a distance d
// along it from where the row's points were, by d·sin θ across n₀. A ball
// pressed by its spin against the wall of a box turning at 12 rad/s (11
// degrees a step) slid along the wall by 0.3 m a step, and the row, which
// saw the gap held along n₀, let it 7 cm into the wall in every step until
// it was through. A contact whose face turns further than kTurningRowAngle
// in the step gets a turning row instead, solved on the scalar path (the
// overflow group: such rows are few). The normal turns with its face, n =
// q·n₀ (q the face's rotation since the step began), and the gap is taken at
// the other body's point: for a face of A, C = (x_B − x_A)·n with x_A, x_B the
// two material points (they coincide when the step begins, so C starts at
// the manifold's separation). Its rate, Ċ = (v_B(x_B) − v_A(x_A))·n +
// (x_B − x_A)·(ω_A × n), is that of a row whose A arm ends at x_B: the face
// acts where the other body's point is, which is how it sweeps it along. A
// circle's point follows the turning normal (it is the circle's point
// nearest the face). The effective masses are taken at these arms in every
// pass.
struct TurningRow {
    Vec2 n, t;
    Vec2 rA[2], rB[2];          ///< the arms the row acts at
    Vec2 pointA[2], pointB[2];  ///< the material points' arms (x_A − c_A, x_B − c_B)
    float separation[2];
    float normalMass[2], tangentMass[2];
};

TurningRow turningRow(const ContactConstraint& cc, const BodyState& sA, const BodyState& sB) {
    TurningRow g;
    const Rot turn = cc.turnA ? sA.dq : sB.dq;
    g.n = rotate(turn, cc.normal);
    g.t = rightPerp(g.n);
    const Rot qA = cc.roundA ? turn : sA.dq, qB = cc.roundB ? turn : sB.dq;
    const Vec2 dp = sB.dp - sA.dp;
    for (int j = 0; j < cc.pointCount; ++j) {
        const ContactPointConstraint& cp = cc.points[j];
        const Vec2 rA = rotate(qA, cp.rA), rB = rotate(qB, cp.rB);
        // x_B − x_A: zero when the step began (both arms end at the manifold's point).
        const Vec2 gap = dp + (rB - rA) - (cp.rB - cp.rA);
        g.separation[j] = cp.adjustedSeparation + dot(cp.rB - cp.rA, cc.normal) + dot(gap, g.n);
        g.pointA[j] = rA;
        g.pointB[j] = rB;
        g.rA[j] = cc.turnA ? rA + gap : rA;
        g.rB[j] = cc.turnB ? rB - gap : rB;
        const float rnA = cross(g.rA[j], g.n), rnB = cross(g.rB[j], g.n);
        const float kn = cc.invMassA + cc.invMassB + cc.invIA * rnA * rnA + cc.invIB * rnB * rnB;
        g.normalMass[j] = kn > 0.0f ? 1.0f / kn : 0.0f;
        const float rtA = cross(g.rA[j], g.t), rtB = cross(g.rB[j], g.t);
        const float kt = cc.invMassA + cc.invMassB + cc.invIA * rtA * rtA + cc.invIB * rtB * rtB;
        g.tangentMass[j] = kt > 0.0f ? 1.0f / kt : 0.0f;
    }
    return g;
}

/// Applies impulse P at point j of a turning row.
void applyTurning(const ContactConstraint& cc, const TurningRow& g, int j, Vec2 P, BodyVelocities& v) {
    v.vA = mulSub(v.vA, cc.invMassA, P);
    v.wA -= cc.invIA * cross(g.rA[j], P);
    v.vB = mulAdd(v.vB, cc.invMassB, P);
    v.wB += cc.invIB * cross(g.rB[j], P);
}

float turningSpeed(const TurningRow& g, int j, Vec2 direction, const BodyVelocities& v) {
    return dot((v.vB + cross(v.wB, g.rB[j])) - (v.vA + cross(v.wA, g.rA[j])), direction);
}

/// C̈ of point j of a turning row at the velocities v, were they kept: how
/// the gap bends within a substep. The bodies move straight in a substep
/// while the face turns, so a row that holds Ċ at 0 lets a body pressed
/// against a spinning face drift into it by ½h²·C̈ every substep, ½(ωh)²·r
/// for a body at r from the axis of a face turning at ω: 6 mm a substep for
/// a ball in a box of 2 m turning at 20 rad/s, which the soft rows' push
/// (about 6 s⁻¹ times the depth) held only some 20 cm deep. The passes
/// before the positions move aim at Ċ = −½h·C̈ instead, the midpoint of the
/// substep, and the gap ends the substep where it began to third order.
/// With C = (x_B − x_A)·n and n turning with the face at ω_F (ṅ = ω_F × n,
/// n̈ = −ω_F²·n): C̈ = (ẍ_B − ẍ_A)·n + 2(ẋ_B − ẋ_A)·ṅ − ω_F²(x_B − x_A)·n,
/// each material point turning about its centre of mass (ẍ = −ω²·r; a
/// circle's point, which follows the normal, at the face's ω).
//
// The face's spin is its body's when the step began (spinA or spinB), and a
// round side's point follows the face: taken from the velocities the sweep
// is changing, the bend fed back into them through ω_F². A box of 24.5 g
// pinched by a force chain between two circles, its face turned at
// 111 rad/s by a warm start in the first substep, was asked to close at
// ½h·ω²·r and more in each pass, and its spin and its rows' impulses
// diverged within the step (830 N·s), throwing a settled pile of 120 bodies
// over 20 m walls (docs/validation.md, "Random passive piles that blew up").
// The other side's own spin, a material point turning about its centre, is
// its current one.
float turningBend(const ContactConstraint& cc, const TurningRow& g, int j, const BodyVelocities& v, float spinA,
                  float spinB) {
    const float wF = cc.turnA ? spinA : spinB;
    const float wA = cc.turnA || cc.roundA ? wF : v.wA, wB = cc.turnB || cc.roundB ? wF : v.wB;
    const Vec2 rA = g.pointA[j], rB = g.pointB[j];
    const Vec2 velocityA = v.vA + cross(wA, rA), velocityB = v.vB + cross(wB, rB);
    const Vec2 accelerationA = -(wA * wA) * rA, accelerationB = -(wB * wB) * rB;
    // x_B − x_A, from the arms the row acts at: rA + gap for a face of A, rB − gap for one of B.
    const Vec2 gap = cc.turnA ? g.rA[j] - rA : rB - g.rB[j];
    return dot(accelerationB - accelerationA, g.n) + 2.0f * wF * dot(velocityB - velocityA, leftPerp(g.n)) -
           wF * wF * dot(gap, g.n);
}

/// A turning row's warm start: its impulses along the turned normal and
/// tangent, at its arms.
void warmStartTurningRow(const ContactConstraint& cc, BodyState& sA, BodyState& sB) {
    const TurningRow g = turningRow(cc, sA, sB);
    BodyVelocities v{sA.v, sA.w, sB.v, sB.w};
    for (int j = 0; j < cc.pointCount; ++j)
        applyTurning(cc, g, j, cc.points[j].normalImpulse * g.n + cc.points[j].tangentImpulse * g.t, v);
    sA.v = v.vA;
    sA.w = v.wA;
    sB.v = v.vB;
    sB.w = v.wB;
}

/// One pass of a turning row: its normal points (side by side when the
/// row's points go together, each increment scaled by pairScale), then
/// friction, as solveContactsFor.
template <SolvePass passKind>
void solveTurningRow(ContactConstraint& cc, BodyState& sA, BodyState& sB, float spinA, float spinB, float invH,
                     float beta, float slop, bool leaveImpacts, float impactSpeed) {
    const TurningRow g = turningRow(cc, sA, sB);
    BodyVelocities v{sA.v, sA.w, sB.v, sB.w};
    PointTarget target[2];
    bool skip[2] = {false, false};
    // The passes the positions move after (turningBend).
    constexpr bool beforeMove = passKind == SolvePass::soft_bias || passKind == SolvePass::baumgarte ||
                                passKind == SolvePass::no_push;
    for (int j = 0; j < cc.pointCount; ++j) {
        const float s = g.separation[j];
        if (leaveImpacts && s > 0.0f) skip[j] = turningSpeed(g, j, g.n, v) < -impactSpeed;
        target[j] = pointTarget<passKind>(cc, cc.points[j], s, invH, beta, slop);
        // Only a touching point's bend into the face is allowed for: allowing
        // for every bend (a speculative point's, a bend away from the face)
        // made a light lever, pinned and struck into a spin by a heavy body,
        // gain up to a thousand times its energy
        // (HeavyOnLight.RandomLandingsOnPinnedBodiesGainNoEnergy: none now).
        // It is not capped: held to the push cap (3 m/s), a box spun at 40
        // rad/s lost all of 100 balls (½h·ω²·r is 6 m/s there), uncapped 9.
        if constexpr (beforeMove) {
            if (s <= 0.0f) target[j].bias += 0.5f / invH * std::min(turningBend(cc, g, j, v, spinA, spinB), 0.0f);
        }
    }
    const bool together = cc.pointsTogether && cc.pointCount == 2 && !skip[0] && !skip[1];
    const float scale = together ? pairScale(cc) : 1.0f;
    float increment[2] = {0.0f, 0.0f};
    for (int j = 0; j < cc.pointCount; ++j) {
        if (skip[j]) continue;
        ContactPointConstraint& cp = cc.points[j];
        const float vn = turningSpeed(g, j, g.n, v);
        const float alone = -g.normalMass[j] * target[j].massScale * (vn + target[j].bias) -
                            target[j].impulseScale * cp.normalImpulse;
        const float newImpulse = std::max(cp.normalImpulse + scale * alone, 0.0f);
        increment[j] = newImpulse - cp.normalImpulse;
        cp.normalImpulse = newImpulse;
        cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, increment[j]);
        if (!together) applyTurning(cc, g, j, increment[j] * g.n, v);
    }
    if (together)
        for (int j = 0; j < 2; ++j) applyTurning(cc, g, j, increment[j] * g.n, v);
    for (int j = 0; j < cc.pointCount; ++j) {
        ContactPointConstraint& cp = cc.points[j];
        const float vt = turningSpeed(g, j, g.t, v) - cc.tangentSpeed;
        const float maxFriction = cc.friction * cp.normalImpulse;
        const float newImpulse = clamp(cp.tangentImpulse - g.tangentMass[j] * vt, -maxFriction, maxFriction);
        const float impulse = newImpulse - cp.tangentImpulse;
        cp.tangentImpulse = newImpulse;
        applyTurning(cc, g, j, impulse * g.t, v);
    }
    sA.v = v.vA;
    sA.w = v.wA;
    sB.v = v.vB;
    sB.w = v.wB;
}

/// One Gauss-Seidel sweep over the contacts, compiled once per pass so the
/// per-point branches on it fold away.
template <SolvePass passKind>
void solveContactsFor(WorldState& w, float h, std::size_t first, bool backward) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    const float slop = set.penetrationSlop;
    const float beta = set.pushFactor;
    // The last relax of a step limits the approach speed for the next step's
    // first substep. With the closed-form impact model a fast approach belongs
    // to the impact law at the start of that step: leave it alone here, or the
    // solver would absorb it inelastically before the law ever sees it
    // (leftApproachSpeed).
    const bool leaveImpacts = passKind == SolvePass::soft_relax_last && set.impactModel == ImpactModel::closed_form;
    const float impactSpeed = leftApproachSpeed(w);
    BodyState* states = w.solver.states.data();
    const std::size_t end = w.solver.constraints.size();
    for (std::size_t k = first; k < end; ++k) {
        ContactConstraint& cc = w.solver.constraints[backward ? end - 1 - (k - first) : k];
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        if (cc.turnA || cc.turnB) {
            // (startSpin is filled in every step with a turning row: anyTurningRow.)
            const std::vector<float>& spin = w.solver.startSpin;
            const auto a = static_cast<std::size_t>(cc.a), b = static_cast<std::size_t>(cc.b);
            solveTurningRow<passKind>(cc, sA, sB, a < spin.size() ? spin[a] : sA.w, b < spin.size() ? spin[b] : sB.w,
                                      invH, beta, slop, leaveImpacts, impactSpeed);
            continue;
        }
        Vec2 vA = sA.v, vB = sB.v;
        float wA = sA.w, wB = sB.w;
        // The separation follows each side's contact point: fixed in the body
        // for a polygon's corner or face, but under the centre for a circle,
        // whose own spin moves no surface towards the other shape (with the
        // anchor turned, a disc rolling at 20 m/s read a gap opening under it
        // and sank 10 mm; at 5 m/s, 2.6 mm).
        const Rot qA = cc.roundA ? Rot{} : sA.dq, qB = cc.roundB ? Rot{} : sB.dq;
        const float mA = cc.invMassA, iA = cc.invIA, mB = cc.invMassB, iB = cc.invIB;
        const Vec2 n = cc.normal;
        const Vec2 dp = sB.dp - sA.dp;

        // Each point's target: Δλ = −m·ms·(vn + bias) − is·λ, with the
        // coefficients of its regime (speculative, soft push, Baumgarte, none).
        PointTarget target[2];
        bool skip[2] = {false, false};
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            float s = currentSeparation(cp, n, dp, qA, qB);
            if (leaveImpacts && s > 0.0f) {
                Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
                skip[j] = dot(dv, n) < -impactSpeed;
            }
            target[j] = pointTarget<passKind>(cc, cp, s, invH, beta, slop);
        }

        BodyVelocities vel{vA, wA, vB, wB};
        const RowMasses masses{mA, iA, mB, iB};
        // Overlaps deep enough to be pushed apart at the capped speed are not
        // resting: they keep the sequential sweep, whose order there is no
        // concern (solved together, a pile of 100 boxes created at one point
        // flew apart at 23 m/s instead of 18).
        if (cc.pointsTogether && !skip[0] && !skip[1]) {
            solvePointPair(cc, masses, target, vel);
        } else {
            for (int j = 0; j < cc.pointCount; ++j) {
                if (skip[j]) continue;
                applyNormalImpulse(cc.points[j], n, masses, pointImpulse(cc.points[j], n, target[j], vel), vel);
            }
        }
        vA = vel.vA;
        wA = vel.wA;
        vB = vel.vB;
        wB = vel.wB;

        // Coulomb friction bounded by μ times this point's own normal impulse
        // (not the μmg bound of Tamis and Maggiore (2015) §5.4, which is wrong for stacks, as it says).
        const Vec2 t = rightPerp(n);
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
            float vt = dot(dv, t) - cc.tangentSpeed;
            float impulse = -cp.tangentMass * vt;
            float maxFriction = cc.friction * cp.normalImpulse;
            float newImpulse = clamp(cp.tangentImpulse + impulse, -maxFriction, maxFriction);
            impulse = newImpulse - cp.tangentImpulse;
            cp.tangentImpulse = newImpulse;
            Vec2 P = impulse * t;
            vA = mulSub(vA, mA, P);
            wA -= iA * cross(cp.rA, P);
            vB = mulAdd(vB, mB, P);
            wB += iB * cross(cp.rB, P);
        }
        sA.v = vA;
        sA.w = wA;
        sB.v = vB;
        sB.w = wB;
    }
}

}  // namespace

// A contact that begins touching at rest (kWideCold: bodies created or
// placed touching, a stack built in one step) starts without the impulse its
// load needs, and the sweeps, one a substep, each carry the support only a few
// rows up. Meanwhile the rows above fall, unsupported, and press the rows
// below past their rest: a pyramid of 5 cm boxes, 30 rows, built at rest
// went 3.5 mm deep in its first 0.13 s and rang for a second and a half,
// though it rests 2.0 mm deep (Box2D v3's Tiny Pyramid, whose bar is 2.5 mm;
// docs/validation.md, "Hard cases not yet met"). In that first step the
// blocks holding such rows are swept again in every substep, until a sweep
// changes no cold row's normal impulse by more than kColdTolerance of the
// largest (at most kColdSweeps more), each sweep in the other direction so
// that no order of the colours is favoured. In every substep: the same
// sweeps in the first substep alone left the others unconverged, and such
// a pyramid jittered 1 to 2 cm deep. The next step the rows carry their
// impulses and are swept once; a step without cold rows is as before.
constexpr int kColdSweeps = 32;
constexpr float kColdTolerance = 0.003f;

namespace {

/// Sweeps the blocks of `list` (ascending, each row group's begin in `start`
/// as in wideContactColourStart) with `pass` again and again, colour by
/// colour, each sweep in the other direction so that no order of the colours
/// is favoured (SolverArrays::sweepBackward), until a sweep changes no
/// normal impulse of a lane flagged `flag` by more than `tolerance` of the
/// largest, or `maxSweeps` sweeps have run.
void sweepListedBlocks(WorldState& w, float h, SolvePass pass, const std::vector<int>& list,
                       const std::vector<int>& start, std::uint32_t flag, int maxSweeps, float tolerance) {
    SolverArrays& s = w.solver;
    const RowContext x = makeRowContext(w, h, true);
    const float maxPush = w.settings.maxPushSpeed, impactSpeed = leftApproachSpeed(w);
    const bool leaveImpacts = pass == SolvePass::soft_relax_last && w.settings.impactModel == ImpactModel::closed_form;
    const bool trackMax = !s.wideContactsOnly;
    const std::size_t groups = start.size() - 1, colours = groups / kWideGroupsPerColour;
    constexpr int kBlockGrain = 32;
    auto block = [&](int i) { return list[static_cast<std::size_t>(i)]; };
    // The flagged lanes' normal impulses after the last sweep, to see
    // whether the next one still changes them.
    std::vector<float>& last = s.listedImpulses;
    auto changeSince = [&](bool record) {
        float change = 0.0f, largest = 0.0f;
        std::size_t k = 0;
        for (int b : list) {
            const WideContactBlock& blk = s.wideContacts[static_cast<std::size_t>(b)];
            for (int lane = 0; lane < 4; ++lane) {
                if ((blk.flags[lane] & flag) == 0) continue;
                for (int j = 0; j < 2; ++j, ++k) {
                    const float now = blk.points[j].normalImpulse[lane];
                    if (!record) change = std::max(change, std::abs(now - last[k]));
                    largest = std::max(largest, now);
                    last[k] = now;
                }
            }
        }
        return record ? 0.0f : (largest > 0.0f ? change / largest : 0.0f);
    };
    last.resize(8 * list.size());
    changeSince(true);
    for (int sweep = 0; sweep < maxSweeps; ++sweep) {
        for (std::size_t c = 0; c < colours; ++c) {
            const bool backward = s.sweepBackward != (sweep % 2 == 1);
            const std::size_t colour = backward ? colours - 1 - c : c;
            for (int part = 0; part < kWideGroupsPerColour; ++part) {
                const std::size_t g = colour * kWideGroupsPerColour + static_cast<std::size_t>(part);
                const int first = start[g], count = start[g + 1] - first;
                if (count == 0) continue;
                // Blocks that follow each other are swept as one range (eight lanes at a time).
                auto range = [&](int b, int e) {
                    for (int i = first + b; i < first + e;) {
                        int j = i + 1;
                        while (j < first + e && block(j) == block(j - 1) + 1) ++j;
                        solveWideContacts(s, x, maxPush, pass, h, leaveImpacts, impactSpeed, block(i), block(j - 1) + 1,
                                          trackMax, part == 0 ? 2 : 1);
                        i = j;
                    }
                };
                w.runner.run(count, kBlockGrain, range);
            }
        }
        if (!(changeSince(false) > tolerance)) break;
    }
}

}  // namespace

void settleColdContacts(WorldState& w, float h) {
    sweepListedBlocks(w, h, SolvePass::soft_bias, w.solver.coldBlocks, w.solver.coldBlockStart, kWideCold, kColdSweeps,
                      kColdTolerance);
}

// A soft row that pushes a body out of an overlap gives it a velocity that
// the relax sweep takes back, but the sweep meets the rows in colour order:
// where it meets the rows between that body and the bodies resting on it
// before the body's own row, they pass the push on (the pushed body closes
// on them), and the body's row then takes back only what is left in the
// body. Eight circles created overlapping on the ground rose so at 0.45 m/s
// within a step and reached 1.03 times their starting energy
// (docs/validation.md, "The relax pass passed a push on"). A relax row's
// update is a projection that never adds kinetic energy, so sweeping again
// takes back what the first sweep passed on: in a step with a deep overlap,
// where the pushes are large, the blocks holding deep rows are relaxed again
// after each substep's relax sweep until their normal impulses change by no
// more than kDeepRelaxTolerance of the largest, at most kDeepRelaxSweeps
// more, each sweep in the other direction. (Relaxing every row twice in
// every step did about as well on piles, at a sweep more in every step.)
// So are the blocks holding a contact created overlapping that is no longer
// deep (kWideFromStart): its soft rows push the last centimetre of the
// overlap out through the velocities, and along a row of bodies those
// pushes add up. A row of 80 boxes of 0.6 m created half overlapping without
// friction slid apart, each box at a speed in proportion to its distance from
// the middle, at 1.021 times its energy with the sideways push at 10c;
// relaxed again, 1.011 (docs/validation.md, "The sideways limit again").
constexpr int kDeepRelaxSweeps = 8;
constexpr float kDeepRelaxTolerance = 0.003f;

void relaxDeepContacts(WorldState& w, float h, SolvePass pass) {
    sweepListedBlocks(w, h, pass, w.solver.deepBlocks, w.solver.deepBlockStart,
                      kWideDeep | kWideUnloaded | kWideFromStart, kDeepRelaxSweeps, kDeepRelaxTolerance);
}

void solveContacts(WorldState& w, float h, SolvePass target) {
    SolverArrays& s = w.solver;
    // The coloured groups four at a time (soft_step only), then the rows left
    // to the scalar sweep; the same order as sweeping every row here. Every
    // other step the sweep runs backward, the scalar rows (last to first)
    // before the colours (last to first): SolverArrays::sweepBackward.
    const bool backward = s.sweepBackward;
    std::size_t first = 0;
    auto scalarRows = [&] {
        switch (target) {
            case SolvePass::soft_bias: solveContactsFor<SolvePass::soft_bias>(w, h, first, backward); break;
            case SolvePass::soft_relax: solveContactsFor<SolvePass::soft_relax>(w, h, first, backward); break;
            case SolvePass::soft_relax_last: solveContactsFor<SolvePass::soft_relax_last>(w, h, first, backward); break;
            case SolvePass::baumgarte: solveContactsFor<SolvePass::baumgarte>(w, h, first, backward); break;
            case SolvePass::no_push: solveContactsFor<SolvePass::no_push>(w, h, first, backward); break;
        }
    };
    if (s.wideContactsActive) {
        first = static_cast<std::size_t>(s.contactOverflowStart);
        if (backward) scalarRows();
        const bool leaveImpacts = target == SolvePass::soft_relax_last &&
                                  w.settings.impactModel == ImpactModel::closed_form;
        const float impactSpeed = leftApproachSpeed(w);
        const bool trackMax = !s.wideContactsOnly;
        const RowContext x = makeRowContext(w, h, true);
        const float maxPush = w.settings.maxPushSpeed;
        forEachWideColour(w, backward, [&](int b, int e, int points) {
            solveWideContacts(s, x, maxPush, target, h, leaveImpacts, impactSpeed, b, e, trackMax, points);
        });
        if (!backward) scalarRows();
    } else {
        scalarRows();
    }
    if (!w.solver.rolling.empty()) solveRollingResistance(w);
}

/// Split mode (Tamis and Maggiore (2015) §8.1): solve the push alone on pseudo-velocities
/// (`biasV`/`biasW`, with the zero entry last like the states).
void solveContactPush(WorldState& w, float h) {
    const WorldSettings& set = w.settings;
    const float invH = 1.0f / h;
    for (ContactConstraint& cc : w.solver.constraints) {
        Vec2& vA = w.solver.biasV[static_cast<std::size_t>(cc.a)];
        float& wA = w.solver.biasW[static_cast<std::size_t>(cc.a)];
        Vec2& vB = w.solver.biasV[static_cast<std::size_t>(cc.b)];
        float& wB = w.solver.biasW[static_cast<std::size_t>(cc.b)];
        const Vec2 n = cc.normal;
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            float s = cp.adjustedSeparation + dot(cp.rB - cp.rA, n);
            float target = std::min(set.pushFactor * invH * std::max(-(s + set.penetrationSlop), 0.0f),
                                    set.maxPushSpeed);
            if (target <= 0.0f && cp.biasImpulse == 0.0f) continue;
            Vec2 dv = (vB + cross(wB, cp.rB)) - (vA + cross(wA, cp.rA));
            float impulse = -cp.normalMass * (dot(dv, n) - target);
            float newImpulse = std::max(cp.biasImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.biasImpulse;
            cp.biasImpulse = newImpulse;
            Vec2 P = impulse * n;
            vA = mulSub(vA, cc.invMassA, P);
            wA -= cc.invIA * cross(cp.rA, P);
            vB = mulAdd(vB, cc.invMassB, P);
            wB += cc.invIB * cross(cp.rB, P);
        }
    }
}

/// Soft step's restitution pass (velocity-bias impact model): after the
/// substeps, drive each point that was hit faster than the threshold to
/// separate at e times its approach speed.
void applyRestitution(WorldState& w) {
    const float threshold = w.settings.restitutionThreshold;
    BodyState* states = w.solver.states.data();
    for (ContactConstraint& cc : w.solver.constraints) {
        if (cc.restitution == 0.0f) continue;
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        const Vec2 n = cc.normal;
        for (int j = 0; j < cc.pointCount; ++j) {
            ContactPointConstraint& cp = cc.points[j];
            if (cp.relativeVelocity > -threshold || cp.maxNormalImpulse == 0.0f) continue;
            Vec2 dv = (sB.v + cross(sB.w, cp.rB)) - (sA.v + cross(sA.w, cp.rA));
            float vn = dot(dv, n);
            float impulse = -cp.normalMass * (vn + cc.restitution * cp.relativeVelocity);
            float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
            impulse = newImpulse - cp.normalImpulse;
            cp.normalImpulse = newImpulse;
            Vec2 P = impulse * n;
            sA.v = mulSub(sA.v, cc.invMassA, P);
            sA.w -= cc.invIA * cross(cp.rA, P);
            sB.v = mulAdd(sB.v, cc.invMassB, P);
            sB.w += cc.invIB * cross(cp.rB, P);
        }
    }
}

void storeContactImpulses(WorldState& w) {
    if (!w.solver.rolling.empty()) storeRollingResistance(w);
    // Row by row into its own contact: shared among the workers.
    const float invH = static_cast<float>(solverSubsteps(w.settings)) / w.stepDt;
    auto store = [&](int b, int e) {
        for (int r = b; r < e; ++r) {
            const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(r)];
            Contact& ct = w.contacts[cc.contact];
            for (int j = 0; j < cc.pointCount; ++j) {
                ct.normalImpulse[j] = cc.points[j].normalImpulse;
                ct.tangentImpulse[j] = cc.points[j].tangentImpulse;
            }
            if (ct.restLoad[0] | ct.restLoad[1]) holdRestLoads(ct, invH);
        }
    };
    w.runner.run(static_cast<int>(w.solver.constraints.size()), 256, store);
}

// ---- Rolling resistance ------------------------------------------------------
// A contact whose shapes resist rolling gets one more row: the relative
// angular velocity ω_B − ω_A is driven to zero with an impulse bounded by the
// resistance times the contact's total normal impulse, so a ball rolling on
// flat ground loses a torque of c·r·N and comes to rest (the rolling
// resistance of Catto's Box2D v3, with the coefficient scaled by the radius as
// there). The rows live in SolverArrays::rolling, apart from the contact rows.

void prepareRollingResistance(WorldState& w, int row, const ContactSurface& surface) {
    const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(row)];
    const float k = cc.invIA + cc.invIB;
    if (k <= 0.0f) return;  // neither body turns
    const float warm = w.settings.enableWarmStarting ? 1.0f : 0.0f;
    w.solver.rolling.push_back({row, surface.rollingResistance, 1.0f / k, warm * surface.rollingImpulse});
}

void warmStartRollingResistance(WorldState& w) {
    BodyState* states = w.solver.states.data();
    for (const RollingConstraint& rc : w.solver.rolling) {
        const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(rc.row)];
        states[cc.a].w -= cc.invIA * rc.impulse;
        states[cc.b].w += cc.invIB * rc.impulse;
    }
}

void solveRollingResistance(WorldState& w) {
    BodyState* states = w.solver.states.data();
    for (RollingConstraint& rc : w.solver.rolling) {
        const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(rc.row)];
        BodyState& sA = states[cc.a];
        BodyState& sB = states[cc.b];
        float totalNormal = 0.0f;
        for (int j = 0; j < cc.pointCount; ++j) totalNormal += cc.points[j].normalImpulse;
        const float maxImpulse = rc.resistance * totalNormal;
        const float old = rc.impulse;
        rc.impulse = clamp(old - rc.mass * (sB.w - sA.w), -maxImpulse, maxImpulse);
        const float impulse = rc.impulse - old;
        sA.w -= cc.invIA * impulse;
        sB.w += cc.invIB * impulse;
    }
}

void storeRollingResistance(WorldState& w) {
    for (const RollingConstraint& rc : w.solver.rolling) {
        const ContactConstraint& cc = w.solver.constraints[static_cast<std::size_t>(rc.row)];
        w.contactSurfaces[static_cast<std::size_t>(cc.contact)].rollingImpulse = rc.impulse;
    }
}

}  // namespace i2d::detail
