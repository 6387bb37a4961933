// PreconditionedConjugateResidual (spec: SOFA's constraint solver of that
// name): the built problem W·f = −dfree solved as a linear system by the
// conjugate residual method with a symmetric Jacobi preconditioner (Saad,
// Iterative methods for sparse linear systems, 2003). The blocks' projection
// laws are not applied: it suits bilateral constraints only.
//
// Kept from SOFA: at most min(maxIterations, rows) iterations, no stop at the
// first one, and the per-block error reads the residual at the *iteration*
// index, r[i], not at the block's rows.
#include <cmath>
#include <vector>

#include "constraint/solver/built_constraint_solver.h"
#include "constraint/solver/resolution.h"
#include "core/registry.h"

namespace sinew {

namespace {

class PreconditionedConjugateResidual final : public BuiltConstraintSolver {
 protected:
  void solve_system() override {
    ConstraintProblem& P = problem_;
    const int n = P.n;
    if (n == 0) return;
    r_.assign(n, 0.0);
    p_.assign(n, 0.0);
    wp_.assign(n, 0.0);
    wr_.assign(n, 0.0);
    inv_sqrt_.assign(n, 0.0);
    mw_.assign(static_cast<std::size_t>(n) * n, 0.0);
    for (int j = 0; j < n; ++j) inv_sqrt_[j] = 1.0 / std::sqrt(P.w(j, j));
    // Jacobi preconditioning on both sides keeps MW symmetric; the unknown is then √W_jj·f.
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) mw_[static_cast<std::size_t>(j) * n + k] = P.w(j, k) * inv_sqrt_[j] * inv_sqrt_[k];
    for (int j = 0; j < n; ++j) r_[j] = -P.dfree[j] * inv_sqrt_[j];
    std::fill(P.f.begin(), P.f.end(), 0.0);
    p_ = r_;
    multiply(p_, wp_);
    multiply(r_, wr_);
    double rwr = dot(r_, wr_);
    double tol = tolerance.value();
    if (scale_tolerance.value() && !all_verified.value()) tol *= n;
    const int max_it = std::min(max_iterations.value(), n);
    int count = 0;
    bool converged = false;
    double error = 0.0;
    for (int i = 0; i < max_it; ++i) {
      ++count;
      bool verified = true;
      const double alpha = rwr / dot(wp_, wp_);
      for (int j = 0; j < n; ++j) P.f[j] += p_[j] * alpha;
      for (int j = 0; j < n; ++j) r_[j] += wp_[j] * -alpha;
      multiply(r_, wr_);
      const double old_rwr = rwr;
      rwr = dot(r_, wr_);
      const double beta = rwr / old_rwr;
      for (int j = 0; j < n; ++j) p_[j] = r_[j] + p_[j] * beta;
      error = 0.0;
      for (const ConstraintBlock& b : P.blocks) {
        double e = 0.0;
        for (int l = 0; l < b.rows; ++l) {
          e += r_[i] * r_[i];  // SOFA's index
          verified = verified && e < tol * tol;
        }
        error += std::sqrt(e);
      }
      if (all_verified.value() ? verified : (error < tol && i > 0)) {
        converged = true;
        break;
      }
      for (int j = 0; j < n; ++j) wp_[j] = wr_[j] + wp_[j] * beta;
    }
    for (int j = 0; j < n; ++j) P.f[j] *= inv_sqrt_[j];
    iterations_ = count + 1;
    error_ = error;
    converged_ = converged;
    for (ConstraintBlock& b : P.blocks) resolution_store(b, P.f.data());
  }

 private:
  void multiply(const std::vector<double>& x, std::vector<double>& out) const {
    const int n = problem_.n;
    for (int j = 0; j < n; ++j) {
      double s = 0.0;
      const double* row = &mw_[static_cast<std::size_t>(j) * n];
      for (int k = 0; k < n; ++k) s += row[k] * x[k];
      out[j] = s;
    }
  }
  static double dot(const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
    return s;
  }

  std::vector<double> r_, p_, wp_, wr_, inv_sqrt_, mw_;
};

}  // namespace

void register_preconditioned_conjugate_residual(Registry& r) {
  ComponentInfo info;
  info.name = "PreconditionedConjugateResidual";
  info.category = "Constraint/Lagrangian/Solver";
  info.description = "conjugate residual on W·f = −dfree with a Jacobi preconditioner (bilateral constraints)";
  info.create = creator<PreconditionedConjugateResidual>();
  r.add(std::move(info));
}

}  // namespace sinew
