// SparseLDLSolver: direct LDLᵀ solver on the assembled system
// (spec/solvers.md §3.4). Templates CompressedRowSparseMatrixd (default) and
// CompressedRowSparseMatrixMat3x3d (the block template only changes the
// assembly; the factorization is always scalar).
//
// invert: exactly non-zero entries of A as a scalar CRS read as CSC (A is
// symmetric); ordering + symbolic factorization when the pattern changed (or
// always without precomputeSymbolicDecomposition); numeric factorization
// (SuiteSparse LDL, up-looking, reads one triangle of the permuted matrix).
// A zero pivot is reported as an error and the solve returns 0.
#pragma once

#include <vector>

#include "solver/linear/matrix_linear_solver.h"
#include "solver/linear/ordering_method.h"

namespace sinew {

class SparseLDLSolver final : public MatrixLinearSolver {
 public:
  Field<bool> precompute_symbolic_decomposition{
      this, "precomputeSymbolicDecomposition", true,
      "reuse the symbolic factorisation while the sparsity pattern is unchanged", "Solver"};
  Field<int> l_nnz{this, "L_nnz", 0, "non-zeros of the L factor (output)", "Solver"};
  Field<bool> saving_matrix_to_file{this, "savingMatrixToFile", false, "deprecated: has no effect", "Solver"};
  Link<OrderingMethod> ordering_method{this, "orderingMethod", "fill-reducing ordering (default: AMD)"};

  void init() override;
  // J·A⁻¹·Jᵀ = Yᵀ·D⁻¹·Y with Y = L⁻¹·P·Jᵀ: one forward solve per row of J,
  // restricted to the rows its few non-zeros reach in the elimination tree
  // (sparse right-hand side), then sparse dot products.
  void add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                   double fact) override;
  // Symbolic factorizations done so far (tests).
  long symbolic_count() const { return symbolic_count_; }
  bool factorized() const { return factorized_; }

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;

 private:
  int n_ = 0;
  std::vector<int> rb_, ci_, prev_rb_, prev_ci_;
  std::vector<double> vals_;
  std::vector<int> perm_, invperm_, lp_, parent_, lnz_, flag_, li_, pattern_;
  std::vector<double> lx_, d_, inv_d_, y_, t_;
  bool factorized_ = false, have_symbolic_ = false, warned_indefinite_ = false;
  // add_jminvjt scratch: Y by column (row of J), its pattern in increasing order.
  std::vector<int> y_start_, y_idx_, reach_mark_, reach_;
  std::vector<double> y_val_, dense_;
  long symbolic_count_ = 0;
};

}  // namespace sinew
