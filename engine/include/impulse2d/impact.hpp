// Impulse2D — the closed-form 2D frictional impact law of Baber (2011), "A
// Correction To Brian Mirtich's Thesis 'Impulse-based Dynamic Simulation of
// Rigid Body Systems'", §5: Baber's correction of the impulse-space
// integration in Mirtich's thesis (1996), with Stronge's energetic
// restitution and stable/unstable sticking, solved in closed form.
//
// Conventions (as in Baber (2011)): the unit normal f points from B to A; body A
// receives the impulse +p and body B receives −p; angular velocities are
// counter-clockwise positive; r is the contact point minus the body's
// centre of mass. An immovable body has inverse mass and inverse inertia 0.
#pragma once

#include <cstdint>

namespace i2d {

/// Double-precision 2D vector used by the impact law.
struct Vec2d {
    double x = 0.0;
    double y = 0.0;
};

struct ImpactBody {
    double invMass = 0.0;     ///< 1/m (1/kg), ≥ 0
    double invInertia = 0.0;  ///< 1/I about the centre of mass (1/(kg·m²)), ≥ 0
    Vec2d r{};                ///< contact point − centre of mass (m)
    Vec2d v{};                ///< linear velocity of the centre of mass (m/s)
    double w = 0.0;           ///< angular velocity (rad/s, counter-clockwise)
};

struct ImpactInput {
    double restitution = 0.0;  ///< Stronge's energetic coefficient e ∈ [0, 1]
    double friction = 0.0;     ///< Coulomb μ ≥ 0
    Vec2d normal{0.0, 1.0};    ///< unit normal f, from B to A
    ImpactBody a{};
    ImpactBody b{};
};

/// Which branch of Baber (2011) §5 decided the result.
enum class ImpactCase : std::uint8_t {
    converging_compression,    ///< sliding ray reaches the sticking origin during compression
    converging_decompression,  ///< sliding ray reaches the origin during decompression
    decompression_ended,       ///< restitution finished before the ray reached the origin
    stable_sticking,           ///< initially sticking (or reached it) and static friction holds
    unstable_sticking,         ///< sticking, but friction cannot hold: slides on along the diverging ray
    diverging,                 ///< sliding along a diverging or stationary ray to the end
    not_colliding,             ///< separating or resting normal velocity: nothing happens
};

struct ImpactResult {
    Vec2d vA{};
    double wA = 0.0;
    Vec2d vB{};
    double wB = 0.0;
    Vec2d impulse{};  ///< p, received by A (B receives −p), world frame (N·s)
    ImpactCase kind = ImpactCase::not_colliding;
};

/// Resolve one impact. Throws i2d::Error on invalid input: non-finite values,
/// negative inverse mass or inertia, both bodies immovable, a normal whose
/// length differs from 1 by more than 1e-6, e outside [0, 1], μ < 0, a
/// singular collision matrix K (only possible when both inverse masses are 0:
/// bodies that can only spin and cannot move the contact point along every
/// direction; Baber (2011) §3.2 needs K positive definite), and finite inputs so
/// large that the result overflows double precision. An immovable body's
/// velocity is that of a kinematic pusher: the law conserves or loses energy
/// in the frame of an immovable body at rest.
ImpactResult resolveImpact(const ImpactInput& input);

/// Stable lower-case name of a case, as printed by `testbed impact`.
const char* toString(ImpactCase kind);

}  // namespace i2d
