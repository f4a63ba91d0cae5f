// Continuous collision of fast bodies against static and kinematic shapes (continuous.cpp).
#pragma once

namespace i2d::detail {

struct Body;
struct BodyState;
struct WorldState;

/// Whether the solver moved `body` (its state `s`, after the write-back) so
/// far in this step that solveContinuous must sweep it: a dynamic body that
/// takes part in continuous collision and whose points moved further than
/// the speculative distance. The write-back asks this on the workers, where
/// the body is in the cache, so that the stage visits the few fast bodies
/// only (SolverArrays::sweeps).
bool needsSweep(const WorldState& w, const Body& body, const BodyState& s);

/// After the solver has moved the bodies: each body that moved further than
/// the speculative distance is swept against the static and kinematic shapes
/// near its path and put back to its first time of impact (it keeps its
/// velocity).
/// After the solve of a step of length dt; the bodies swept are those the
/// write-back flagged (needsSweep).
void solveContinuous(WorldState& w, float dt);

}  // namespace i2d::detail
