#include "solver/linear/assembled_cg_linear_solver.h"

#include <cmath>

namespace sinew {

namespace {
// Sequential sums, as SOFA's FullVector dot product.
double dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double s = 0;
  const Eigen::Index n = a.size();
  for (Eigen::Index i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}
}  // namespace

std::unique_ptr<Component> create_assembled_cg_linear_solver() { return std::make_unique<AssembledCGLinearSolver>(); }

const std::vector<std::string>& assembled_cg_templates() {
  static const std::vector<std::string> t = {
      "FullMatrix",
      "SparseMatrix",
      "CompressedRowSparseMatrixd",
      "CompressedRowSparseMatrixMat2x2d",
      "CompressedRowSparseMatrixMat3x3d",
      "CompressedRowSparseMatrixMat4x4d",
      "CompressedRowSparseMatrixMat6x6d",
      "CompressedRowSparseMatrixMat8x8d",
  };
  return t;
}

void AssembledCGLinearSolver::init() {
  for (auto* f : {static_cast<BaseField*>(&iterations), static_cast<BaseField*>(&tolerance),
                  static_cast<BaseField*>(&threshold)})
    if (!f->is_set())
      msg_warning("Required data '" + f->name() + "' has not been set. Falling back to default value: " +
                  f->default_text());
  if (tolerance.value() < 0) {
    msg_warning("'tolerance' must be a positive value; reset to 1e-5");
    tolerance.set(1e-5);
  }
  if (threshold.value() < 0) {
    msg_warning("'threshold' must be a positive value; reset to 1e-5");
    threshold.set(1e-5);
  }
  time_step_count_ = 0;
  MatrixLinearSolver::init();
}

void AssembledCGLinearSolver::solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  const bool first_solve = time_step_count_ == 0;
  r_.resize(n);
  p_.resize(n);
  q_.resize(n);
  if (x.size() != n) x.setZero(n);
  if (warm_start.value()) {
    A.mult(x.data(), q_.data());
    for (Eigen::Index i = 0; i < n; ++i) r_[i] = b[i] - q_[i];
  } else {
    x.setZero();
    r_ = b;
  }
  const double nb = std::sqrt(dot(b, b));
  const unsigned max_it = iterations.value();
  const double tol = tolerance.value(), thr = threshold.value();
  last_iterations_ = 0;

  if (nb != 0.0) {
    double rho_prev = 0;
    for (unsigned k = 1; k <= max_it; ++k) {
      const double rho = dot(r_, r_);
      const double err = std::sqrt(rho) / nb;
      if (err <= tol) {
        if (!(k == 1 && first_solve)) break;
        msg_warning("tolerance reached at first iteration of CG. Check the 'tolerance' data field, you might "
                    "decrease it");
      }
      if (k == 1) {
        p_ = r_;
      } else {
        const double beta = rho / rho_prev;
        for (Eigen::Index i = 0; i < n; ++i) p_[i] = p_[i] * beta + r_[i];
      }
      A.mult(p_.data(), q_.data());
      const double den = dot(p_, q_);
      last_iterations_ = static_cast<int>(k);
      if (den == 0.0) {
        msg_warning("den = 0.0, break the iterations");
        break;
      }
      if (std::abs(den) <= thr) {
        if (!(k == 1 && first_solve)) break;
        msg_warning("denominator threshold reached at first iteration of CG. Check the 'threshold' data field, you "
                    "might decrease it");
      }
      const double alpha = rho / den;
      for (Eigen::Index i = 0; i < n; ++i) {
        x[i] += p_[i] * alpha;
        r_[i] += q_[i] * -alpha;
      }
      rho_prev = rho;
    }
  } else if (first_solve) {
    A.mult(r_.data(), q_.data());
    const double den = dot(r_, q_);
    if (den != 0.0 && std::abs(den) <= thr)
      msg_warning("denominator threshold reached at first iteration of CG. Check the 'threshold' data field, you "
                  "might decrease it");
  }
  ++time_step_count_;
}

}  // namespace sinew
