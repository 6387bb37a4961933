// CGLinearSolver: conjugate gradient, matrix-free (template GraphScattered).
//
// Stopping rules exactly as SOFA (spec/solvers.md §3.1): stop when
// ‖r‖/‖b‖ ≤ tolerance (not squared) or |pᵀAp| ≤ threshold (absolute); at the
// very first solve ever, neither test may stop the first iteration.
// A·p is the scope's m·M + b·B + k·K product, projected.
#pragma once

#include "core/roles.h"

namespace sinew {

class CGLinearSolver final : public LinearSolver {
 public:
  Field<unsigned> iterations{this, "iterations", 25, "maximum number of iterations", "Solver"};
  Field<double> tolerance{this, "tolerance", 1e-5, "stop when |r|/|b| ≤ tolerance", "Solver"};
  Field<double> threshold{this, "threshold", 1e-5, "stop when |pᵀAp| ≤ threshold (denominator)", "Solver"};
  Field<bool> warm_start{this, "warmStart", false, "start from the previous solution", "Solver"};
  Field<bool> parallel_inverse_product{this, "parallelInverseProduct", false, "no effect for CG", "Solver"};

  void init() override;
  void bwd_init() override;  // warns about iterations far beyond the system size
  void build_system(MechanicalOps& ops, double m, double b, double k) override;
  void solve_system(MechanicalOps& ops, int x, int rhs) override;

  // Iterations done by the last solve and its last relative residual.
  int last_iterations() const { return last_iterations_; }
  double last_error() const { return last_error_; }

 private:
  void product(MechanicalOps& ops, int p, int q);  // q = A·p

  double m_ = 0, b_ = 0, k_ = 0;
  int r_ = -1, p_ = -1, q_ = -1;
  long time_step_count_ = 0;
  int last_iterations_ = 0;
  bool breakdown_reported_ = false;  // the non-finite step-length warning, once
  double last_error_ = 0;
};

}  // namespace sinew
