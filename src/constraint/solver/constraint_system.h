// What every constraint solver does around its own algorithm
// (spec/interaction.md §5.2): gather the constraints and corrections under
// its node, build J on every state (constraints top-down, then mappings
// bottom-up), project J with the projective constraints, fill dfree and the
// resolution blocks, then apply each correction's motion correction.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/constraint_problem.h"
#include "core/mechanical_ops.h"

namespace sinew {

class Node;

// Components under a solver's node, gathered again when the graph changed.
struct ConstraintScope {
  std::uint64_t version = 0;
  std::unique_ptr<MechanicalOps> ops;               // states, mappings, projective constraints
  std::vector<LagrangianConstraint*> constraints;   // top-down, node object order
  std::vector<ConstraintCorrection*> corrections;   // top-down (SOFA's search-down order)
};

// Brings the scope up to date with the graph (one comparison when nothing changed).
void sync_constraint_scope(Node& node, ConstraintScope& scope);

// Clears every state's Jacobian, lets each constraint append its rows, maps
// rows down to independent states and (with `project`) projects them.
// Returns the number of rows.
int build_constraint_jacobian(ConstraintScope& scope, const ConstraintParams& p, bool project);

// problem.clear(n), then dfree and the blocks from every constraint. False
// (after an error on `owner`) when the blocks do not cover the rows exactly.
bool fill_constraint_problem(ConstraintScope& scope, const ConstraintParams& p, int n, ConstraintProblem& problem,
                             Component& owner);

// W += every active correction's compliance, then regularisation on the diagonal.
void add_compliances(ConstraintScope& scope, const ConstraintParams& p, ConstraintProblem& problem,
                     double regularization);

// Every active correction applies the motion correction of λ (order of p),
// then `dx` is projected and propagated to mapped states.
void apply_corrections(ConstraintScope& scope, const ConstraintParams& p, const std::vector<double>& lambda, int x_out,
                       int v_out, int dx);

}  // namespace sinew
