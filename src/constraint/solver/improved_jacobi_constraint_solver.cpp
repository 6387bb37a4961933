#include "constraint/solver/improved_jacobi_constraint_solver.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <Eigen/Eigenvalues>

#include "constraint/solver/resolution.h"
#include "core/registry.h"

namespace sinew {

void ImprovedJacobiConstraintSolver::solve_system() {
  ConstraintProblem& P = problem_;
  const int n = P.n;
  if (n == 0) return;
  double* f = P.f.data();
  double* d = P.d.data();
  std::copy(P.dfree.begin(), P.dfree.end(), P.d.begin());
  std::fill(P.f.begin(), P.f.end(), 0.0);
  last_f_.assign(n, 0.0);
  delta_f_.assign(n, 0.0);
  corrected_d_.assign(n, 0.0);
  const double tol = effective_tolerance();
  // The blocks' init may write warm starts: they count as the first change of force.
  for (ConstraintBlock& b : P.blocks) resolution_init(b, P, f);

  double rho = 1.0;
  if (use_spectral_correction.value()) {
    // SOFA takes the largest std::norm of W's eigenvalues, i.e. |λ|² (W is
    // read as a general matrix); kept as is.
    Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> W(P.W.data(), n, n);
    Eigen::EigenSolver<Eigen::MatrixXd> es(Eigen::MatrixXd(W), /*computeEigenvectors=*/false);
    double radius = 0.0;
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i)
      radius = std::max(radius, std::norm(std::complex<double>(es.eigenvalues()(i))));
    rho = spectral_correction_factor.value() * std::min(1.0, 0.9 * 2 / radius);
  }

  const int max_it = max_iterations.value();
  int count = 0;
  bool converged = false;
  double error = 0.0;
  for (int i = 0; i < max_it; ++i) {
    ++count;
    bool verified = true;
    error = 0.0;
    const double beta =
        use_conjugate_residue.value()
            ? std::min(1.0, std::pow(static_cast<double>(static_cast<float>(i) / max_it),
                                     conjugate_residue_speed_factor.value()))
            : 0.0;
    // d += W·Δf on every row (Jacobi: the same d for every block).
    for (int l = 0; l < n; ++l) {
      const double* wr = &P.W[static_cast<std::size_t>(l) * n];
      for (int k = 0; k < n; ++k) d[l] += wr[k] * delta_f_[k];
      corrected_d_[l] = rho * d[l];
    }
    for (const ConstraintBlock& b : P.blocks) {
      const int j = b.first, nb = b.rows;
      resolution_solve(b, P, corrected_d_.data(), f);
      for (int l = j; l < j + nb; ++l) {
        f[l] += beta * delta_f_[l];
        delta_f_[l] = f[l] - last_f_[l];
        last_f_[l] = f[l];
      }
      // Δf of later blocks still holds the previous iteration's values here (SOFA's order).
      double block_error = 0.0;
      for (int l = j; l < j + nb; ++l) {
        const double* wr = &P.W[static_cast<std::size_t>(l) * n];
        for (int k = 0; k < n; ++k) block_error += std::pow(wr[k] * delta_f_[k], 2);
        verified = verified && block_error < tol * tol;
      }
      error += std::sqrt(block_error);
    }
    if (all_verified.value() ? verified : (error < tol && i > 0)) {
      converged = true;
      break;
    }
  }
  iterations_ = count + 1;
  error_ = error;
  converged_ = converged;
  for (ConstraintBlock& b : P.blocks) resolution_store(b, f);
}

// Plain projected Jacobi (ρ = 1, no extrapolation) overshoots when many rows
// share a body: each block is solved as if the others held still, so their
// corrections add up. SOFA's Contact_ImprovedJacobi.scn diverges this way at
// its first contacts (SOFA's own scene tests skip that scene).
std::string ImprovedJacobiConstraintSolver::divergence_hint() const {
  if (use_spectral_correction.value()) return GenericConstraintSolver::divergence_hint();
  return "projected Jacobi without useSpectralCorrection diverges when many constraints act on one body: set "
         "useSpectralCorrection=\"1\" or use BlockGaussSeidelConstraintSolver";
}

void register_improved_jacobi_constraint_solver(Registry& r) {
  ComponentInfo info;
  info.name = "ImprovedJacobiConstraintSolver";
  info.category = "Constraint/Lagrangian/Solver";
  info.description = "projected Jacobi on the assembled W with spectral and conjugate-residue corrections";
  info.create = creator<ImprovedJacobiConstraintSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
