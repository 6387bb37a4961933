// JacobiPreconditioner: z = D⁻¹·r with D the diagonal of the assembled
// system (template DiagonalMatrix only; spec/solvers.md §4.1). Used as the
// `preconditioner` of PCGLinearSolver. Legacy names JacobiLinearSolver, JacobiSolver.
#pragma once

#include <vector>

#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class JacobiPreconditioner final : public MatrixLinearSolver {
 public:
  Field<bool> verbose{this, "verbose", false, "deprecated: has no effect", "Solver"};

  void init() override;
  // 1/A(i,i) after the last invert (tests).
  const std::vector<double>& inverse_diagonal() const { return inv_; }

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;
  std::string system_template() const override { return "DiagonalMatrix"; }

 private:
  std::vector<double> inv_;
  bool warned_ = false;
};

}  // namespace sinew
