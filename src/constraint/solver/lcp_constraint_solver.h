// LCPConstraintSolver (spec/interaction.md §5.5): contacts as a (nonlinear)
// complementarity problem solved by Gauss-Seidel, built (whole W) or unbuilt
// (diagonal blocks, coupling through the constraint corrections), with a
// warm start from the previous step's forces matched by persistent contact id.
//
// Its own pipeline, not GenericConstraintSolver's: J is not projected by the
// projective constraints, no resolution objects are used (the solver's `mu`
// picks the algorithm: NLCP with 3-row contacts when mu > 0, else 1-row LCP),
// and the corrections apply the forces through apply_contact_force (state
// x, v and dx, as SOFA's applyContactForce).
#pragma once

#include <cstdint>
#include <vector>

#include "constraint/solver/constraint_system.h"
#include "constraint/solver/lcp_gauss_seidel.h"
#include "core/constraint_problem.h"

namespace sinew {

class LCPConstraintSolver : public ConstraintSolver {
 public:
  Field<bool> display_debug{this, "displayDebug", false, "print debug information (no effect here)", "Solver"};
  Field<bool> initial_guess{this, "initial_guess", true,
                            "start from the previous step's forces of the same contacts (persistent ids)", "Solver"};
  Field<bool> build_lcp{this, "build_lcp", true,
                        "assemble the whole compliance W (false: diagonal blocks only, unbuilt Gauss-Seidel)",
                        "Solver"};
  Field<double> tolerance{this, "tolerance", 0.001, "residual error threshold of the Gauss-Seidel iterations",
                          "Solver"};
  Field<int> max_it{this, "maxIt", 1000, "maximum number of Gauss-Seidel iterations", "Solver"};
  Field<double> regularization_term{this, "regularizationTerm", 0.0,
                                    "added to the diagonal of W when greater than machine epsilon", "Solver"};
  Field<double> mu{this, "mu", 0.6,
                   "friction coefficient of the solver; > 0 selects the friction (3-row) algorithm", "Solver"};
  Field<double> min_w{this, "minW", 0.0, "if not 0: constraints with a smaller diagonal compliance get no force",
                      "Solver"};
  Field<double> max_f{this, "maxF", 0.0, "if not 0: constraints whose force reaches it are released", "Solver"};
  Field<std::vector<double>> constraint_forces{this, "constraintForces", {},
                                               "output: λ of the last solve (with computeConstraintForces)", "Stats"};
  Field<bool> compute_constraint_forces{this, "computeConstraintForces", false, "store constraintForces", "Stats"};
  Field<std::vector<int>> group{this, "group", {0}, "constraint groups handled (kept for SOFA; all are)", "Solver"};
  Field<double> show_cell_width{this, "showCellWidth", 0.0, "viewer: distance between constraint cells", "Visual"};
  Field<std::vector<double>> show_translation{this, "showTranslation", {}, "viewer: position of the first cell",
                                              "Visual"};
  // Attributes of older SOFA versions (multigrid resolution, timing): accepted, ignored.
  Field<bool> multi_grid{this, "multi_grid", false, "legacy, ignored", "Legacy"};
  Field<int> multi_grid_levels{this, "multi_grid_levels", 2, "legacy, ignored", "Legacy"};
  Field<int> merge_method{this, "merge_method", 0, "legacy, ignored", "Legacy"};
  Field<double> merge_spatial_step{this, "merge_spatial_step", 2.0, "legacy, ignored", "Legacy"};
  Field<int> merge_local_levels{this, "merge_local_levels", 2, "legacy, ignored", "Legacy"};
  Field<bool> display_time{this, "displayTime", false, "legacy, ignored", "Legacy"};
  Field<bool> show_levels{this, "showLevels", false, "legacy, ignored", "Legacy"};
  Field<std::vector<double>> show_level_translation{this, "showLevelTranslation", {}, "legacy, ignored", "Legacy"};

  void init() override;
  void solve_constraint(const ConstraintParams& p, int x_out, int v_out) override;
  // SOFA's LCP solver corrects the state's own dx vector.
  int dx_vec() const override { return kDx; }

  // The last problem (W is only the diagonal blocks when not build_lcp).
  const ConstraintProblem& problem() const { return problem_; }
  const ConstraintProblem* last_problem() const override { return &problem_; }
  // The forces the last solve started from (the initial guess).
  const std::vector<double>& initial_forces() const { return initial_forces_; }
  const LcpResult& last_result() const { return result_; }

 private:
  void compute_initial_guess();
  void keep_contact_forces();
  void solve_unbuilt_nlcp();
  void solve_unbuilt_lcp();
  // The (up to two) corrections holding `row`; false when none does.
  bool find_owners(int row, ConstraintCorrection*& a, ConstraintCorrection*& b) const;
  bool active(const ConstraintCorrection& cc) const;

  ConstraintScope scope_;
  ConstraintProblem problem_;
  ConstraintParams params_;
  LcpResult result_;
  std::vector<double> initial_forces_;
  // warm start by persistent id
  std::vector<LagrangianConstraint::BlockInfo> infos_;
  std::vector<std::int64_t> ids_;
  struct PrevEntry {
    const LagrangianConstraint* parent;
    std::int64_t id;
    int row;
    int order;  // position in the step's list (a later duplicate id wins)
  };
  struct PrevLines {
    const LagrangianConstraint* parent;
    int lines;
  };
  std::vector<PrevEntry> prev_entries_;  // last step's (constraint, id) → first row, sorted
  std::vector<PrevLines> prev_lines_;    // last step's rows per group, per constraint
  std::vector<double> prev_forces_;
  // unbuilt resolution
  std::vector<int> sequence_;
  std::vector<ConstraintCorrection*> owner1_, owner2_;
  std::vector<ContactBlock33> w33_;
  std::vector<double> d_, df_, lcp_work_;
  bool warned_divergence_ = false, warned_rows_ = false, warned_owner_ = false;
};

}  // namespace sinew
