#include "solver/preconditioner/jacobi_preconditioner.h"

#include "core/registry.h"

namespace sinew {

void JacobiPreconditioner::init() {
  if (verbose.is_set())
    msg_warning("Attribute 'verbose' has no use in this component. To disable this warning, remove the attribute "
                "from the scene.");
  MatrixLinearSolver::init();
}

void JacobiPreconditioner::invert(const BlockCsrMatrix& A) {
  // SOFA inverts the diagonal in place; a separate array gives the same values.
  const std::size_t n = A.size();
  inv_.resize(n);
  std::size_t zero = n;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = A.coeff(i, i);
    if (d == 0.0 && zero == n) zero = i;
    inv_[i] = 1.0 / d;
  }
  if (zero != n && !warned_) {
    warned_ = true;
    msg_error("zero diagonal entry at row " + std::to_string(zero) +
              ": the Jacobi preconditioner is undefined (infinite values)");
  }
}

void JacobiPreconditioner::solve(const BlockCsrMatrix&, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  if (x.size() != n) x.setZero(n);
  for (Eigen::Index i = 0; i < n && static_cast<std::size_t>(i) < inv_.size(); ++i)
    x[i] = inv_[static_cast<std::size_t>(i)] * b[i];
}

void register_jacobi_preconditioner(Registry& r) {
  ComponentInfo info;
  info.name = "JacobiPreconditioner";
  info.category = "LinearSolver/Preconditioner";
  info.description = "Jacobi preconditioner: inverse of the diagonal of the assembled system";
  info.templates = {"DiagonalMatrix"};
  info.default_template = "DiagonalMatrix";
  info.aliases = {"JacobiLinearSolver", "JacobiSolver"};
  info.create = creator<JacobiPreconditioner>();
  r.add(std::move(info));
}

}  // namespace sinew
