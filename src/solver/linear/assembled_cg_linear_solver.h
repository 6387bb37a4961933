// AssembledCGLinearSolver: CGLinearSolver on an assembled matrix (templates
// FullMatrix, SparseMatrix, CompressedRowSparseMatrixd and the
// CompressedRowSparseMatrixMat{N}x{N}d block variants; spec/solvers.md §3.1).
// Same XML class as the matrix-free CGLinearSolver (GraphScattered), which
// creates this class for the assembled templates. Same stopping rules:
// ‖r‖/‖b‖ ≤ tolerance, |pᵀAp| ≤ threshold, first solve never stops at
// iteration 1; vector dot products sum scalars sequentially.
#pragma once

#include <memory>

#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class AssembledCGLinearSolver final : public MatrixLinearSolver {
 public:
  Field<unsigned> iterations{this, "iterations", 25, "maximum number of CG iterations", "Solver"};
  Field<double> tolerance{this, "tolerance", 1e-5, "stop when |r|²/|b|² falls below this value", "Solver"};
  Field<double> threshold{this, "threshold", 1e-5, "stop when the CG denominator pᵀAp falls below this value",
                          "Solver"};
  Field<bool> warm_start{this, "warmStart", false, "start from the previous solution instead of zero", "Solver"};

  void init() override;
  int last_iterations() const { return last_iterations_; }

 protected:
  void invert(const BlockCsrMatrix&) override {}
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;

 private:
  Eigen::VectorXd r_, p_, q_;
  long time_step_count_ = 0;
  int last_iterations_ = 0;
};

// Used by CGLinearSolver's registration for the assembled templates.
std::unique_ptr<Component> create_assembled_cg_linear_solver();
const std::vector<std::string>& assembled_cg_templates();

}  // namespace sinew
