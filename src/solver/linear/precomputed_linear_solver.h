// PrecomputedLinearSolver: inverts the first assembled matrix once, densely,
// and reuses that inverse for every later solve (spec/solvers.md §3.7).
// Template CompressedRowSparseMatrixd only.
//
// First invert: factInt = dt when the node has an ODE solver (else 1); Minv
// read from "<node>-<n>-<dt>.comp" when use_file and the file exists, else
// built column by column with a simplicial LLᵀ (AMD ordering) as
// A⁻¹·e_j·factInt (and written when use_file); then Minv /= factInt and the
// linked system's assembly is disabled. solve: x = Minv·b.
#pragma once

#include <Eigen/Core>

#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class PrecomputedLinearSolver final : public MatrixLinearSolver {
 public:
  Field<bool> jmjt_twostep{this, "jmjt_twostep", true, "compute J·A⁻¹·Jᵀ in two passes", "Solver"};
  Field<bool> use_file{this, "use_file", true, "store/reuse the precomputed matrix in a file", "Solver"};
  Field<bool> verbose{this, "verbose", false, "deprecated: has no effect", "Solver"};

  void init() override;
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& inverse() const { return minv_; }

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;

 private:
  bool computed_ = false;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> minv_;
};

}  // namespace sinew
