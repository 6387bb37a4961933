#include "constraint/solver/generic_constraint_solver.h"

#include <cmath>
#include <string>

#include "constraint/solver/resolution.h"
#include "core/node.h"
#include "core/simulation.h"
#include "core/value_text.h"

namespace sinew {

void GenericConstraintSolver::init() {
  dx_ = MechanicalOps::alloc_vec();
  if (max_iterations.value() < 0) {
    msg_error("maxIterations must be >= 0");
    set_state(ComponentState::invalid);
  }
}

double GenericConstraintSolver::effective_tolerance() const {
  double tol = tolerance.value();
  if (scale_tolerance.value() && !all_verified.value()) tol *= problem_.n;
  return tol;
}

void GenericConstraintSolver::build_system(const ConstraintParams& p) {
  add_compliances(scope_, p, problem_, regularization_term.value());
}

// A row whose diagonal in W is not positive moves nothing (both sides fixed:
// no constraint correction, or DOFs held by projective constraints); SOFA
// would divide by zero there. Such blocks keep zero forces, with one warning.
void GenericConstraintSolver::disable_rigid_blocks() {
  for (ConstraintBlock& b : problem_.blocks) {
    for (int r = 0; r < b.rows && !b.disabled; ++r) {
      const double w = problem_.w(b.first + r, b.first + r);
      b.disabled = !(w > 0.0) || !std::isfinite(w);
    }
    if (b.disabled && !warned_rigid_rows_) {
      warned_rigid_rows_ = true;
      msg_warning("rows " + std::to_string(b.first) + ".." + std::to_string(b.first + b.rows - 1) +
                  " have no compliance (no constraint correction can move them, or projective constraints hold "
                  "their DoFs): their forces stay zero (warned once)");
    }
  }
}

void GenericConstraintSolver::gauss_seidel_sweep(bool measure_error, double tol, double& error, bool& verified) {
  ConstraintProblem& P = problem_;
  double* f = P.f.data();
  double* d = P.d.data();
  const int n = P.n;
  for (const ConstraintBlock& b : P.blocks) {
    const int j = b.first, nb = b.rows;
    f_old_.assign(f + j, f + j + nb);
    // d = dfree + W·f on the block's rows (full rows, current forces).
    for (int l = 0; l < nb; ++l) {
      const double* wr = &P.W[static_cast<std::size_t>(j + l) * n];
      double s = P.dfree[j + l];
      for (int k = 0; k < n; ++k) s += wr[k] * f[k];
      d[j + l] = s;
    }
    resolution_solve(b, P, d, f);
    if (!measure_error) continue;
    error += resolution_error(b, P, f, f_old_.data(), tol, verified);
  }
}

void GenericConstraintSolver::solve_constraint(const ConstraintParams& p, int x_out, int v_out) {
  sync_constraint_scope(*node(), scope_);
  // prepareStates: the correction vector starts at zero on every state.
  for (MechanicalState* st : scope_.ops->all_states()) {
    std::vector<double>& dx = st->write(vec_for(*st, dx_, kDx));
    std::fill(dx.begin(), dx.end(), 0.0);
  }
  const int n = build_constraint_jacobian(scope_, p, /*project=*/true);
  if (!fill_constraint_problem(scope_, p, n, problem_, *this)) return;
  build_system(p);
  send_event(Event::Kind::build_constraint_system_end);
  disable_rigid_blocks();
  iterations_ = 0;
  error_ = 0.0;
  converged_ = true;
  solve_system();
  current_error.set(error_);
  current_iterations.set(iterations_);
  current_num_constraints.set(problem_.n);
  current_num_constraint_groups.set(static_cast<int>(problem_.blocks.size()));
  if (compute_constraint_forces.value()) constraint_forces.set(problem_.f);
  bool finite = true;
  for (double v : problem_.f) finite = finite && std::isfinite(v);
  if (!finite) {
    msg_error("the constraint forces are not finite after " + std::to_string(iterations_) + " iterations (" +
              std::to_string(problem_.n) + " rows), the solve diverged: no correction applied; " + divergence_hint());
    std::fill(problem_.f.begin(), problem_.f.end(), 0.0);
  } else if (!converged_ && !warned_divergence_) {
    warned_divergence_ = true;
    msg_warning("no convergence after " + std::to_string(iterations_) + " iterations: residual " +
                parse::format_double(error_) + " > tolerance " + parse::format_double(effective_tolerance()) +
                " (" + std::to_string(problem_.n) + " rows); the constraints may contradict each other (warned once)");
  }
  send_event(Event::Kind::solve_constraint_system_end);
  apply_corrections(scope_, p, problem_.f, x_out, v_out, dx_);
  store_lambdas();
}

void GenericConstraintSolver::send_event(Event::Kind kind) {
  Event e{kind};
  propagate_event(*node(), e);
}

void GenericConstraintSolver::store_lambdas() {
  for (MechanicalState* st : scope_.ops->all_states()) {
    Field<FlatVec>* out = st->lambda_field();
    if (!out) continue;
    const int w = st->info().deriv_width;
    FlatVec& L = out->edit();
    L.width = w;
    L.data.assign(st->size() * static_cast<std::size_t>(w), 0.0);
    // After the solve the Jacobian of an independent state is projected: at a DoF fixed
    // by a projective constraint its lambda is 0 (SOFA, which accumulates the lambda of
    // mapped states through the mappings, keeps the unprojected value there).
    ConstraintMatrix& J = st->constraint_jacobian();
    if (J.empty() || J.width() != w) continue;
    J.compress();
    for (const ConstraintMatrix::Row& r : J.rows()) {
      if (r.id < 0 || r.id >= problem_.n) continue;
      const double f = problem_.f[r.id];
      for (int e = r.begin; e < r.end; ++e) {
        const auto dof = static_cast<std::size_t>(J.entries()[e].dof);
        if (dof >= st->size()) continue;
        const double* v = J.value(e);
        for (int c = 0; c < w; ++c) L.data[dof * w + c] += v[c] * f;
      }
    }
  }
}

}  // namespace sinew
