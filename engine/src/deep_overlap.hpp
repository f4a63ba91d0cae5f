// Deep overlaps in the soft step: bodies created or driven into each other
// deeper than kDeepOverlap are pushed apart on pseudo-velocities that move
// the positions for one substep and are then dropped (deep_overlap.cpp).
#pragma once

namespace i2d::detail {

struct WorldState;

/// The push of every deep contact, solved by a few Gauss-Seidel sweeps on
/// the pseudo-velocities SolverArrays::biasV/biasW (zeroed here first); each
/// body's pseudo-velocity is then limited to WorldSettings::maxPushSpeed.
void pushDeepOverlaps(WorldState& w);

}  // namespace i2d::detail
