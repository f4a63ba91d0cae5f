// The first loads of contacts that begin touching at rest (rest_load.hpp).
#include "rest_load.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact_solver.hpp"
#include "solver.hpp"
#include "wide_contact.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

/// A cold row counts as a support when its normal is within about 45° of
/// the vertical (|n·up| above this): the bodies beside, against which
/// nothing rests, get no estimate and start from zero as before.
constexpr float kLeastSupportUp = 0.7f;

/// Rows between two moving bodies whose masses differ more than this many
/// times get no first load and hold none built in (unlikeMasses).
constexpr float kLeastLikeMasses = 10.0f;

/// Whether a row's bodies (inverse masses; 0 for one that cannot move) are
/// two moving bodies whose masses differ more than kLeastLikeMasses times.
/// Between such bodies the soft rows' Gauss-Seidel couples a light body to
/// the heavy one's load poorly, and a record's push on their row, held while
/// the light body moved under it, fed an oscillation: a 24 kg plank under a
/// 902 kg box near its end (and a 199 kg slab on the box), built touching,
/// rocked, the box rose 6.5 mm and the tower's energy 0.36 % (built apart:
/// none). With the rule, none of 400 random towers of boxes up to 500 times
/// each other's mass gains more than 0.1 % (at 1 and 4 substeps, 1/60 and
/// 1/30 s steps), and the plank's tower none.
bool unlikeMasses(float invMassA, float invMassB) {
    return invMassA > 0.0f && invMassB > 0.0f &&
           std::max(invMassA, invMassB) > kLeastLikeMasses * std::min(invMassA, invMassB);
}

/// The least share of its own weight, against an even share among its
/// support points, that each point of a body must carry for the body to get
/// a first load and records (estimateRestLoads). A body resting near the edge
/// of its support rocks as it settles, loading and unloading its points, and
/// its records, which only fall, then held it tilted on the side they were
/// kept on: a block on a plank, its centre 90 % of the way to the plank's
/// end, climbed 2.3 mm (+0.11 % of its energy) for equal masses at one
/// substep, 7 mm (+0.37 %) for a block 9.5 times the plank's; none built
/// apart. With half an even share, blocks 9.5 times the plank's 75 % of the
/// way still gained 0.12 and 0.14 %; at three quarters none of those layouts
/// (blocks 0.2 to 9.5 times the plank's, 60 to 90 % of the way, 1, 2 and 4
/// substeps) gains more than 0.03 %, none of 300 random towers more than
/// 0.1 %.
constexpr double kLeastRestShare = 0.75;

/// One cold lane whose upper body rests on its lower one.
struct Support {
    float height;  ///< the upper body's centre along up (m)
    int upper, lower;
    int block, lane;
    float up;  ///< n·up seen from the upper body, in (kLeastSupportUp, 1]
};

/// Whether body `b` may be held otherwise than by its cold rows: it touches
/// something through a contact that is not cold (`cold`, by contact slot)
/// and holds it up (a support as kLeastSupportUp), or one deeper than its
/// deep depth (being pushed apart, not resting).
bool heldOtherwise(const WorldState& w, int b, Vec2 up, const std::vector<std::uint8_t>& cold) {
    for (const int c : w.bodies[b].contacts) {
        const Contact& ct = w.contacts[c];
        if (!ct.touching || ct.isSensor || ct.manifold.pointCount == 0 || cold[static_cast<std::size_t>(c)]) continue;
        if (ct.stillDeep) return true;
        // n points from A to B: a support of B's points up, of A's down.
        const float along = dot(ct.manifold.normal, up);
        if ((ct.bodyB == b ? along : -along) > kLeastSupportUp) return true;
    }
    return false;
}

}  // namespace

void holdRestLoads(Contact& ct, float invH) {
    const int count = ct.manifold.pointCount;
    const float separations[2] = {ct.manifold.points[0].separation, ct.manifold.points[1].separation};
    holdRestLoads(ct.restLoad, ct.normalImpulse, separations, count, invH);
    for (int j = count; j < 2; ++j) ct.restLoad[j] = 0;  // (a point the manifold no longer has)
}

void estimateRestLoads(WorldState& w, float h) {
    SolverArrays& s = w.solver;
    const float g = length(w.settings.gravity);
    if (s.coldBlocks.empty() || !(g > 0.0f)) return;
    const Vec2 up = (-1.0f / g) * w.settings.gravity;
    const int zero = static_cast<int>(s.states.size()) - 1;
    const RowContext x = makeRowContext(w, h, true);
    std::vector<Support> supports;
    std::vector<std::uint8_t> cold(static_cast<std::size_t>(w.contacts.capacity()), 0);
    for (const int b : s.coldBlocks) {
        const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(b)];
        for (int lane = 0; lane < 4; ++lane) {
            if (!(k.flags[lane] & kWideCold)) continue;
            const int slot = s.wideContactCold[static_cast<std::size_t>(b)].contact[lane];
            cold[static_cast<std::size_t>(slot)] = 1;
            if (!restsTouching(w.contacts[slot].manifold)) continue;  // built apart: it holds nothing yet
            // n points from A to B: B rests on A where it points up.
            const float along = k.nx[lane] * up.x + k.ny[lane] * up.y;
            const bool bOnA = along > kLeastSupportUp;
            if (!bOnA && !(along < -kLeastSupportUp)) continue;
            const int upper = bOnA ? k.b[lane] : k.a[lane], lower = bOnA ? k.a[lane] : k.b[lane];
            if (upper == zero) continue;  // an immovable body's weight is not carried
            const Vec2 c = w.bodies[s.stateBodies[static_cast<std::size_t>(upper)]].center;
            supports.push_back({dot(c, up), upper, lower, b, lane, bOnA ? along : -along});
        }
    }
    if (supports.empty()) return;
    // Top down: a body's supports after those of every body resting on it
    // (whose centres are higher), so its load includes theirs. Ties by state,
    // then by lane, for an order that does not depend on the workers.
    std::sort(supports.begin(), supports.end(), [](const Support& p, const Support& q) {
        if (p.height != q.height) return p.height > q.height;
        if (p.upper != q.upper) return p.upper < q.upper;
        return p.block != q.block ? p.block < q.block : p.lane < q.lane;
    });
    // What rests on each body, passed down from the bodies above it: the
    // vertical load (N) and its moment about the body's centre (N·m, the
    // load times its arm across `up`).
    std::vector<float> carried(s.states.size(), 0.0f), carriedMoment(s.states.size(), 0.0f);
    const Vec2 across{up.y, -up.x};
    struct Point {
        Support sp;
        int j;
        float arm, lowerArm;  ///< across `up`, from the upper body's centre and from the lower one's (m)
    };
    std::vector<Point> points;
    for (std::size_t first = 0; first < supports.size();) {
        std::size_t last = first;
        const int body = supports[first].upper;
        points.clear();
        for (; last < supports.size() && supports[last].upper == body; ++last) {
            const Support& sp = supports[last];
            const WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(sp.block)];
            const bool upperIsB = k.b[sp.lane] == body;
            for (int j = 0; j < 2; ++j) {
                if (!(k.flags[sp.lane] & (j == 0 ? kWidePoint0 : kWidePoint1))) continue;
                const WideContactPoint& p = k.points[j];
                const Vec2 rA{p.rAx[sp.lane], p.rAy[sp.lane]}, rB{p.rBx[sp.lane], p.rBy[sp.lane]};
                points.push_back({sp, j, dot(upperIsB ? rB : rA, across), dot(upperIsB ? rA : rB, across)});
            }
        }
        first = last;
        // A body that may be held otherwise (a box sliding onto the next piece
        // of a floor, held by the last; a box of a pile being pushed apart)
        // keeps to the solver: shared over its cold rows alone its load would
        // be held twice, and it would be lifted (a frictionless box sliding
        // over 150 pieces at one substep gained 1.2 % of its energy; boxes
        // created overlapping at one point on the ground, 2.2 %). Nor is what
        // rests on it passed on.
        if (heldOtherwise(w, s.stateBodies[static_cast<std::size_t>(body)], up, cold)) continue;
        // Its weight (gravity and the forces on it, along −up) at its centre,
        // and what rests on it.
        const Support& first0 = points.front().sp;
        const WideContactBlock& k0 = s.wideContacts[static_cast<std::size_t>(first0.block)];
        const float invMass = k0.b[first0.lane] == body ? k0.mB[first0.lane] : k0.mA[first0.lane];
        const float fall = -dot(s.integration[static_cast<std::size_t>(body)].linearAcceleration, up);
        const float load = (invMass > 0.0f && fall > 0.0f ? fall / invMass : 0.0f) +
                           carried[static_cast<std::size_t>(body)];
        const float moment = carriedMoment[static_cast<std::size_t>(body)];
        if (!(load > 0.0f) || !std::isfinite(load) || !std::isfinite(moment)) continue;
        // The normal forces N_i = u_i·(α + β·d_i) (u_i the normal's part along
        // up, d_i the point's arm across it): the least-squares forces whose
        // upward parts add up to the load and whose moment about the centre
        // balances the moment of what rests on it, Σ N_i·u_i·d_i = M. Friction
        // holds the rest of each point's share of the load, as it does for a
        // body on a slope. A body those forces cannot hold (one would pull:
        // its centre or its load beyond its supports), or hold only unevenly
        // (kLeastRestShare), is left to the solver.
        double s0 = 0.0, s1 = 0.0, s2 = 0.0;
        for (const Point& q : points) {
            const double u2 = static_cast<double>(q.sp.up) * q.sp.up;
            s0 += u2;
            s1 += u2 * q.arm;
            s2 += u2 * q.arm * q.arm;
        }
        const double det = s0 * s2 - s1 * s1;
        double alpha = 0.0, beta = 0.0;
        if (det > 1e-9 * s0 * s2) {
            alpha = (load * s2 - moment * s1) / det;
            beta = (s0 * moment - s1 * load) / det;
        } else {
            // Points at one arm (a disc's one point, a corner): the moment is
            // balanced only if the load's line passes through them.
            alpha = load / s0;
            if (std::abs(moment - load * s1 / s0) > load * kLinearSlop) continue;
        }
        bool pulls = false;
        for (const Point& q : points) pulls = pulls || !(alpha + beta * q.arm >= 0.0);
        if (pulls) continue;
        // Only a body whose own weight rests squarely: its weight alone
        // (no moment) shared with every point given at least kLeastRestShare
        // of an even share (for a level support). What rests on it may load
        // it unevenly (the end box of a pyramid's row carries the row above
        // on one half only): its neighbours hold it.
        if (det > 1e-9 * s0 * s2) {
            const double betaOwn = -s1 / det, alphaOwn = s2 / det;  // per unit of its own weight
            bool uneven = false;
            for (const Point& q : points) uneven = uneven || !(alphaOwn + betaOwn * q.arm >= kLeastRestShare / s0);
            if (uneven) continue;
        }
        for (const Point& q : points) {
            const Support& sp = q.sp;
            WideContactBlock& k = s.wideContacts[static_cast<std::size_t>(sp.block)];
            WideContactPoint& p = k.points[q.j];
            const bool immovable = (k.flags[sp.lane] & kWideImmovableSide) != 0;
            const float compliance = immovable ? x.staticRestCompliance : x.dynamicRestCompliance;
            Contact& contact = w.contacts[s.wideContactCold[static_cast<std::size_t>(sp.block)].contact[sp.lane]];
            const float most = deepOverlapOf(contact);
            const float force = static_cast<float>(sp.up * (alpha + beta * q.arm));
            // The warm start this load needs, and the row's overlap measured
            // from its sag (restSag): neither for a load whose sag is beyond
            // the contact's deep depth, nor is it passed down: the rows
            // below would hold up, from the first substep, a load the row
            // above them does not carry yet (a light box under one 5,000 times
            // its mass shot up 2 cm in the first step).
            const float sag = force / p.normalMass[sp.lane] * compliance;
            if (!(p.normalMass[sp.lane] > 0.0f) || !(sag <= most)) continue;
            // Nor for a row between two moving bodies whose masses differ more
            // than kLeastLikeMasses times (unlikeMasses).
            if (unlikeMasses(k.mA[sp.lane], k.mB[sp.lane])) continue;
            p.normalImpulse[sp.lane] = force * h;
            p.adjustedSeparation[sp.lane] -= sag;
            contact.restLoad[q.j] = restRecord(force);
            if (sp.lower != zero) {
                carried[static_cast<std::size_t>(sp.lower)] += force * sp.up;
                carriedMoment[static_cast<std::size_t>(sp.lower)] += force * sp.up * q.lowerArm;
            }
        }
    }
}

}  // namespace i2d::detail
