// BlockGaussSeidelConstraintSolver (ex ProjectedGaussSeidel,
// spec/interaction.md §5.4.1): projected block Gauss-Seidel on the assembled
// W, blocks swept in row order, each projected by its own law.
#include "constraint/solver/block_gauss_seidel_constraint_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SVD>

#include "constraint/solver/resolution.h"
#include "core/registry.h"

namespace sinew {

void BlockGaussSeidelConstraintSolver::build_system(const ConstraintParams& p) {
  if (!use_svd_for_regularization.value()) return GenericConstraintSolver::build_system(p);
  add_compliances(scope_, p, problem_, 0.0);
  const double reg = regularization_term.value();
  const int n = problem_.n;
  if (n == 0 || reg <= std::numeric_limits<double>::epsilon()) return;
  // Only the rows that take part in the numerical null space of W get the
  // regularisation: those with a large component in a singular vector whose
  // singular value is small next to the largest one.
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> W(problem_.W.data(), n, n);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(W), Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  int begin = -1;
  for (int i = 0; i < n; ++i)
    if (std::fabs(sv(i)) < std::fabs(sv(0)) * svd_value_factor.value()) {
      begin = i;
      break;
    }
  std::vector<bool> in_null_space(n, false);
  for (int i = begin; i != -1 && i < n; ++i)
    for (int j = 0; j < n; ++j)
      in_null_space[j] = in_null_space[j] || std::fabs(svd.matrixV()(j, i)) > svd_vector_factor.value();
  for (int i = 0; i < n; ++i) W(i, i) += in_null_space[i] * reg;
}

void BlockGaussSeidelConstraintSolver::solve_system() {
    ConstraintProblem& P = problem_;
    if (P.n == 0) return;
    double* f = P.f.data();
    for (ConstraintBlock& b : P.blocks) resolution_init(b, P, f);
    const double tol = effective_tolerance();
    const double s = sor.value();
    std::vector<double>& copy = sor_copy_;
    int count = 0;
    bool converged = false;
    double error = 0.0;
    for (int it = 0; it < max_iterations.value(); ++it) {
      ++count;
      bool verified = true;
      if (s != 1.0) copy.assign(P.f.begin(), P.f.end());
      error = 0.0;
      gauss_seidel_sweep(true, tol, error, verified);
      if (s != 1.0)
        for (int j = 0; j < P.n; ++j) f[j] = s * f[j] + (1 - s) * copy[j];
      if (all_verified.value() ? verified : error < tol) {
        converged = true;
        break;
      }
    }
    // SOFA reports one more iteration than it ran.
    iterations_ = count + 1;
    error_ = error;
    converged_ = converged;
    for (ConstraintBlock& b : P.blocks) resolution_store(b, f);
}

void register_block_gauss_seidel_constraint_solver(Registry& r) {
  ComponentInfo info;
  info.name = "BlockGaussSeidelConstraintSolver";
  info.category = "Constraint/Lagrangian/Solver";
  info.description = "projected block Gauss-Seidel on the assembled compliance W";
  info.create = creator<BlockGaussSeidelConstraintSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
