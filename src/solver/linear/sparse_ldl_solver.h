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

#include "solver/linear/ldl_factorization.h"
#include "solver/linear/matrix_linear_solver.h"
#include "solver/linear/ordering_method.h"

namespace sinew {

class SparseLDLSolver : public MatrixLinearSolver {
 public:
  Field<bool> precompute_symbolic_decomposition{
      this, "precomputeSymbolicDecomposition", true,
      "reuse the symbolic factorisation while the sparsity pattern is unchanged", "Solver"};
  Field<int> l_nnz{this, "L_nnz", 0, "non-zeros of the L factor (output)", "Solver"};
  Field<bool> saving_matrix_to_file{this, "savingMatrixToFile", false, "deprecated: has no effect", "Solver"};
  Link<OrderingMethod> ordering_method{this, "orderingMethod", "fill-reducing ordering (default: AMD)"};

  void init() override;
  // J·A⁻¹·Jᵀ with the factorization (ldl_add_jminvjt).
  void add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                   double fact) override;
  // Symbolic factorizations done so far (tests).
  long symbolic_count() const { return factor_->symbolic_count; }
  bool factorized() const { return factor_->factorized; }

 protected:
  void invert(const BlockCsrMatrix& A) override;
  void solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) override;
  // Messages for a factorization's outcome (simulation thread); true when usable.
  bool report(const LdlOutcome& outcome, const LdlFactorization& f);
  // Solves with `f` (zero when it is not usable).
  void solve_with(LdlFactorization& f, Eigen::VectorXd& x, const Eigen::VectorXd& b);

  LdlFactorization first_;
  // The factorization solves use: first_ here; AsyncSparseLDLSolver swaps it.
  LdlFactorization* factor_ = &first_;
  LdlJminvjtScratch jminvjt_;

 private:
  bool warned_indefinite_ = false;
};

}  // namespace sinew
