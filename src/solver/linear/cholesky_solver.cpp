#include "solver/linear/cholesky_solver.h"

#include <cmath>
#include <string>

#include "core/registry.h"

namespace sinew {

namespace {
constexpr std::size_t kMaxDenseSize = 20000;  // a dense factor beyond this is gigabytes
}  // namespace

std::string CholeskySolver::system_template() const {
  return template_name().empty() ? std::string("SparseMatrix") : template_name();
}

void CholeskySolver::invert(const BlockCsrMatrix& A) {
  factorized_ = false;
  const std::size_t n = A.size();
  n_ = static_cast<int>(n);
  if (n == 0) return;
  if (n > kMaxDenseSize) {
    msg_error("the system has " + std::to_string(n) + " rows: a dense Cholesky factor would need " +
              std::to_string(n * n * 8 / (1u << 20)) + " MiB; use SparseLDLSolver");
    return;
  }
  const Eigen::MatrixXd M = A.to_dense();
  r_.assign(n * n, 0.0);
  const auto R = [this, n](std::size_t row, std::size_t col) -> double& { return r_[row * n + col]; };
  const auto not_pd = [this](std::size_t j) {
    msg_error("the matrix is not positive definite (pivot " + std::to_string(j) + "): cannot factorize");
  };
  if (!(M(0, 0) > 0)) return not_pd(0);
  double d = 1.0 / std::sqrt(M(0, 0));
  for (std::size_t i = 0; i < n; ++i) R(0, i) = M(static_cast<Eigen::Index>(i), 0) * d;
  for (std::size_t j = 1; j < n; ++j) {
    double ss = 0;
    for (std::size_t k = 0; k < j; ++k) ss += R(k, j) * R(k, j);
    const double pivot = M(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)) - ss;
    if (!(pivot > 0)) return not_pd(j);
    d = 1.0 / std::sqrt(pivot);
    R(j, j) = pivot * d;
    for (std::size_t i = j + 1; i < n; ++i) {
      ss = 0;
      for (std::size_t k = 0; k < j; ++k) ss += R(k, i) * R(k, j);
      R(j, i) = (M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) - ss) * d;
    }
  }
  factorized_ = true;
}

void CholeskySolver::solve(const BlockCsrMatrix&, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  if (x.size() != n) x.resize(n);
  if (!factorized_ || n != n_) {
    x.setZero();
    return;
  }
  const std::size_t un = static_cast<std::size_t>(n);
  const auto R = [this, un](std::size_t row, std::size_t col) { return r_[row * un + col]; };
  // Rᵀ·u = b
  for (std::size_t j = 0; j < un; ++j) {
    double t = 0.0;
    const double d = 1.0 / R(j, j);
    for (std::size_t i = 0; i < j; ++i) t += x[static_cast<Eigen::Index>(i)] * R(i, j);
    x[static_cast<Eigen::Index>(j)] = (b[static_cast<Eigen::Index>(j)] - t) * d;
  }
  // R·x = u
  for (std::size_t j = un; j-- > 0;) {
    double t = 0.0;
    const double d = 1.0 / R(j, j);
    for (std::size_t i = j + 1; i < un; ++i) t += x[static_cast<Eigen::Index>(i)] * R(j, i);
    x[static_cast<Eigen::Index>(j)] = (x[static_cast<Eigen::Index>(j)] - t) * d;
  }
}

void register_cholesky_solver(Registry& r) {
  ComponentInfo info;
  info.name = "CholeskySolver";
  info.category = "LinearSolver/Direct";
  info.description = "direct linear solver based on a dense Cholesky factorization";
  info.templates = {"SparseMatrix", "FullMatrix"};
  info.default_template = "SparseMatrix";
  info.create = creator<CholeskySolver>();
  r.add(std::move(info));
}

}  // namespace sinew
