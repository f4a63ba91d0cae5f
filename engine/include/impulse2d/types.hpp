// Impulse2D — definitions used to create worlds, bodies, shapes and joints,
// the world's settings, and the events and query results a world reports.
//
// Definitions are plain aggregates with defaults: fill in what differs, e.g.
//   i2d::BodyDef def{.type = i2d::BodyType::dynamic_body, .position = {0, 4}};
//
// Sources cited below: Tamis and Maggiore (2015), "Constraint based physics
// solver"; Baber (2011), "A Correction To Brian Mirtich's Thesis
// 'Impulse-based Dynamic Simulation of Rigid Body Systems'"; Catto, Box2D v3
// and the "Solver2D" blog post (2024). Full references: docs/references.md.
#pragma once

#include <cstdint>
#include <functional>

#include "impulse2d/collision.hpp"
#include "impulse2d/id.hpp"
#include "impulse2d/joints.hpp"
#include "impulse2d/math.hpp"

namespace i2d {

/// How position error (overlap, joint drift) is corrected.
enum class PositionCorrection : std::uint8_t {
    /// Tamis and Maggiore (2015) §5.2–5.3: the push factor β adds a velocity β·d/Δt (d the
    /// penetration beyond the slop) to the velocity constraint. Simple, but
    /// the push velocity stays in the body after the overlap is gone.
    baumgarte,
    /// Tamis and Maggiore (2015) §8.1, the single-frame push factor: the push is solved on a
    /// separate pseudo-velocity that moves positions for one step and is then
    /// dropped, so correcting overlap adds no kinetic energy.
    split,
    /// Substepping with soft constraints and a relax pass (the "soft step"
    /// of Box2D v3, Catto's "Solver2D"): the step is divided into `substeps`, each solving
    /// spring-damped contacts and joints, then relaxing without the push.
    soft_step,
};

/// How a contact that begins with an approach speed is resolved.
enum class ImpactModel : std::uint8_t {
    /// Baber (2011) §5: closed-form 2D frictional impact with Stronge's energetic
    /// restitution, applied before the iterative solver. Never creates energy.
    closed_form,
    /// Restitution as a velocity bias in the contact solver (Tamis and Maggiore (2015) §8.2), as Box2D does.
    velocity_bias,
};

/// Settings of a world. All can be changed between steps with World::setSettings(),
/// which checks them (read the current ones with World::settings()).
struct WorldSettings {
    Vec2 gravity{0.0f, -10.0f};  ///< m/s²

    PositionCorrection positionCorrection = PositionCorrection::soft_step;
    ImpactModel impactModel = ImpactModel::closed_form;

    /// Velocity iterations per step (baumgarte, split). soft_step does not
    /// iterate: each substep is one solve and one relax pass (substeps are
    /// its accuracy knob, as in Box2D v3).
    int velocityIterations = 8;
    /// Iterations of the position (pseudo-velocity) pass in split mode; not
    /// used by baumgarte or soft_step.
    int positionIterations = 3;
    /// Substeps per step (soft_step only).
    int substeps = 4;

    /// Push factor β ∈ [0, 1] of Tamis and Maggiore (2015) eq. 5.2.3 (baumgarte and split).
    /// Dimensionless.
    float pushFactor = 0.2f;
    /// Penetration allowed without correction (m). Keeps resting contacts
    /// touching so the narrowphase keeps reporting them (Tamis and Maggiore (2015) §8.1, last note).
    float penetrationSlop = 0.005f;
    /// Largest speed used to push overlapping bodies apart (m/s). Overlaps
    /// deeper than 5 cm in soft_step (less between thin shapes) are pushed on
    /// pseudo-velocities that leave no velocity behind, until they are within
    /// a quarter of that depth (overlaps bodies were created or moved into:
    /// within 1 cm); those may move a body across gravity at fifteen times this (a
    /// sideways move lifts nothing), up or down at most this.
    float maxPushSpeed = 3.0f;
    /// Contact stiffness (Hz) and damping ratio for soft_step. The stiffness is
    /// capped at a quarter of the substep rate (60 Hz at 60 Hz × 4 substeps),
    /// and doubled for contacts with a body that cannot move. A contact
    /// carrying a load F sinks F/(m_eff·ω²), ω = 2π·hertz, whatever the
    /// damping; the overdamped row pushes an overlap out at about ω/(2ζ) per
    /// second (6.3 per second at these defaults). 50 Hz sinks a stack 0.36
    /// times as far as Box2D v3's 30 Hz (pyramid100's top 0.30 m instead of
    /// 0.73 m, at the same cost); ζ = 25 pushes overlaps out more gently
    /// than ζ = 16.7 (30 Hz's push), which threw up towers of small boxes
    /// created overlapping (docs/validation.md, "The pyramid's compliance").
    float contactHertz = 50.0f;
    float contactDampingRatio = 25.0f;
    /// Joint stiffness (Hz) and damping ratio for the position error of rigid joints in soft_step
    /// (the stiffness is capped at a quarter of the substep rate: 60 Hz at 60 Hz × 4 substeps).
    float jointHertz = 60.0f;
    float jointDampingRatio = 2.0f;
    /// Joints whose bodies form a tree (a chain, a ragdoll) have their
    /// equality rows (the revolute joint's point, a weld's rigid point and
    /// angle, a rigid distance joint) solved exactly, not swept, when the
    /// tree's heaviest body is at least this many times its lightest, or the
    /// masses its rows see at the joints' anchors (1/(1/m + |r|²/I)) are, or
    /// one of its bodies is rigidly welded to two others, or when no loop
    /// closes through it, its bodies together are this many times its
    /// lightest and its soft rows would stretch under their weight by a tenth
    /// of its smallest body's reach (a long chain of light links at long
    /// substeps, docs/joints.md): Gauss-Seidel leaves a chain carrying a
    /// heavy body stretched, and the soft step's sweep over such trees can
    /// gain energy (docs/joints.md). A joint closing a loop through such
    /// trees has its equality rows solved with them (up to 12 rows a step;
    /// docs/joints.md, "Loops through exact trees"). Such a tree of
    /// hinges and rigid welds, closed by no loop, is solved rigid in soft_step while none of its
    /// bodies touches anything, its position error closed on pseudo-velocities
    /// at the jointHertz rate (docs/joints.md, "Rigid trees and the tension's
    /// geometric stiffness"). 1 solves every tree exactly; infinity none.
    /// Dimensionless, ≥ 1.
    float exactJointMassRatio = 10.0f;
    /// soft_step: the tilt of two-point contacts stacked in columns (the
    /// difference of a manifold's two normal impulses, a couple) solved
    /// exactly along each column after every contact sweep, so a column's
    /// joints do not bend under their contacts' softness: a column built
    /// leaning, or a light stack under a heavy top, stands where the soft
    /// rows let it buckle (docs/validation.md, "Columns solved as one").
    /// Only bodies whose every contact row is such a manifold, pressed from
    /// opposite sides, without joints, take part (contact_tilt.cpp).
    bool exactColumnTilt = true;

    /// Approach speed (m/s) below which a contact gets no restitution
    /// (velocity_bias; with closed_form, impactThreshold decides which
    /// contacts are impacts and so bounce).
    float restitutionThreshold = 1.0f;
    /// Approach speed (m/s), at the moment the surfaces meet within the step,
    /// above which a contact is resolved as an impact by the closed-form law
    /// (when impactModel == closed_form).
    float impactThreshold = 1.0f;

    /// Approach speed (m/s) above which a touching contact with a shape that
    /// enables hit events reports a ContactHitEvent.
    float hitEventThreshold = 1.0f;

    /// Contacts are created when shapes are closer than this (m).
    float speculativeDistance = 0.02f;
    /// A touching contact between flat shapes (polygons, segments) with two
    /// points keeps its manifold, with its points fixed in the two bodies
    /// and its normal fixed, while no point of one body has moved further
    /// than this (m) relative to the other since the manifold was computed;
    /// beyond it, after a
    /// turn of one body against the other of about 11°, after the first
    /// body has turned 2° (its normal is fixed in the world), or once one
    /// body has slid 2 cm along the other's face, the manifold is
    /// recomputed. This is what keeps tall stacks standing with soft
    /// contacts (docs/validation.md, "Columns").
    /// 0 recomputes every manifold every step.
    float manifoldReuseDistance = 0.05f;
    /// Fattening of broadphase boxes (m): a proxy moves in the tree only when
    /// its shape leaves the fat box. A moving body's new box is also
    /// stretched ahead along its velocity: the coming step's motion and two
    /// steps beyond it.
    float aabbMargin = 0.1f;
    /// Speed limit for stability (m/s).
    float maxLinearSpeed = 400.0f;

    bool enableWarmStarting = true;
    /// Continuous collision against static and kinematic shapes: a dynamic
    /// body whose points may move further than speculativeDistance in a step
    /// is swept against the static and kinematic shapes near its path (against
    /// a kinematic one along its motion relative to it) and, if it would touch
    /// one, put back to its first time of impact (keeping its velocity), so it
    /// cannot pass through thin walls. Dynamic-versus-dynamic pairs are swept
    /// only for bullets (BodyDef::isBullet) against bodies that are not bullets.
    bool enableContinuous = true;
    bool enableSleep = true;
    /// Seconds an island must rest before it sleeps.
    float timeToSleep = 0.5f;
    /// Speeds under which a body counts as resting (m/s and rad/s).
    float linearSleepTolerance = 0.05f;
    float angularSleepTolerance = 2.0f / 180.0f * 3.14159265f;
};

/// How a body moves.
enum class BodyType : std::uint8_t {
    static_body,     ///< never moves; infinite mass
    kinematic_body,  ///< moves by its velocity only; infinite mass
    dynamic_body,    ///< moved by forces, contacts and joints
};

/// Everything World::createBody needs; the defaults make a static body at the origin.
struct BodyDef {
    BodyType type = BodyType::static_body;
    Vec2 position{};               ///< body origin, world (m)
    float angle = 0.0f;            ///< radians, counter-clockwise
    Vec2 linearVelocity{};         ///< of the centre of mass (m/s)
    float angularVelocity = 0.0f;  ///< rad/s
    float linearDamping = 0.0f;    ///< 1/s, ≥ 0
    float angularDamping = 0.0f;   ///< 1/s, ≥ 0
    float gravityScale = 1.0f;     ///< multiplies the world's gravity for this body
    bool fixedRotation = false;    ///< no rotation (infinite rotational inertia)
    bool isAwake = true;           ///< false: created asleep (when sleep is enabled)
    bool enableSleep = true;       ///< false: this body never sleeps
    /// A fast dynamic body (a projectile): its continuous collision also
    /// sweeps it against the other dynamic bodies that are not bullets, so it
    /// cannot pass through a thin moving body (continuous.cpp). Costs a sweep
    /// per step while it moves fast.
    bool isBullet = false;
    std::uintptr_t userData = 0;  ///< any value of the game's; never read by the engine
};

/// Which shapes may collide. Two shapes collide when each one's category is
/// in the other's mask, unless they share a non-zero group: a positive group
/// always collides, a negative one never does.
struct Filter {
    std::uint32_t categoryBits = 0x0001;
    std::uint32_t maskBits = 0xFFFFFFFF;
    std::int32_t groupIndex = 0;
};

/// The rule above, as the broadphase applies it.
constexpr bool shouldCollide(const Filter& a, const Filter& b) {
    if (a.groupIndex == b.groupIndex && a.groupIndex != 0) return a.groupIndex > 0;
    return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

/// Material and flags of a shape, given to the World::create*Shape functions.
struct ShapeDef {
    float density = 1.0f;      ///< kg/m², ≥ 0 (0 adds no mass)
    float friction = 0.6f;     ///< Coulomb coefficient μ ≥ 0
    float restitution = 0.0f;  ///< coefficient of restitution e ∈ [0, 1]
    Filter filter{};
    bool isSensor = false;            ///< detects overlap, makes no contact
    bool enableContactEvents = true;  ///< report contact begin/end events for this shape
    bool enableSensorEvents = true;   ///< a sensor: report sensor events
    /// Report a ContactHitEvent when this shape's contacts close faster than
    /// WorldSettings::hitEventThreshold (off by default: nothing is computed).
    bool enableHitEvents = false;
    /// Resistance to rolling (dimensionless, ≥ 0): a contact resists the
    /// relative turning of its two bodies with a torque of at most
    /// rollingResistance × normal force × 1 m (the larger of the two shapes'
    /// values). Lets a ball on flat ground come to rest.
    float rollingResistance = 0.0f;
    /// Speed of the shape's surface along its contacts' tangent (m/s; the
    /// two shapes' values add): a conveyor belt. Positive moves a touching
    /// body in the direction of the contact tangent, the normal turned
    /// clockwise (for ground under a body: towards +x).
    float tangentSpeed = 0.0f;
    std::uintptr_t userData = 0;
};

enum class ShapeType : std::uint8_t { circle, capsule, segment, polygon };

/// A chain: segments joined end to end (World::createChain), for static
/// level geometry such as terrain. Each segment collides on one side only, its
/// right side looking from a point to the next (so a counter-clockwise loop
/// is solid inside, as in Box2D), and knows its neighbours' far points (its
/// ghost vertices), so that a body sliding or rolling across a joint between
/// two segments meets one smooth surface: no catch on a seam, no kick from a
/// joint's rounded corner, at any speed.
struct ChainDef {
    /// The points in the body frame (m); an open chain needs at least 2, a
    /// loop at least 3. Consecutive points further apart than kLinearSlop,
    /// and no segment may cross or touch another one that is not its neighbour.
    std::span<const Vec2> points{};
    bool isLoop = false;       ///< true: the last point joins the first
    float friction = 0.6f;     ///< of every segment (Coulomb μ ≥ 0)
    float restitution = 0.0f;  ///< of every segment (e ∈ [0, 1])
    Filter filter{};
    bool enableContactEvents = true;
    std::uintptr_t userData = 0;  ///< given to every segment
};

/// Two shapes began to touch in the last step (manifold at that moment).
struct ContactBeginEvent {
    ShapeId shapeA{};
    ShapeId shapeB{};
    Manifold manifold{};
};

/// Two shapes stopped touching (or their contact was destroyed).
struct ContactEndEvent {
    ShapeId shapeA{};
    ShapeId shapeB{};
};

/// A touching contact whose shapes approached faster than
/// WorldSettings::hitEventThreshold at the start of the last step (one of the
/// shapes enables hit events): for impact sounds and damage.
struct ContactHitEvent {
    ShapeId shapeA{};
    ShapeId shapeB{};
    Vec2 point{};                ///< the manifold point that approached fastest (world, m)
    Vec2 normal{};               ///< the manifold normal, from A to B
    float approachSpeed = 0.0f;  ///< normal speed at which the surfaces closed (m/s, > 0)
};

/// A shape (`visitor`) began to overlap a sensor shape.
struct SensorBeginEvent {
    ShapeId sensor{};
    ShapeId visitor{};
};

/// A shape stopped overlapping a sensor shape.
struct SensorEndEvent {
    ShapeId sensor{};
    ShapeId visitor{};
};

/// A contact whose shapes touch (the manifold has points), for inspection.
struct ContactData {
    ShapeId shapeA{};
    ShapeId shapeB{};
    Manifold manifold{};
    float normalImpulse[2]{};  ///< accumulated over the last step (N·s)
    float tangentImpulse[2]{};
};

/// Filter for queries: a shape is reported when its category is in `maskBits`
/// and `categoryBits` is in its mask, and, when `accept` is set, accept(shape)
/// returns true. `accept` is called for every candidate that passes the bits
/// (in no particular order) while the world is locked: it may read the
/// world but not change it (a locked call throws i2d::Error).
struct QueryFilter {
    std::uint32_t categoryBits = 0x0001;
    std::uint32_t maskBits = 0xFFFFFFFF;
    std::function<bool(ShapeId)> accept{};
};

/// A convex shape placed in the world, for shape casts and overlap queries:
/// the convex hull of `count` points (world, m) grown by `radius`. Build it
/// with makeProxy.
struct ShapeProxy {
    Vec2 points[kMaxPolygonVertices]{};
    int count = 0;
    float radius = 0.0f;
};

/// A shape cast's first hit: the shape hit, the point on its surface and
/// its outward normal there (world), and the fraction t ∈ [0, 1] of the
/// translation at which the cast shape reaches it.
struct ShapeCastResult {
    ShapeId shape{};
    Vec2 point{};
    Vec2 normal{};
    float fraction = 0.0f;
};

/// A proxy for a circle, capsule, polygon or segment placed by `xf`.
ShapeProxy makeProxy(const Circle& shape, const Transform& xf);
ShapeProxy makeProxy(const Capsule& shape, const Transform& xf);
ShapeProxy makeProxy(const Polygon& shape, const Transform& xf);
ShapeProxy makeProxy(const Segment& shape, const Transform& xf);

/// The pair filter of World::setCustomFilter: return false and the two
/// shapes make no contact.
using CustomFilterFn = std::function<bool(ShapeId shapeA, ShapeId shapeB)>;

/// The callback of World::setPreSolve: called in the step for each touching
/// contact with its new manifold (normal from shapeA to shapeB); return false
/// to switch the contact off for this step (it is then not touching).
using PreSolveFn = std::function<bool(ShapeId shapeA, ShapeId shapeB, const Manifold& manifold)>;

/// An explosion (World::explode): every dynamic body with a shape within
/// radius + falloff of the centre gets an impulse pushing it away, at the
/// point of its shape nearest the centre: `impulse` (N·s) within radius of
/// the centre, falling linearly to 0 at radius + falloff.
struct ExplosionDef {
    Vec2 center{};         ///< world (m)
    float radius = 1.0f;   ///< m, ≥ 0
    float falloff = 0.0f;  ///< m, ≥ 0
    float impulse = 1.0f;  ///< N·s per shape, ≥ 0
    QueryFilter filter{};  ///< which shapes feel it
};

/// A ray hit: the shape, the entry point and the surface's outward normal
/// there (world), and the fraction t of the translation at which it is reached.
struct RayResult {
    ShapeId shape{};
    Vec2 point{};
    Vec2 normal{};
    float fraction = 0.0f;
};

/// Time spent in each stage of the last step (milliseconds).
struct Profile {
    float step = 0.0f;
    float pairs = 0.0f;
    float collide = 0.0f;
    float impacts = 0.0f;
    float solve = 0.0f;
    float prepare = 0.0f;     ///< colouring and preparing the solver rows (part of `solve`)
    float continuous = 0.0f;  ///< continuous collision and bounding-box refresh
    float sweeps = 0.0f;      ///< continuous collision alone (part of `continuous`)
    float sleep = 0.0f;
};

}  // namespace i2d
