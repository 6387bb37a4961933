// BTDLinearSolver: block-tridiagonal (6×6 blocks) direct solver, block
// Thomas algorithm (spec/solvers.md §3.8). Template BTDMatrix6d only; its
// linear system keeps only the blocks (i,i−1), (i,i), (i,i+1).
//
// invert: α⁻¹₀ = inv(A₀₀), λ₀ = α⁻¹₀·A₀₁; αᵢ⁻¹ = inv(Aᵢᵢ − Bᵢ·λᵢ₋₁) with
// Bᵢ = Aᵢ,ᵢ₋₁, λᵢ = αᵢ⁻¹·Aᵢ,ᵢ₊₁. inv(m) takes 1/m(i,i) when the block is
// (numerically) diagonal, else a full-pivoting inverse.
// solve: forward xᵢ = αᵢ⁻¹(bᵢ − Bᵢ·xᵢ₋₁), backward xᵢ −= λᵢ·xᵢ₊₁.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "solver/linear/matrix_linear_solver.h"

namespace sinew {

class BTDLinearSolver final : public MatrixLinearSolver {
 public:
  using Block = Eigen::Matrix<double, 6, 6>;
  using BlockVec = Eigen::Matrix<double, 6, 1>;

  Field<bool> verbose{this, "verbose", false, "log the system at each iteration", "Solver"};
  Field<bool> show_problem{this, "showProblem", false, "log the partial-solve computations", "Solver"};
  Field<bool> subpart_solve{this, "subpartSolve", false, "solve only the needed part of the system", "Solver"};
  Field<bool> verification{this, "verification", false, "check the partial solve against a full one", "Solver"};
  Field<int> block_size{this, "blockSize", 6, "deprecated: the block size is given by the template", "Solver"};

  void init() override;
  // Inverse of a 6×6 block as BTDLinearSolver computes it (tests).
  static Block invert_block(const Block& m);

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;

 private:
  Block block(const BlockCsrMatrix& A, std::size_t i, std::size_t j) const;
  std::vector<Block> alpha_inv_, lambda_, lower_;
  std::size_t nb_ = 0;
};

}  // namespace sinew
