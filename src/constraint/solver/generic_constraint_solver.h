// Base of the Gauss-Seidel family of constraint solvers (SOFA's
// GenericConstraintSolver, spec/interaction.md §5.4): BlockGaussSeidel,
// NNCG (built: the whole W is assembled) and UnbuiltGaussSeidel.
//
// solve_constraint = prepare (zero dx) → build J, dfree, blocks → W (built
// solvers) → solve (the subclass' iterations) → outputs → corrections.
#pragma once

#include <string>
#include <vector>

#include "constraint/solver/constraint_system.h"
#include "core/constraint_problem.h"

namespace sinew {

class GenericConstraintSolver : public ConstraintSolver {
 public:
  Field<int> max_iterations{this, "maxIterations", 1000, "maximum number of iterations", "Solver"};
  Field<double> tolerance{this, "tolerance", 0.001, "residual error threshold to stop iterating", "Solver"};
  Field<double> sor{this, "sor", 1.0, "successive over-relaxation factor (0-2)", "Solver"};
  Field<double> regularization_term{this, "regularizationTerm", 0.0,
                                    "added to the diagonal of W when greater than machine epsilon", "Solver"};
  Field<bool> scale_tolerance{this, "scaleTolerance", true, "scale the tolerance by the number of rows", "Solver"};
  Field<bool> all_verified{this, "allVerified", false, "stop only when every block's error is below the tolerance",
                           "Solver"};
  Field<bool> compute_graphs{this, "computeGraphs", false, "record errors and forces per iteration (viewer)",
                             "Graph"};
  Field<int> current_num_constraints{this, "currentNumConstraints", 0, "output: rows of the last problem", "Stats"};
  Field<int> current_num_constraint_groups{this, "currentNumConstraintGroups", 0,
                                           "output: blocks of the last problem", "Stats"};
  Field<int> current_iterations{this, "currentIterations", 0, "output: iterations of the last solve", "Stats"};
  Field<double> current_error{this, "currentError", 0.0, "output: error at the end of the last solve", "Stats"};
  Field<std::vector<double>> constraint_forces{this, "constraintForces", {},
                                               "output: λ of the last solve (with computeConstraintForces)", "Stats"};
  Field<bool> compute_constraint_forces{this, "computeConstraintForces", false, "store constraintForces", "Stats"};

  GenericConstraintSolver() { max_iterations.add_alias("maxIt"); }

  void init() override;
  void solve_constraint(const ConstraintParams& p, int x_out, int v_out) override;
  int dx_vec() const override { return dx_; }
  const ConstraintProblem& problem() const { return problem_; }
  const ConstraintProblem* last_problem() const override { return &problem_; }

 protected:
  // W (built solvers): every correction's compliance and the regularisation.
  virtual void build_system(const ConstraintParams& p);
  // Finds problem_.f; sets iterations_ and error_, converged_.
  virtual void solve_system() = 0;
  // What to tell the user when the forces come out non-finite.
  virtual std::string divergence_hint() const { return "check the compliance of the constraint corrections"; }
  // The effective tolerance (scaled by the number of rows unless allVerified).
  double effective_tolerance() const;
  // One Gauss-Seidel sweep over the blocks (SOFA's gaussSeidel_increment);
  // with measure_error, adds each block's error and clears `verified` when a
  // line exceeds tol.
  void gauss_seidel_sweep(bool measure_error, double tol, double& error, bool& verified);
  // Marks the blocks with a non-positive diagonal in W (nothing can move them).
  void disable_rigid_blocks();

  ConstraintScope scope_;
  ConstraintProblem problem_;
  int iterations_ = 0;
  double error_ = 0.0;
  bool converged_ = true;

 private:
  // Tells the solver's node and below (SOFA's postBuildSystem / postSolveSystem).
  void send_event(Event::Kind kind);
  // lambda = Jᵀλ on every state of the scope, from the Jacobian each state holds
  // (SOFA's storeConstraintLambdas).
  void store_lambdas();
  int dx_ = -1;
  bool warned_divergence_ = false;
  bool warned_rigid_rows_ = false;
  std::vector<double> f_old_;
};

}  // namespace sinew
