// The distance joint's constraint (its rows are in distance_joint.cpp).
//
// Constraint (Tamis and Maggiore (2015), Constraint based physics solver,
// §5.2): C = |p_B − p_A| − L, with p_A, p_B the anchors in world space. Its
// Jacobian is the unit axis u = (p_B − p_A)/|p_B − p_A| applied at the
// anchors: J v = u·(v_B + ω_B × r_B − v_A − ω_A × r_A). The paper's
// ½(|p_AB|² − L²) has the same Jacobian direction scaled by |p_AB|, so the
// effective mass is taken along the unit axis:
//   m_eff = 1 / (m_A⁻¹ + m_B⁻¹ + I_A⁻¹ (r_A × u)² + I_B⁻¹ (r_B × u)²).
// Rigid: one bilateral row, softened in soft_step by the joint hertz and
// damping ratio of the world (soft_constraint.hpp), pushed by the push factor
// in baumgarte and split. Spring: the row softened by the joint's own hertz
// and damping ratio in every pass. Limits: two one-sided rows, length ≥ min
// (pushes apart) and length ≤ max (a rope, pulls together), speculative
// while inside the range. Impulses: axial (the rigid or spring row), lower, upper.
#pragma once

#include "joint_rows.hpp"
