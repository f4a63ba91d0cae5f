// The load a contact was built carrying (Contact::restLoad).
//
// A soft row (soft_step) is a spring of stiffness m_eff·ω²: at rest under a
// force F its point sinks F/(m_eff·ω²) = F·K/ω² (K = 1/m_eff, the row's
// inverse effective mass), where the push of that overlap, biasRate·C,
// balances the row's leak, impulseScale·λ (with the soft coefficients of
// Catto's Box2D v3: impulseScale/(massScale·biasRate) = 1/(h·ω²)). Bodies
// built touching start with no overlap, so under their weight every row
// sinks to that sag and overshoots it: a pyramid of 100 rows built touching
// dropped 0.52 m at its top within 0.4 s, twice its 0.29 m sag, and rang in
// its slowest vertical mode for seconds, out of the reach of the rows'
// damping (docs/validation.md, "The load a stack was built with").
//
// A contact that begins touching at rest (kWideCold: a row settled in its
// first step), its points within kRestTouchGap, is given its first load by
// an estimate (estimateRestLoads), and records it: each point's normal force
// (Contact::restLoad). From then on its row measures the overlap from that
// force's sag: the separation the row is given is the true one less
// F_rest·K/ω². The row then holds that load where it was built, and sinks
// only under load beyond it. The record only ever falls: at the end of every
// step it is held to the force the point carries then (a record above it
// would lift the bodies apart by the difference's sag), it goes once the
// bodies come apart, and a load taken away takes its part with it; so a row
// never holds its bodies further apart than touching for more than a step.
// Carried from manifold to manifold by feature id, as the impulses are.
//
// The record is the estimate, not what the first step's solve ends with: a
// light plank under a heavy box near one end, with the slab above it,
// carried more at that step's end than at rest while the plank was still
// settling, and recorded so, the plank was held down and the box pushed up
// by the excess, rising 6.5 mm (the tower's energy +0.36 %). Nor does a cold
// row the estimate leaves to the solver record anything.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

#include "impulse2d/collision.hpp"
#include "impulse2d/geometry.hpp"

namespace i2d::detail {

/// 1/ω² of a soft row of `hertz` (s²), the sag per unit of F·K; 0 for a
/// rigid row.
inline float restCompliance(float hertz) {
    constexpr float kTwoPi = 6.28318530717959f;
    const float omega = kTwoPi * hertz;
    return hertz > 0.0f ? 1.0f / (omega * omega) : 0.0f;
}

/// How far apart a row's points may be and count as built touching (m):
/// bodies built just apart (or closing on each other at the speed of a
/// step of gravity) hold nothing yet, and their row must not start as if
/// they did.
constexpr float kRestTouchGap = 0.1f * kLinearSlop;

/// Whether every point of a manifold is within kRestTouchGap of touching.
inline bool restsTouching(const Manifold& m) {
    for (int j = 0; j < m.pointCount; ++j)
        if (!(m.points[j].separation <= kRestTouchGap)) return false;
    return m.pointCount > 0;
}

/// A record is kept in 16 bits, a float's upper half (its sign, exponent and
/// first 7 bits of mantissa): rounded down, within 0.8 % of the force, so
/// the record is never above it. Four bytes per contact, which keeps the
/// memory per touching contact below Box2D 2.4.1's (docs/performance.md).
using RestLoad = std::uint16_t;

/// The force of a record (N).
inline float restForce(RestLoad record) { return std::bit_cast<float>(static_cast<std::uint32_t>(record) << 16); }

/// The record of a force (N), rounded down; 0 for none, a non-positive or
/// a non-finite force.
inline RestLoad restRecord(float force) {
    if (!(force > 0.0f) || !(force <= std::numeric_limits<float>::max())) return 0;
    return static_cast<RestLoad>(std::bit_cast<std::uint32_t>(force) >> 16);
}

/// How far a point's row measures its overlap from (m): the sag of the force
/// it was built carrying, F_rest·K/ω² (`compliance` = 1/ω², K the row's
/// inverse effective mass), if it is at most `most`, else zero. Zero
/// without a record (K is then not read, so an unbounded K makes no NaN).
///
/// `most` is the contact's deep-overlap depth (deepOverlapOf): a load that
/// would sag a row deeper is beyond the soft rows' regime (a deep row is
/// rigid, its overlap pushed apart on pseudo-velocities), and the row holds
/// none of it built-in, as without a record. Told of such sags (a light box
/// built under one 5,000 times its mass: 0.16 and 0.63 m a point), the rows
/// pushed the light box up 33 mm between them and squeezed it out sideways;
/// in random towers of boxes up to 500 times each other's mass built
/// touching, with the limit at what the rows' push cap can hold (about
/// 0.25 m and 0.5 m), 3 to 32 of 120 gained more than 0.1 % of their energy
/// (per substep count and step length), against 0 to 2 built 0.6 mm apart;
/// at the deep depth, 0 to 3.
inline float restSag(RestLoad record, float inverseMass, float compliance, float most) {
    if (record == 0) return 0.0f;
    const float sag = restForce(record) * inverseMass * compliance;
    return sag <= most ? sag : 0.0f;
}

/// A record scaled by `factor` (in [0, 1]): part of the load taken away
/// (lost_load.cpp, holdRestLoads), whose sag the row must then count again.
inline RestLoad scaledRestLoad(RestLoad record, float factor) { return restRecord(restForce(record) * factor); }

/// A contact's records at the end of a step (`records`, one per point of
/// its manifold, `count`): held to its points' loads, their normal impulses
/// over the substep (`impulses`, N·s) times 1/h, all by one factor, the
/// smallest of load over record among its points, so that what they hold
/// keeps its shape (the moment between the points as well as the load); and
/// none once a point's bodies are more than kRestTouchGap apart
/// (`separations`, m, its manifold's as the step began). The load a record
/// holds comes from the record's own push, so a load that shifted away from
/// a point (an off-centre block on a light plank, rocking as it settled)
/// was not seen to: the row held its side up by up to its sag, and the block
/// climbed 1.6 cm, tilted, and its energy rose 0.8 %. Held point by point, a
/// block rocking on a plank near its end lost the record on the side it
/// rocked off and kept it on the other, and climbed on the difference (8 mm
/// and +0.44 % of its energy for a block 9.5 times the plank's at one
/// substep). Held together it climbed less, but still (+0.37 %): such a body
/// gets no records at all (kLeastRestShare, rest_load.cpp).
inline void holdRestLoads(RestLoad* records, const float* impulses, const float* separations, int count, float invH) {
    float scale = 1.0f;
    for (int j = 0; j < count; ++j) {
        if (records[j] == 0) continue;
        const float held = restForce(records[j]);
        const float load = impulses[j] * invH;
        if (!(separations[j] <= kRestTouchGap) || !(load > 0.0f)) {
            scale = 0.0f;
            break;
        }
        if (load < held) scale = std::min(scale, load / held);
    }
    if (scale == 1.0f) return;
    for (int j = 0; j < count; ++j) records[j] = scaledRestLoad(records[j], scale);
}

struct Contact;
/// holdRestLoads for contact `ct`, its impulses just stored (rest_load.cpp).
void holdRestLoads(Contact& ct, float invH);

struct WorldState;

/// soft_step, once the rows are prepared, in a step with cold lanes
/// (SolverArrays::coldBlocks): the load each cold row that holds a body up
/// will carry, estimated top down, as its warm start, its overlap measured
/// from that load's sag (rest_load.cpp).
void estimateRestLoads(WorldState& w, float h);

}  // namespace i2d::detail
