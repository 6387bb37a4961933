// SVDLinearSolver: solves the assembled system through a singular value
// decomposition of its dense copy (spec/solvers.md §3; SOFA's
// SVDLinearSolver). Templates FullMatrix (default), CompressedRowSparseMatrixd
// and CompressedRowSparseMatrixMat3x3d: the template only changes how the
// system is stored; the decomposition is always dense, O(n³) per assembly:
// for small or ill-conditioned systems. SOFA uses Eigen's JacobiSVD; Sinew
// uses Eigen's divide-and-conquer BDCSVD (the same decomposition to
// round-off): Jacobi sweeps take 40 s per step on FEMBAR's 960 unknowns,
// BDCSVD well under a second.
//
// x = V·S⁺·Uᵀ·b where S⁺ inverts the singular values above
// `minSingularValue` and zeroes the others (a least-squares solution that
// ignores the near-null directions: stabilises rank-deficient systems).
// `conditionNumber` (output) = largest / smallest singular value.
#pragma once

#include <Eigen/SVD>

#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class SVDLinearSolver final : public MatrixLinearSolver {
 public:
  Field<bool> verbose{this, "verbose", false, "print the singular values and vectors at each solve", "Solver"};
  Field<double> min_singular_value{this, "minSingularValue", 1e-6,
                                   "singular values at or below this threshold are treated as zero", "Solver"};
  Field<double> condition_number{this, "conditionNumber", 0.0,
                                 "ratio of the largest to the smallest singular value (output)", "Solver"};

  void init() override;

 protected:
  // The decomposition is computed once per assembled matrix (SOFA recomputes it
  // at every solve of the same matrix: same numbers).
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;
  std::string system_template() const override;

 private:
  Eigen::BDCSVD<Eigen::MatrixXd> svd_;
  Eigen::VectorXd utb_;
  bool decomposed_ = false;
};

}  // namespace sinew
