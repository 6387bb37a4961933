#include "solver/linear/eigen_direct_solver.h"

#include <cmath>

#include "core/node.h"

namespace sinew {

void EigenDirectSolver::init() {
  MatrixLinearSolver::init();
  OrderingMethod* o = find_or_create_ordering(*this, ordering_method);
  ordering_name_ = o ? o->method_name() : "AMD";
  factor_ = make(ordering_name_);
  if (!factor_) {
    msg_error("the ordering method '" + ordering_name_ + "' is not supported by this solver");
    set_state(ComponentState::invalid);
  }
}

void EigenDirectSolver::invert(const BlockCsrMatrix& A) {
  factorized_ = false;
  if (!factor_) return;
  A.to_filtered_csr(rb_, ci_, vals_);
  const int n = static_cast<int>(A.size());
  if (n == 0) {
    msg_warning("Invalid Linear System to solve (null size). Please ensure that there are DoFs to solve.");
    return;
  }
  // Eigen's SparseLU and SparseQR never return on some singular inputs (an
  // all-zero matrix loops forever): the input is checked before calling Eigen.
  if (std::string why = check_input(n); !why.empty()) {
    if (!input_reported_) {
      input_reported_ = true;
      msg_error("Solver cannot factorize: " + why);
    }
    return;
  }
  Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor, int>> map(n, n, static_cast<int>(vals_.size()),
                                                                           rb_.data(), ci_.data(), vals_.data());
  matrix_ = map;
  if (!analyzed_ || rb_ != prev_rb_ || ci_ != prev_ci_) {
    factor_->analyze(matrix_);
    prev_rb_ = rb_;
    prev_ci_ = ci_;
    analyzed_ = true;
  }
  factor_->factorize(matrix_);
  switch (factor_->info()) {
    case Eigen::Success: factorized_ = true; break;
    case Eigen::NumericalIssue:
      msg_error("Solver cannot factorize: numerical issue (the system matrix is singular or not positive definite)");
      break;
    case Eigen::NoConvergence: msg_error("Solver cannot factorize: no convergence"); break;
    case Eigen::InvalidInput: msg_error("Solver cannot factorize: invalid input"); break;
  }
}

std::string EigenDirectSolver::check_input(int n) const {
  if (vals_.empty())
    return "the system matrix is zero (no mass, no stiffness: is a mass or a force field missing?)";
  for (std::size_t k = 0; k < vals_.size(); ++k)
    if (!std::isfinite(vals_[k])) {
      std::size_t row = 0;
      while (static_cast<std::size_t>(rb_[row + 1]) <= k) ++row;
      return "the system matrix has a non-finite entry at row " + std::to_string(row) + ", column " +
             std::to_string(ci_[k]);
    }
  int zero_rows = 0, first = -1;
  for (int i = 0; i < n; ++i)
    if (rb_[static_cast<std::size_t>(i)] == rb_[static_cast<std::size_t>(i) + 1]) {
      if (first < 0) first = i;
      ++zero_rows;
    }
  if (zero_rows > 0)
    return "the system matrix is singular: " + std::to_string(zero_rows) + " of its " + std::to_string(n) +
           " rows are zero (first: row " + std::to_string(first) +
           "; a degree of freedom with no mass and no stiffness?)";
  return {};
}

void EigenDirectSolver::solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  if (!factorized_ || b.size() != static_cast<Eigen::Index>(A.size())) {
    x.setZero(b.size());
    return;
  }
  factor_->solve(b, x);
}

}  // namespace sinew
