// Continuous collision of fast bodies against static shapes (continuous.cpp).
#pragma once

namespace i2d::detail {

struct WorldState;

/// After the solver has moved the bodies: each body that moved further than
/// the speculative distance is swept against the static shapes near its
/// path and put back to its first time of impact (it keeps its velocity).
void solveContinuous(WorldState& w);

}  // namespace i2d::detail
