// Deep overlaps in the soft step, pushed apart without adding kinetic energy.
//
// The soft step pushes an overlap apart through the velocity: the soft row's
// bias adds up to maxPushSpeed to the bodies' velocities and the relax pass
// takes it out again, but only as far as the row's accumulated impulse
// allows and only while the contact is still active. A pile of bodies
// created at one point defeats that: each body is pushed by many contacts
// whose pushes add (along different normals, through chains of bodies), the
// contacts that part are relaxed no more, and what the relax cannot take
// back stays as velocity. 50 boxes created at one point in the air threw
// one 3.8 m up (9.4 m/s) with the pushes shared (a body's n deep contacts
// getting the cap over n each, which made separation take 8-12 s), and 50
// capsules 23 m up (21 m/s).
//
// A deep contact's push is therefore solved on pseudo-velocities, as in the
// single-frame push factor (split impulses) of Tamis and Maggiore (2015),
// Constraint based physics solver, §8.1: within each substep the push moves
// the positions and is then dropped, so no push velocity is ever left in a
// body. The velocity rows of a deep contact are rigid: they keep the bodies
// from approaching and carry the load (contact_solver.cpp; what their warm
// start carries from substep to substep is a load, not a strike:
// carryDeepLoads). Each point asks for a separating pseudo-speed of
// biasRate·d (d its depth: the soft row's own push, so the push is
// continuous where a contact becomes shallow) less the push its load needs
// (loadPush: the push at which a soft row would hold the point's
// accumulated impulse), up to maxPushSpeed. A contact sunk deep
// under a heavy load is thus held where a soft row would hold it, not pushed
// out: pushed by its full depth, the contact under a box 100 times heavier
// than the 5-box stack below it (7 cm deep) went out of and back into the
// deep regime every few steps, and the stack rocked 13 cm; at 150:1 it fell.
// Every body's pseudo-velocity is limited afterwards (below): pushes that add
// along a chain of bodies move none faster than the limit, whatever the
// number of its contacts. Box2D 2.4.1 moves positions directly in its
// position iterations (nonlinear Gauss-Seidel,
// b2ContactSolver::SolvePositionConstraints), to the same end, without a
// limit per body.
//
// Pushed along its normal, a deep overlap between two bodies one above the
// other lifts the upper one by the whole depth when the lower one rests on
// the ground: a pile created on the ground was pushed into leaning columns
// (three boxes created 0.4 m above and 0.25 m beside each other became a
// column whose top box rose 1.2 m, then toppled; the pile's energy reached
// 1.56 times its start). Such a row is pushed sideways instead (perpendicular
// to gravity, the way that clears the two with the shorter move) when the
// lower body is supported (rests, through rows whose normals point up, on
// something that does not move), the lift would take the upper body above
// the highest it has been (Body::highest; a push may give back height a body
// had, as to the bodies of a pile that fell onto the ground, never add
// height), and neither body moves further than its own width. The sideways
// move keeps the potential energy; the pile spreads out rather than up.
//
// A manifold's two points are pushed together, as the exact solution of
// their 2×2 complementarity problem (pushPointPair), not one after the other,
// and the push may not drive a body it moves into something that does not
// move and holds it up (guardAgainstImmovable): docs/validation.md, "Rows
// turned by the push".
// Nor may it drive a body it moves into a moving body beside it: it shoves
// that body along (shoveTouching; docs/validation.md, "Shoves between moving
// bodies").
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "contact_row.hpp"
#include "deep_overlap.hpp"
#include "world_state.hpp"

namespace i2d::detail {

namespace {

// Gauss-Seidel sweeps of the push per substep. The push must travel through
// a pile: each sweep carries it one body further, and a body slid aside must
// move the row of bodies beside it. With one sweep 50 boxes created at one
// point and dropped from 10 m were still 0.22 m deep 2 s later. Over 40
// layouts of 20 boxes on the ground the deepest contact at 2 s was within
// 2 cm in 23 with four sweeps, 29 with eight, 34 with sixteen (33 with four
// while a body's sideways move was held to the narrower width of the pair,
// below). Piles created at one point in the air, once pushed sideways at
// twice the cap, were left deep by four: the outer bodies, pushed through the
// pile at the cap, moved out together while its core stayed a metre deep for
// the first second. Of 36 piles of 50 boxes, circles and capsules dropped
// from 5 and 10 m (seeds not used before), 17 were deeper than 2 cm at 2 s
// with four sweeps (up to 7.9 cm), none with sixteen (at most 1.6 cm), no
// rise above 0.24 m, energy at most 1.0002 times the start; with 32, bodies
// of piles of 80 moved up to 0.56 m/s faster than a free fall from their
// height plus the cap allows. The sweeps run only in steps with a deep
// overlap, over its deep rows alone.
constexpr int kPushSweeps = 16;
// Beyond kPushSweeps the sweeps go on, up to kMaxPushSweeps, while a sweep
// still changes some row's own separating pseudo-speed by more than
// kPushConverged·c (c = maxPushSpeed; 3 cm/s at the defaults, an eighth of a
// millimetre a substep). Sixteen sweeps left long chains far from the
// push's answer, somewhere new in every substep: in a row of 80 boxes 0.6 m
// wide created 0.3 m apart on the ground without friction, rows were still
// closing at up to 2.7 m/s after them and some overlaps deepened from 0.3 to
// 0.59 m (with the sideways limit at 3c), and the row was 31 cm deep at 2 s
// (3.3 cm now); 50 unit boxes created at one point on the ground, once
// spread into one layer, took about two more seconds to push its last
// overlaps out. Converged, the push turned boxes
// resting on the ground onto their corners, which the guards now prevent
// (guardAgainstImmovable). Of the outside probe's 3,500 piles, 1,293 broke a
// bound of the issue with sixteen sweeps, 1,082 converged, 1,016 converged
// and guarded both ways (1,097 with at most 32 sweeps; docs/validation.md,
// "A push that converges"). A
// step with a deep overlap costs up to twice as much (50 boxes at one point
// on the ground, the engine against itself: 0.24 against 0.48 ms a step over
// their first 5 s).
constexpr int kMaxPushSweeps = 64;
constexpr float kPushConverged = 0.01f;
// The sideways limit, kSidewaysPushFactor (deep_overlap.hpp): why it is
// not the cap. A sideways push leaves no velocity and lifts nothing, so the
// cap, which bounds the energy an upward push adds, need not hold it to the
// same speed; what it bounds there is how far a body jumps in a step. A pile
// created at one point must spread before it parts: 50 unit boxes cover
// 50 m², a disc of radius 4 m, which at 3 m/s takes 1.3 s before any lag of
// the sweeps, and 50 boxes or capsules created at one point in the air were
// still up to 52 cm deep at 2 s. At twice the cap, of 180 such piles not used
// in choosing it (30, 50 and 80 boxes, circles or capsules from 5 and 10 m),
// 106 instead of 74 were within 2 cm at 2 s. At three times, for bodies
// resting on nothing first, of the 180 piles 158 instead of 154 (and 82
// instead of 75 of 90 not used in choosing it); 60 circles of radius 5 to
// 25 cm created at one point beside a static wall 1 or 4 cm thick crossed it
// no more often than at twice. A supported body was held to twice while the
// soft rows took over a pile's overlaps at the deep depth (at three times,
// piles created on the ground met every bound less often); since a deep
// overlap stays deep to a quarter of that depth (kDeepExitFraction), every
// body may reach three times: 20 boxes, circles and capsules created at one
// point on the ground spread 20 m, and at twice their edges took 1.6 s to
// get there and the piles 2.1 to 2.7 s to part (docs/validation.md, "Deep
// until well apart"). At three times, a pile created at one point on the
// ground still spread at the limit: the edges of 40 unit boxes moved out at
// exactly 9 m/s for 1.5 s, and 50 such boxes (seeds 1 to 20) parted after
// 4.6 to 5.6 s, 10 of them rising above 1.02 times their energy while their
// layer was still closing (up to 1.038). Then five times (docs/validation.md,
// "A wider sideways limit"), now ten: 50 unit boxes created at one point on
// the ground must spread into one layer 50 m long (the energy bound,
// 1.02 times the start, leaves no room to lift a second layer), whose ends,
// 24.5 m out, moved at exactly the limit (1.6 s at 5c), and the last
// overlaps took 0.3 to 0.8 s more to hop out along the row: over seeds 1 to
// 20, 2.00 to 2.42 s at 5c, 1.42 to 2.07 s at 10c with the last of a created
// overlap relaxed again (contact_solver.cpp), 1.22 to 1.47 s with level deep
// rows never stalled as well (kStallMove below); docs/validation.md, "The
// sideways limit again". Now fifteen: 50 capsules (1.5 m long) created at
// one point on the ground spread further, and at 10c parted after 1.83 to
// 2.28 s, 10 of seeds 1 to 20 still deeper than 2 cm at 2 s; at 15c after
// 1.43 to 2.07 s, one of them. Of the outside probe's 3,500 piles, 649 break
// a bound instead of 681, and no circle of 160 layouts beside a static wall
// 1 or 4 cm thick ends beyond it; at 20c the capsules were no better (6
// late) and the probe no better (654) (docs/validation.md, "A wider
// sideways limit, once more").
//
// No point of a pushed body turns faster than kTurnPushFactor·c. Unlimited,
// a push between two boxes nearly on top of each other turned one by
// 0.26 rad in a step and back by 0.6 rad in the next (a corner at up to
// 25 m/s), driving a corner 16 cm into the ground. The ground's deep row then
// lifted the box out, and a body leaving something immovable may rise above
// the highest it has been: it was left standing on the corner. Of 20 piles of
// 50 unit boxes created at one point on the ground, 15 peaked above 1.02
// times their energy, up to 1.104; at c, 1.5c, 2c and 3c, 0, 3, 6 and 10 of
// them, but below 3c capsule piles at one point on the ground parted later,
// turning being how they untangle (docs/validation.md, "Turns the push may
// give"). Kept at 3c when the sideways limit became 5c: a turn drives a
// corner into what is below, a slide does not.
constexpr float kTurnPushFactor = 3.0f;
// The fraction of a deep row's push impulse at the end of a step that the
// next step's push starts from (within a step each substep starts from all of
// the last one's). Started from zero in every substep, the sweeps found a
// different, unconverged answer each time for a pile's rows, which push
// across each other in every direction: bodies wedged between two others
// were pushed left in one step and right in the next, and 50 boxes created at
// one point 1 m up spread 40 m along the ground but were still 0.6 to 0.8 m
// deep after 5 s, apart only at 8.9 to 10.3 s. The push warm-started as the
// velocity rows are keeps one answer from step to step. Over the pile
// batteries (docs/validation.md, "Pushes that remember"), half of the last
// step's impulse broke fewer bounds than none, a quarter, three quarters or
// all of it: with all of it, piles landing from 10 m threw more bodies faster
// than their fall allows (44 layouts against 31 with none, 20 with half).
constexpr float kPushCarry = 0.5f;
// A pushed body shoves (shoveTouching) along the normal only across rows
// within 15° of level, |n·ĝ| ≤ sin 15°: along a steeper normal a shove lifts
// the shoved body or drives it down into what is below. Of the outside
// probe's 3,500 piles (without the stall rule below), with shoves along the
// normals of rows within 45° of level, 240 rose beyond 1.02 times their
// energy (216 without shoves; 195 at 15°), and 7 were still deeper than
// 10 cm after 20 s, three with boxes sunk into the ground (5 without shoves,
// none deeper than 0.33 m; 2 at 15°). docs/validation.md, "Shoves between
// moving bodies".
constexpr float kShoveLevel = 0.25881904f;
// Across a steeper row, up to 60° from level (|n·ĝ| ≤ sin 60°), a pushed body
// shoves along the row's level part alone: the two centres may not close
// across gravity, and nothing is lifted. Without it, a body the push slid out
// of one neighbour was driven into another leaning on it, whose overlap the
// push drove back out the next step: capsules of a pile created at one point
// on the ground, fallen against each other like dominoes, were slid 5 cm back
// and forth every step for a second, 4 to 15 cm deep. With it, of the outside
// probe's 3,500 piles 322 instead of 492 are deeper than 2 cm at 2 s
// (docs/validation.md, "Shoves across leaning rows"). Such a shove is
// measured and applied along the same level direction (the centres'
// pseudo-velocities along it), so that the shoves' sweeps solve a symmetric
// system: measured at the contact points along the normal and applied along
// the level, the sweeps grew the impulses without bound in piles whose shoves
// formed loops, until the pushed bodies' pseudo-velocities were dropped as
// non-finite (dropNonFinitePush) and 35 of the probe's piles stayed frozen,
// up to 1.44 m deep for 20 s.
// Steeper still (a body resting on another) it does not shove: a level shove
// there would carry the upper body along with the lower.
constexpr float kShoveSteepest = 0.8660254f;
// A deep row whose two bodies' centres moved less than this (m) relative to
// each other over the last step has stalled: neither body shoves or is
// shoved in this step. Shoves can hold a pile still, every body's push
// balanced by the shoves of the bodies around it: 59 boxes of mixed
// densities created at one point in the air (the probe's air piles, seed
// 51; shoves across rows within 45° of level and the lift limit held
// within the sweeps) landed and stayed 1.15 m deep for 20 s with 32 of them
// sunk into the ground. With this, of the probe's piles one is deeper than
// 10 cm after 20 s (0.26 m), against 2 without it (up to 0.46 m) and 5 (up to
// 0.33 m) without shoves; 50 unit boxes created at one point on the ground
// part later, after 2.00 to 2.42 s instead of 1.90 to 2.13 s (seeds 1 to 20).
// At 0.3 mm they part after 1.92 to 2.12 s, but the probe's air pile of seed
// 25 stays 0.58 m deep (0.46 m without the rule).
// A level deep row (within kShoveLevel, as the shoves) does not stall: its
// bodies lie side by side, and without their shoves the push drove them into
// their neighbours, whose soft rows pushed them back; in a row of 50 boxes
// spread on the ground one pair stayed 2.5 cm deep for 0.6 s, and 2 of 20
// such piles missed the issue's 2 s (docs/validation.md, "The sideways limit
// again": all 20 part after 1.22 to 1.47 s now).
constexpr float kStallMove = 0.001f;

/// Calls f(row, sidePush) for each deep row in row order, sidePush the row's
/// SidePush or null when it is pushed along its normal.
template <class F>
void forEachDeepRow(SolverArrays& s, F&& f) {
    std::size_t nextSide = 0;
    for (int r : s.deepRows) {
        const bool sideways = nextSide < s.sidePushes.size() && s.sidePushes[nextSide].row == r;
        f(s.constraints[static_cast<std::size_t>(r)], sideways ? &s.sidePushes[nextSide++] : nullptr);
    }
}

/// A sideways push's impulse P (along its axis) on the two bodies' pseudo-velocities.
void applySidePush(SolverArrays& s, const ContactConstraint& cc, const SidePush& sp, Vec2 P) {
    Vec2& vA = s.biasV[static_cast<std::size_t>(cc.a)];
    Vec2& vB = s.biasV[static_cast<std::size_t>(cc.b)];
    vA = mulSub(vA, sp.invMassA, P);
    vB = mulAdd(vB, sp.invMassB, P);
}

/// A point's push impulse P (along the normal) on the two bodies' pseudo-velocities.
void applyPointPush(SolverArrays& s, const ContactConstraint& cc, const ContactPointConstraint& cp, Vec2 P) {
    Vec2& vA = s.biasV[static_cast<std::size_t>(cc.a)];
    Vec2& vB = s.biasV[static_cast<std::size_t>(cc.b)];
    vA = mulSub(vA, cc.invMassA, P);
    s.biasW[static_cast<std::size_t>(cc.a)] -= cc.invIA * cross(cp.rA, P);
    vB = mulAdd(vB, cc.invMassB, P);
    s.biasW[static_cast<std::size_t>(cc.b)] += cc.invIB * cross(cp.rB, P);
}

/// How fast the two bodies' pseudo-velocities separate point cp of row cc
/// along its normal (negative: closing).
float pushSpeed(const SolverArrays& s, const ContactConstraint& cc, const ContactPointConstraint& cp) {
    const std::size_t a = static_cast<std::size_t>(cc.a), b = static_cast<std::size_t>(cc.b);
    return dot((s.biasV[b] + cross(s.biasW[b], cp.rB)) - (s.biasV[a] + cross(s.biasW[a], cp.rA)), cc.normal);
}

/// A point of a contact created overlapping (Contact::overlapFromStart) asks
/// for this many times the push of pointPushTarget below the cap: the same
/// rest (a load it carries is still held where its soft row would hold it),
/// approached twice as fast. The soft rows' rate, heavily damped so that
/// stacks stand, took an overlap's last centimetres slowly: two unit boxes
/// created half inside each other without gravity, the overlap beyond the
/// slop shrank by 13 % a step (now 23 %), and 20 capsules created at one
/// point on the ground were still 2.4 cm deep at 2 s (now 0.9 cm;
/// docs/validation.md, "A created overlap's last centimetres"). Not for a
/// contact that sank under a load: pushed out faster, a ragdoll with a
/// torso 50 times as dense as its limbs
/// (JointTree.RagdollsWithAHeavyTorsoComeToRestOnTheGround) did not come to
/// rest.
constexpr float kStartOverlapPushFactor = 2.0f;

/// The separating pseudo-speed a deep point asks for: its current separation
/// (as the velocity rows read it) times the bias rate, beyond what its load
/// explains (times kStartOverlapPushFactor for a contact created
/// overlapping), up to the cap (none once it is closed).
float pointPushTarget(const ContactConstraint& cc, const ContactPointConstraint& cp, Vec2 dp, Rot qA, Rot qB,
                      float cap) {
    const float sep = currentSeparation(cp, cc.normal, dp, qA, qB);
    const float factor = cc.overlapFromStart ? kStartOverlapPushFactor : 1.0f;
    return std::max(std::min(factor * (-cc.biasRate * sep - loadPush(cc, cp)), cap), 0.0f);
}

/// Whether bodies a and b also touch through a contact other than c (bodies
/// of several shapes).
bool touchElsewhere(const WorldState& w, int c, int a, int b) {
    for (const int k : w.bodies[a].contacts) {
        if (k == c) continue;
        const Contact& o = w.contacts[k];
        if (o.touching && ((o.bodyA == a && o.bodyB == b) || (o.bodyA == b && o.bodyB == a))) return true;
    }
    return false;
}

/// The push of a manifold's two points solved together, sweep after sweep:
/// the exact solution of their 2×2 linear complementarity problem (each
/// accumulated push impulse ≥ 0, each point reaching its target
/// pseudo-speed or left at zero opening faster), found by trying which
/// points push: the direct enumeration of Box2D 2.4.1's block solve of its
/// velocity rows (Catto, 2009, b2ContactSolver, after Murty), which the
/// velocity rows here take too (contact_solver.cpp, where the same order
/// effect tilted columns). One point after the other, the first point's push
/// turned the bodies before the second was solved, and the sweeps, which
/// stop before the push has travelled along a chain of bodies, left that
/// turn in them, always the same way: twenty unit boxes created in a row,
/// each half inside the next, were turned up to 0.063 rad in the first step
/// and ended leaning on each other, 2.8 % over their energy. False (nothing
/// done) where the two rows are nearly parallel (kLeastBlockDeterminant) or
/// no case holds (a NaN): the points are then solved one after the other.
bool pushPointPair(SolverArrays& s, ContactConstraint& cc, const PairMatrix& k, Vec2 dp, Rot qA, Rot qB, float cap) {
    ContactPointConstraint& c1 = cc.points[0];
    ContactPointConstraint& c2 = cc.points[1];
    const float det = k.k11 * k.k22 - k.k12 * k.k12;
    if (!(k.k11 > 0.0f && k.k22 > 0.0f && det > kLeastBlockDeterminant * k.k11 * k.k22)) return false;
    // b: how far each point's pseudo-speed, without any push of this row,
    // falls short of its target. w = K·x + b ≥ 0, x ≥ 0, x·w = 0.
    auto shortfall = [&](const ContactPointConstraint& cp) {
        return pushSpeed(s, cc, cp) - pointPushTarget(cc, cp, dp, qA, qB, cap);
    };
    const float a1 = c1.biasImpulse, a2 = c2.biasImpulse;
    const float b1 = shortfall(c1) - (k.k11 * a1 + k.k12 * a2);
    const float b2 = shortfall(c2) - (k.k12 * a1 + k.k22 * a2);
    float x1 = (k.k12 * b2 - k.k22 * b1) / det, x2 = (k.k12 * b1 - k.k11 * b2) / det;  // both push
    if (!(x1 >= 0.0f && x2 >= 0.0f)) {
        x1 = -b1 / k.k11, x2 = 0.0f;  // the first alone
        if (!(x1 >= 0.0f && k.k12 * x1 + b2 >= 0.0f)) {
            x1 = 0.0f, x2 = -b2 / k.k22;  // the second alone
            if (!(x2 >= 0.0f && k.k12 * x2 + b1 >= 0.0f)) {
                if (!(b1 >= 0.0f && b2 >= 0.0f)) return false;
                x1 = x2 = 0.0f;  // neither
            }
        }
    }
    c1.biasImpulse = x1;
    c2.biasImpulse = x2;
    applyPointPush(s, cc, c1, (x1 - a1) * cc.normal);
    applyPointPush(s, cc, c2, (x2 - a2) * cc.normal);
    return true;
}

/// One sweep of the guards (SolverArrays::pushGuards): each shallow row
/// between a pushed body and something that does not move and holds it up
/// (the row's normal points up at the body, against its own gravity) takes
/// an impulse that keeps its points from closing on the pseudo-velocities
/// (non-negative for one point; two points below). A push turning a box resting on the ground about its
/// centre drove one corner of its base into the ground, and the soft row
/// there then lifted the box out through the velocities, a lift the push
/// itself is never allowed (it may not raise a body above the highest it has
/// been): boxes of a pile created at one point on the ground were left
/// propped on each other's corners, up to 5 cm high. With the pairs solved
/// together but unguarded, 20 such piles (seeds 40001 to 40020) rose to up
/// to 1.027 times their energy; guarded, 1.006. A row's two points are
/// solved side by side, from the same pseudo-velocities, scaled by
/// pairScale where they close together, so that a body pressed evenly onto
/// the ground is held evenly: solved one after the other, a light box
/// crushed under a column of boxes 1,000 times its mass
/// (RestLoad.ALightBoxBuiltUnderFarHeavierOnesIsNotPushedUp) was turned and
/// squeezed out 1.9 mm sideways; side by side, not at all. Walls and
/// ceilings are not guards: guarded too, 625 weightless circles jammed in a
/// box of four static capsules (Confined, docs/validation.md) jiggled with
/// 0.17 to 0.35 J from 5 to 20 s instead of 0.05 to 0.13 J.
///
/// A guard of two points (a body resting flat on its support) holds them
/// both ways: the push neither drives them in nor opens them, so it may
/// slide such a body along its support but not tilt or lift it off. Held
/// one way, a push turning the body about its centre drove one corner down,
/// the guard held that corner, and the body turned about it instead, its
/// centre rising: 50 unit boxes created at one point on the ground, pushed
/// by the converged sweeps (kMaxPushSweeps), stood tilted up to 0.26 rad on
/// corners, and 19 of 20 such piles rose beyond 1.02 times their energy (up
/// to 1.052) while nearly still; held both ways, at most 1.0045.
void guardAgainstImmovable(SolverArrays& s) {
    for (std::size_t g = 0; g < s.pushGuards.size(); ++g) {
        ContactConstraint& cc = s.constraints[static_cast<std::size_t>(s.pushGuards[g])];
        const float scale = s.pushGuardScales[g];
        float impulse[2] = {0.0f, 0.0f}, speed[2] = {0.0f, 0.0f};
        for (int j = 0; j < cc.pointCount; ++j) speed[j] = pushSpeed(s, cc, cc.points[j]);  // both before either acts
        for (int j = 0; j < cc.pointCount; ++j) {
            const ContactPointConstraint& cp = cc.points[j];
            float& accumulated = s.pushGuardImpulses[2 * g + static_cast<std::size_t>(j)];
            const float held = accumulated - scale * cp.normalMass * speed[j];
            const float next = cc.pointCount == 2 ? held : std::max(held, 0.0f);  // two points: both ways
            impulse[j] = next - accumulated;
            accumulated = next;
        }
        for (int j = 0; j < cc.pointCount; ++j) applyPointPush(s, cc, cc.points[j], impulse[j] * cc.normal);
    }
}

/// One sweep of the shoves (SolverArrays::pushShoves): each shallow row
/// between two moving bodies, one of them pushed, takes an impulse along its
/// normal (a row steeper than kShoveLevel: along its level part,
/// kShoveSteepest) through the two centres (on their translation alone) that
/// keeps it from closing on the pseudo-velocities, so a pushed body shoves the body
/// beside it along instead of driving into it. Driven in, the new overlap was
/// the soft rows' to part, through the velocities: 50 unit boxes created at
/// one point on the ground spread into one layer and then took most of a
/// second more to push out the last overlaps between boxes side by side,
/// parting after 2.60 to 2.92 s (seeds 1 to 20; now 2.00 to 2.42 s), and a
/// row of 80 boxes created half overlapping without friction was still 3.3 cm
/// deep at 2 s, at 1.022 times its energy (now 0.2 cm, 1.018). Through the
/// contact points instead, the shoves turned the bodies they pushed off
/// centre: capsules lying on the ground were stood on end, and of the outside
/// probe's 3,500 piles 420 rose beyond 1.02 times their energy instead of 216
/// (up to 1.27 times; now 194). A body touching something immovable that
/// does not hold it up (a wall, a ceiling, a kinematic drum's side) neither
/// shoves nor is shoved: shoved into the side of a chain drum turning at
/// 20 rad/s, thin boxes were pushed through it
/// (KeptManifolds.AFasterChainDrumKeepsTheThinBodiesItPressesIntoItsSides).
/// Only under gravity: between 625 weightless circles jammed in a box
/// (Confined, docs/validation.md) shoves left 0.09 to 0.23 J of jiggle from 5
/// to 20 s and a circle at 2.2 m/s, against 0.066 to 0.11 J and 0.71 m/s
/// without.
void shoveTouching(SolverArrays& s) {
    for (std::size_t k = 0; k < s.pushShoves.size(); ++k) {
        const ContactConstraint& cc = s.constraints[static_cast<std::size_t>(s.pushShoves[k])];
        Vec2& vA = s.biasV[static_cast<std::size_t>(cc.a)];
        Vec2& vB = s.biasV[static_cast<std::size_t>(cc.b)];
        // A level row: its points' closing along the normal. A steeper one
        // (kShoveSteepest): the centres' closing along its level direction.
        const Vec2 axis = s.pushShoveAxes[k];
        const bool level = axis.x == 0.0f && axis.y == 0.0f;
        const float closing = !level ? dot(vB - vA, axis)
                              : cc.pointCount == 2
                                  ? std::min(pushSpeed(s, cc, cc.points[0]), pushSpeed(s, cc, cc.points[1]))
                                  : pushSpeed(s, cc, cc.points[0]);
        float& accumulated = s.pushShoveImpulses[k];
        const float next = std::max(accumulated - closing / (cc.invMassA + cc.invMassB), 0.0f);
        const Vec2 P = (next - accumulated) * (level ? cc.normal : axis);
        accumulated = next;
        vA = mulSub(vA, cc.invMassA, P);
        vB = mulAdd(vB, cc.invMassB, P);
    }
}

}  // namespace

void prepareDeepOverlaps(WorldState& w) {
    SolverArrays& s = w.solver;
    s.sidePushes.clear();
    const Vec2 g = w.settings.gravity;
    const float gl = length(g);
    // The bodies a deep row pushes out of something that does not move (a
    // body created inside the ground) may be lifted above the highest they
    // have been, but only as far as that row's depth along up: what clears
    // them (pushDeepOverlaps).
    s.pushOffFixedLift.assign(s.states.size(), 0.0f);
    const Vec2 down = gl > 0.0f ? (1.0f / gl) * g : Vec2{};
    for (int r : s.deepRows) {
        const ContactConstraint& cc = s.constraints[static_cast<std::size_t>(r)];
        if ((cc.invMassA == 0.0f) == (cc.invMassB == 0.0f)) continue;
        const std::size_t moving = static_cast<std::size_t>(cc.invMassA == 0.0f ? cc.b : cc.a);
        const float depth = -deepestSeparation(w.contacts[cc.contact].manifold);
        const float lift = gl > 0.0f ? depth * std::abs(dot(cc.normal, down)) : depth;
        s.pushOffFixedLift[moving] = std::max(s.pushOffFixedLift[moving], lift);
    }
    // The guards: the shallow rows of the bodies a deep row pushes (those
    // with a deep contact, SolverArrays::deepContactCount) against something
    // immovable that holds them up (guardAgainstImmovable).
    s.pushGuards.clear();
    s.pushGuardScales.clear();
    s.pushShoves.clear();
    s.pushWalled.assign(s.states.size(), 0);
    for (std::size_t r = 0; r < s.constraints.size(); ++r) {
        const ContactConstraint& cc = s.constraints[r];
        const bool fixedA = cc.invMassA == 0.0f, fixedB = cc.invMassB == 0.0f;
        if (fixedA == fixedB) continue;
        const int moving = fixedA ? cc.b : cc.a;
        // Only what holds the body up: its normal points up at the body,
        // against the body's own gravity.
        const float upAtMoving = (fixedA ? -1.0f : 1.0f) * dot(cc.normal, g);
        if (!(upAtMoving > 0.0f) || !(w.bodies[s.stateBodies[static_cast<std::size_t>(moving)]].gravityScale > 0.0f)) {
            s.pushWalled[static_cast<std::size_t>(moving)] = 1;
            continue;
        }
        if (cc.deepOverlap || s.deepContactCount[static_cast<std::size_t>(moving)] == 0) continue;
        s.pushGuards.push_back(static_cast<int>(r));
        s.pushGuardScales.push_back(cc.pointCount == 2 ? pairScale(cc) : 1.0f);
    }
    if (gl == 0.0f) {
        s.supported.assign(s.states.size(), 0);  // pushDeepOverlaps reads it
        return;
    }
    const Vec2 up = (-1.0f / gl) * g;
    // Supported: resting, through a chain of rows whose normals point up at
    // the body above, on something that does not move (the zero state, a
    // static or kinematic body). The lists of what rests on each state are
    // built by counting.
    const std::size_t stateCount = s.states.size();
    std::vector<std::uint8_t>& supported = s.supported;
    std::vector<int>& start = s.supportStart;
    std::vector<int>& above = s.supportAbove;
    std::vector<int>& queue = s.supportQueue;
    supported.assign(stateCount, 0);
    start.assign(stateCount + 1, 0);
    queue.clear();
    for (std::size_t i = 0; i < s.stateBodies.size(); ++i)
        if (w.bodies[s.stateBodies[i]].invMass == 0.0f) queue.push_back(static_cast<int>(i));
    queue.push_back(static_cast<int>(stateCount) - 1);
    for (int q : queue) supported[static_cast<std::size_t>(q)] = 1;
    auto below = [&](const ContactConstraint& cc, float nu) {
        return static_cast<std::size_t>(nu > 0.0f ? cc.a : cc.b);
    };
    for (const ContactConstraint& cc : s.constraints) {
        const float nu = dot(cc.normal, up);
        if (nu != 0.0f) ++start[below(cc, nu)];
    }
    for (std::size_t i = 1; i <= stateCount; ++i) start[i] += start[i - 1];
    above.resize(static_cast<std::size_t>(start[stateCount]));
    for (const ContactConstraint& cc : s.constraints) {
        const float nu = dot(cc.normal, up);
        if (nu != 0.0f) above[static_cast<std::size_t>(--start[below(cc, nu)])] = nu > 0.0f ? cc.b : cc.a;
    }
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::size_t i = static_cast<std::size_t>(queue[q]);
        for (int k = start[i]; k < start[i + 1]; ++k) {
            const int j = above[static_cast<std::size_t>(k)];
            if (supported[static_cast<std::size_t>(j)]) continue;
            supported[static_cast<std::size_t>(j)] = 1;
            queue.push_back(j);
        }
    }
    // A deep row between two moving bodies is pushed sideways when (1) the
    // lower body is supported, so pushing along the normal would lift the
    // upper one by the whole depth; (2) that lift would take the upper body's
    // centre above the highest it has been (Body::highest): a push may give a
    // body back height it had, never new height; (3) neither body moves further
    // than its own width: the row moves the two apart in inverse proportion to
    // their masses, so the bodies' shares of the clearing distance are
    // clear·m⁻¹/(m_A⁻¹ + m_B⁻¹), or, where that moves one beyond its width,
    // split otherwise (below): a box deep in a long plank slides out by its
    // width while the plank gives way by the rest (a box 0.2 m deep in the
    // middle of a 6 m plank: the plank moves 1.9 m); two like bodies, one
    // deep in the other, slide apart however deep. Held to the narrower width of the pair
    // instead (the upper body moving it all), a body created almost wholly
    // inside another was lifted out of it, up to its whole height: of 8 boxes
    // created on the ground (seed 113) one rose 0.67 m above where it was
    // created; over 40 layouts each, up to 0.84 m of 8 boxes and 1.05 m of
    // 20, and a pile's energy up to 1.33 times the start plus the lift out of
    // the ground.
    const Vec2 side = leftPerp(up);
    for (int r : s.deepRows) {  // ascending: sidePushes stay in row order
        const ContactConstraint& cc = s.constraints[static_cast<std::size_t>(r)];
        if (cc.invMassA == 0.0f || cc.invMassB == 0.0f) continue;
        const float nu = dot(cc.normal, up);
        if (nu == 0.0f || !supported[below(cc, nu)]) continue;
        const Contact& ct = w.contacts[cc.contact];
        const Body& bA = w.bodies[ct.bodyA];
        const Body& bB = w.bodies[ct.bodyB];
        const Body& upper = nu > 0.0f ? bB : bA;
        // Lifted, a body that gravity does not pull down (gravity scale 0 or
        // below) gains no potential energy: it is pushed the shorter way,
        // along the normal. Slid aside by the world's gravity instead, 625
        // weightless circles jammed in a box (Confined) were pushed sideways
        // from every row resting on the bottom wall and crowded into one
        // another: circles up to 0.99 m into each other and 10 to 25 J of
        // jiggle after 10 s, against up to 0.89 m and 2.6 to 5.9 J pushed
        // along the normals (docs/validation.md, "Hard cases not yet met").
        if (upper.gravityScale <= 0.0f) continue;
        const float depth = -deepestSeparation(ct.manifold);
        if (dot(upper.center, up) + depth * std::abs(nu) <= upper.highest) continue;
        const Shape& shA = w.shapes[ct.shapeA];
        const Shape& shB = w.shapes[ct.shapeB];
        const float hiA = shapeSupport(shA, bA.xf, side), loA = -shapeSupport(shA, bA.xf, -side);
        const float hiB = shapeSupport(shB, bB.xf, side), loB = -shapeSupport(shB, bB.xf, -side);
        const float toSide = hiA - loB, toOtherSide = hiB - loA;  // how far B must move along ±side to clear A
        const float clear = std::min(toSide, toOtherSide);
        const float widthA = hiA - loA, widthB = hiB - loB;
        const float shareB = cc.invMassB / (cc.invMassA + cc.invMassB);
        float invMassA = cc.invMassA, invMassB = cc.invMassB;
        if (shareB * clear > widthB || (1.0f - shareB) * clear > widthA) {
            // Split by the masses, one body would move beyond its own width:
            // it moves its width and the other the rest, within its own
            // width. A 1 m box created inside a 2 m box on the ground was
            // lifted out, the big box ending on the small one (rise 1 m,
            // energy 1.7 times the start); it now slides out while the big
            // one gives way. The rest was also held to the lift it would
            // replace (depth·|n·up|), and beyond that the pair was pushed
            // along its normal. But this row is pushed sideways only where
            // that lift would take the upper body above the highest it has
            // been, which no push may do: what lifted such a pair was the
            // ground's soft row, into which the push drove the lower body,
            // and since the push may not (guardAgainstImmovable) such a pair
            // stalled. A box of 0.25 m on the ground under a 0.9 m box
            // created 0.11 and 0.2 m deep in it was still 4.3 and 7.6 cm deep
            // at 2 s, the big box pushed up 0.11 and 0.20 m by the soft rows
            // (1.18 and 1.39 times the energy); now the small box slides out
            // within a second
            // (OverlapPiles.ASmallBoxUnderABigOneSlidesOutFromUnderIt), and a
            // box created deep in a long plank, which never parted either,
            // slides out while the plank gives way
            // (OverlapPiles.ABoxInsideALongPlankOnTheGroundParts).
            // Split so, the row moves the pair's centre of mass, which it may
            // do only where it is the pair's one contact: two L-shaped bodies
            // created overlapping touch through several, whose pushes can
            // oppose, and a re-split row held by another row of the pair
            // drove both along the ground at twice the cap without parting
            // them (0.37 m deep for 9 s, 6 m/s); they are lifted apart instead.
            if (clear > widthA + widthB || touchElsewhere(w, cc.contact, ct.bodyA, ct.bodyB)) continue;
            const float movedB = std::clamp(shareB * clear, clear - widthA, widthB);
            const float sum = cc.invMassA + cc.invMassB;
            invMassB = sum * (movedB / clear);
            invMassA = sum - invMassB;
        }
        const Vec2 axis = toSide <= toOtherSide ? side : -side;
        s.sidePushes.push_back({r, axis, clear, invMassA, invMassB});
        // The pair does not slide back into each other along the push's axis
        // while it is pushed apart along it: their relative velocity against
        // the push is taken out, an exchange of momentum between the two
        // along the axis (as a rigid row would make; the kinetic energy can
        // only fall). Left in, it cancelled the push: on a frictionless
        // ground, where nothing else takes it out, a circle deep in a flat
        // box slid one way at the velocities' 2.3 m/s while the push moved
        // it back at as much, the pair drifting along together 0.25 m deep
        // for 18 s (docs/validation.md, "Shoves across leaning rows").
        Vec2& vA = s.states[static_cast<std::size_t>(cc.a)].v;
        Vec2& vB = s.states[static_cast<std::size_t>(cc.b)].v;
        const float against = dot(vB - vA, axis);
        if (against < 0.0f) {
            const Vec2 P = (-against / (cc.invMassA + cc.invMassB)) * axis;
            vA = mulSub(vA, cc.invMassA, P);
            vB = mulAdd(vB, cc.invMassB, P);
        }
    }
    // Each row's push starts from kPushCarry of where the last step's ended,
    // if it was pushed the same way (sideways or along its normal).
    // pushCarry gets this step's rows, in deepRows' order, for
    // pushDeepOverlaps to fill in; the last step's, sorted, are looked up.
    std::vector<PushCarry>& last = s.pushCarryLast;
    std::swap(s.pushCarry, last);
    if (s.pushCarryStamp + 1 != w.stepStamp) last.clear();
    auto byContact = [](const PushCarry& a, const PushCarry& b) { return a.contact < b.contact; };
    std::sort(last.begin(), last.end(), byContact);
    s.pushCarry.clear();
    s.pushStalled.assign(s.states.size(), 0);
    // Steeper than kShoveLevel: the rows that shove along their level part
    // alone (kShoveSteepest), and the deep rows that may stall.
    auto steep = [&](const ContactConstraint& cc) { return std::abs(dot(cc.normal, g)) > kShoveLevel * gl; };
    forEachDeepRow(s, [&](ContactConstraint& cc, const SidePush* sp) {
        const Contact& ct = w.contacts[cc.contact];
        const Vec2 apart = w.bodies[ct.bodyB].center - w.bodies[ct.bodyA].center;
        s.pushCarry.push_back({cc.contact, ct.shapeA, ct.shapeB, sp != nullptr, {0.0f, 0.0f}, apart});
        const PushCarry& key = s.pushCarry.back();
        const auto it = std::lower_bound(last.begin(), last.end(), key, byContact);
        if (it == last.end() || it->contact != key.contact || it->shapeA != key.shapeA || it->shapeB != key.shapeB)
            return;
        if (length(apart - it->apart) < kStallMove && steep(cc)) {
            s.pushStalled[static_cast<std::size_t>(cc.a)] = 1;
            s.pushStalled[static_cast<std::size_t>(cc.b)] = 1;
        }
        if (it->sideways != key.sideways) return;
        for (int j = 0; j < cc.pointCount; ++j) cc.points[j].biasImpulse = kPushCarry * it->impulse[j];
    });
    // The shoves: the shallow rows within kShoveSteepest of level between two
    // moving bodies under gravity, one with a deep contact, neither touching
    // a wall (SolverArrays::pushWalled) nor in a stalled deep row
    // (kStallMove) (shoveTouching); a row steeper than kShoveLevel with its
    // level direction.
    s.pushShoveAxes.clear();
    for (std::size_t r = 0; r < s.constraints.size(); ++r) {
        const ContactConstraint& cc = s.constraints[r];
        if (cc.deepOverlap || cc.invMassA == 0.0f || cc.invMassB == 0.0f) continue;
        const std::size_t a = static_cast<std::size_t>(cc.a), b = static_cast<std::size_t>(cc.b);
        if ((s.deepContactCount[a] == 0 && s.deepContactCount[b] == 0) || s.pushWalled[a] || s.pushWalled[b]) continue;
        if (s.pushStalled[a] || s.pushStalled[b]) continue;
        if (!(w.bodies[s.stateBodies[a]].gravityScale > 0.0f) || !(w.bodies[s.stateBodies[b]].gravityScale > 0.0f))
            continue;
        const float across = dot(cc.normal, g);
        if (std::abs(across) > kShoveSteepest * gl) continue;
        Vec2 axis{};
        if (steep(cc)) {
            const Vec2 levelPart = mulSub(cc.normal, across / (gl * gl), g);  // n less its part along g
            axis = (1.0f / length(levelPart)) * levelPart;
        }
        s.pushShoves.push_back(static_cast<int>(r));
        s.pushShoveAxes.push_back(axis);
    }
}

void pushDeepOverlaps(WorldState& w, float h) {
    SolverArrays& s = w.solver;
    const float cap = w.settings.maxPushSpeed;
    const float sidewaysCap = kSidewaysPushFactor * cap;
    const float turnCap = kTurnPushFactor * cap;
    s.biasV.assign(s.states.size(), Vec2{});
    s.biasW.assign(s.states.size(), 0.0f);
    const BodyState* states = s.states.data();
    // The warm start: each row's impulse so far (from the last substep, or
    // carried from the last step by prepareDeepOverlaps) applied first.
    forEachDeepRow(s, [&](const ContactConstraint& cc, const SidePush* sp) {
        if (sp) {
            applySidePush(s, cc, *sp, cc.points[0].biasImpulse * sp->axis);
            return;
        }
        for (int j = 0; j < cc.pointCount; ++j)
            applyPointPush(s, cc, cc.points[j], cc.points[j].biasImpulse * cc.normal);
    });
    s.pushGuardImpulses.assign(2 * s.pushGuards.size(), 0.0f);
    s.pushShoveImpulses.assign(s.pushShoves.size(), 0.0f);
    // Each deep row's pair matrix, for its pair solve (pushPointPair), once
    // for the substep's 16 sweeps.
    std::vector<float>& pairs = s.pushPairs;
    pairs.clear();
    forEachDeepRow(s, [&](const ContactConstraint& cc, const SidePush*) {
        const PairMatrix k = cc.pointCount == 2 ? pairMatrix(cc) : PairMatrix{0.0f, 0.0f, 0.0f};
        pairs.insert(pairs.end(), {k.k11, k.k22, k.k12});
    });
    // The largest change a sweep made to a row's own separating pseudo-speed
    // (its impulse's change times the row's inverse mass).
    float sweepChange = 0.0f;
    for (int sweep = 0; sweep < kMaxPushSweeps; ++sweep) {
        if (sweep >= kPushSweeps && !(sweepChange > kPushConverged * cap)) break;
        sweepChange = 0.0f;
        guardAgainstImmovable(s);
        shoveTouching(s);
        std::size_t d = 0;                                                  // the row's place in deepRows
        forEachDeepRow(s, [&](ContactConstraint& cc, const SidePush* sp) {  // ascending, as the rows
            const float* pair = &pairs[3 * d++];
            if (sp) {
                // Pushed sideways (prepareDeepOverlaps): one row through the
                // centres, on the two bodies' translation, until B has moved
                // the clearing distance along the axis.
                const Vec2 vA = s.biasV[static_cast<std::size_t>(cc.a)];
                const Vec2 vB = s.biasV[static_cast<std::size_t>(cc.b)];
                const float sep = dot(states[cc.b].dp - states[cc.a].dp, sp->axis) - sp->depth;
                const float target = std::max(std::min(-cc.biasRate * sep, cap), 0.0f);
                const float mass = 1.0f / (sp->invMassA + sp->invMassB);
                ContactPointConstraint& cp = cc.points[0];
                const float accumulated = std::max(cp.biasImpulse - mass * (dot(vB - vA, sp->axis) - target), 0.0f);
                const Vec2 P = (accumulated - cp.biasImpulse) * sp->axis;
                sweepChange = std::max(sweepChange, std::abs(accumulated - cp.biasImpulse) / mass);
                cp.biasImpulse = accumulated;
                applySidePush(s, cc, *sp, P);
                return;
            }
            const BodyState& sA = states[cc.a];
            const BodyState& sB = states[cc.b];
            const Rot qA = cc.roundA ? Rot{} : sA.dq, qB = cc.roundB ? Rot{} : sB.dq;
            const Vec2 n = cc.normal;
            const Vec2 dp = sB.dp - sA.dp;
            if (cc.pointCount == 2) {
                const float b1 = cc.points[0].biasImpulse, b2 = cc.points[1].biasImpulse;
                if (pushPointPair(s, cc, {pair[0], pair[1], pair[2]}, dp, qA, qB, cap)) {
                    sweepChange = std::max(sweepChange, std::max(std::abs(cc.points[0].biasImpulse - b1) * pair[0],
                                                                 std::abs(cc.points[1].biasImpulse - b2) * pair[1]));
                    return;
                }
            }
            for (int j = 0; j < cc.pointCount; ++j) {
                ContactPointConstraint& cp = cc.points[j];
                const float target = pointPushTarget(cc, cp, dp, qA, qB, cap);
                // Projected Gauss-Seidel on the accumulated push impulse (≥ 0).
                const float accumulated = std::max(cp.biasImpulse - cp.normalMass * (pushSpeed(s, cc, cp) - target),
                                                   0.0f);
                const float impulse = accumulated - cp.biasImpulse;
                sweepChange = std::max(sweepChange, std::abs(impulse) / cp.normalMass);
                cp.biasImpulse = accumulated;
                applyPointPush(s, cc, cp, impulse * n);
            }
        });
    }
    // What the next step starts from (the last substep's is the one kept),
    // into the rows' entries prepareDeepOverlaps made.
    if (s.pushCarry.size() == s.deepRows.size()) {
        std::size_t d = 0;
        forEachDeepRow(s, [&](const ContactConstraint& cc, const SidePush*) {
            PushCarry& carry = s.pushCarry[d++];
            carry.impulse[0] = cc.points[0].biasImpulse;
            carry.impulse[1] = cc.pointCount > 1 ? cc.points[1].biasImpulse : 0.0f;
        });
        s.pushCarryStamp = w.stepStamp;
    }
    // Each body's pseudo-velocity: along its free acceleration (down, under
    // gravity) at most maxPushSpeed c, against it (up) at most c less its
    // speed along that acceleration, and never less than c/2; across it at
    // most kSidewaysPushFactor·c (without gravity, in any direction).
    // A body at rest may be pushed up at c (out of the ground under a stack
    // of four boxes: stack5_overlap, apart in 1.8 s; at c/2 it took 2.2 s).
    // A body of a falling pile pushed up at u while it falls at g·t gains g·u·t of
    // energy per unit mass; its speed stays within what a free fall from its
    // height allows plus c at every moment iff u ≤ c/2 (at g·t = 2u its
    // height is back where it started and it falls at 2u): at c, piles of 50
    // bodies created at one point were up to 2.9 m/s faster than that.
    //
    // A supported body pushed up while its velocity falls is held up by what
    // it rests on, and a held body does not keep falling: the push lifts it
    // by u·h (u its pseudo-velocity up) at an energy of m·g·u·h, while its
    // velocity, which the push does not see, goes on gaining g·h downwards.
    // A circle of a pile created on the ground, pushed up out of its
    // neighbours while they slid aside, was held at one height for 12 steps
    // while its velocity fell to 1.1 m/s (8 circles, seed 31): the pile's
    // energy rose 0.1 to 0.3 J per step, to 1.062 times the start plus the
    // lift out of the ground. So the lift is paid from the fall: the falling
    // speed f becomes √(max(f² − 2·g·u·h, 0)), which takes m·g·u·h of kinetic
    // energy, or all of the fall. A body that is not supported is pushed by
    // the bodies around it alone, which the push moves the other way (a pile
    // falling in the air keeps its centre of mass), so its fall is left as
    // it is: held up there as well, the pushed-up bodies of piles created at
    // one point in the air stopped falling and rose 1 to 2.6 m.
    auto limitTo = [](Vec2& x, float limit) {
        const float speed = length(x);
        if (speed > limit) x *= limit / speed;
    };
    const std::size_t n = s.stateBodies.size();
    for (std::size_t i = 0; i < n; ++i) {
        Vec2& v = s.biasV[i];
        // Its pseudo-spin: no point turns faster than turnCap (reach: the
        // farthest point from the centre of mass; kTurnPushFactor above).
        // (A body the push does not turn is not read: most of a large world.)
        if (float& turn = s.biasW[i]; turn != 0.0f) {
            const float reach = w.bodies[s.stateBodies[i]].reach;
            if (reach > 0.0f && std::abs(turn) * reach > turnCap) turn *= turnCap / (std::abs(turn) * reach);
        }
        // A body no deep row pushed (most of a large world) has nothing to
        // limit, lift or wake.
        if (v.x == 0.0f && v.y == 0.0f) continue;
        const Vec2 a = s.integration[i].linearAcceleration;
        const float g = length(a);
        Vec2 up{};
        if (g > 0.0f) {
            up = (-1.0f / g) * a;
            const float falling = std::max(-dot(s.states[i].v, up), 0.0f);
            float limit = cap - std::min(falling, 0.5f * cap);
            // No body is lifted above the highest it has been, as the
            // sideways rows above hold the supported ones, unless a row
            // pushes it out of something that does not move. Lifted so at
            // rest, with no fall to pay for it, bodies of 50 boxes created
            // at one point 3 m up were pushed from 2.7 m to 3.7 m while their
            // velocities stayed at zero, 0.45 m above the highest they had
            // been; from 1 m up the pile's potential energy climbed from 456
            // to 522 J (500 J at the start) with the kinetic energy near
            // zero. Held to their highest, the supported bodies alone: 1.037
            // times the start (bodies resting on nothing had been lifted 32 J
            // at rest as the pile landed); every body: 1.000
            // (docs/validation.md, "Variants beyond the layouts").
            // Pushed out of something that does not move, a body rises no
            // further than that row's depth along up at the step's start
            // (SolverArrays::pushOffFixedLift): without that bound, a body
            // the push had turned or driven into the ground was lifted out
            // above where it had been, step after step (of the outside
            // probe's piles, a body rose up to 2.54 m above where it was
            // created; with the bound, 1.14 m; docs/validation.md, "Shoves
            // between moving bodies").
            const Body& body = w.bodies[s.stateBodies[i]];
            const float room = std::max(body.highest - dot(body.center, up), s.pushOffFixedLift[i]) -
                               dot(s.states[i].dp, up);
            limit = std::min(limit, std::max(room, 0.0f) / h);
            const float u = dot(v, up);
            Vec2 across = v - u * up;
            limitTo(across, sidewaysCap);
            v = across + clamp(u, -cap, limit) * up;
        } else {
            limitTo(v, sidewaysCap);
        }
        const float speed = length(v);
        const float lift = dot(v, up) * h;
        const float falling = -dot(s.states[i].v, up);
        if (lift > 0.0f && falling > 0.0f && s.supported[i]) s.states[i].v += fallPaidForLift(falling, g, lift) * up;
        // Moved by the push, the body is not resting (its velocity says
        // nothing of it: a box created inside the ground slept there).
        if (speed > w.settings.linearSleepTolerance) w.bodies[s.stateBodies[i]].sleepTime = 0.0f;
    }
}

}  // namespace i2d::detail
