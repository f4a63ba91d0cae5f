// Four contact manifolds at a time (see wide_contact.hpp): packing rows into
// blocks or preparing lanes straight from the contacts, the four-lane policy
// of the sweeps (wide_contact_kernel.hpp holds the sweeps, wide_avx2.cpp the
// eight-lane policy), the choice between four and eight lanes, and the
// write-back of the impulses into the rows.
#include "wide_contact.hpp"

#include <algorithm>

#include "contact_row.hpp"
#include "float4.hpp"
#include "rest_load.hpp"
#include "solver.hpp"
#include "wide_contact_kernel.hpp"
#include "wide_lanes4.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// Whether contact ct may start cold (kWideCold): its manifold got points
/// this step and neither body has a joint. The extra sweeps
/// (settleColdContacts) solve contacts alone: beside a joint they would move
/// its bodies with the joint left as it was.
bool mayBeCold(const WorldState& w, const Contact& ct) {
    return ct.touchBegan && w.bodies[ct.bodyA].jointCount == 0 && w.bodies[ct.bodyB].jointCount == 0;
}

/// Lane `lane` of block k from row cc (null: an empty lane), every field written.
inline std::uint32_t packLane(WideContactBlock& k, WideContactCold& cold, int lane, const ContactConstraint* cc,
                              int row, int zero, const BodyState* states = nullptr, const WorldState* w = nullptr,
                              const RowContext* x = nullptr) {
    const bool used = cc != nullptr;
    k.a[lane] = used ? cc->a : zero;
    k.b[lane] = used ? cc->b : zero;
    cold.row[lane] = used ? row : -1;
    cold.contact[lane] = used ? cc->contact : -1;
    k.nx[lane] = used ? cc->normal.x : 0.0f, k.ny[lane] = used ? cc->normal.y : 0.0f;
    k.friction[lane] = used ? cc->friction : 0.0f;
    k.tangentSpeed[lane] = used ? cc->tangentSpeed : 0.0f;
    k.mA[lane] = used ? cc->invMassA : 0.0f, k.iA[lane] = used ? cc->invIA : 0.0f;
    k.mB[lane] = used ? cc->invMassB : 0.0f, k.iB[lane] = used ? cc->invIB : 0.0f;
    k.pairCoupling[lane] = used ? cc->pairCoupling : 0.0f;
    std::uint32_t flags = 0;
    if (used) {
        if (cc->pointsTogether) flags |= kWideTogether;
        if (cc->roundA) flags |= kWideRoundA;
        if (cc->roundB) flags |= kWideRoundB;
        if (cc->deepOverlap) flags |= kWideDeep;
        if (cc->overlapFromStart && !cc->deepOverlap) flags |= kWideFromStart;
        if (againstImmovable(*cc)) flags |= kWideImmovableSide;
        if (cc->pointCount > 0) flags |= kWidePoint0;
        if (cc->pointCount > 1) flags |= kWidePoint1;
        flags |= moveFlags(cc->invMassA, cc->invIA, cc->invMassB, cc->invIB);
        // A contact that began touching at rest, as prepareWideContactLanes finds it.
        if (x && x->restingSpeed >= 0.0f && !cc->deepOverlap && mayBeCold(*w, w->contacts[cc->contact])) {
            const BodyState& sA = states[cc->a];
            const BodyState& sB = states[cc->b];
            float depth[2], speed[2];
            for (int j = 0; j < cc->pointCount; ++j) {
                const ContactPointConstraint& cp = cc->points[j];
                depth[j] = cp.adjustedSeparation + dot(cp.rB - cp.rA, cc->normal);
                speed[j] = dot((sB.v + cross(sB.w, cp.rB)) - (sA.v + cross(sA.w, cp.rA)), cc->normal);
            }
            if (coldAtRest(*x, cc->pointCount, depth, speed)) flags |= kWideCold;
        }
    }
    k.flags[lane] = flags;
    for (int j = 0; j < 2; ++j) {
        WideContactPoint& p = k.points[j];
        const bool present = used && j < cc->pointCount;
        const ContactPointConstraint* cp = present ? &cc->points[j] : nullptr;
        p.rAx[lane] = present ? cp->rA.x : 0.0f, p.rAy[lane] = present ? cp->rA.y : 0.0f;
        p.rBx[lane] = present ? cp->rB.x : 0.0f, p.rBy[lane] = present ? cp->rB.y : 0.0f;
        p.adjustedSeparation[lane] = present ? cp->adjustedSeparation : 0.0f;
        p.normalMass[lane] = present ? cp->normalMass : 0.0f;
        p.tangentMass[lane] = present ? cp->tangentMass : 0.0f;
        p.normalImpulse[lane] = present ? cp->normalImpulse : 0.0f;
        p.tangentImpulse[lane] = present ? cp->tangentImpulse : 0.0f;
        cold.maxNormalImpulse[j][lane] = present ? cp->maxNormalImpulse : 0.0f;
    }
    return flags & kWideFound;
}

}  // namespace

std::uint32_t packWideContactBlock(SolverArrays& s, int block, int start, int last, const WorldState* w,
                                   const RowContext* x) {
    const int zero = static_cast<int>(s.states.size()) - 1;
    WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(block)];
    WideContactCold& cold = s.wideContactCold[static_cast<std::size_t>(block)];
    std::uint32_t found = 0;
    for (int lane = 0; lane < 4; ++lane) {
        const int r = start + lane;
        found |= packLane(k, cold, lane, r < last ? &s.constraints[static_cast<std::size_t>(r)] : nullptr, r, zero,
                          s.states.data(), w, x);
    }
    return found;
}

std::uint32_t prepareWideContactLanes(const WorldState& w, const RowContext& x, const WideLaneTarget* targets,
                                      int count) {
    std::uint32_t found = 0;
    // Each lane's contact and bodies are read one lane at a time, as
    // prepareContactRow reads them; what the arithmetic below does not change
    // goes straight to the lane, the rest into rows of four values, one row
    // per lane, transposed below into one register per value. (Written lane
    // by lane into arrays of four and loaded whole, each array's load waited
    // for its four stores to reach the cache, a store-forwarding stall per
    // array: the preparation stage of a pile of 1,000 circles took 4 %
    // longer.) Lanes past `count` stay zero (their results are not written).
    const Float4 zero = splat(0.0f), one = splat(1.0f);
    Float4 base[4] = {zero, zero, zero, zero};    // n.x, n.y, A's inverse mass and inertia
    Float4 masses[4] = {zero, zero, zero, zero};  // B's inverse mass and inertia, biasRate, rest compliance
    // Per point: the arms (rA.x, rA.y, rB.x, rB.y), and its separation, rest
    // load (rest_load.hpp: restSag), 1 where the lane has it, and restSag's
    // most (the lane's deep-overlap depth).
    Float4 arms[2][4] = {{zero, zero, zero, zero}, {zero, zero, zero, zero}};
    Float4 gaps[2][4] = {{zero, zero, zero, zero}, {zero, zero, zero, zero}};
    std::uint32_t flags[4] = {0, 0, 0, 0};
    int pointCount[4] = {0, 0, 0, 0};
    const std::vector<RowBody>& rowBodies = w.solver.rowBodies;
    // A body with a state is read from its RowBody, one without (static or
    // asleep: immovable this step, few and shared by many contacts) from
    // the body; contactRowBodies's values either way.
    auto rowBody = [&](int slot) {
        const RowBody& r = rowBodies[static_cast<std::size_t>(slot)];
        if (r.state != kNullIndex) return r;
        RowBody immovable = rowBodyOf(w.bodies[slot], x.zeroState);
        immovable.invMass = immovable.invInertia = 0.0f;
        return immovable;
    };
    const bool shifted = w.startsShiftedAt == w.stepStamp;  // impactShift reads the bodies only then
    const ContactSurface* surfaces = w.contactSurfaces.empty() ? nullptr : w.contactSurfaces.data();
    for (int i = 0; i < count; ++i) {
        const int c = targets[i].contact;
        WideContactBlock& k = *targets[i].block;
        WideContactCold& cold = *targets[i].cold;
        const int lane = targets[i].lane;
        const Contact& ct = w.contacts[c];
        const RowBody bA = rowBody(ct.bodyA), bB = rowBody(ct.bodyB);
        k.a[lane] = bA.state, k.b[lane] = bB.state;
        cold.row[lane] = -1;
        cold.contact[lane] = c;
        k.mA[lane] = bA.invMass, k.iA[lane] = bA.invInertia;
        k.mB[lane] = bB.invMass, k.iB[lane] = bB.invInertia;
        const Vec2 n = ct.manifold.normal;
        k.nx[lane] = n.x, k.ny[lane] = n.y;
        base[i] = make4(n.x, n.y, bA.invMass, bA.invInertia);
        k.friction[lane] = ct.friction;
        k.tangentSpeed[lane] = surfaces ? surfaces[c].tangentSpeed : 0.0f;
        const bool immovable = againstImmovable(bA.invMass, bB.invMass);
        masses[i] = make4(bB.invMass, bB.invInertia, (immovable ? x.staticSoft : x.dynamicSoft).biasRate,
                          immovable ? x.staticRestCompliance : x.dynamicRestCompliance);
        std::uint32_t f = immovable ? kWideImmovableSide : 0u;
        if (ct.roundA) f |= kWideRoundA;
        if (ct.roundB) f |= kWideRoundB;
        f |= moveFlags(bA.invMass, bA.invInertia, bB.invMass, bB.invInertia);
        const int points = pointCount[i] = ct.manifold.pointCount;
        const float deep = deepOverlapOf(ct);
        Vec2 laneRA[2], laneRB[2];  // the arms, for the look at a contact at rest below
        for (int j = 0; j < 2; ++j) {
            WideContactPoint& p = k.points[j];
            cold.maxNormalImpulse[j][lane] = 0.0f;
            if (j >= points) {
                // No such point: zero in the lane, as in packLane.
                gaps[j][i] = make4(0.0f, 0.0f, 0.0f, deep);
                p.rAx[lane] = p.rAy[lane] = p.rBx[lane] = p.rBy[lane] = 0.0f;
                p.adjustedSeparation[lane] = p.normalMass[lane] = p.tangentMass[lane] = 0.0f;
                p.normalImpulse[lane] = p.tangentImpulse[lane] = 0.0f;
                continue;
            }
            const ManifoldPoint& mp = ct.manifold.points[j];
            if (mp.separation < -deep) f |= kWideDeep;
            f |= j == 0 ? kWidePoint0 : kWidePoint1;
            Vec2 rA, rB;
            contactArms(ct, bA, bB, j, rA, rB);
            laneRA[j] = rA, laneRB[j] = rB;
            p.rAx[lane] = rA.x, p.rAy[lane] = rA.y;
            p.rBx[lane] = rB.x, p.rBy[lane] = rB.y;
            arms[j][i] = make4(rA.x, rA.y, rB.x, rB.y);
            const float shift = shifted ? impactShift(w, c, w.bodies[ct.bodyA], w.bodies[ct.bodyB], mp.point, n) : 0.0f;
            gaps[j][i] = make4(mp.separation + shift, restForce(ct.restLoad[j]), 1.0f, deep);
            p.normalImpulse[lane] = x.warm * ct.normalImpulse[j];
            p.tangentImpulse[lane] = x.warm * ct.tangentImpulse[j];
        }
        // A contact at rest that began touching this step (kWideCold); the
        // speeds of others are not computed.
        if (x.restingSpeed >= 0.0f && (f & kWideDeep) == 0 && mayBeCold(w, ct)) {
            const BodyState& sA = w.solver.states[static_cast<std::size_t>(bA.state)];
            const BodyState& sB = w.solver.states[static_cast<std::size_t>(bB.state)];
            float depth[2], speed[2];
            for (int j = 0; j < points; ++j) {
                depth[j] = ct.manifold.points[j].separation;
                const Vec2 rA = laneRA[j], rB = laneRB[j];
                speed[j] = dot((sB.v + cross(sB.w, rB)) - (sA.v + cross(sA.w, rA)), n);
            }
            if (coldAtRest(x, points, depth, speed)) f |= kWideCold;
        }
        if (ct.overlapFromStart && (f & kWideDeep) == 0) f |= kWideFromStart;
        found |= f & kWideFound;
        flags[i] = f;
    }
    // The arithmetic of prepareContactRow and finishContactRow (soft_step),
    // four lanes at once, in the same order: the bits are the scalar row's.
    transpose(base[0], base[1], base[2], base[3]);
    transpose(masses[0], masses[1], masses[2], masses[3]);
    const Float4 n_x = base[0], n_y = base[1], t_x = n_y, t_y = -n_x;  // t = rightPerp(n)
    const Float4 invMassA = base[2], invIA = base[3], invMassB = masses[0], invIB = masses[1];
    const Float4 biasRate = masses[2], restCompliance = masses[3];
    const Float4 mAB = invMassA + invMassB;
    Float4 kn[2], rnA[2], rnB[2], normalMass[2] = {zero, zero}, tangentMass[2] = {zero, zero};
    Float4 adjusted[2] = {zero, zero};
    Float4 deepest = zero;
    // Lanes of one point each (circles) skip the second point's arithmetic.
    const int points = std::max(std::max(pointCount[0], pointCount[1]), std::max(pointCount[2], pointCount[3]));
    Float4 present[2] = {zero, zero};  // 1 where the lane has the point
    for (int j = 0; j < points; ++j) {
        transpose(arms[j][0], arms[j][1], arms[j][2], arms[j][3]);
        transpose(gaps[j][0], gaps[j][1], gaps[j][2], gaps[j][3]);
        const Float4 ax = arms[j][0], ay = arms[j][1], bx = arms[j][2], by = arms[j][3];
        const Float4 separation = gaps[j][0], restSagMost = gaps[j][3];
        present[j] = gaps[j][2];
        rnA[j] = ax * n_y - ay * n_x;  // cross(rA, n)
        rnB[j] = bx * n_y - by * n_x;
        kn[j] = mAB + invIA * rnA[j] * rnA[j] + invIB * rnB[j] * rnB[j];
        normalMass[j] = select(kn[j] > zero, one / kn[j], zero);
        const Float4 rtA = ax * t_y - ay * t_x, rtB = bx * t_y - by * t_x;
        const Float4 kt = mAB + invIA * rtA * rtA + invIB * rtB * rtB;
        tangentMass[j] = select(kt > zero, one / kt, zero);
        const Float4 arm = (bx - ax) * n_x + (by - ay) * n_y;  // dot(rB − rA, n)
        // Less the sag of the load the point was built carrying (restSag).
        const Float4 rest = gaps[j][1];
        const Float4 sag = rest * kn[j] * restCompliance;
        adjusted[j] = (separation - arm) - select((rest > zero) & (sag <= restSagMost), sag, zero);
        deepest = select(present[j] > zero, min4(deepest, adjusted[j] + arm), deepest);
    }
    // pointsTogether and pairCoupling (finishContactRow, pairMatrix).
    Float4 pairCoupling = zero, togetherLanes = zero;
    if (points == 2) {
        const Float4 push = (-biasRate) * deepest;
        const Float4 k12 = mAB + invIA * rnA[0] * rnA[1] + invIB * rnB[0] * rnB[1];
        const Mask4 pressing = (present[1] > zero) & (push < splat(w.settings.maxPushSpeed));
        // blockDeterminant, in its operations.
        const Float4 positive = select(k12 > zero, k12, zero);
        const Float4 det = one - (normalMass[0] * positive) * (normalMass[1] * positive);
        const Mask4 together = pressing & (det > splat(kLeastBlockDeterminant));
        pairCoupling = select(pressing, positive, zero);
        togetherLanes = select(together, one, zero);
    }
    alignas(16) float outNormalMass[2][4], outTangentMass[2][4], outAdjusted[2][4], outPairCoupling[4];
    alignas(16) float outTogether[4];
    for (int j = 0; j < points; ++j) {
        store4(outNormalMass[j], normalMass[j]);
        store4(outTangentMass[j], tangentMass[j]);
        store4(outAdjusted[j], adjusted[j]);
    }
    store4(outPairCoupling, pairCoupling);
    store4(outTogether, togetherLanes);
    // What the arithmetic made, each lane to its block (the points it has).
    for (int i = 0; i < count; ++i) {
        WideContactBlock& k = *targets[i].block;
        const int lane = targets[i].lane;
        k.pairCoupling[lane] = outPairCoupling[i];
        k.flags[lane] = flags[i] | (outTogether[i] != 0.0f ? kWideTogether : 0u);
        for (int j = 0; j < pointCount[i]; ++j) {
            WideContactPoint& p = k.points[j];
            p.adjustedSeparation[lane] = outAdjusted[j][i];
            p.normalMass[lane] = outNormalMass[j][i];
            p.tangentMass[lane] = outTangentMass[j][i];
        }
    }
    return found;
}

void packEmptyWideContactLane(WideContactBlock& k, WideContactCold& cold, int lane, int zeroState) {
    packLane(k, cold, lane, nullptr, -1, zeroState);
}

namespace {

int& laneLimit() {
    static int limit = 8;
    return limit;
}

#if defined(I2D_AVX2_KERNEL)
bool cpuHasAvx2() {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
}
#endif

}  // namespace

#if defined(I2D_AVX2_KERNEL)
// wide_avx2.cpp: pairs of blocks from `first`; each returns the first
// block it left (the odd one at the end, if any).
int warmStartWideContactsAvx2(WideContactBlock* blocks, BodyState* states, int first, int last, int points);
int solveWideContactsAvx2(WideContactBlock* blocks, WideContactCold* cold, BodyState* states, const SweepParams& sp,
                          int first, int last, int points);
#endif

int wideLanes() {
#if defined(I2D_AVX2_KERNEL)
    static const bool avx2 = cpuHasAvx2();
    return avx2 && laneLimit() >= 8 ? 8 : 4;
#else
    return 4;
#endif
}

void limitWideLanes(int lanes) { laneLimit() = lanes; }

void warmStartWideContacts(SolverArrays& s, int firstBlock, int lastBlock, int points) {
#if defined(I2D_AVX2_KERNEL)
    if (wideLanes() == 8 && lastBlock > firstBlock)
        firstBlock = warmStartWideContactsAvx2(&s.wideContacts[0], s.states.data(), firstBlock, lastBlock, points);
#endif
    withPointCount(points, [&](auto n) {
        for (int i = firstBlock; i < lastBlock; ++i)
            warmStartBlock<n()>(Lanes4<WideContactBlock>{&s.wideContacts[static_cast<std::size_t>(i)]},
                                s.states.data());
    });
}

void solveWideContacts(SolverArrays& s, const RowContext& x, float maxPush, SolvePass pass, float h, bool leaveImpacts,
                       float impactSpeed, int firstBlock, int lastBlock, bool trackMax, int points) {
    const SweepParams sp{1.0f / h,     -impactSpeed, pass == SolvePass::soft_bias,
                         leaveImpacts, trackMax,     x.dynamicSoft,
                         x.staticSoft, maxPush};
#if defined(I2D_AVX2_KERNEL)
    if (wideLanes() == 8 && lastBlock > firstBlock)
        firstBlock = solveWideContactsAvx2(&s.wideContacts[0], &s.wideContactCold[0], s.states.data(), sp, firstBlock,
                                           lastBlock, points);
#endif
    withPointCount(points, [&](auto n) {
        for (int i = firstBlock; i < lastBlock; ++i) {
            const std::size_t b = static_cast<std::size_t>(i);
            solveBlock<n()>(Lanes4<WideContactBlock>{&s.wideContacts[b], &s.wideContactCold[b]}, s.states.data(), sp);
        }
    });
}

void writeBackWideContacts(SolverArrays& s, int firstBlock, int lastBlock) {
    for (int i = firstBlock; i < lastBlock; ++i) {
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(i)];
        const WideContactCold& cold = s.wideContactCold[static_cast<std::size_t>(i)];
        for (int lane = 0; lane < 4; ++lane) {
            if (cold.row[lane] < 0) continue;
            ContactConstraint& cc = s.constraints[static_cast<std::size_t>(cold.row[lane])];
            for (int j = 0; j < cc.pointCount; ++j) {
                ContactPointConstraint& cp = cc.points[j];
                cp.normalImpulse = k.points[j].normalImpulse[lane];
                cp.tangentImpulse = k.points[j].tangentImpulse[lane];
                cp.maxNormalImpulse = cold.maxNormalImpulse[j][lane];
            }
        }
    }
}

void readWideNormalImpulses(SolverArrays& s, const std::vector<int>& rows) {
    // The blocks hold the coloured rows in ascending order, each from its
    // first row (wideBlockRows); the rows asked for ascend too.
    const std::vector<int>& blockRows = s.wideBlockRows;
    const std::size_t blocks = blockRows.size() / 2;
    std::size_t block = 0;
    for (int r : rows) {
        if (r >= s.contactOverflowStart) break;  // the rest are scalar rows
        while (block + 1 < blocks && blockRows[2 * (block + 1)] <= r) ++block;
        const int lane = r - blockRows[2 * block];
        const WideContactBlock& k = s.wideContacts[block];
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(r)];
        for (int j = 0; j < cc.pointCount; ++j) cc.points[j].normalImpulse = k.points[j].normalImpulse[lane];
    }
}

void dropWideContactImpulses(SolverArrays& s, const std::vector<char>& bad) {
    for (std::size_t i = 0; i < s.wideContacts.size(); ++i) {
        WideContactBlock& k = s.wideContacts[i];
        for (int lane = 0; lane < 4; ++lane) {
            if (!bad[static_cast<std::size_t>(k.a[lane])] && !bad[static_cast<std::size_t>(k.b[lane])]) continue;
            for (int j = 0; j < 2; ++j)
                k.points[j].normalImpulse[lane] = k.points[j].tangentImpulse[lane] =
                    s.wideContactCold[i].maxNormalImpulse[j][lane] = 0.0f;
        }
    }
}

}  // namespace i2d::detail
