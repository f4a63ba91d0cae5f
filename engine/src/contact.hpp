// Contacts: one per pair of shapes whose fattened boxes overlap, from the
// step the broadphase finds the pair until the boxes part. A contact keeps
// the manifold of the last narrowphase update and the impulses the solver
// accumulated at each manifold point, carried to the next step by feature
// id (the warm start).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "impulse2d/collision.hpp"
#include "rest_load.hpp"
#include "slot_array.hpp"

namespace i2d::detail {

struct WorldState;
struct Shape;

/// An overlap deeper than this (m; ten times the linear slop) is not a
/// resting contact but bodies created or pushed into each other: the soft
/// step pushes such contacts apart on pseudo-velocities (deep_overlap.cpp),
/// baumgarte shares the push cap among them (contact_solver.cpp), and they
/// never keep a manifold (contact_persistence.cpp). Resting stacks overlap by
/// millimetres; the bottom of a column of 50 by 4.4 cm.
constexpr float kDeepOverlap = 0.05f;
/// A contact between shapes thinner than kDeepOverlap / kDeepFraction counts
/// as deep from this fraction of the thinner one's thickness instead
/// (Contact::deepScale, deepOverlapOf). The soft rows push an overlap out
/// along its normal, lifting the body above; the deep push slides it aside
/// where a lift would add height. Below the deep depth, then, a pile created
/// overlapping is lifted apart, and the lift, up to the deep depth per
/// layer, is a larger share of a pile's potential energy the smaller its
/// bodies: bodies 0.1 m across overlap mostly less than 5 cm, and their
/// piles on the ground gained up to 29 % of their (small) energy. From a
/// fifth of the thickness, 0.2 m bodies still did: 29 of 600 such piles
/// broke the 2 % (circles up to 11 %), and 0.3 m bodies, 11 of 600;
/// from a tenth, 2 and 0 (docs/validation.md, "Small bodies"). A contact's
/// sag under load does not grow with the bodies' size (a column of 50 boxes
/// sinks the same centimetres at any size), so the bottom of a tall column
/// of small boxes sags into the deep regime; such columns and pyramids stand
/// as before (the deep push holds them a little stiffer).
constexpr float kDeepFraction = 0.1f;
/// ... but never from less than this (m): a box resting on a plate 1 cm
/// thick sags a few tenths of a millimetre under its own weight, and 35
/// boxes stacked on it 1 cm; such sags stay soft rows.
constexpr float kMinDeepOverlap = 0.01f;
/// A deep overlap stays deep until its deepest point is within this fraction
/// of the depth at which it became deep (Contact::stillDeep): pushed apart
/// on pseudo-velocities (deep_overlap.cpp) to 1.25 cm rather than 5 cm, so
/// that the soft rows, whose push goes through the velocities, take over
/// only the last of it. Handed over at 5 cm, the soft rows' pushes added
/// along the chains of a pile created on the ground and were left in the
/// velocities where the relax pass could not take them back: piles of 20
/// bodies created at one point on the ground peaked at up to 1.12 times
/// their energy, and 20 circles rolled apart with 4 % of it added for good
/// (docs/validation.md, "Deep until well apart"). A contact sagging under a
/// load is pushed only beyond what the load explains, deep or not.
constexpr float kDeepExitFraction = 0.25f;
/// A contact whose bodies were created or moved inside each other
/// (Contact::overlapFromStart) is a deep overlap while any point of it is
/// deeper than this (m), twice the default penetration slop, whether it has
/// been deep before or not. Its overlap is then pushed apart on
/// pseudo-velocities down to here, and the soft rows push only the last of
/// it, through the velocities. The soft rows cannot hold what the push moves:
/// in a row of boxes created half inside one another on the ground, the
/// push of the middle's deep contacts squeezed the contacts of the ends,
/// already out of the deep regime, back to just under the deep depth.
/// Their soft rows then pushed all that overlap out at once through the
/// velocities, where the relax pass could not take it back. Eighty such
/// boxes 0.6 m wide without friction slid apart at up to 1.4 m/s, with 14 %
/// more energy than they started with, and forty with friction 0.6 with
/// 4.7 %; now 3.5 % and 0.7 % (with kStartOverlapPushFactor as well;
/// docs/validation.md, "Overlaps squeezed back"). At the slop itself the
/// push never ends (its target falls to zero there) and piles separate more
/// slowly.
constexpr float kStartOverlapDeep = 0.01f;
/// Contact::deepScale of a contact deep from kDeepOverlap itself.
constexpr std::uint8_t kFullDeepScale = 255;

/// Where a manifold was computed, for reusing it (contact_persistence.hpp).
struct ManifoldFrame {
    Transform relative{};   ///< B's pose in A's frame then
    Rot rotationA{};        ///< A's rotation then
    Vec2 anchorA[2]{};      ///< the manifold points in A's frame then
    float separation[2]{};  ///< their separations then (m)
};

struct Contact {
    // What every pass over the active contacts reads first (the impact
    // stage's look, the colouring, the narrowphase) lies together, next to
    // the manifold.
    int shapeA = kNullIndex, shapeB = kNullIndex;
    int bodyA = kNullIndex, bodyB = kNullIndex;
    bool alive = false;
    bool touching = false;  ///< the manifold has points (sensors: an overlap)
    bool isSensor = false;
    bool enableEvents = false;
    bool framed = false;           ///< a flat pair whose manifold has points: it may be reused
    bool enableHitEvents = false;  ///< either shape enables hit events
    /// Shape A, B is a circle, whose contact point does not turn with it
    /// (contact_solver.hpp): kept here so that preparing the rows reads no shape.
    bool roundA : 1 = false, roundB : 1 = false;
    /// The pair is flat and solid (canPersist): a manifold of it may be
    /// reused (contact_persistence.hpp). Fixed for the contact's life, as the
    /// shapes' types and sensor flags are, so the narrowphase reads no shape for it.
    bool persists : 1 = false;
    /// A seam rule may drop points of this pair's manifolds (seams.cpp,
    /// hasSeamRule): a chain segment, a two-sided segment, or a static body
    /// on one side only. A body's type change destroys its contacts, so this
    /// too is fixed for the contact's life; most pairs of a pile have none.
    bool seamRule : 1 = false;
    /// The contact's first touch overlapped deeper than deepOverlapOf, and
    /// it has not come within the penetration slop since: two bodies
    /// created (or moved) inside each other, whose manifold is an overlap's,
    /// not surfaces meeting. The impact stage passes it over
    /// (passesOverImpacts); set and cleared by the narrowphase.
    bool overlapFromStart : 1 = false;
    /// Its manifold got points in this step's narrowphase and had none
    /// before: its rows start without the load they will carry (kWideCold).
    bool touchBegan : 1 = false;
    /// Its manifold got points after a body of it was struck in this step's
    /// impact stage (refreshStruckContacts): it could close its gap only
    /// after that strike, which the stage's timing of it allows for.
    /// Cleared by the narrowphase.
    bool foundAfterStrike : 1 = false;
    /// A point of it went deeper than its deep depth and none has come
    /// within kDeepExitFraction of that depth since: it stays a deep overlap
    /// (deepOverlapOf) until then. Set and cleared by the narrowphase.
    bool stillDeep : 1 = false;
    /// How deep a point must be to count as a deep overlap, in 1/255 of
    /// kDeepOverlap (kFullDeepScale: kDeepOverlap itself); set from the two
    /// shapes' thickness when the contact is created (deepOverlapOf).
    std::uint8_t deepScale = kFullDeepScale;
    Manifold manifold{};
    float normalImpulse[2]{};  ///< accumulated at each manifold point (N·s)
    float tangentImpulse[2]{};
    /// The normal force each point was built carrying, whose sag its soft
    /// row does not count as overlap; 0 for none (rest_load.hpp).
    RestLoad restLoad[2]{};
    float friction = 0.0f, restitution = 0.0f;  ///< mixed from the two shapes
    ManifoldFrame frame{};                      ///< valid when `framed`
    std::uint32_t generation = 1;
    std::uint32_t stamp = 0;  ///< step stamp, to gather each active contact once
};

/// Contact::deepScale's depths (m), looked up rather than computed: the
/// look of every contact and the preparation of every row read one. The
/// second half: the depths a contact that is still deep stays deep to
/// (kDeepExitFraction of the first).
inline constexpr std::array<float, 512> kDeepDepths = [] {
    std::array<float, 512> depths{};
    for (int q = 0; q < 256; ++q) {
        const float depth = q == kFullDeepScale ? kDeepOverlap : kDeepOverlap * (static_cast<float>(q) / 255.0f);
        depths[static_cast<std::size_t>(q)] = depth;
        depths[static_cast<std::size_t>(q) + 256] = kDeepExitFraction * depth;
    }
    return depths;
}();
/// The separation of the manifold's deepest point (m), or 0 if none is deeper.
inline float deepestSeparation(const Manifold& m) {
    // Both points' slots, the missing ones as zero, then the smaller: no
    // branch on a separation's sign, which at rest lies at zero either way
    // and was mispredicted (a 100-row pyramid standing where it was built).
    const float first = m.pointCount > 0 ? m.points[0].separation : 0.0f;
    const float second = m.pointCount > 1 ? m.points[1].separation : 0.0f;
    return std::min(std::min(first, second), 0.0f);
}

/// The depth from which a point of `c` is a deep overlap by its shapes'
/// thickness alone (m): the depth it becomes deep from, or, while it is
/// still deep, the shallower one it stays deep to.
inline float deepDepthOf(const Contact& c) {
    return kDeepDepths[static_cast<std::size_t>(c.deepScale) | (c.stillDeep ? 256u : 0u)];
}
/// The depth beyond which a point of `c` is a deep overlap (m): deepDepthOf,
/// or kStartOverlapDeep if that is shallower and the contact has overlapped
/// since its bodies were created or moved (Contact::overlapFromStart).
inline float deepOverlapOf(const Contact& c) {
    const float depth = deepDepthOf(c);
    return c.overlapFromStart ? std::min(depth, kStartOverlapDeep) : depth;
}
static_assert(sizeof(Contact) == 152, "memory per contact is held below Box2D 2.4.1's: grow it only knowingly");

/// A contact's rolling resistance and tangent speed, and its rolling row's
/// accumulated impulse. Kept beside the contacts, by contact slot, once any
/// of the world's contacts has either (WorldState::contactSurfaces): a world
/// whose shapes have neither holds none.
struct ContactSurface {
    float rollingResistance = 0.0f;  ///< the larger coefficient × the larger rolling radius (m)
    float tangentSpeed = 0.0f;       ///< the sum of the two shapes' (m/s)
    float rollingImpulse = 0.0f;     ///< accumulated by the rolling-resistance row (N·m·s)
};

/// The surface of contact `c`, or null when no contact of the world has one.
const ContactSurface* contactSurface(const WorldState& w, int c);

/// Sets the surface of contact `c` from its two shapes (slots), starting the
/// side array when they are the first to have one.
void setContactSurface(WorldState& w, int c, int shapeA, int shapeB);

/// The manifold of two shapes at the given poses, normal from a to b (the
/// narrowphase without a contact; continuous.cpp measures overlaps with it).
Manifold collideShapes(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                       float speculativeDistance);

/// Finds the new pairs among the shapes whose proxies moved (broad_phase.hpp)
/// and creates a contact for each one that passes the filters.
void updatePairs(WorldState& w);

/// Creates the contact of two shapes (ordered for the manifold functions).
void createContact(WorldState& w, int shapeA, int shapeB);

/// Destroys a contact; a touching one reports its end when `emitEvents`.
void destroyContact(WorldState& w, int contact, bool emitEvents);

/// What the narrowphase found of an active contact for the stages after it
/// (WorldState::activeLooks, in activeContacts' order), taken while the
/// contact and its bodies are in the cache: its bodies, the impact stage's
/// first look (impact_stage.cpp) and what decides its row's path in the
/// colouring (solver.cpp). The later stages read these 12 bytes instead of
/// the contact: the colouring's reading of every contact was half its time in
/// a large scene. Nothing changes them between the narrowphase and the solve
/// (the impact stage keeps the manifolds as they are).
struct ContactLook {
    int bodyA, bodyB;
    bool passOver;          ///< the impact stage passes it over (passesOverImpacts)
    std::uint8_t rowFlags;  ///< kLook* below
};
/// Touching, not a sensor, with points: it gets a row if a body moves.
constexpr std::uint8_t kLookRow = 1;
constexpr std::uint8_t kLookOnePoint = 2;        ///< one manifold point
constexpr std::uint8_t kLookDeep = 4;            ///< a point deeper than kDeepOverlap
constexpr std::uint8_t kLookRollingSurface = 8;  ///< its surface resists rolling
/// Between two moving bodies, one at least kShockMassRatio times the other's
/// mass, closing (lookAtImpacts, impact_look.hpp).
constexpr std::uint8_t kLookHeavyOnLight = 16;
/// Its normal is a face of A (kLookTurnA) or of B (kLookTurnB) that turns
/// more than kTurningRowAngle within the step (turningLook; set by the
/// colouring, which runs after the impact stage has changed the spins).
constexpr std::uint8_t kLookTurnA = 32;
constexpr std::uint8_t kLookTurnB = 64;

/// Turning rows. A contact's rows keep the normal of the manifold computed at the step's
/// start, which is right while the face it belongs to turns little in the
/// step. A face turning faster than this (rad per step; 3 rad/s at 60 Hz)
/// gets a turning row (contact_solver.cpp, "Turning rows"): a ball pressed
/// into the wall of a box spun at 12 rad/s slid along the wall, the wall
/// turned 11 degrees under it, and the row, measuring the gap along the old
/// normal, let it through the wall (Box2D 2.4.1, whose position pass uses
/// the current normal, held it at 40 rad/s). At 0.05 rad the old normal's
/// error, d·sin θ for a point sliding d along the face, stays within the
/// penetration slop (5 mm) for slides up to 0.1 m a step; with 0.1 rad, a
/// ball in a box of 2 m turning at 5 rad/s (below it) went 7.4 cm into the
/// wall, 3.5 cm with 0.05.
inline constexpr float kTurningRowAngle = 0.05f;

struct WorldState;
/// kLookTurnA, kLookTurnB or 0: whether contact ct's normal is a flat side
/// of A (or, reversed, of B: a polygon's side, a capsule's or a segment's
/// length, within 0.8°) whose body turns further than kTurningRowAngle in a
/// step of dt at its angular velocity now (contact.cpp).
std::uint8_t turningLook(const WorldState& w, const Contact& ct, float dt);

/// The narrowphase: updates the manifold of every contact with an awake body,
/// reports begin and end events, wakes islands that are touched, destroys
/// contacts whose boxes parted and fills WorldState::activeContacts and
/// activeLooks.
void collide(WorldState& w);

/// In the impact stage, after each sweep and after the shock pass: each
/// contact of a body in `struckBodies` (bodies just struck) whose manifold is
/// not full (no point, or one where two can be: at their velocities when
/// the step began its bodies could not close the rest of the gap within it)
/// gets its manifold again at the poses the step began with and the new
/// velocities, taken when it has more points (impulses carried by feature
/// id; Contact::foundAfterStrike set). A point found there is struck by the
/// stage's next sweep and is a row for the solver, so that a body knocked
/// into a neighbour meets it rather than going into it for a step. A new
/// touch's events and wakes are collide's.
void refreshStruckContacts(WorldState& w, const std::vector<int>& struckBodies);

/// Destroys every contact of `body` whose other shape is `shape` (or any of the
/// body's contacts when `shape` is kNullIndex), reporting touching ones as ended.
void destroyBodyContacts(WorldState& w, int body, int shape);

}  // namespace i2d::detail
