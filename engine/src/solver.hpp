// The step: the order of the stages, and the solver's per-step arrays.
#pragma once

#include <cstdint>
#include <vector>

#include "body.hpp"
#include "contact_solver.hpp"
#include "joint.hpp"
#include "joint_tree.hpp"
#include "scratch_array.hpp"

namespace i2d::detail {

struct WorldState;

/// Arrays rebuilt by every step. Each is sized for this step's awake bodies,
/// contacts or joints.
struct SolverArrays {
    std::vector<BodyState> states;             ///< awake bodies, then one zero state for immovable sides
    std::vector<BodyIntegration> integration;  ///< per awake body
    std::vector<int> stateBodies;              ///< body slot of each state (awake bodies only)
    std::vector<Vec2> biasV;                   ///< split mode pseudo-velocities (zero entry last)
    std::vector<float> biasW;
    ScratchArray<ContactConstraint> constraints;  ///< in colour order (solver.cpp)
    std::vector<std::uint8_t> contactColours;     ///< per active contact: its row's colour, or kNoRow
    std::vector<int> colourOffsets;               ///< per colour: its first row (advanced as rows are placed)
    std::vector<std::uint64_t> colourBits;        ///< per colour, one bit per state
    int rowCount = 0;                             ///< contact rows this step
    std::vector<JointConstraint> joints;          ///< in colour order (joint_solver.cpp)
    std::vector<JointConstraint> jointScratch;    ///< the colour sort's other buffer
    JointTrees trees;                             ///< joints solved exactly (joint_tree.cpp)
    std::vector<std::uint8_t> jointColours;
    std::vector<int> deepContactCount;       ///< per state: contacts overlapping deeper than kDeepOverlap
    bool anyDeepOverlap = false;             ///< some row overlaps deeper than kDeepOverlap this step
    std::vector<RollingConstraint> rolling;  ///< contacts with rolling resistance (contact_solver.cpp)
};

/// Advances the world by dt: pairs → narrowphase → impacts → solve →
/// continuous collision → proxies → sleep.
void stepWorld(WorldState& w, float dt);

}  // namespace i2d::detail
