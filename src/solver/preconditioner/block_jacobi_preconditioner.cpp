#include "solver/preconditioner/block_jacobi_preconditioner.h"

#include "core/registry.h"

namespace sinew {

bool BlockJacobiPreconditioner::invert3(const Mat3& m, Mat3& out) {
  const double det = m(0, 0) * (m(1, 1) * m(2, 2) - m(2, 1) * m(1, 2)) -
                     m(1, 0) * (m(0, 1) * m(2, 2) - m(2, 1) * m(0, 2)) +
                     m(2, 0) * (m(0, 1) * m(1, 2) - m(1, 1) * m(0, 2));
  out(0, 0) = (m(1, 1) * m(2, 2) - m(2, 1) * m(1, 2)) / det;
  out(0, 1) = (m(2, 1) * m(0, 2) - m(0, 1) * m(2, 2)) / det;
  out(0, 2) = (m(0, 1) * m(1, 2) - m(1, 1) * m(0, 2)) / det;
  out(1, 0) = (m(2, 0) * m(1, 2) - m(1, 0) * m(2, 2)) / det;
  out(1, 1) = (m(0, 0) * m(2, 2) - m(2, 0) * m(0, 2)) / det;
  out(1, 2) = (m(1, 0) * m(0, 2) - m(0, 0) * m(1, 2)) / det;
  out(2, 0) = (m(1, 0) * m(2, 1) - m(2, 0) * m(1, 1)) / det;
  out(2, 1) = (m(2, 0) * m(0, 1) - m(0, 0) * m(2, 1)) / det;
  out(2, 2) = (m(0, 0) * m(1, 1) - m(1, 0) * m(0, 1)) / det;
  return det != 0.0;
}

void BlockJacobiPreconditioner::invert(const BlockCsrMatrix& A) {
  const std::size_t nb = A.size() / 3;
  inv_.assign(nb, Mat3::Identity());
  std::size_t bad = nb;
  for (std::size_t k = 0; k < nb; ++k) {
    Mat3 m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m(i, j) = A.coeff(3 * k + i, 3 * k + j);
    if (!invert3(m, inv_[k]) && bad == nb) bad = k;
  }
  if (A.size() % 3 != 0 && !warned_) {
    warned_ = true;
    msg_error("the system size (" + std::to_string(A.size()) + ") is not a multiple of 3; the last rows are not "
              "preconditioned");
  }
  if (bad != nb && !warned_) {
    warned_ = true;
    msg_error("singular 3×3 diagonal block " + std::to_string(bad) +
              ": the block-Jacobi preconditioner is undefined (infinite values)");
  }
}

void BlockJacobiPreconditioner::solve(const BlockCsrMatrix&, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  if (x.size() != n) x.setZero(n);
  for (std::size_t k = 0; k < inv_.size() && static_cast<Eigen::Index>(3 * k + 2) < n; ++k) {
    const Mat3& m = inv_[k];
    const Eigen::Index o = static_cast<Eigen::Index>(3 * k);
    const double r0 = b[o], r1 = b[o + 1], r2 = b[o + 2];
    x[o] = m(0, 0) * r0 + m(0, 1) * r1 + m(0, 2) * r2;
    x[o + 1] = m(1, 0) * r0 + m(1, 1) * r1 + m(1, 2) * r2;
    x[o + 2] = m(2, 0) * r0 + m(2, 1) * r1 + m(2, 2) * r2;
  }
}

void register_block_jacobi_preconditioner(Registry& r) {
  ComponentInfo info;
  info.name = "BlockJacobiPreconditioner";
  info.category = "LinearSolver/Preconditioner";
  info.description = "block-Jacobi preconditioner: inverses of the 3×3 diagonal blocks of the assembled system";
  info.templates = {"BlockDiagonalMatrixMat3x3d"};
  info.default_template = "BlockDiagonalMatrixMat3x3d";
  info.create = creator<BlockJacobiPreconditioner>();
  r.add(std::move(info));
}

}  // namespace sinew
