// SSORPreconditioner: symmetric successive over-relaxation
// (spec/solvers.md §4.3). With A = D + L + U: a backward sweep with the
// upper part, then a forward sweep with the lower part, then z *= (2 − ω)
// when ω ≠ 1. Templates CompressedRowSparseMatrixd (default, scalar sweeps)
// and CompressedRowSparseMatrixMat3x3d (block sweeps: off-diagonal blocks
// first, then inside the diagonal block; no (2 − ω) scaling, as SOFA).
// Legacy names SSORLinearSolver, SSORSolver.
#pragma once

#include <vector>

#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class SSORPreconditioner final : public MatrixLinearSolver {
 public:
  Field<double> omega{this, "omega", 1.0, "relaxation factor ω", "Solver"};
  Field<bool> verbose{this, "verbose", false, "deprecated: has no effect", "Solver"};

  void init() override;

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;

 private:
  std::vector<double> inv_diag_;
  bool warned_ = false;
};

}  // namespace sinew
