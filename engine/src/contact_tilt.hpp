// The tilt of stacked two-point contacts, solved exactly along columns
// (contact_tilt.cpp).
#pragma once

#include <cstdint>
#include <vector>

namespace i2d::detail {

struct WorldState;

/// One manifold's two rows of the chain solve. Its tilt row is the
/// difference of its two points' normal rows, J_t·v = v_n1 − v_n2 =
/// c_B·ω_B − c_A·ω_A with c = (r_1 − r_2) × n on each side (the linear parts
/// cancel: the two rows share the normal); an impulse x on it adds x to the
/// first point's normal impulse and takes x from the second's, a couple
/// with no net force. Its shear row is the sum of its two points' friction
/// rows, J_s·v = t·(v_B − v_A) + s_B·ω_B − s_A·ω_A: their difference acts on
/// nothing (the two points lie along t), so the sum is split between the
/// points as their normal impulses are, each within its own cone.
struct TiltRow {
    int block = 0, lane = 0;  ///< its wide lane (SolverArrays::wideContacts)
    int a = 0, b = 0;         ///< solver state indices (the zero state for an immovable side)
    float cA = 0, cB = 0;     ///< (r_1 − r_2) × n on each side
    float sA = 0, sB = 0;     ///< r_m × t on each side, r_m the arm to the points' midpoint
    float mA = 0, iA = 0;     ///< A's inverse mass and inertia (0 for a side that does not move or turn)
    float mB = 0, iB = 0;
    float nx = 0, ny = 0;  ///< the manifold's normal (from A to B)
    float friction = 0;    ///< the manifold's friction coefficient (no shear row without)
};

/// The factors of a step's chains for one kind of solve (contact_tilt.cpp).
struct ChainFactors {
    /// Per row pair, 2×2 blocks: A's diagonal block, then D'⁻¹ once factored;
    /// its block with the next pair; the factor's multiplier.
    std::vector<double> diag, upper, lower;
    std::vector<std::uint8_t> active;  ///< per row: bit 0 its tilt row solved, bit 1 its shear row (0: dependent)
};

/// The tilt rows of one step in chains: each chain is a path of bodies that
/// touch one another through two-point manifolds (a column), every body of
/// it with at most two such manifolds, in order from one end to the other.
struct TiltChains {
    std::vector<TiltRow> rows;
    std::vector<int> chainStart;  ///< per chain its first row; then the row count
    /// The wide lanes of this step's candidates, as block·4 + lane (solver.cpp).
    std::vector<int> candidate;
    // Scratch of the selection and the solve.
    std::vector<TiltRow> found;
    std::vector<int> degree, link;
    std::vector<char> visited;
    ChainFactors velocity;       ///< the passes' solve: tilt rows, and shear rows where there is friction
    ChainFactors push;           ///< the pseudo-velocities' solve: tilt rows only
    std::vector<double> rhs, x;  ///< per row pair: tilt, shear
};

/// Picks this step's tilt rows (after prepareContactRows): the wide rows of
/// two-point manifolds that carried load at both points when the step began.
void buildTiltChains(WorldState& w);

/// Solves every chain's rows exactly for the velocities now (after a contact
/// sweep of a soft_step pass, bias or relax): no manifold of a column is left
/// tilting or shearing, the solution scaled down where it would make a
/// point pull or slip.
void solveTiltChains(WorldState& w, float h);

/// Solves the chains' tilt rows on the pseudo-velocities (SolverArrays::biasV,
/// biasW; the deep push's, or zero): they close each manifold's tilt error
/// (the difference of its points' separations) at the soft rows' rate, and
/// a deep push does not tilt a column apart.
void pushTiltChains(WorldState& w, float h);

}  // namespace i2d::detail
