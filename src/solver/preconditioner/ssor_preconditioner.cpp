#include "solver/preconditioner/ssor_preconditioner.h"

#include "core/registry.h"

namespace sinew {

void SSORPreconditioner::init() {
  if (verbose.is_set())
    msg_warning("Attribute 'verbose' has no use in this component. To disable this warning, remove the attribute "
                "from the scene.");
  MatrixLinearSolver::init();
}

void SSORPreconditioner::invert(const BlockCsrMatrix& A) {
  const std::size_t n = A.size();
  inv_diag_.resize(n);
  std::size_t zero = n;
  for (std::size_t j = 0; j < n; ++j) {
    const double d = A.coeff(j, j);
    if (d == 0.0 && zero == n) zero = j;
    inv_diag_[j] = 1.0 / d;
  }
  if (zero != n && !warned_) {
    warned_ = true;
    msg_error("zero diagonal entry at row " + std::to_string(zero) +
              ": the SSOR preconditioner is undefined (infinite values)");
  }
}

void SSORPreconditioner::solve(const BlockCsrMatrix& A, Eigen::VectorXd& z, const Eigen::VectorXd& r) {
  const long n = static_cast<long>(A.size());
  if (z.size() != n) z.setZero(n);
  if (r.size() != n || static_cast<long>(inv_diag_.size()) != n || !A.has_pattern()) return;
  const double w = omega.value();
  const auto& rb = A.row_begin();
  const auto& cols = A.block_cols();
  const auto& vals = A.values();
  const double* id = inv_diag_.data();

  if (A.block_size() == 1) {
    // (D/ω + U)·t = r, rows from the last one.
    for (long j = n - 1; j >= 0; --j) {
      double temp = 0.0;
      int xi = rb[j];
      while (xi < rb[j + 1] && cols[xi] <= j) ++xi;
      for (; xi < rb[j + 1]; ++xi) temp += z[cols[xi]] * vals[xi];
      z[j] = (r[j] - temp) * w * id[j];
    }
    // (I + ω·D⁻¹·L)·z = t
    for (long j = 0; j < n; ++j) {
      double temp = 0.0;
      for (int xi = rb[j]; xi < rb[j + 1] && cols[xi] < j; ++xi) temp += z[cols[xi]] * vals[xi];
      z[j] -= temp * w * id[j];
    }
    if (w != 1.0)
      for (long j = 0; j < n; ++j) z[j] *= 2 - w;
    return;
  }

  if (A.block_size() != 3) {
    if (!warned_) {
      warned_ = true;
      msg_error("only scalar and 3×3 block matrices are supported; the preconditioner returns 0");
    }
    z.setZero();
    return;
  }
  const long nb = n / 3;
  auto block = [&](int xi, int r1, int c1) { return vals[static_cast<std::size_t>(xi) * 9 + r1 * 3 + c1]; };
  for (long jb = nb - 1; jb >= 0; --jb) {
    const long j0 = jb * 3;
    double temp[3] = {0, 0, 0};
    int xi = rb[jb];
    while (xi < rb[jb + 1] && cols[xi] < jb) ++xi;
    const int diag = xi;  // the pattern always holds the diagonal block
    for (++xi; xi < rb[jb + 1]; ++xi) {
      const long i0 = static_cast<long>(cols[xi]) * 3;
      for (int j1 = 0; j1 < 3; ++j1)
        for (int i1 = 0; i1 < 3; ++i1) temp[j1] += z[i0 + i1] * block(xi, j1, i1);
    }
    for (int j1 = 2; j1 >= 0; --j1) {
      const long j = j0 + j1;
      for (int i1 = j1 + 1; i1 < 3; ++i1) temp[j1] += z[j0 + i1] * block(diag, j1, i1);
      z[j] = (r[j] - temp[j1]) * w * id[j];
    }
  }
  for (long jb = 0; jb < nb; ++jb) {
    const long j0 = jb * 3;
    double temp[3] = {0, 0, 0};
    int xi = rb[jb];
    for (; xi < rb[jb + 1] && cols[xi] < jb; ++xi) {
      const long i0 = static_cast<long>(cols[xi]) * 3;
      for (int j1 = 0; j1 < 3; ++j1)
        for (int i1 = 0; i1 < 3; ++i1) temp[j1] += z[i0 + i1] * block(xi, j1, i1);
    }
    for (int j1 = 0; j1 < 3; ++j1) {
      const long j = j0 + j1;
      for (int i1 = 0; i1 < j1; ++i1) temp[j1] += z[j0 + i1] * block(xi, j1, i1);
      z[j] -= temp[j1] * w * id[j];
    }
  }
}

void register_ssor_preconditioner(Registry& r) {
  ComponentInfo info;
  info.name = "SSORPreconditioner";
  info.category = "LinearSolver/Preconditioner";
  info.description = "Symmetric Successive Over-Relaxation preconditioner on the assembled system";
  info.templates = {"CompressedRowSparseMatrixd", "CompressedRowSparseMatrixMat3x3d"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.aliases = {"SSORLinearSolver", "SSORSolver"};
  info.create = creator<SSORPreconditioner>();
  r.add(std::move(info));
}

}  // namespace sinew
