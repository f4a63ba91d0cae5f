// Continuous collision of fast bodies against static shapes (continuous.cpp).
#pragma once

namespace i2d::detail {

struct WorldState;

/// After the solver has moved the bodies: each body that moved further than
/// the speculative distance is swept against the static shapes near its
/// path and put back to its first time of impact (it keeps its velocity).
/// After the solve of a step of length dt.
void solveContinuous(WorldState& w, float dt);

}  // namespace i2d::detail
