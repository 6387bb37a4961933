#include "solver/min_res_linear_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/mechanical_ops.h"
#include "core/registry.h"

namespace sinew {

void MinResLinearSolver::init() {
  for (auto* f : {static_cast<BaseField*>(&iterations), static_cast<BaseField*>(&tolerance)})
    if (!f->is_set())
      msg_warning("required field '" + f->name() + "' has not been set; using the default value " +
                  f->default_text());
  if (verbose.is_set())
    msg_warning("Attribute 'verbose' has no use in this component. To disable this warning, remove the attribute "
                "from the scene.");
  r1_ = MechanicalOps::alloc_vec();
  r2_ = MechanicalOps::alloc_vec();
  y_ = MechanicalOps::alloc_vec();
  w_ = MechanicalOps::alloc_vec();
  w2_ = MechanicalOps::alloc_vec();
  v_ = MechanicalOps::alloc_vec();
}

void MinResLinearSolver::build_system(MechanicalOps& ops, double m, double b, double k) {
  m_ = m;
  b_ = b;
  k_ = k;
  ops.m_fact = m;
  ops.b_fact = b;
  ops.k_fact = k;
}

void MinResLinearSolver::product(MechanicalOps& ops, int p, int q) const {
  ops.propagate_dx_and_reset_df(p, q);
  ops.add_mbk_dx(q, m_, b_, k_, p, /*clear=*/false);
  ops.project_response(q);
}

void MinResLinearSolver::solve_system(MechanicalOps& ops, int x, int b) {
  const double tol = tolerance.value();
  const unsigned max_iter = iterations.value();
  graph_.assign(1, 1.0);
  last_iterations_ = 0;

  int r1 = r1_, r2 = r2_, w = w_, w2 = w2_;
  const int y = y_, v = v_;
  // Temporaries start at zero at every solve.
  for (int id : {r1, r2, y, w, w2, v}) ops.v_clear(id);

  product(ops, x, r1);
  ops.v_op(r1, b, r1, -1.0);  // r1 = b + r1·(−1)
  double beta1 = ops.v_dot(r1, r1);
  if (!(beta1 > 0)) return;  // b − A·x = 0 exactly: x unchanged

  beta1 = std::sqrt(beta1);
  ops.v_eq(y, r1);
  double oldb = 0, beta = beta1, dbar = 0, epsln = 0, oldeps = 0;
  double phi = 0, phibar = beta1, tnorm2 = 0;
  double cs = -1, sn = 0, gmax = 0, gmin = std::numeric_limits<double>::max();
  double alpha = 0, gamma = 0, delta = 0, gbar = 0;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double Anorm = 0, ynorm = 0;

  for (unsigned itn = 0; itn < max_iter; ++itn) {
    last_iterations_ = static_cast<int>(itn) + 1;
    ops.v_eq(r2, y);
    const double s = 1. / beta;
    ops.v_eq(v, y);
    ops.v_teq(v, s);  // v = y·s
    product(ops, v, y);
    if (itn) ops.v_peq(y, r1, -beta / oldb);
    alpha = ops.v_dot(v, y);
    ops.v_peq(y, r2, -alpha / beta);
    std::swap(r1, r2);
    oldb = beta;
    beta = ops.v_dot(y, y);
    if (beta < 0) break;
    beta = std::sqrt(beta);
    tnorm2 += alpha * alpha + oldb * oldb + beta * beta;

    oldeps = epsln;
    delta = cs * dbar + sn * alpha;
    gbar = sn * dbar - cs * alpha;
    epsln = sn * beta;
    dbar = -cs * beta;
    const double root = std::sqrt(gbar * gbar + dbar * dbar);

    gamma = std::sqrt(gbar * gbar + beta * beta);
    gamma = std::max(gamma, eps);
    const double denom = 1. / gamma;
    cs = gbar * denom;
    sn = beta * denom;
    phi = cs * phibar;
    phibar = sn * phibar;

    std::swap(w, w2);
    ops.v_teq(w, -oldeps);
    ops.v_peq(w, w2, -delta);
    ops.v_peq(w, v, 1.0);  // w += v
    ops.v_teq(w, denom);
    ops.v_peq(x, w, phi);

    if (itn == 0 && beta / beta1 < 10.0 * eps) break;

    Anorm = std::sqrt(tnorm2);
    ynorm = std::sqrt(ops.v_dot(x, x));
    const double test1 = phibar / (Anorm * ynorm);
    graph_.push_back(test1);
    gmax = std::max(gmax, gamma);
    gmin = std::min(gmin, gamma);
    const double test2 = root / Anorm;
    if (test1 <= 0. || test2 <= 0. || itn >= max_iter - 1 || gmax / gmin >= .1 / eps || Anorm * eps * ynorm >= beta1 ||
        test2 <= tol || test1 <= tol)
      break;
  }
  if (!ops.all_finite(x))
    msg_error("the solution is not finite after " + std::to_string(last_iterations_) +
              " MINRES iterations: the system matrix is singular or has non-finite entries");
}

void register_min_res_linear_solver(Registry& r) {
  ComponentInfo info;
  info.name = "MinResLinearSolver";
  info.category = "LinearSolver/Iterative";
  info.description = "MINRES (minimum residual) iterative solver, matrix-free, warm-started from the previous solution";
  info.templates = {"GraphScattered"};
  info.default_template = "GraphScattered";
  info.aliases = {"MINRESSolver", "MinResSolver"};
  info.create = creator<MinResLinearSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
