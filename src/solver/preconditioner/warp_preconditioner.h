// WarpPreconditioner: z = R·A₀⁻¹·Rᵀ·r, with A₀ the matrix of an inner
// (direct) linear solver assembled at the last refresh and R the per-point
// rotations since then (template RotationMatrixd; spec/solvers.md §4.4).
// Its linear system is a RotationMatrixSystem (created when absent), which
// assembles the inner solver's system every assemblingRate steps.
#pragma once

#include "solver/linear/matrix_linear_solver.h"
#include "solver/system/rotation_matrix_system.h"

namespace sinew {

class WarpPreconditioner final : public MatrixLinearSolver {
 public:
  Link<LinearSolver> linear_solver{this, "linearSolver", "linear solver factorising the rotated system"};
  Field<unsigned> use_rotation_finder{this, "useRotationFinder", 0u, "deprecated, no effect", "Solver"};
  Field<unsigned> update_step{this, "update_step", 1u, "deprecated: use assemblingRate of RotationMatrixSystem",
                              "Solver"};

  void init() override;
  void bwd_init() override;
  MatrixLinearSolver* inner() const { return inner_; }
  // Constraint corrections: J is rotated (J·R) and handed to the inner solver.
  void add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                   double fact) override;

 protected:
  void invert(const BlockCsrMatrix&) override {}
  void solve(const BlockCsrMatrix& R, Eigen::VectorXd& z, const Eigen::VectorXd& r) override;
  std::string system_template() const override { return "RotationMatrixd"; }

 private:
  RotationMatrixSystem* rotations_ = nullptr;
  MatrixLinearSolver* inner_ = nullptr;
  bool warned_ = false;
};

}  // namespace sinew
