// LdlFactorization: one sparse LDLᵀ factorization of a symmetric matrix
// (SuiteSparse LDL, up-looking, reading one triangle of the permuted matrix),
// as plain data with free functions, so that a solver can hold one
// (SparseLDLSolver) or two and factorize on another thread
// (AsyncSparseLDLSolver).
//
// ldl_load copies the exactly-non-zero entries of A as a scalar CRS (read as
// CSC: A is symmetric). ldl_factorize then orders and factorizes symbolically
// when the pattern changed (or always without `reuse_symbolic`) and
// numerically. ldl_factorize touches nothing but the factorization and the
// ordering component, which is what makes it safe to run on a worker thread
// while the simulation thread assembles the next matrix.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace sinew {

class BlockCsrMatrix;
class OrderingMethod;

struct LdlFactorization {
  int n = 0;
  // A, scalar CRS of its non-zeros; the pattern of the last symbolic factorization.
  std::vector<int> rb, ci, prev_rb, prev_ci;
  std::vector<double> vals;
  // Ordering, elimination tree and factors (L strictly lower, D diagonal).
  std::vector<int> perm, invperm, lp, parent, lnz, flag, li, pattern;
  std::vector<double> lx, d, inv_d, y, t;
  bool factorized = false;
  bool have_symbolic = false;
  long symbolic_count = 0;
};

enum class LdlStatus { ok, empty, zero_pivot, non_finite_pivot };

struct LdlOutcome {
  LdlStatus status = LdlStatus::ok;
  int row = -1;                 // zero or non-finite pivot's row (permuted order)
  bool negative_pivot = false;  // the matrix is not positive definite
};

// Copies A into f (simulation thread; O(nnz)).
void ldl_load(LdlFactorization& f, const BlockCsrMatrix& A);

// Factorizes what ldl_load copied. `ordering` null: natural order.
LdlOutcome ldl_factorize(LdlFactorization& f, OrderingMethod* ordering, bool reuse_symbolic);

// x = A⁻¹·b with the factorization (x and b of size f.n; may alias).
// Precondition: f.factorized.
void ldl_solve(LdlFactorization& f, double* x, const double* b);

// Scratch of ldl_add_jminvjt, kept by its caller between calls.
struct LdlJminvjtScratch {
  std::vector<int> y_start, y_idx, reach_mark, reach;
  std::vector<double> y_val, dense;
};

// result += fact·J·A⁻¹·Jᵀ = fact·Yᵀ·D⁻¹·Y with Y = L⁻¹·P·Jᵀ: one forward solve
// per row of J restricted to the rows its non-zeros reach in the elimination
// tree (sparse right-hand side), then sparse dot products.
// Preconditions: f.factorized, J.cols() == f.n, result at least m×m.
void ldl_add_jminvjt(const LdlFactorization& f, LdlJminvjtScratch& s, Eigen::MatrixXd& result,
                     const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J, double fact);

}  // namespace sinew
