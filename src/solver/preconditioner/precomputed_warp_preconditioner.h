// PrecomputedWarpPreconditioner: z = R·Minv·Rᵀ·r with Minv the dense inverse
// of the system matrix computed once (template Vec3d; spec/solvers.md §4.5).
//
// First invert: systemSize = the linear system's matrixSize; Minv read from
// "<node>-<n>-<dt>.comp" (use_file), shared between instances with the same
// file name (share_matrix), or built by column solves (an internal simplicial
// LLᵀ, or the linked linear solver when its system is assembled) times
// factInt (dt under EulerImplicitSolver, else 1), then divided by factInt.
// Every invert refreshes R from the node's rotation finder.
// Its default system, PrecomputedMatrixSystem, never assembles: the size is 0
// and the preconditioner leaves z untouched (SOFA's observed behaviour: PCG
// then stops at once and nothing moves).
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "math/types.h"
#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class PrecomputedWarpPreconditioner final : public MatrixLinearSolver {
 public:
  using Dense = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  Field<bool> jmjt_twostep{this, "jmjt_twostep", true, "compute J·A⁻¹·Jᵀ in two passes", "Solver"};
  Field<bool> use_file{this, "use_file", true, "store/reuse the precomputed matrix in a file", "Solver"};
  Field<bool> share_matrix{this, "share_matrix", true, "share one in-memory matrix among instances using the same file",
                           "Solver"};
  Link<LinearSolver> linear_solver{this, "linearSolver", "linear solver computing the initial inverse"};
  Field<bool> use_rotations{this, "use_rotations", true,
                            "rotate the precomputed inverse with the current element rotations", "Solver"};
  Field<double> draw_rotations_scale{this, "draw_rotations_scale", 0.0, "size of the drawn rotation frames (viewer)",
                                     "Visualization"};

  void init() override;
  std::size_t system_size() const { return system_size_; }
  const Dense* inverse() const { return minv_.get(); }
  const std::vector<Mat3>& rotations() const { return rot_; }
  // Constraint corrections, as SOFA: result(row_a, row_b) += (float)fact · (J·R·Minv·J_bᵀ)
  // over the non-empty rows of J (the second factor is the unrotated J).
  void add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                   double fact) override;

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& z, const Eigen::VectorXd& r) override;
  std::string system_template() const override { return "CompressedRowSparseMatrixd"; }

 private:
  void load_matrix(const BlockCsrMatrix& A);
  void rotate();

  bool first_ = true, warned_rotation_ = false, rotated_ = false;
  std::size_t system_size_ = 0, nb_dofs_ = 0;
  std::shared_ptr<Dense> minv_;
  std::vector<Mat3> rot_;
  Eigen::VectorXd tmp_, t_;
};

}  // namespace sinew
