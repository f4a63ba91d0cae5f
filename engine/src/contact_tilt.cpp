#include "contact_tilt.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "contact_solver.hpp"
#include "solver.hpp"
#include "wide_contact.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {
/// How nearly opposite (the cosine) the pushes of a chain body's two rows must be.
constexpr float kOpposite = 0.9f;
void factorChains(TiltChains& t);
}  // namespace

void buildTiltChains(WorldState& w) {
    SolverArrays& s = w.solver;
    TiltChains& t = s.tilt;
    t.rows.clear();
    t.chainStart.clear();
    if (t.candidate.empty()) return;
    const int zero = static_cast<int>(s.states.size()) - 1;
    // Each turning body's count of candidate rows, read from the lanes alone
    // (most candidates, a pyramid's, fail it: their rows are not built).
    t.degree.assign(s.states.size(), 0);
    auto turning = [&](const WideContactBlock& k, int lane, bool sideB) {
        const int state = sideB ? k.b[lane] : k.a[lane];
        return state != zero && (sideB ? k.iB[lane] : k.iA[lane]) > 0.0f;
    };
    for (int packed : t.candidate) {
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(packed / 4)];
        const int lane = packed % 4;
        if (turning(k, lane, false)) ++t.degree[static_cast<std::size_t>(k.a[lane])];
        if (turning(k, lane, true)) ++t.degree[static_cast<std::size_t>(k.b[lane])];
    }
    // A body of a chain has two rows at most, and no other row or joint: it
    // turns only as its chain's rows let it.
    for (std::size_t i = 0; i + 1 < s.states.size(); ++i) {
        const int count = t.degree[i];
        if (count == 0 || count > 2) continue;
        const int slot = s.stateBodies[i];
        const int rows = std::popcount(s.contactColourMasks[static_cast<std::size_t>(slot)]);
        if (rows != count || w.bodies[slot].jointCount != 0) t.degree[i] = 3;
    }
    // The rows of the candidates whose turning bodies may be in a chain.
    t.found.clear();
    for (int packed : t.candidate) {
        const int block = packed / 4, lane = packed % 4;
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(block)];
        if ((turning(k, lane, false) && t.degree[static_cast<std::size_t>(k.a[lane])] > 2) ||
            (turning(k, lane, true) && t.degree[static_cast<std::size_t>(k.b[lane])] > 2))
            continue;
        TiltRow r;
        r.block = block;
        r.lane = lane;
        r.a = k.a[lane];
        r.b = k.b[lane];
        const float nx = k.nx[lane], ny = k.ny[lane];
        r.nx = nx;
        r.ny = ny;
        r.friction = k.friction[lane];
        const WideContactPoint& p1 = k.points[0];
        const WideContactPoint& p2 = k.points[1];
        r.cA = (p1.rAx[lane] - p2.rAx[lane]) * ny - (p1.rAy[lane] - p2.rAy[lane]) * nx;  // (r_1 − r_2) × n
        r.cB = (p1.rBx[lane] - p2.rBx[lane]) * ny - (p1.rBy[lane] - p2.rBy[lane]) * nx;
        // r_m × t, t = rightPerp(n) = (n_y, −n_x) as the sweep's friction rows take it.
        const float tx = ny, ty = -nx;
        r.sA = 0.5f * ((p1.rAx[lane] + p2.rAx[lane]) * ty - (p1.rAy[lane] + p2.rAy[lane]) * tx);
        r.sB = 0.5f * ((p1.rBx[lane] + p2.rBx[lane]) * ty - (p1.rBy[lane] + p2.rBy[lane]) * tx);
        r.mA = r.a != zero ? k.mA[lane] : 0.0f;
        r.iA = r.a != zero ? k.iA[lane] : 0.0f;
        r.mB = r.b != zero ? k.mB[lane] : 0.0f;
        r.iB = r.b != zero ? k.iB[lane] : 0.0f;
        // A row that cannot take part leaves its bodies out: one without a
        // second point or cold (no load yet), one that turns nothing, and one
        // on a body that moves but does not turn (fixed rotation).
        const bool usable = (k.flags[lane] & kWidePoint1) != 0 && (k.flags[lane] & kWideCold) == 0 &&
                            !((r.mA > 0.0f && r.iA <= 0.0f) || (r.mB > 0.0f && r.iB <= 0.0f)) &&
                            r.iA * r.cA * r.cA + r.iB * r.cB * r.cB > 0.0f;
        if (!usable) {
            if (r.iA > 0.0f) t.degree[static_cast<std::size_t>(r.a)] = 3;
            if (r.iB > 0.0f) t.degree[static_cast<std::size_t>(r.b)] = 3;
            continue;
        }
        t.found.push_back(r);
    }
    // A body of a chain is pressed from opposite sides by its two rows, as
    // a box of a column is from below and from above. A body held by two
    // rows on one side (a lintel on two posts) closes a loop through what
    // holds those up, which the rows' normal loads already do: held rigid,
    // its tilt fought the posts' sags, and the lintel rocked them.
    auto turnsOn = [&](const TiltRow& r, int side) {
        return (side == 0 ? r.iA : r.iB) > 0.0f && t.degree[static_cast<std::size_t>(side == 0 ? r.a : r.b)] <= 2;
    };
    auto linkRows = [&] {
        t.link.assign(2 * s.states.size(), -1);
        for (int f = 0; f < static_cast<int>(t.found.size()); ++f) {
            const TiltRow& r = t.found[static_cast<std::size_t>(f)];
            for (int side = 0; side < 2; ++side) {
                if (!turnsOn(r, side)) continue;
                int* l = &t.link[2 * static_cast<std::size_t>(side == 0 ? r.a : r.b)];
                (l[0] < 0 ? l[0] : l[1]) = f;
            }
        }
    };
    linkRows();
    for (std::size_t i = 0; i + 1 < s.states.size(); ++i) {
        const int* l = &t.link[2 * i];
        if (l[1] < 0) continue;
        // Each row's push on this body: along n on its B side, −n on its A side.
        auto push = [&](int f) {
            const TiltRow& r = t.found[static_cast<std::size_t>(f)];
            const float sign = r.b == static_cast<int>(i) ? 1.0f : -1.0f;
            return Vec2{sign * r.nx, sign * r.ny};
        };
        if (!(dot(push(l[0]), push(l[1])) < -kOpposite)) t.degree[i] = 3;
    }
    // A body one of whose rows is not kept is not kept either: a soft row
    // on a body that a chain turns with others meets more inertia than its
    // own effective mass says (a box under a box 20 times as dense, held to
    // it, rocked on two one-point floor rows with growing swings).
    for (bool changed = true; changed;) {
        changed = false;
        for (const TiltRow& r : t.found) {
            const bool keptA = r.iA <= 0.0f || turnsOn(r, 0), keptB = r.iB <= 0.0f || turnsOn(r, 1);
            if (keptA && keptB) continue;
            for (int side = 0; side < 2; ++side) {
                if (!turnsOn(r, side)) continue;
                t.degree[static_cast<std::size_t>(side == 0 ? r.a : r.b)] = 3;
                changed = true;
            }
        }
    }
    // Kept: the rows whose turning sides are all kept bodies.
    int kept = 0;
    for (const TiltRow& r : t.found) {
        if (((r.iA > 0.0f) && !turnsOn(r, 0)) || ((r.iB > 0.0f) && !turnsOn(r, 1))) continue;
        t.found[static_cast<std::size_t>(kept++)] = r;
    }
    t.found.resize(static_cast<std::size_t>(kept));
    linkRows();
    // The body on a row's side that leads on to another row, or −1.
    auto onward = [&](int row, int side) {
        const TiltRow& r = t.found[static_cast<std::size_t>(row)];
        const int state = side == 0 ? r.a : r.b;
        if ((side == 0 ? r.iA : r.iB) <= 0.0f) return -1;
        const int* l = &t.link[2 * static_cast<std::size_t>(state)];
        return l[0] == row ? l[1] : l[0];
    };
    // Each chain walked from an end (a row one of whose sides leads nowhere)
    // to the other; rows closing a ring are never reached from an end and
    // stay with the sweep.
    t.visited.assign(static_cast<std::size_t>(kept), 0);
    for (int i = 0; i < kept; ++i) {
        if (t.visited[static_cast<std::size_t>(i)]) continue;
        int side;
        if (onward(i, 0) < 0)
            side = 1;
        else if (onward(i, 1) < 0)
            side = 0;
        else
            continue;  // inside a chain: reached from an end
        t.chainStart.push_back(static_cast<int>(t.rows.size()));
        const int startSide = side;
        int row = i;
        while (row >= 0 && !t.visited[static_cast<std::size_t>(row)]) {
            t.visited[static_cast<std::size_t>(row)] = 1;
            t.rows.push_back(t.found[static_cast<std::size_t>(row)]);
            const int next = onward(row, side);
            if (next < 0) break;
            // The next row's side away from the body it shares with this one.
            const TiltRow& r = t.found[static_cast<std::size_t>(row)];
            const int shared = side == 0 ? r.a : r.b;
            const TiltRow& q = t.found[static_cast<std::size_t>(next)];
            side = (q.a == shared && q.iA > 0.0f) ? 1 : 0;
            row = next;
        }
        // A chain held by immovable bodies at both ends (a column wedged
        // under a ceiling, a row wedged between walls) closes a loop through
        // them: its m row pairs act on m − 1 bodies, and A is singular. It
        // stays with the sweep. (Its last row left to the sweep instead, a
        // row of five boxes held by friction between two walls slid down at
        // 2 mm/s: the chain's solve, last in each pass, undid the friction
        // the sweep had found at the row it left out.)
        const TiltRow& head = t.rows[static_cast<std::size_t>(t.chainStart.back())];
        const TiltRow& tail = t.rows.back();
        const bool heldAtStart = (startSide == 1 ? head.iA : head.iB) <= 0.0f;
        const bool heldAtEnd = (side == 0 ? tail.iA : tail.iB) <= 0.0f;
        if (heldAtStart && heldAtEnd) {
            t.rows.resize(static_cast<std::size_t>(t.chainStart.back()));
            t.chainStart.pop_back();
        }
    }
    t.chainStart.push_back(static_cast<int>(t.rows.size()));
    if (!t.rows.empty()) factorChains(t);
}

namespace {

/// The least pivot of the elimination, relative to the row's own diagonal.
constexpr double kLeastPivot = 1e-9;

/// A manifold's two rows (tilt, shear) on one of its bodies: J's 2×3 block
/// there, in (v_x, v_y, ω), and that body's inverse mass and inertia.
struct SideRows {
    double j[2][3];
    double m, i;
};

SideRows sideRows(const TiltRow& r, bool sideB) {
    const double sign = sideB ? 1.0 : -1.0;
    const double tx = r.ny, ty = -r.nx;
    SideRows g;
    g.j[0][0] = g.j[0][1] = 0.0;
    g.j[0][2] = sign * (sideB ? r.cB : r.cA);
    g.j[1][0] = sign * tx;
    g.j[1][1] = sign * ty;
    g.j[1][2] = sign * (sideB ? r.sB : r.sA);
    g.m = sideB ? r.mB : r.mA;
    g.i = sideB ? r.iB : r.iA;
    return g;
}

/// G1·M⁻¹·G2ᵀ for two rows' blocks on the same body (2×2, added to out).
void addCoupling(const SideRows& g1, const SideRows& g2, double out[4]) {
    for (int p = 0; p < 2; ++p)
        for (int q = 0; q < 2; ++q)
            out[2 * p + q] += g1.m * (g1.j[p][0] * g2.j[q][0] + g1.j[p][1] * g2.j[q][1]) +
                              g1.i * g1.j[p][2] * g2.j[q][2];
}

/// Whether side B (else A) of row r is body `state`, a body that moves.
bool onBody(const TiltRow& r, bool sideB, int state) {
    return sideB ? (r.b == state && (r.mB > 0.0f || r.iB > 0.0f)) : (r.a == state && (r.mA > 0.0f || r.iA > 0.0f));
}

/// 2×2 inverse; false when singular against `scale`.
bool invert2(const double m[4], double out[4], double scale) {
    const double det = m[0] * m[3] - m[1] * m[2];
    if (!(std::abs(det) > kLeastPivot * scale * scale)) return false;
    out[0] = m[3] / det;
    out[1] = -m[1] / det;
    out[2] = -m[2] / det;
    out[3] = m[0] / det;
    return true;
}

/// A = J·M⁻¹·Jᵀ of chain [first, last) in 2×2 blocks: each row pair's
/// diagonal block D_i (TiltChains::diag) and its block with the next pair
/// U_i (upper; the block below is U_iᵀ), the rows left out (`active` clear)
/// with a unit diagonal and no coupling.
void assemble(const TiltChains& t, ChainFactors& f, int first, int last) {
    for (int i = first; i < last; ++i) {
        const auto u = static_cast<std::size_t>(i);
        const TiltRow& r = t.rows[u];
        double* d = &f.diag[4 * u];
        double* e = &f.upper[4 * u];
        std::fill_n(d, 4, 0.0);
        std::fill_n(e, 4, 0.0);
        const SideRows gA = sideRows(r, false), gB = sideRows(r, true);
        addCoupling(gA, gA, d);
        addCoupling(gB, gB, d);
        if (i + 1 < last) {
            const TiltRow& q = t.rows[u + 1];
            for (int side = 0; side < 2; ++side) {
                const int state = side == 0 ? r.a : r.b;
                if (!onBody(r, side == 1, state)) continue;
                if (onBody(q, false, state)) addCoupling(side == 0 ? gA : gB, sideRows(q, false), e);
                if (onBody(q, true, state)) addCoupling(side == 0 ? gA : gB, sideRows(q, true), e);
            }
        }
    }
    for (int i = first; i < last; ++i) {
        const auto u = static_cast<std::size_t>(i);
        for (int p = 0; p < 2; ++p) {
            if (f.active[u] & (1u << p)) continue;
            double* d = &f.diag[4 * u];
            d[2 * p] = d[2 * p + 1] = d[p] = d[2 + p] = 0.0;
            d[3 * p] = 1.0;
            for (int q = 0; q < 2; ++q) {
                f.upper[4 * u + static_cast<std::size_t>(2 * p + q)] = 0.0;                       // row p of U_i
                if (i > first) f.upper[4 * (u - 1) + static_cast<std::size_t>(2 * q + p)] = 0.0;  // column p of U_{i−1}
            }
        }
    }
}

/// The block LDLᵀ of the assembled chain, in place: diag becomes D'_i⁻¹
/// (D'_i = D_i − U_{i−1}ᵀ D'_{i−1}⁻¹ U_{i−1}) and lower the multipliers
/// L_i = U_{i−1}ᵀ D'_{i−1}⁻¹. Returns the first row pair whose pivot
/// vanishes (it depends on the pairs before it), or −1.
int factor(ChainFactors& f, int first, int last) {
    for (int i = first; i < last; ++i) {
        const auto u = static_cast<std::size_t>(i);
        double* d = &f.diag[4 * u];
        double* m = &f.lower[4 * u];
        if (i > first) {
            const double* dp = &f.diag[4 * (u - 1)];
            const double* e = &f.upper[4 * (u - 1)];
            for (int p = 0; p < 2; ++p)
                for (int q = 0; q < 2; ++q) m[2 * p + q] = e[p] * dp[q] + e[2 + p] * dp[2 + q];
            for (int p = 0; p < 2; ++p)
                for (int q = 0; q < 2; ++q) d[2 * p + q] -= m[2 * p] * e[q] + m[2 * p + 1] * e[2 + q];
        }
        double inv[4];
        if (!invert2(d, inv, std::max(std::abs(d[0]) + std::abs(d[3]), 1e-30))) return i;
        std::copy_n(inv, 4, d);
    }
    return -1;
}

/// Assembles and factors the chain, leaving out the row pairs the
/// elimination finds dependent on the ones before them.
void assembleAndFactor(const TiltChains& t, ChainFactors& f, int first, int last) {
    for (;;) {
        assemble(t, f, first, last);
        const int singular = factor(f, first, last);
        if (singular < 0) return;
        f.active[static_cast<std::size_t>(singular)] = 0;
    }
}

/// x = A⁻¹·rhs by the factors: forward b'_i = b_i − L_i b'_{i−1}, back
/// x_i = D'⁻¹_i (b'_i − U_i x_{i+1}).
void substitute(TiltChains& t, const ChainFactors& f, int first, int last) {
    for (int i = first; i < last; ++i) {
        const auto u = static_cast<std::size_t>(i);
        double b0 = (f.active[u] & 1u) ? t.rhs[2 * u] : 0.0, b1 = (f.active[u] & 2u) ? t.rhs[2 * u + 1] : 0.0;
        if (i > first) {
            const double* m = &f.lower[4 * u];
            b0 -= m[0] * t.x[2 * u - 2] + m[1] * t.x[2 * u - 1];
            b1 -= m[2] * t.x[2 * u - 2] + m[3] * t.x[2 * u - 1];
        }
        t.x[2 * u] = b0;
        t.x[2 * u + 1] = b1;
    }
    for (int i = last - 1; i >= first; --i) {
        const auto u = static_cast<std::size_t>(i);
        double b0 = t.x[2 * u], b1 = t.x[2 * u + 1];
        if (i + 1 < last) {
            const double* e = &f.upper[4 * u];
            b0 -= e[0] * t.x[2 * u + 2] + e[1] * t.x[2 * u + 3];
            b1 -= e[2] * t.x[2 * u + 2] + e[3] * t.x[2 * u + 3];
        }
        const double* d = &f.diag[4 * u];
        t.x[2 * u] = d[0] * b0 + d[1] * b1;
        t.x[2 * u + 1] = d[2] * b0 + d[3] * b1;
    }
}

/// Each chain's factors for the passes and for the push (the row pairs the
/// elimination finds dependent left out), once per step: the rows' arms and
/// masses do not change within it.
void factorChains(TiltChains& t) {
    const std::size_t n = t.rows.size();
    t.rhs.resize(2 * n);
    t.x.resize(2 * n);
    for (ChainFactors* f : {&t.velocity, &t.push}) {
        f->diag.resize(4 * n);
        f->upper.resize(4 * n);
        f->lower.resize(4 * n);
        f->active.resize(n);
    }
    // The velocities: a tilt and a shear row per manifold, the shear only
    // where there is friction (frictionless columns crept sideways and fell
    // while shear rows and the push held their bodies along their faces).
    // The push: tilt rows only; it closes a tilt error, and holds nothing
    // along the faces.
    for (std::size_t i = 0; i < n; ++i) {
        t.velocity.active[i] = t.rows[i].friction > 0.0f ? 3 : 1;
        t.push.active[i] = 1;
    }
    for (std::size_t c = 0; c + 1 < t.chainStart.size(); ++c) {
        assembleAndFactor(t, t.velocity, t.chainStart[c], t.chainStart[c + 1]);
        assembleAndFactor(t, t.push, t.chainStart[c], t.chainStart[c + 1]);
    }
}

/// The chains' solve on the velocities (push false: the passes' own, with
/// their impulses and cones) or on the pseudo-velocities (push true:
/// SolverArrays::biasV and biasW, the deep push's if any, which must not tilt
/// a chain's manifolds but close their tilt error; tilt rows only, no
/// impulse kept).
void solveChains(WorldState& w, float h, bool push) {
    SolverArrays& s = w.solver;
    TiltChains& t = s.tilt;
    if (t.rows.empty()) return;
    auto velocity = [&](int state) -> std::pair<Vec2, float> {
        if (push) return {s.biasV[static_cast<std::size_t>(state)], s.biasW[static_cast<std::size_t>(state)]};
        const BodyState& st = s.states[static_cast<std::size_t>(state)];
        return {st.v, st.w};
    };
    const float maxPush = w.settings.maxPushSpeed;
    const ChainFactors& f = push ? t.push : t.velocity;
    // The soft rows' rates, which only the push's targets read.
    const RowContext x = push ? makeRowContext(w, h, true) : RowContext{};
    BodyState* states = s.states.data();
    for (std::size_t c = 0; c + 1 < t.chainStart.size(); ++c) {
        const int first = t.chainStart[c], last = t.chainStart[c + 1];
        // Each row pair's right-hand side: its targets less its speeds now.
        for (int i = first; i < last; ++i) {
            const auto u = static_cast<std::size_t>(i);
            const TiltRow& r = t.rows[u];
            const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(r.block)];
            const auto [vA, wA] = velocity(r.a);
            const auto [vB, wB] = velocity(r.b);
            const float tx = r.ny, ty = -r.nx;
            const float tilt = r.cB * wB - r.cA * wA;  // v_n1 − v_n2
            const float shear = tx * (vB.x - vA.x) + ty * (vB.y - vA.y) + r.sB * wB - r.sA * wA;
            // The tilt's target: none on the velocities (the rows are rigid);
            // on the pseudo-velocities, what closes the difference of the two
            // points' separations at the soft rows' own rate (a column landed
            // bent straightens as its contacts would close their overlaps).
            float target = 0.0f;
            if (push) {
                const BodyState& sA = states[r.a];
                const BodyState& sB = states[r.b];
                const Vec2 nrm{r.nx, r.ny};
                const Softness& soft = (k.flags[r.lane] & kWideImmovableSide) != 0 ? x.staticSoft : x.dynamicSoft;
                const Rot qA = (k.flags[r.lane] & kWideRoundA) != 0 ? Rot{} : sA.dq;
                const Rot qB = (k.flags[r.lane] & kWideRoundB) != 0 ? Rot{} : sB.dq;
                float bias[2];
                for (int j = 0; j < 2; ++j) {
                    const WideContactPoint& p = k.points[j];
                    ContactPointConstraint cp{};
                    cp.rA = {p.rAx[r.lane], p.rAy[r.lane]};
                    cp.rB = {p.rBx[r.lane], p.rBy[r.lane]};
                    cp.adjustedSeparation = p.adjustedSeparation[r.lane];
                    const float sep = currentSeparation(cp, nrm, sB.dp - sA.dp, qA, qB);
                    bias[j] = clamp(soft.biasRate * sep, -maxPush, maxPush);
                }
                target = -(bias[0] - bias[1]);
            }
            t.rhs[2 * u] = static_cast<double>(target) - tilt;
            t.rhs[2 * u + 1] = static_cast<double>(push ? 0.0f : k.tangentSpeed[r.lane]) - shear;
        }
        // Solve A·x = rhs. Where the solution would make a point pull or
        // slip past its friction cone, the whole of it is scaled down until
        // none would: every impulse applied is one the contacts can give, and
        // the sweep does the rest. A column is a cantilever: a tip speed of
        // float noise (1e-5 m/s) asks couples thousands of times larger all
        // down it, more than the top's light rows can give. Leaving such rows
        // out and solving again left tall_stack50's top two rows out in
        // every pass: its top box kept 0.06 m/s that its position did not
        // follow, and the factors were made again twice a pass.
        substitute(t, f, first, last);
        double scale = 1.0;
        for (int i = first; i < last && !push; ++i) {
            const auto u = static_cast<std::size_t>(i);
            const TiltRow& r = t.rows[u];
            const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(r.block)];
            const double l1 = k.points[0].normalImpulse[r.lane], l2 = k.points[1].normalImpulse[r.lane];
            const double tilt = t.x[2 * u], shear = t.x[2 * u + 1];
            if (tilt < 0.0 && l1 + tilt < 0.0) scale = std::min(scale, l1 / -tilt);
            if (tilt > 0.0 && l2 - tilt < 0.0) scale = std::min(scale, l2 / tilt);
            const double total = k.points[0].tangentImpulse[r.lane] + k.points[1].tangentImpulse[r.lane];
            const double bound = k.friction[r.lane] * (l1 + l2);
            if (shear > 0.0 && total + shear > bound) scale = std::min(scale, std::max(bound - total, 0.0) / shear);
            if (shear < 0.0 && total + shear < -bound) scale = std::min(scale, std::max(bound + total, 0.0) / -shear);
        }
        if (scale < 1.0)
            for (int i = 2 * first; i < 2 * last; ++i) t.x[static_cast<std::size_t>(i)] *= scale;
        for (int i = first; i < last; ++i) {
            const auto u = static_cast<std::size_t>(i);
            if (f.active[u] == 0) continue;
            const TiltRow& r = t.rows[u];
            WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(r.block)];
            const float tiltImpulse = (f.active[u] & 1u) ? static_cast<float>(t.x[2 * u]) : 0.0f;
            const float shearImpulse = (f.active[u] & 2u) ? static_cast<float>(t.x[2 * u + 1]) : 0.0f;
            if (!push) {
                WideContactPoint& p1 = k.points[0];
                WideContactPoint& p2 = k.points[1];
                p1.normalImpulse[r.lane] = std::max(p1.normalImpulse[r.lane] + tiltImpulse, 0.0f);
                p2.normalImpulse[r.lane] = std::max(p2.normalImpulse[r.lane] - tiltImpulse, 0.0f);
                if (shearImpulse != 0.0f) {
                    // The shear split as the normal impulses are (its split acts on nothing).
                    const float total = p1.tangentImpulse[r.lane] + p2.tangentImpulse[r.lane] + shearImpulse;
                    const float load = p1.normalImpulse[r.lane] + p2.normalImpulse[r.lane];
                    const float share = load > 0.0f ? p1.normalImpulse[r.lane] / load : 0.5f;
                    p1.tangentImpulse[r.lane] = total * share;
                    p2.tangentImpulse[r.lane] = total - total * share;
                }
            }
            // v += M⁻¹ Jᵀ x on each side.
            for (int side = 0; side < 2; ++side) {
                const SideRows g = sideRows(r, side == 1);
                if (g.m == 0.0 && g.i == 0.0) continue;
                const int state = side == 0 ? r.a : r.b;
                Vec2& v = push ? s.biasV[static_cast<std::size_t>(state)] : states[state].v;
                float& spin = push ? s.biasW[static_cast<std::size_t>(state)] : states[state].w;
                const double px = g.j[0][0] * tiltImpulse + g.j[1][0] * shearImpulse;
                const double py = g.j[0][1] * tiltImpulse + g.j[1][1] * shearImpulse;
                const double pw = g.j[0][2] * tiltImpulse + g.j[1][2] * shearImpulse;
                v.x += static_cast<float>(g.m * px);
                v.y += static_cast<float>(g.m * py);
                spin += static_cast<float>(g.i * pw);
            }
        }
    }
}

}  // namespace

void solveTiltChains(WorldState& w, float h) { solveChains(w, h, false); }

void pushTiltChains(WorldState& w, float h) { solveChains(w, h, true); }

}  // namespace i2d::detail
