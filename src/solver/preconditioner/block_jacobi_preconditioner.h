// BlockJacobiPreconditioner: z_b = (A_bb)⁻¹·r_b with A_bb the 3×3 diagonal
// blocks of the assembled system (template BlockDiagonalMatrixMat3x3d only;
// spec/solvers.md §4.2). Blocks are inverted in closed form (cofactors over
// the determinant). Used as the `preconditioner` of PCGLinearSolver.
#pragma once

#include <vector>

#include "math/types.h"
#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class BlockJacobiPreconditioner final : public MatrixLinearSolver {
 public:
  const std::vector<Mat3>& inverse_blocks() const { return inv_; }
  // Closed-form inverse of a 3×3 matrix (SOFA's invertMatrix); false when singular.
  static bool invert3(const Mat3& m, Mat3& out);

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;
  std::string system_template() const override { return "BlockDiagonalMatrixMat3x3d"; }

 private:
  std::vector<Mat3> inv_;
  bool warned_ = false;
};

}  // namespace sinew
