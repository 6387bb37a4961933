// CholeskySolver: dense Cholesky factorization A = RᵀR of the assembled
// system, then two triangular solves (SOFA's CholeskySolver). Templates
// SparseMatrix (default) and FullMatrix; the factor is dense either way, so
// this is for small systems (O(n³) per assembly, n² memory).
//
// Same operation order as SOFA: R's diagonal is (a_jj − s)·(1/√(a_jj − s)),
// the triangular solves multiply by the inverse diagonal. A non-positive
// pivot (matrix not positive definite) is an error; the solve then returns
// zero instead of NaNs (SOFA reports it and goes on with NaNs).
#pragma once

#include <vector>

#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class CholeskySolver final : public MatrixLinearSolver {
 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;
  std::string system_template() const override;

 private:
  int n_ = 0;
  std::vector<double> r_;  // upper factor R, row-major n×n (R(j, i) for i ≥ j)
  bool factorized_ = false;
};

}  // namespace sinew
