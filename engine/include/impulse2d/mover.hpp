// Impulse2D — a character mover: a capsule moved through the world by
// geometry alone (no body), sliding along the surfaces it meets.
//
// One move, as moveCharacter does it:
//   1. collide: the planes of the shapes the capsule touches or overlaps
//      (World::collideMover);
//   2. solve: the nearest translation to the wanted one that does not push
//      into any of those planes (solvePlanes);
//   3. cast: sweep the capsule along that translation and stop at the first
//      shape it would enter (World::castMover);
//   4. repeat from the new position with what is left of the move, a few
//      times; then clip the velocity against the planes (clipVector) so
//      speed does not build up against a wall.
// This is the collide-and-slide approach of Catto's Box2D v3.1 mover; the
// code here is Impulse2D's own (docs/references.md).
#pragma once

#include <span>
#include <vector>

#include "impulse2d/geometry.hpp"
#include "impulse2d/id.hpp"

namespace i2d {

/// A surface the mover touches, as a plane in the mover's frame of motion:
/// moving by a translation d changes the gap to it by dot(normal, d) − offset.
struct CollisionPlane {
    Vec2 normal{};        ///< unit, out of the shape towards the mover
    float offset = 0.0f;  ///< how deep the mover overlaps the shape (m, ≥ 0)
    ShapeId shape{};      ///< the shape (null for planes the caller makes)
    Vec2 point{};         ///< the point of the shape's surface nearest the mover (world)
    float push = 0.0f;    ///< written by solvePlanes: how far this plane pushed (m)
};

/// The result of solvePlanes.
struct PlaneSolution {
    Vec2 delta{};        ///< the translation to use (m)
    int iterations = 0;  ///< relaxation sweeps used
};

/// The translation nearest `targetDelta` (m) that leaves the mover
/// overlapping no plane by more than kLinearSlop (a slop that keeps the
/// planes found again next move, so the mover rests on them without
/// jitter): Gauss-Seidel relaxation over the planes, each adding a push
/// along its normal that is never negative (a plane only pushes out),
/// until the pushes change by less than kLinearSlop in a sweep (at most 20
/// sweeps). Writes each plane's total push.
PlaneSolution solvePlanes(Vec2 targetDelta, std::span<CollisionPlane> planes);

/// `v` without the components that point into the planes that pushed
/// (push > 0): what is left of a velocity after sliding along them.
Vec2 clipVector(Vec2 v, std::span<const CollisionPlane> planes);

class World;
struct QueryFilter;

/// The result of moveCharacter.
struct MoverResult {
    Vec2 position{};                     ///< where the mover ended (the capsule's frame origin, world)
    Vec2 velocity{};                     ///< the velocity given, clipped by the planes
    std::vector<CollisionPlane> planes;  ///< the planes of the last collide
    int iterations = 0;                  ///< collide-solve-cast rounds used (≤ 5)
};

/// Move a capsule (given in its own frame, placed at `position`) by
/// `delta` (m) through `world`, sliding along what it meets, in up to five
/// collide-solve-cast rounds; a round that moves it less than 1 cm ends the move.
/// `velocity` is returned clipped against the final planes. The world is only
/// read. Throws i2d::Error as World::castMover.
MoverResult moveCharacter(const World& world, const Capsule& capsule, Vec2 position, Vec2 delta, Vec2 velocity,
                          const QueryFilter& filter);

}  // namespace i2d
