// The exact solve of the joints' equality rows where they form a tree
// (joint_tree.cpp): Baraff (1996), Linear-Time Dynamics using Lagrange
// Multipliers. Gauss-Seidel converges slowly on a chain carrying a heavy body
// (the error it leaves grows with the mass ratio and the chain's length); a
// direct solve of the same rows leaves none, in time linear in the joints.
#pragma once

#include <cstdint>
#include <vector>

#include "joint_rows.hpp"

namespace i2d::detail {

struct WorldState;

/// A node of the body–joint tree: a body (3 unknowns v_x, v_y, ω) or a joint's
/// equality rows (up to 3 unknowns: −Δλ), with the blocks of its elimination.
struct TreeNode {
    int parent = -1;             ///< node index, −1 for a root
    int body = -1;               ///< solver state index (body node)
    int row = -1;                ///< index in SolverArrays::joints (joint node)
    int nodeA = -1, nodeB = -1;  ///< joint node: the nodes of its bodies (−1: a body that does not move)
    double diag[3][3];           ///< H_ii, then its Schur complement D_i; after factoring, D_i⁻¹
    double link[3][3];           ///< H_i,parent: this node's unknowns by the parent's
    double rhs[3];               ///< right-hand side, then the solution
    double compliance[3][3];     ///< joint node: Γ of its rows in the factored pass
    float mask[3];               ///< body node: 1 for a degree of freedom it has (non-zero inverse mass or inertia)
    bool speculative;            ///< joint node: its held limit is not reached yet (its target closes the gap)
    bool pushed;        ///< its tree is pushed (JointSlot::treePushed): rigid in the biased pass (pushJointTrees)
    EqualityRows rows;  ///< joint node: its rows at the factored positions
};

/// The most auxiliary rows (JointSlot::treeLoop, JointSlot::treeSpring)
/// solved with the trees in a step: each costs a substitution through every
/// node when the trees are factored, and their dense system grows as its cube.
inline constexpr int kMaxLoopRows = 12;

/// Auxiliary rows of the tree solve (Baraff (1996), §8): the equality rows of
/// a joint closing a loop through the trees (JointSlot::treeLoop), or the
/// one row of a spring between the trees' bodies (JointSlot::treeSpring).
struct TreeLoop {
    int row = -1;                ///< index in SolverArrays::joints
    int nodeA = -1, nodeB = -1;  ///< the nodes of its bodies (−1: a body that does not move)
    int first = 0;               ///< its first row in the dense system (JointTrees::loopMatrix)
    bool spring = false;         ///< the joint's spring (its accumulated impulse: springImpulse), not its equality rows
    float springRate = 0.0f;     ///< a spring's bias rate: b = rate·C in every pass (its softness, not the pass's)
    double compliance[3][3];     ///< Γ of its rows in the factored pass (a spring's own in every pass)
    EqualityRows rows;           ///< its rows at the factored positions
};

/// A limit the trees held and let go of in a solve (it pulled), with what
/// its impulse was: taken off through the trees in the solves that follow.
struct ReleasedLimit {
    int row = -1;                ///< index in SolverArrays::joints
    bool lower = false;          ///< the lower limit (else the upper)
    int nodeA = -1, nodeB = -1;  ///< the nodes of its bodies (−1: a body that does not move)
    float jA[3], jB[3];          ///< its row's Jacobian
    double impulse = 0.0;        ///< its accumulated impulse along +J when let go
};

/// The trees of one step: nodes with every child before its parent.
struct JointTrees {
    std::vector<TreeNode> nodes;
    std::vector<TreeLoop> loops;  ///< the joints closing loops through them
    int loopRows = 0;             ///< their rows in all
    /// The loops' rows' system through the trees, S = J_L P J_Lᵀ + Γ_L (P the
    /// bodies' mobility with the trees' rows held), factored as L Lᵀ with the
    /// rows that add nothing independent dropped (loopDropped).
    double loopMatrix[kMaxLoopRows][kMaxLoopRows];
    bool loopDropped[kMaxLoopRows];
    /// Each loop row's least pivot (kLoopPivot times its own J M⁻¹ Jᵀ + Γ, no
    /// tree, no other row): one below it is dropped.
    double loopPivotFloor[kMaxLoopRows];
    std::vector<int> unionParent;  ///< scratch of the spanning-forest search
    std::vector<int> adjacency, adjacencyStart, nodeOfBody;
    std::vector<float> lightest, heaviest;  ///< per union-find root (kg)
    std::vector<float> treeMass;            ///< per union-find root: its bodies' summed mass (kg)
    std::vector<float> leastReach;          ///< per union-find root: its bodies' least Body::reach (m)
    std::vector<std::uint8_t> welds;        ///< per solver state: rigid welds it holds (counted to 2; scratch)
    std::vector<std::uint8_t> weldCluster;  ///< per union-find root: a body welded to two others or more
    std::vector<float> lightestAnchor, heaviestAnchor;  ///< the masses at the tree joints' anchors, per root (kg)
    std::vector<std::uint8_t> stretched;                ///< per union-find root: holds a stretched joint
    std::vector<float>
        extraInertia;  ///< per solver state: inertia added for the geometric stiffness (kg·m²; empty: none)
    std::vector<std::uint8_t> pointsOnly;  ///< per union-find root: every joint a hinge or a rigid weld
    std::vector<std::uint8_t> closed;      ///< per union-find root: a joint outside the tree closes a loop through it
    /// What the factorization in `nodes` was made for (see solveJointTrees).
    int factoredPositions = -1;
    int limitsDecidedAt = -1;  ///< the positions the held limits were last decided for (holdTreeLimits)
    bool anyLimit = false;     ///< some tree joint has a limit (else none is ever held)
    bool factoredSoft = false;
    bool holdsLimits = false;  ///< some joint's limit is held in that factorization (JointConstraint::treeLimit)
    /// The trees' bodies' states and joints' impulses before a solve that
    /// holds limits, in node order, to solve again from when one pulls
    /// (solveJointTrees).
    std::vector<BodyState> savedStates;
    std::vector<JointImpulses> savedImpulses;
    std::vector<ReleasedLimit> releasedLimits;  ///< let go of in the solve under way (solveJointTrees)
};

/// Picks the joints whose equality rows are solved exactly (a spanning forest
/// of the body–joint graph, every static body one node, so a loop such as a
/// bridge's or a grid's keeps one or more joints in the Gauss-Seidel sweep;
/// only trees of unlike masses, WorldSettings::exactJointMassRatio, each
/// judged by its own bodies: the trees hung from the same static bodies are
/// judged apart; trees no loop closes whose soft rows, jointOmega over
/// substeps of h, would stretch under their weight by kLoadStretch of their
/// smallest body's reach; and trees holding a stretched joint, JointSlot::stretched,
/// that no loop closes) and marks them (JointSlot::inTree, false when
/// called). A world whose jointed bodies are alike (in mass and at their
/// anchors), without a stretched joint or a welded cluster, skips the search. A
/// tree no joint outside it closes into a loop, whose joints all hold their
/// load at a point or that holds a stretched joint, may be pushed
/// (JointSlot::treePushed; buildJointTrees decides).
void selectTreeJoints(WorldState& w, std::vector<JointSlot>& slots, float h);

/// The stiffness (rad/s) of the joints' soft rows over substeps of h
/// (jointHertzOver, solver.hpp).
float jointOmega(const WorldSettings& settings, float h);

/// What a tree's soft rows stretch under its load, as a fraction of its
/// smallest body's reach, from which the tree is solved exactly
/// (selectTreeJoints): see kLoadStretch in joint_tree.cpp.
inline constexpr float kLoadStretch = 0.1f;
/// A hinge or a rigid weld: its rows hold a point (and an angle), whose load
/// turns its bodies as the tension's geometric stiffness (buildJointTrees).
bool holdsLoadAtPoint(const Joint& joint);
/// Orders the trees' nodes over the rows in their final order and marks the
/// pushed trees: those that may be (JointSlot::treePushed) while none of their
/// bodies touches anything through a contact, and those holding a stretched
/// joint. The bodies of a pushed tree that touches nothing get the inertia of
/// the tension's geometric stiffness where substeps of h do not resolve it
/// (JointTrees::extraInertia; the joints' rows take it too).
void buildJointTrees(WorldState& w, float h);

/// Decides which limits the trees hold at the positions now, once per
/// `positions` (the count of position updates), before the sweep that
/// precedes their solve: a limit the trees will hold is left out of the
/// sweep too. Decided only when the trees were factored, after the sweep, the
/// first sweep of each step and each sweep after the positions changed swept
/// it with its bodies' own masses: a hinge's upper limit warm started with
/// the impulse that had stopped a 160 kg body, moving a 0.3 kg link by its
/// own inertia, drove the sweep's lower limit row of the same hinge to
/// 5,000 N·m against it, and the tree gained 2 % of its energy.
void holdTreeLimits(WorldState& w, int positions);

/// Solves the trees' equality rows exactly for the velocities now, in ctx's
/// pass: (J M⁻¹ Jᵀ + Γ) Δλ = −(J v + b + Γ λ), and applies Δλ. `positions`
/// counts the position updates of the step: the factorization is reused
/// while neither it nor the pass changes.
void solveJointTrees(WorldState& w, const JointContext& ctx, int positions);

/// Closes the trees' position error on the pseudo-velocities
/// (SolverArrays::biasV, biasW) at ctx.pushFactor of it per substep, solved
/// exactly, a row that holds a point or a line moving its bodies and a row
/// that holds an angle turning them: the error of a stretched joint
/// (Joint::stretched). The velocities and the joints' impulses are left as
/// they were.
void pushJointTrees(WorldState& w, const JointContext& ctx);

}  // namespace i2d::detail
