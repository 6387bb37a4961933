#include "solver/linear/min_res_linear_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/mechanical_ops.h"
#include "core/registry.h"
#include "solver/linear/assembled_cg_linear_solver.h"

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

namespace {

// The tminres iteration, written once over a vector backend: V::Handle names a
// vector; the backend provides product (q = A·p), dot, copy (r = a), scale
// (r *= f), peq (r += a·f), residual (r = b + r·(−1)) and clear.
template <class V>
int minres(V& o, typename V::Handle x, typename V::Handle b, typename V::Handle r1, typename V::Handle r2,
           typename V::Handle y, typename V::Handle w, typename V::Handle w2, typename V::Handle v, unsigned max_iter,
           double tol, std::vector<double>& graph) {
  graph.assign(1, 1.0);
  for (auto id : {r1, r2, y, w, w2, v}) o.clear(id);  // temporaries start at zero
  o.product(x, r1);
  o.residual(r1, b);  // r1 = b + r1·(−1)
  double beta1 = o.dot(r1, r1);
  if (!(beta1 > 0)) return 0;  // b − A·x = 0 exactly: x unchanged

  beta1 = std::sqrt(beta1);
  o.copy(y, r1);
  double oldb = 0, beta = beta1, dbar = 0, epsln = 0, oldeps = 0;
  double phi = 0, phibar = beta1, tnorm2 = 0;
  double cs = -1, sn = 0, gmax = 0, gmin = std::numeric_limits<double>::max();
  double alpha = 0, gamma = 0, delta = 0, gbar = 0;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double Anorm = 0, ynorm = 0;
  int passes = 0;

  for (unsigned itn = 0; itn < max_iter; ++itn) {
    passes = static_cast<int>(itn) + 1;
    o.copy(r2, y);
    const double s = 1. / beta;
    o.copy(v, y);
    o.scale(v, s);  // v = y·s
    o.product(v, y);
    if (itn) o.peq(y, r1, -beta / oldb);
    alpha = o.dot(v, y);
    o.peq(y, r2, -alpha / beta);
    std::swap(r1, r2);
    oldb = beta;
    beta = o.dot(y, y);
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
    o.scale(w, -oldeps);
    o.peq(w, w2, -delta);
    o.peq(w, v, 1.0);  // w += v
    o.scale(w, denom);
    o.peq(x, w, phi);

    if (itn == 0 && beta / beta1 < 10.0 * eps) break;

    Anorm = std::sqrt(tnorm2);
    ynorm = std::sqrt(o.dot(x, x));
    const double test1 = phibar / (Anorm * ynorm);
    graph.push_back(test1);
    gmax = std::max(gmax, gamma);
    gmin = std::min(gmin, gamma);
    const double test2 = root / Anorm;
    if (test1 <= 0. || test2 <= 0. || itn >= max_iter - 1 || gmax / gmin >= .1 / eps || Anorm * eps * ynorm >= beta1 ||
        test2 <= tol || test1 <= tol)
      break;
  }
  return passes;
}

// Matrix-free vectors: ids on the scope's independent states (dot sums per DoF first).
struct GraphVectors {
  using Handle = int;
  MechanicalOps& ops;
  const MinResLinearSolver& solver;
  void product(int p, int q) { solver.product(ops, p, q); }
  double dot(int a, int b) { return ops.v_dot(a, b); }
  void copy(int r, int a) { ops.v_eq(r, a); }
  void scale(int r, double f) { ops.v_teq(r, f); }
  void peq(int r, int a, double f) { ops.v_peq(r, a, f); }
  void residual(int r, int b) { ops.v_op(r, b, r, -1.0); }
  void clear(int r) { ops.v_clear(r); }
};

// Assembled vectors (sequential scalar sums, as SOFA's FullVector).
struct FullVectors {
  using Handle = Eigen::VectorXd*;
  const BlockCsrMatrix& A;
  void product(Handle p, Handle q) {
    q->resize(p->size());
    A.mult(p->data(), q->data());
  }
  double dot(Handle a, Handle b) {
    double s = 0;
    for (Eigen::Index i = 0; i < a->size(); ++i) s += (*a)[i] * (*b)[i];
    return s;
  }
  void copy(Handle r, Handle a) { *r = *a; }
  void scale(Handle r, double f) {
    for (Eigen::Index i = 0; i < r->size(); ++i) (*r)[i] *= f;
  }
  void peq(Handle r, Handle a, double f) {
    for (Eigen::Index i = 0; i < r->size(); ++i) (*r)[i] += (*a)[i] * f;
  }
  void residual(Handle r, Handle b) {
    for (Eigen::Index i = 0; i < r->size(); ++i) (*r)[i] = (*b)[i] + (*r)[i] * -1.0;
  }
  void clear(Handle r) { r->setZero(static_cast<Eigen::Index>(A.size())); }
};

}  // namespace

void MinResLinearSolver::solve_system(MechanicalOps& ops, int x, int b) {
  GraphVectors o{ops, *this};
  last_iterations_ = minres(o, x, b, r1_, r2_, y_, w_, w2_, v_, iterations.value(), tolerance.value(), graph_);
  if (!ops.all_finite(x))
    msg_error("the solution is not finite after " + std::to_string(last_iterations_) +
              " MINRES iterations: the system matrix is singular or has non-finite entries");
}

// ---------------------------------------------------------------- assembled templates

std::unique_ptr<Component> create_assembled_min_res_linear_solver() {
  return std::make_unique<AssembledMinResLinearSolver>();
}

void AssembledMinResLinearSolver::init() {
  for (auto* f : {static_cast<BaseField*>(&iterations), static_cast<BaseField*>(&tolerance)})
    if (!f->is_set())
      msg_warning("Required data '" + f->name() + "' has not been set. Falling back to default value: " +
                  f->default_text());
  if (verbose.is_set())
    msg_warning("Attribute 'verbose' has no use in this component. To disable this warning, remove the attribute "
                "from the scene.");
  MatrixLinearSolver::init();
}

void AssembledMinResLinearSolver::solve(const BlockCsrMatrix& A, Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  const Eigen::Index n = b.size();
  if (x.size() != n) x.setZero(n);
  if (static_cast<Eigen::Index>(A.size()) != n) {
    msg_error("System matrix is not setup properly (size " + std::to_string(A.size()) + ", right-hand side " +
              std::to_string(n) + ")");
    return;
  }
  FullVectors o{A};
  Eigen::VectorXd bb = b;
  last_iterations_ = minres(o, &x, &bb, &t_[0], &t_[1], &t_[2], &t_[3], &t_[4], &t_[5], iterations.value(),
                            tolerance.value(), graph_);
  if (!x.allFinite())
    msg_error("the solution is not finite after " + std::to_string(last_iterations_) +
              " MINRES iterations: the system matrix is singular or has non-finite entries");
}

void register_min_res_linear_solver(Registry& r) {
  ComponentInfo info;
  info.name = "MinResLinearSolver";
  info.category = "LinearSolver/Iterative";
  info.description = "MINRES (minimum residual) iterative solver, matrix-free, warm-started from the previous solution";
  info.templates = {"GraphScattered"};
  for (const auto& t : assembled_cg_templates()) info.templates.push_back(t);
  info.default_template = "GraphScattered";
  info.aliases = {"MINRESSolver", "MinResSolver"};
  // Assembled templates: AssembledMinResLinearSolver on a MatrixLinearSystem of that type.
  info.create = [](const std::string& tmpl) -> std::unique_ptr<Component> {
    if (tmpl.empty() || tmpl == "GraphScattered") return std::make_unique<MinResLinearSolver>();
    return create_assembled_min_res_linear_solver();
  };
  r.add(std::move(info));
}

}  // namespace sinew
