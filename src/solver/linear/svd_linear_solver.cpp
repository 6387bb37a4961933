#include "solver/linear/svd_linear_solver.h"

#include <sstream>
#include <string>

#include "core/registry.h"

namespace sinew {

namespace {
// Dense systems beyond this size would take minutes per step and gigabytes.
constexpr std::size_t kMaxDenseSize = 20000;
}  // namespace

std::string SVDLinearSolver::system_template() const {
  // A dense system for FullMatrix; the sparse templates assemble as their name says.
  return template_name().empty() ? std::string("FullMatrix") : template_name();
}

void SVDLinearSolver::init() {
  if (min_singular_value.value() < 0) {
    msg_warning("'minSingularValue' must not be negative; set to 0");
    min_singular_value.set(0.0);
  }
  MatrixLinearSolver::init();
}

void SVDLinearSolver::invert(const BlockCsrMatrix& A) {
  decomposed_ = false;
  if (A.size() == 0) return;
  if (A.size() > kMaxDenseSize) {
    msg_error("the system has " + std::to_string(A.size()) + " rows: a dense SVD of it would need " +
              std::to_string(A.size() * A.size() * 8 / (1u << 20)) + " MiB; use a sparse solver");
    return;
  }
  svd_.compute(A.to_dense(), Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd_.singularValues();
  condition_number.set(s(0) / s(s.size() - 1));
  if (verbose.value()) {
    std::ostringstream os;
    os << "the singular values are:\n" << s.transpose() << "\nleft singular vectors (columns of U):\n"
       << svd_.matrixU() << "\nright singular vectors (columns of V):\n" << svd_.matrixV();
    msg_info(os.str());
  }
  decomposed_ = true;
}

void SVDLinearSolver::solve(const BlockCsrMatrix&, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  if (!decomposed_ || svd_.cols() != n) {
    x.setZero(n);
    return;
  }
  utb_.noalias() = svd_.matrixU().transpose() * b;
  const Eigen::VectorXd& s = svd_.singularValues();
  const double threshold = min_singular_value.value();
  for (Eigen::Index i = 0; i < n; ++i) utb_[i] = s[i] > threshold ? utb_[i] / s[i] : 0.0;
  x.noalias() = svd_.matrixV() * utb_;
}

void register_svd_linear_solver(Registry& r) {
  ComponentInfo info;
  info.name = "SVDLinearSolver";
  info.category = "LinearSolver/Direct";
  info.description = "linear system solver using a singular value decomposition of the dense matrix";
  info.templates = {"FullMatrix", "CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "FullMatrix";
  info.create = creator<SVDLinearSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
