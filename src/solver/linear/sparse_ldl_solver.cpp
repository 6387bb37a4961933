#include "solver/linear/sparse_ldl_solver.h"

#include <algorithm>

#include <cmath>

extern "C" {
#include <ldl.h>
}

#include "core/registry.h"

namespace sinew {

void SparseLDLSolver::init() {
  if (saving_matrix_to_file.is_set())
    msg_warning("'savingMatrixToFile' is deprecated and has no effect");
  MatrixLinearSolver::init();
  find_or_create_ordering(*this, ordering_method);
}

void SparseLDLSolver::invert(const BlockCsrMatrix& A) {
  factorized_ = false;
  A.to_filtered_csr(rb_, ci_, vals_);
  n_ = static_cast<int>(A.size());
  if (n_ == 0) {
    msg_warning("Invalid Linear System to solve (null size). Please ensure that there are DoFs to solve.");
    return;
  }
  const bool new_pattern = !have_symbolic_ || rb_ != prev_rb_ || ci_ != prev_ci_;
  if (new_pattern || !precompute_symbolic_decomposition.value()) {
    OrderingMethod* ordering = find_or_create_ordering(*this, ordering_method);
    if (ordering) {
      ordering->compute_permutation(n_, rb_.data(), ci_.data(), perm_);
    } else {
      perm_.resize(static_cast<std::size_t>(n_));
      for (int i = 0; i < n_; ++i) perm_[static_cast<std::size_t>(i)] = i;
    }
    const std::size_t n = static_cast<std::size_t>(n_);
    invperm_.assign(n, 0);
    lp_.assign(n + 1, 0);
    parent_.assign(n, 0);
    lnz_.assign(n, 0);
    flag_.assign(n, 0);
    ldl_symbolic(n_, rb_.data(), ci_.data(), lp_.data(), parent_.data(), lnz_.data(), flag_.data(), perm_.data(),
                 invperm_.data());
    const int nnz = lp_[n];
    li_.assign(static_cast<std::size_t>(nnz), 0);
    lx_.assign(static_cast<std::size_t>(nnz), 0.0);
    d_.assign(n, 0.0);
    inv_d_.assign(n, 0.0);
    y_.assign(n, 0.0);
    t_.assign(n, 0.0);
    pattern_.assign(n, 0);
    l_nnz.set(nnz);
    prev_rb_ = rb_;
    prev_ci_ = ci_;
    have_symbolic_ = true;
    ++symbolic_count_;
  }
  const int k = ldl_numeric(n_, rb_.data(), ci_.data(), vals_.data(), lp_.data(), parent_.data(), lnz_.data(),
                            li_.data(), lx_.data(), d_.data(), y_.data(), pattern_.data(), flag_.data(), perm_.data(),
                            invperm_.data());
  if (k != n_) {
    msg_error("Failed to factorize, D(k,k) is zero (k = " + std::to_string(k) +
              "): the system matrix is singular (are there fixed points?)");
    return;
  }
  bool negative = false;
  for (int i = 0; i < n_; ++i) {
    const double d = d_[static_cast<std::size_t>(i)];
    if (!std::isfinite(d)) {
      msg_error("Failed to factorize: non-finite pivot at row " + std::to_string(i) + " (the system matrix has NaNs)");
      return;
    }
    if (d < 0) negative = true;
    inv_d_[static_cast<std::size_t>(i)] = 1.0 / d;
  }
  if (negative && !warned_indefinite_) {
    warned_indefinite_ = true;
    msg_warning("the system matrix is not positive definite (negative pivots in LDLᵀ); check for negative stiffness");
  }
  factorized_ = true;
}

void SparseLDLSolver::solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  if (x.size() != n) x.setZero(n);
  if (!factorized_ || n != n_) {
    x.setZero();
    return;
  }
  double* t = t_.data();
  for (int i = 0; i < n_; ++i) t[i] = b[perm_[static_cast<std::size_t>(i)]];
  ldl_lsolve(n_, t, lp_.data(), li_.data(), lx_.data());
  for (int i = 0; i < n_; ++i) t[i] *= inv_d_[static_cast<std::size_t>(i)];
  ldl_ltsolve(n_, t, lp_.data(), li_.data(), lx_.data());
  for (int i = 0; i < n_; ++i) x[perm_[static_cast<std::size_t>(i)]] = t[i];
}

void SparseLDLSolver::add_jminvjt(Eigen::MatrixXd& result, const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J,
                                  double fact) {
  MatrixLinearSystem* sys = system();
  if (!sys) return;
  if (sys->matrix_changed()) {
    invert(sys->matrix());
    sys->clear_matrix_changed();
  }
  const Eigen::Index m = J.rows();
  if (result.rows() < m || result.cols() < m) result.conservativeResize(m, m);
  if (!factorized_ || J.cols() != n_) return MatrixLinearSolver::add_jminvjt(result, J, fact);
  const std::size_t n = static_cast<std::size_t>(n_);
  reach_mark_.assign(n, -1);
  dense_.assign(n, 0.0);
  y_start_.assign(1, 0);
  y_idx_.clear();
  y_val_.clear();
  for (Eigen::Index row = 0; row < m; ++row) {
    // Pattern of L⁻¹·b: the etree paths from b's non-zeros to the root.
    reach_.clear();
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(J, row); it; ++it) {
      for (int k = invperm_[static_cast<std::size_t>(it.col())]; k != -1 && reach_mark_[k] != row;
           k = parent_[static_cast<std::size_t>(k)]) {
        reach_mark_[k] = static_cast<int>(row);
        reach_.push_back(k);
      }
    }
    std::sort(reach_.begin(), reach_.end());  // children before parents
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(J, row); it; ++it)
      dense_[static_cast<std::size_t>(invperm_[static_cast<std::size_t>(it.col())])] += it.value();
    // Forward solve on the pattern (ldl_lsolve restricted to it).
    for (int k : reach_) {
      const double yk = dense_[static_cast<std::size_t>(k)];
      if (yk == 0.0) continue;
      for (int p = lp_[static_cast<std::size_t>(k)]; p < lp_[static_cast<std::size_t>(k) + 1]; ++p)
        dense_[static_cast<std::size_t>(li_[static_cast<std::size_t>(p)])] -= lx_[static_cast<std::size_t>(p)] * yk;
    }
    for (int k : reach_) {
      y_idx_.push_back(k);
      y_val_.push_back(dense_[static_cast<std::size_t>(k)]);
      dense_[static_cast<std::size_t>(k)] = 0.0;
    }
    y_start_.push_back(static_cast<int>(y_idx_.size()));
  }
  // result(r1, r2) += fact · Σ_k y_r1[k] · y_r2[k] / d_k (symmetric).
  for (Eigen::Index r1 = 0; r1 < m; ++r1) {
    const int b1 = y_start_[static_cast<std::size_t>(r1)], e1 = y_start_[static_cast<std::size_t>(r1) + 1];
    if (b1 == e1) continue;
    for (int p = b1; p < e1; ++p)
      dense_[static_cast<std::size_t>(y_idx_[static_cast<std::size_t>(p)])] =
          y_val_[static_cast<std::size_t>(p)] * inv_d_[static_cast<std::size_t>(y_idx_[static_cast<std::size_t>(p)])];
    for (Eigen::Index r2 = r1; r2 < m; ++r2) {
      double acc = 0.0;
      for (int p = y_start_[static_cast<std::size_t>(r2)]; p < y_start_[static_cast<std::size_t>(r2) + 1]; ++p)
        acc += y_val_[static_cast<std::size_t>(p)] * dense_[static_cast<std::size_t>(y_idx_[static_cast<std::size_t>(p)])];
      if (acc == 0.0) continue;
      result(r1, r2) += fact * acc;
      if (r2 != r1) result(r2, r1) += fact * acc;
    }
    for (int p = b1; p < e1; ++p) dense_[static_cast<std::size_t>(y_idx_[static_cast<std::size_t>(p)])] = 0.0;
  }
}

void register_sparse_ldl_solver(Registry& r) {
  ComponentInfo info;
  info.name = "SparseLDLSolver";
  info.category = "LinearSolver/Direct";
  info.description = "direct LDLᵀ solver on the assembled sparse system";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<SparseLDLSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
