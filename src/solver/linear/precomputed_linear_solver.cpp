#include "solver/linear/precomputed_linear_solver.h"

#include <Eigen/SparseCholesky>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void PrecomputedLinearSolver::init() {
  if (verbose.is_set()) msg_warning("'verbose' is deprecated and has no effect");
  MatrixLinearSolver::init();
}

void PrecomputedLinearSolver::invert(const BlockCsrMatrix& A) {
  if (computed_) return;
  const Eigen::Index n = static_cast<Eigen::Index>(A.size());
  const bool has_ode = !node()->solvers.empty();
  const double fact_int = has_ode ? node()->dt.value() : 1.0;
  std::ostringstream file;
  file << node()->name.value() << "-" << n << "-" << fact_int << ".comp";
  minv_.resize(n, n);
  bool loaded = false;
  if (use_file.value() && std::filesystem::exists(file.str())) {
    std::ifstream in(file.str(), std::ios::binary);
    std::vector<double> buf(static_cast<std::size_t>(n * n));
    in.read(reinterpret_cast<char*>(buf.data()), static_cast<std::streamsize>(buf.size() * sizeof(double)));
    if (in) {
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) minv_(i, j) = buf[static_cast<std::size_t>(i * n + j)];
      loaded = true;
      msg_info("inverse read from " + file.str());
    }
  }
  if (!loaded) {
    std::vector<int> rb, ci;
    std::vector<double> v;
    A.to_filtered_csr(rb, ci, v);
    Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor, int>> map(static_cast<int>(n), static_cast<int>(n),
                                                                             static_cast<int>(v.size()), rb.data(),
                                                                             ci.data(), v.data());
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int> M = map;
    Eigen::SimplicialLLT<Eigen::SparseMatrix<double, Eigen::ColMajor, int>> llt;
    llt.compute(M);
    if (llt.info() != Eigen::Success) {
      msg_error("Solver cannot factorize: the system matrix is singular or not positive definite");
      minv_.setZero();
    } else {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n), col(n);
      for (Eigen::Index j = 0; j < n; ++j) {
        e[j] = 1.0;
        col = llt.solve(e);
        e[j] = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) minv_(j, i) = col[i] * fact_int;
      }
    }
    if (use_file.value()) {
      std::ofstream out(file.str(), std::ios::binary);
      std::vector<double> buf(static_cast<std::size_t>(n * n));
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) buf[static_cast<std::size_t>(i * n + j)] = minv_(i, j);
      out.write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(buf.size() * sizeof(double)));
    }
  }
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) minv_(i, j) /= fact_int;
  if (linear_system) linear_system->enable_assembly.set(false);
  computed_ = true;
}

void PrecomputedLinearSolver::solve(const BlockCsrMatrix&, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = minv_.rows();
  x.resize(b.size());
  if (n != b.size()) {
    x.setZero();
    return;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    double s = 0;
    for (Eigen::Index j = 0; j < n; ++j) s += minv_(i, j) * b[j];
    x[i] = s;
  }
}

void register_precomputed_linear_solver(Registry& r) {
  ComponentInfo info;
  info.name = "PrecomputedLinearSolver";
  info.category = "LinearSolver/Direct";
  info.description = "inverts the first assembled matrix once (dense) and reuses it";
  info.templates = {"CompressedRowSparseMatrixd"};
  info.default_template = "CompressedRowSparseMatrixd";
  info.create = creator<PrecomputedLinearSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
