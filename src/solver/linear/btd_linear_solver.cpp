#include "solver/linear/btd_linear_solver.h"

#include <Eigen/LU>
#include <cmath>

#include "core/registry.h"

namespace sinew {

void BTDLinearSolver::init() {
  if (block_size.is_set()) msg_warning("'blockSize' is deprecated: the block size is given by the template (6)");
  MatrixLinearSolver::init();
}

BTDLinearSolver::Block BTDLinearSolver::invert_block(const Block& m) {
  Block inv = Block::Zero();
  int i0 = 0;
  for (; i0 < 6; ++i0) {
    bool diagonal = true;
    for (int j = i0 + 1; j < 6; ++j)
      if (std::abs(m(i0, j)) > m(i0, i0) * 1e-10) diagonal = false;
    if (!diagonal) break;
    inv(i0, i0) = 1.0 / m(i0, i0);
  }
  if (i0 < 6) inv = m.fullPivLu().inverse();
  return inv;
}

BTDLinearSolver::Block BTDLinearSolver::block(const BlockCsrMatrix& A, std::size_t i, std::size_t j) const {
  Block b = Block::Zero();
  const std::int64_t s = A.slot(6 * i, 6 * j);
  if (s < 0) return b;
  const double* v = &A.values()[static_cast<std::size_t>(s)];
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) b(r, c) = v[r * 6 + c];
  return b;
}

void BTDLinearSolver::invert(const BlockCsrMatrix& A) {
  if (A.block_size() != 6) {
    msg_error("the system matrix is not made of 6×6 blocks (template BTDMatrix6d expected)");
    nb_ = 0;
    return;
  }
  nb_ = A.size() / 6;
  alpha_inv_.resize(nb_);
  lambda_.resize(nb_);
  lower_.resize(nb_);
  if (nb_ == 0) return;
  alpha_inv_[0] = invert_block(block(A, 0, 0));
  if (nb_ > 1) lambda_[0] = alpha_inv_[0] * block(A, 0, 1);
  for (std::size_t i = 1; i < nb_; ++i) {
    lower_[i] = block(A, i, i - 1);
    alpha_inv_[i] = invert_block(block(A, i, i) - lower_[i] * lambda_[i - 1]);
    if (i + 1 < nb_) lambda_[i] = alpha_inv_[i] * block(A, i, i + 1);
  }
  for (const Block& b : alpha_inv_)
    if (!b.allFinite()) {
      msg_error("Failed to factorize: a diagonal block is singular");
      nb_ = 0;
      return;
    }
}

void BTDLinearSolver::solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  x.setZero(b.size());
  if (nb_ == 0 || static_cast<std::size_t>(b.size()) != nb_ * 6) return;
  auto seg = [](auto& v, std::size_t i) { return v.template segment<6>(static_cast<Eigen::Index>(6 * i)); };
  seg(x, 0) = alpha_inv_[0] * seg(b, 0);
  for (std::size_t i = 1; i < nb_; ++i) {
    const BlockVec r = seg(b, i) - lower_[i] * seg(x, i - 1);
    seg(x, i) = alpha_inv_[i] * r;
  }
  for (std::size_t i = nb_ - 1; i-- > 0;) {
    const BlockVec r = lambda_[i] * seg(x, i + 1);
    seg(x, i) -= r;
  }
}

void register_btd_linear_solver(Registry& r) {
  ComponentInfo info;
  info.name = "BTDLinearSolver";
  info.category = "LinearSolver/Direct";
  info.description = "direct solver for block-tridiagonal systems (6×6 blocks, e.g. beams)";
  info.templates = {"BTDMatrix6d"};
  info.default_template = "BTDMatrix6d";
  info.create = creator<BTDLinearSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
