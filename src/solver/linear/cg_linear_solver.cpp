#include "solver/linear/cg_linear_solver.h"

#include <algorithm>
#include <cmath>

#include "core/interrupt.h"
#include "core/mechanical_ops.h"
#include "core/registry.h"
#include "core/node.h"
#include "core/profile.h"
#include "solver/linear/assembled_cg_linear_solver.h"

namespace sinew {

namespace {
void warn_if_too_many_iterations(const CGLinearSolver& cg, Node& node) {
  // CG converges in at most n iterations in exact arithmetic; a few times n
  // covers round-off. Far more, with tolerances that never stop it, runs for hours.
  std::vector<MechanicalState*> states;
  node.collect_down(states);
  std::size_t n = 0;
  for (const MechanicalState* s : states) n += s->read(kVelocity).size();
  const double bound = std::max(1000.0, 10.0 * static_cast<double>(n));
  if (cg.iterations.value() > bound)
    cg.msg_warning("iterations = " + std::to_string(cg.iterations.value()) + " is far more than the system size (" +
                std::to_string(n) + " unknowns): CG converges in at most n iterations in exact arithmetic" +
                (cg.tolerance.value() == 0 && cg.threshold.value() == 0
                     ? "; with tolerance and threshold 0 every solve runs all of them"
                     : ""));
}
}  // namespace

void CGLinearSolver::init() {
  for (auto* f : {static_cast<BaseField*>(&iterations), static_cast<BaseField*>(&tolerance),
                  static_cast<BaseField*>(&threshold)})
    if (!f->is_set())
      msg_warning("required field '" + f->name() + "' has not been set; using the default value " +
                  f->default_text());
  if (tolerance.value() < 0) {
    msg_warning("tolerance must be positive; reset to 1e-5");
    tolerance.set(1e-5);
  }
  if (threshold.value() < 0) {
    msg_warning("threshold must be positive; reset to 1e-5");
    threshold.set(1e-5);
  }
  r_ = MechanicalOps::alloc_vec();
  p_ = MechanicalOps::alloc_vec();
  q_ = MechanicalOps::alloc_vec();
  time_step_count_ = 0;
}

void CGLinearSolver::bwd_init() {
  // After every init: the states know their sizes.
  if (node()) warn_if_too_many_iterations(*this, *node());
}

void CGLinearSolver::build_system(MechanicalOps& ops, double m, double b, double k) {
  // Matrix-free: only the factors are kept.
  m_ = m;
  b_ = b;
  k_ = k;
  ops.m_fact = m;
  ops.b_fact = b;
  ops.k_fact = k;
}

void CGLinearSolver::product(MechanicalOps& ops, int p, int q) {
  SINEW_TIMED(ops.node().root()->profile(), "linear solve/matrix-free product");
  ops.propagate_dx_and_reset_df(p, q);
  ops.add_mbk_dx(q, m_, b_, k_, p, /*clear=*/false);
  ops.project_response(q);
}

void CGLinearSolver::solve_system(MechanicalOps& ops, int x, int rhs) {
  const bool first_solve = time_step_count_ == 0;
  if (warm_start.value()) {
    product(ops, x, q_);
    ops.v_op(r_, rhs, q_, -1.0);  // r = b − A·x
  } else {
    ops.v_clear(x);
    ops.v_eq(r_, rhs);
  }
  const double nb = std::sqrt(ops.v_dot(rhs, rhs));
  const unsigned max_it = iterations.value();
  const double tol = tolerance.value(), thr = threshold.value();
  last_iterations_ = 0;
  last_error_ = 0;

  if (nb != 0.0) {
    double rho_prev = 0;
    for (unsigned k = 1; k <= max_it; ++k) {
      if (interrupt_requested()) {
        msg_warning("interrupted after " + std::to_string(k - 1) + " CG iterations");
        break;
      }
      const double rho = ops.v_dot(r_, r_);
      const double err = std::sqrt(rho) / nb;
      last_error_ = err;
      if (err <= tol) {
        // At the very first solve, the first iteration is always performed.
        if (!(k == 1 && first_solve)) break;
        msg_warning("tolerance reached at the first iteration of CG; check the tolerance value");
      }
      if (k == 1) ops.v_eq(p_, r_);
      else ops.v_scale_add(p_, rho / rho_prev, r_);  // p = p·β + r
      product(ops, p_, q_);
      const double den = ops.v_dot(p_, q_);
      last_iterations_ = static_cast<int>(k);
      if (den == 0.0) {
        msg_warning("den = 0.0, breaking the CG iterations");
        break;
      }
      if (std::abs(den) <= thr) {
        if (!(k == 1 && first_solve)) break;
        msg_warning("denominator threshold reached at the first iteration of CG; check the threshold value");
      }
      const double alpha = rho / den;
      // Past convergence with tolerance and threshold 0, rho and den underflow towards
      // denormals and alpha overflows: SOFA's loop then writes inf/NaN into x. Stop at the
      // last finite iterate instead, once said.
      if (!std::isfinite(alpha) || !std::isfinite(rho)) {
        if (!breakdown_reported_)
          msg_warning("CG breakdown at iteration " + std::to_string(k) +
                      " (step length not finite): the iterations stop at the last finite solution");
        breakdown_reported_ = true;
        break;
      }
      ops.v_peq(x, p_, alpha);
      ops.v_peq(r_, q_, -alpha);
      rho_prev = rho;
    }
  } else if (first_solve) {
    product(ops, r_, q_);
    const double den = ops.v_dot(r_, q_);
    if (den != 0.0 && std::abs(den) <= thr)
      msg_warning("denominator threshold reached at the first iteration of CG; check the threshold value");
  }
  ++time_step_count_;
}


void register_cg_linear_solver(Registry& r) {
  ComponentInfo info;
  info.name = "CGLinearSolver";
  info.category = "Solver/Linear";
  info.description = "conjugate gradient, matrix-free (GraphScattered, default) or on an assembled matrix";
  info.templates = {"GraphScattered"};
  for (const auto& t : assembled_cg_templates()) info.templates.push_back(t);
  info.default_template = "GraphScattered";
  // Assembled templates: solver/assembled_cg_linear_solver.h.
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    if (tmpl.empty() || tmpl == "GraphScattered") return std::make_unique<CGLinearSolver>();
    return create_assembled_cg_linear_solver();
  };
  r.add(std::move(info));
}

}  // namespace sinew
