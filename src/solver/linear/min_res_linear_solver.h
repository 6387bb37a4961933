// MinResLinearSolver: unpreconditioned MINRES (tminres port), matrix-free
// (template GraphScattered, the default; spec/solvers.md §3.3). The assembled
// templates (FullMatrix, SparseMatrix, CompressedRowSparseMatrix{d,Mat NxN d})
// create AssembledMinResLinearSolver, the same iteration on the matrix of a
// MatrixLinearSystem.
//
// Warm-started from the incoming x (the ODE's previous solution). Stops on
// the tminres tests (‖r‖/(‖A‖‖x‖) ≤ tolerance, ‖Ar‖/(‖A‖‖r‖) ≤ tolerance,
// conditioning, iteration count); at most `iterations` passes.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/roles.h"
#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class MinResLinearSolver final : public LinearSolver {
 public:
  Field<unsigned> iterations{this, "iterations", 25u, "maximum number of iterations", "Solver"};
  Field<double> tolerance{this, "tolerance", 1e-5,
                          "stop when the residual norm ratio (current / initial) falls below this value", "Solver"};
  Field<bool> verbose{this, "verbose", false, "deprecated: has no effect", "Solver"};
  Field<bool> parallel_inverse_product{this, "parallelInverseProduct", false, "no effect for MinRes", "Solver"};

  void init() override;
  void build_system(MechanicalOps& ops, double m, double b, double k) override;
  void solve_system(MechanicalOps& ops, int x, int rhs) override;

  // Loop passes of the last solve and its "Error" graph (1, then test1 per pass).
  int last_iterations() const { return last_iterations_; }
  const std::vector<double>& graph() const { return graph_; }

  void product(MechanicalOps& ops, int p, int q) const;  // q = A·p (matrix-free, projected)

 private:
  double m_ = 0, b_ = 0, k_ = 0;
  int r1_ = -1, r2_ = -1, y_ = -1, w_ = -1, w2_ = -1, v_ = -1;
  int last_iterations_ = 0;
  std::vector<double> graph_;
};

class AssembledMinResLinearSolver final : public MatrixLinearSolver {
 public:
  Field<unsigned> iterations{this, "iterations", 25u, "maximum number of iterations", "Solver"};
  Field<double> tolerance{this, "tolerance", 1e-5,
                          "stop when the residual norm ratio (current / initial) falls below this value", "Solver"};
  Field<bool> verbose{this, "verbose", false, "deprecated: has no effect", "Solver"};

  void init() override;
  int last_iterations() const { return last_iterations_; }
  const std::vector<double>& graph() const { return graph_; }

 protected:
  void invert(const BlockCsrMatrix&) override {}
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;

 private:
  std::array<Eigen::VectorXd, 6> t_;
  int last_iterations_ = 0;
  std::vector<double> graph_;
};

// Used by MinResLinearSolver's registration for the assembled templates.
std::unique_ptr<Component> create_assembled_min_res_linear_solver();

}  // namespace sinew
