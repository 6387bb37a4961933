#include "constraint/solver/nncg_constraint_solver.h"

#include <cmath>

#include "constraint/solver/resolution.h"
#include "core/registry.h"

namespace sinew {

namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

void NNCGConstraintSolver::solve_system() {
  ConstraintProblem& P = problem_;
  const int n = P.n;
  if (n == 0) return;
  lam_.assign(n, 0.0);
  delta_.assign(n, 0.0);
  delta_new_.assign(n, 0.0);
  p_.assign(n, 0.0);
  double* f = P.f.data();
  const double tol = effective_tolerance();
  for (ConstraintBlock& b : P.blocks) resolution_init(b, P, f);

  // A first sweep without error measure gives the first direction.
  double error = 0.0;
  bool verified = true;
  lam_.assign(P.f.begin(), P.f.end());
  gauss_seidel_sweep(false, tol, error, verified);
  for (int j = 0; j < n; ++j) {
    delta_[j] = -(f[j] - lam_[j]);
    p_[j] = -delta_[j];
  }

  // SOFA counts from 1 and reports count + 1; sor is not applied here.
  int count = 0;
  bool converged = false;
  for (int it = 1; it < max_iterations.value(); ++it) {
    ++count;
    verified = true;
    lam_.assign(P.f.begin(), P.f.end());
    error = 0.0;
    gauss_seidel_sweep(true, tol, error, verified);
    if (all_verified.value() ? verified : error < tol) {
      converged = true;
      break;
    }
    for (int j = 0; j < n; ++j) delta_new_[j] = -(f[j] - lam_[j]);
    // β can be 0/0 only if a sweep repeats a sweep that changed nothing,
    // which then converged above; a non-finite force is caught by the caller.
    const double beta = dot(delta_new_, delta_new_) / dot(delta_, delta_);
    delta_.swap(delta_new_);
    if (beta > 1) {
      std::fill(p_.begin(), p_.end(), 0.0);
    } else {
      for (int j = 0; j < n; ++j) {
        f[j] += beta * p_[j];
        p_[j] = beta * p_[j] - delta_[j];
      }
    }
    // Stop when the forces barely move (|Δ_new|, now in delta_). SOFA does
    // not call this convergence, but only uses the flag for its log; it is
    // reported as converged here so that no warning is given for it.
    if (std::sqrt(dot(delta_, delta_)) < tol) {
      converged = true;
      break;
    }
  }
  iterations_ = count + 1;
  error_ = error;
  converged_ = converged;
  for (ConstraintBlock& b : P.blocks) resolution_store(b, f);
}

void register_nncg_constraint_solver(Registry& r) {
  ComponentInfo info;
  info.name = "NNCGConstraintSolver";
  info.category = "Constraint/Lagrangian/Solver";
  info.description = "block Gauss-Seidel accelerated as a nonsmooth nonlinear conjugate gradient";
  info.create = creator<NNCGConstraintSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
