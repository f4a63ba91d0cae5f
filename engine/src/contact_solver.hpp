// The contact rows of the sequential-impulse solver (Tamis and Maggiore
// (2015), Constraint based physics solver, §5.3 and §7): a normal row and a
// friction row per manifold point, prepared once per step and streamed by
// every pass in the order the solver colours them (solver.cpp).
//
// Layout: ContactConstraint is one manifold (normal, material, the inverse
// masses of its two bodies, soft coefficients) with up to two points inline,
// 176 bytes (static_assert below: 72 for the manifold, 52 per point); a side that cannot move points at the zero
// BodyState kept after the awake bodies, so the passes have no branch per
// side. Rows reference bodies by solver index only: the passes read
// ContactConstraint and BodyState and nothing else.
#pragma once

#include <cstdint>
#include <vector>

#include "body.hpp"
#include "contact.hpp"

#include "impulse2d/math.hpp"
#include "slot_array.hpp"
#include "soft_constraint.hpp"

namespace i2d::detail {

struct WorldState;
struct SolverArrays;

/// Solver row data of one contact point. Rows are plain data without
/// default values: prepareContacts writes every field a pass reads.
struct ContactPointConstraint {
    Vec2 rA, rB;               ///< anchors relative to the centres of mass at step start
    float adjustedSeparation;  ///< separation − (rB − rA)·n, so s = (Δ)·n + this
    float normalMass, tangentMass;
    float normalImpulse, tangentImpulse;
    float maxNormalImpulse;
    float relativeVelocity;  ///< normal approach speed at step start (for restitution)
    float restitutionBias;   ///< Tamis and Maggiore (2015) eq. 8.2.1 target, baumgarte/split modes
    float biasImpulse;       ///< split mode: accumulated push impulse
};

struct ContactConstraint {
    int contact;
    int a, b;  ///< state indices; an immovable side uses the zero state
    Vec2 normal;
    float friction, restitution;
    float invMassA, invIA, invMassB, invIB;
    float biasRate, massScale, impulseScale;  ///< soft contact coefficients
    float maxPush;  ///< push speed cap of this contact (m/s); baumgarte and split share it among a body's deep contacts
    float tangentSpeed;         ///< friction's target relative tangent speed (m/s): 0 but on conveyors
    bool deepOverlap : 1;       ///< a point overlaps by more than kDeepOverlap (contact_solver.cpp)
    bool overlapFromStart : 1;  ///< the contact's Contact::overlapFromStart
    /// Two points solved together (contact_solver.cpp), unless the overlap is
    /// so deep that its push is at the cap (bodies being pushed apart, not
    /// resting) or their rows are nearly parallel (kLeastBlockDeterminant).
    bool pointsTogether : 1;
    /// A side whose contact point does not turn with it: a circle's closest
    /// point to anything stays under its centre however it spins.
    bool roundA : 1;
    bool roundB : 1;
    /// A turning row (contact_solver.cpp): the normal is a face of A (turnA)
    /// or of B (turnB) that turns fast within the step (kTurningRowAngle),
    /// so the row turns it with that face and measures the gap at the
    /// other body's point. Set from the contact's look (ContactLook).
    bool turnA : 1;
    bool turnB : 1;
    std::uint8_t pointCount;
    /// K12 of two points solved together where positive (pairMatrix), else 0.
    float pairCoupling;
    ContactPointConstraint points[2];  ///< the first pointCount are in use
};
static_assert(sizeof(ContactConstraint) == 176, "the layout documented above");

/// The rolling-resistance row of a contact whose shapes resist rolling
/// (kept apart: most contacts have none and their rows stay as they are). An
/// angular row on the bodies' relative turning, its impulse bounded by the
/// resistance (N·m per N) times the contact's total normal impulse.
struct RollingConstraint {
    int row;           ///< the contact's row in SolverArrays::constraints
    float resistance;  ///< coefficient × rolling radius (m)
    float mass;        ///< 1 / (1/I_A + 1/I_B)
    float impulse;     ///< accumulated (N·m·s)
};

/// The bodies of a contact's row: solver state indices (the zero state for a
/// side that does not move this step) and inverse masses.
struct RowBodies {
    int a = kNullIndex, b = kNullIndex;
    float invMassA = 0, invIA = 0, invMassB = 0, invIB = 0;
};
/// False when the contact gets no row: not touching, a sensor, or neither
/// body moves. bA and bB are the contact's bodies. Inline: the colouring and
/// the preparation read every active contact through it.
inline bool contactRowBodies(const Contact& ct, const Body& bA, const Body& bB, int zeroState, RowBodies& out) {
    if (!ct.touching || ct.isSensor || ct.manifold.pointCount == 0) return false;
    // solverIndex is set for this step's awake bodies only (static and sleeping: none).
    out.a = bA.solverIndex >= 0 ? bA.solverIndex : zeroState;
    out.b = bB.solverIndex >= 0 ? bB.solverIndex : zeroState;
    out.invMassA = out.a != zeroState ? bA.invMass : 0.0f;
    out.invIA = out.a != zeroState ? bA.invInertia : 0.0f;
    out.invMassB = out.b != zeroState ? bB.invMass : 0.0f;
    out.invIB = out.b != zeroState ? bB.invInertia : 0.0f;
    // Neither side moves (two sleeping or infinitely heavy bodies): no row.
    return out.invMassA != 0.0f || out.invIA != 0.0f || out.invMassB != 0.0f || out.invIB != 0.0f;
}

/// The push speed (m/s) at which a soft row holds its accumulated impulse
/// λ steady: its update Δλ = −m·ms·(vn + bias) − is·λ is zero at vn = 0 for
/// bias = −is·λ/(m·ms). The push that carries the load the point bears, the
/// depth biasRate⁻¹ times it being the sag that load explains.
inline float loadPush(const ContactConstraint& cc, const ContactPointConstraint& cp, float impulse) {
    const float k = cp.normalMass * cc.massScale;
    return k > 0.0f ? cc.impulseScale * impulse / k : 0.0f;
}
inline float loadPush(const ContactConstraint& cc, const ContactPointConstraint& cp) {
    return loadPush(cc, cp, cp.normalImpulse);
}

/// The point's separation now, from its bodies' motion since the step began:
/// dp their centres' relative displacement, qA and qB their rotations (the
/// identity for a round side, whose contact point does not turn with it).
/// What the velocity rows, the push of deep overlaps and the carry of their
/// loads all read.
inline float currentSeparation(const ContactPointConstraint& cp, Vec2 n, Vec2 dp, Rot qA, Rot qB) {
    const Vec2 d = dp + (rotate(qB, cp.rB) - rotate(qA, cp.rA));
    return dot(d, n) + cp.adjustedSeparation;
}

/// What the warm start of a deep row carries from substep to substep
/// (carryDeepLoads): where its impulses live this step, and the normal
/// impulses it ended the substep before the last with.
struct DeepCarry {
    int block;  ///< its wide block, −1 for a scalar row
    int lane;
    float previous[2];
};

/// Marks an active contact without a row in SolverArrays::contactColours.
inline constexpr std::uint8_t kNoRow = 0xFF;

/// What the rows of one step share (prepareContactRow).
struct RowContext {
    int zeroState;
    Softness dynamicSoft, staticSoft;
    /// 1/ω² of those rows (soft_step; 0 otherwise): the sag of a built-in
    /// load per unit of F·K (rest_load.hpp).
    float dynamicRestCompliance, staticRestCompliance;
    bool biasRestitution;  ///< the classic modes' restitution target (velocity-bias impacts)
    bool soft;             ///< soft_step
    float fullDt, warm, pushRate;
    /// soft_step with warm starting: the normal speed up to which a contact
    /// without a warm start is at rest, one step of gravity (kWideCold);
    /// negative otherwise (no row is cold).
    float restingSpeed;
    float restingDepth;  ///< ... and overlaps no deeper than this (the penetration slop)
};
RowContext makeRowContext(const WorldState& w, float h, bool soft);

/// prepareContactRow and finishContactRow, the row of one contact: contact_row.hpp.

/// Rows of every contact in WorldState::activeContacts that gets one (see
/// contactRowBodies), for substeps of length h (`soft`: soft_step), each
/// written at its place in colour order: the colouring (solver.cpp) comes first.
void prepareContacts(WorldState& w, float h, bool soft);
void warmStartContacts(WorldState& w);
/// soft_step, after each substep's soft_bias sweep, in a step with cold
/// lanes (SolverArrays::coldBlocks): more soft_bias sweeps of the blocks
/// that hold them, colour by colour, until the cold rows' normal impulses
/// settle (contact_solver.cpp).
void settleColdContacts(WorldState& w, float h);
/// soft_step, after each substep's relax sweep, in a step with deep overlaps
/// in the wide blocks (SolverArrays::deepBlocks): more `pass` sweeps of the
/// blocks that hold them until their normal impulses settle (contact_solver.cpp).
void relaxDeepContacts(WorldState& w, float h, SolvePass pass);
/// soft_step with deep rows, once the rows are prepared (and packed): each
/// deep row's DeepCarry, the impulses the step starts it with as its previous.
void beginDeepCarry(SolverArrays& s);
/// soft_step with deep rows, before the warm start of every substep but the
/// first, and before the store: each deep point being pushed apart (its
/// depth more than its load explains) keeps the smaller of its accumulated
/// normal impulse and the one it had a substep earlier, its friction within
/// μ times that (contact_solver.cpp says why). `inRows`: read and write the
/// rows, not the blocks (after writeBackWideContacts).
void carryDeepLoads(SolverArrays& s, bool inRows = false);
/// One Gauss-Seidel sweep over the contacts, with the velocity target of `pass`.
void solveContacts(WorldState& w, float h, SolvePass pass);
/// Split mode (Tamis and Maggiore (2015) §8.1): the push alone, on the pseudo-velocities.
void solveContactPush(WorldState& w, float h);
/// soft_step with the velocity-bias impact model: the restitution pass.
void applyRestitution(WorldState& w);
/// Impulses back into the contacts for the next step's warm start.
void storeContactImpulses(WorldState& w);

/// Rolling resistance rows (SolverArrays::rolling), prepared, warm-started,
/// solved and stored beside the contact rows by the functions above; a step
/// without rolling resistance does none of it.
void prepareRollingResistance(WorldState& w, int row, const ContactSurface& surface);
void warmStartRollingResistance(WorldState& w);
void solveRollingResistance(WorldState& w);
void storeRollingResistance(WorldState& w);

}  // namespace i2d::detail
