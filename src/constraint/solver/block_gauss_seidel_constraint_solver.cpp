// BlockGaussSeidelConstraintSolver (ex ProjectedGaussSeidel,
// spec/interaction.md §5.4.1): projected block Gauss-Seidel on the assembled
// W, blocks swept in row order, each projected by its own law.
#include "constraint/solver/block_gauss_seidel_constraint_solver.h"

#include "constraint/solver/resolution.h"
#include "core/registry.h"

namespace sinew {

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
