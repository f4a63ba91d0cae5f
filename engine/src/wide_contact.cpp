// Four contact manifolds at a time (see wide_contact.hpp): packing rows into
// blocks or preparing lanes straight from the contacts, the four-lane policy
// of the sweeps (wide_contact_kernel.hpp holds the sweeps, wide_avx2.cpp the
// eight-lane policy), the choice between four and eight lanes, and the
// write-back and store of the impulses.
#include "wide_contact.hpp"

#include "contact_row.hpp"
#include "solver.hpp"
#include "wide_contact_kernel.hpp"
#include "wide_lanes4.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// Lane `lane` of block k from row cc (null: an empty lane), every field written.
inline void packLane(WideContactBlock& k, WideContactCold& cold, int lane, const ContactConstraint* cc, int row,
                     int zero) {
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
    k.pairScale[lane] = used ? cc->pairScale : 1.0f;
    std::uint32_t flags = 0;
    if (used) {
        if (cc->pointsTogether) flags |= kWideTogether;
        if (cc->roundA) flags |= kWideRoundA;
        if (cc->roundB) flags |= kWideRoundB;
        if (cc->deepOverlap) flags |= kWideDeep;
        if (againstImmovable(*cc)) flags |= kWideImmovableSide;
        if (cc->pointCount > 0) flags |= kWidePoint0;
        if (cc->pointCount > 1) flags |= kWidePoint1;
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
}

}  // namespace

void packWideContactBlock(SolverArrays& s, int block, int start, int last) {
    const int zero = static_cast<int>(s.states.size()) - 1;
    WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(block)];
    WideContactCold& cold = s.wideContactCold[static_cast<std::size_t>(block)];
    for (int lane = 0; lane < 4; ++lane) {
        const int r = start + lane;
        packLane(k, cold, lane, r < last ? &s.constraints[static_cast<std::size_t>(r)] : nullptr, r, zero);
    }
}

void prepareWideContactLane(const WorldState& w, const RowContext& x, int contact, WideContactBlock& k,
                            WideContactCold& cold, int lane) {
    // The scalar row's own preparation, on the stack: the lane holds exactly
    // what packing that row would have given.
    ContactConstraint cc;
    prepareContactRow(w, x, contact, cc);
    finishContactRow(x, w.settings.penetrationSlop, cc);
    packLane(k, cold, lane, &cc, -1, x.zeroState);
}

void packEmptyWideContactLane(WideContactBlock& k, WideContactCold& cold, int lane, int zeroState) {
    packLane(k, cold, lane, nullptr, -1, zeroState);
}

void storeWideContacts(SolverArrays& s, SlotArray<Contact>& contacts, int firstBlock, int lastBlock) {
    for (int i = firstBlock; i < lastBlock; ++i) {
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(i)];
        const WideContactCold& cold = s.wideContactCold[static_cast<std::size_t>(i)];
        for (int lane = 0; lane < 4; ++lane) {
            if (cold.contact[lane] < 0) continue;
            Contact& ct = contacts[cold.contact[lane]];
            for (int j = 0; j < ct.manifold.pointCount; ++j) {
                ct.normalImpulse[j] = k.points[j].normalImpulse[lane];
                ct.tangentImpulse[j] = k.points[j].tangentImpulse[lane];
            }
        }
    }
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
