#include "solver/ode/bdf_ode_solver.h"

#include <algorithm>

#include "core/node.h"
#include "core/profile.h"
#include "core/registry.h"

namespace sinew {

void bdf_coefficients(const std::deque<double>& t, std::vector<double>& a, std::vector<double>& b) {
  const std::size_t s = t.size() - 1;
  a.assign(s + 1, 0.0);
  b.assign(s + 1, 0.0);
  // a_j = L_j'(t_s): Σ_{i≠j} Π_{m≠i,j} (t_s − t_m)/(t_j − t_m) / (t_j − t_i).
  for (std::size_t j = 0; j <= s; ++j) {
    double aj = 0;
    for (std::size_t i = 0; i <= s; ++i) {
      if (i == j) continue;
      double product = 1.0;
      for (std::size_t m = 0; m <= s; ++m)
        if (m != i && m != j) product *= (t[s] - t[m]) / (t[j] - t[m]);
      aj += product / (t[j] - t[i]);
    }
    a[j] = aj;
  }
  const double h = t[s] - t[s - 1];
  for (double& x : a) x *= h;
  for (std::size_t j = 0; j < s; ++j) a[j] /= a[s];
  b[s] = 1 / a[s];
  a[s] = 1;
}

namespace {

// The nonlinear function of one step (see the header): residuals r1, r2 and
// the Newton step over the history slots of the solver.
class BdfStep final : public NonlinearFunction {
 public:
  MechanicalOps* ops = nullptr;
  LinearSolver* ls = nullptr;
  std::size_t s = 1;
  const std::vector<double>* a = nullptr;
  const std::vector<double>* b = nullptr;
  double h = 0, rK = 0, rM = 0, time = 0;
  const std::vector<int>* x = nullptr;
  const std::vector<int>* v = nullptr;
  const std::vector<int>* f = nullptr;
  int r1 = -1, r2 = -1, rhs = -1, dv = -1, dx = -1, vsum = -1;

  double evaluate() override {
    const auto &A = *a, &B = *b;
    const int xs = (*x)[s], vs = (*v)[s], fs = (*f)[s];
    ops->compute_force(fs, true, true, xs, vs);
    ops->add_mbk_dx(fs, -rM, 0.0, rK, vs);  // Rayleigh damping of this state
    ops->project_response(fs);
    ops->v_clear(r1);
    ops->v_clear(r2);
    for (std::size_t i = 0; i <= s; ++i)
      if (A[i] != 0) ops->v_peq(r1, (*x)[i], A[i]);
    for (std::size_t i = 0; i <= s; ++i)
      if (B[i] != 0) ops->v_peq(r1, (*v)[i], -h * B[i]);
    ops->v_clear(vsum);
    for (std::size_t i = 0; i <= s; ++i)
      if (A[i] != 0) ops->v_peq(vsum, (*v)[i], A[i]);
    ops->add_mdx(r2, vsum, 1.0);
    for (std::size_t i = 0; i <= s; ++i)
      if (B[i] != 0) ops->v_peq(r2, (*f)[i], -h * B[i]);
    ops->project_response(r1);
    ops->project_response(r2);
    return ops->v_dot(r2, r2);
  }

  void solve_linear_step() override {
    const double as = (*a)[s], bs = (*b)[s];
    ls->build_system(*ops, as + h * bs * rM, -h * bs, -h * bs * (rK + h * bs / as));
    ops->v_clear(rhs);
    ops->v_peq(rhs, r2, -1.0);
    ops->add_mbk_dx(rhs, 0.0, 0.0, -h * bs / as, r1);
    ops->project_response(rhs);
    ops->v_clear(dv);
    ls->solve_system(*ops, dv, rhs);
  }

  void update(double alpha) override {
    const double as = (*a)[s], bs = (*b)[s];
    const int xs = (*x)[s], vs = (*v)[s];
    ops->v_peq(vs, dv, alpha);
    // Positions follow from r1 = 0 at the new velocity.
    ops->v_clear(dx);
    ops->v_peq(dx, dv, h * bs / as);
    ops->v_peq(dx, r1, -1 / as);
    ops->v_peq(xs, dx);
    ops->project_position(xs, time);
    ops->project_velocity(vs, time);
    ops->propagate_x_and_v(xs, vs);
  }

  double dx_norm2() override { return ops->v_dot(dv, dv); }
  double x_norm2() override { return ops->v_dot((*v)[s], (*v)[s]); }
};

}  // namespace

void BDFOdeSolver::init() {
  if (order.value() > 6) msg_warning("order " + std::to_string(order.value()) + ": the method is not zero-stable");
  if (order.value() == 0) {
    msg_warning("the method cannot have order 0: 1 is used");
    order.set(1u);
  }
  if (!linear_solver) linear_solver.set(node()->find_down<LinearSolver>());
  if (!linear_solver) {
    msg_error("a linear solver is required (in this node or below) but none was found");
    set_state(ComponentState::invalid);
  }
  if (!newton_solver) newton_solver.set(node()->find_down<NewtonRaphsonSolver>());
  if (!newton_solver) {
    msg_error("a NewtonRaphsonSolver is required (in this node or below) but none was found");
    set_state(ComponentState::invalid);
  }
  times_.push_back(node()->time.value());
  for (int* id : {&r1_, &r2_, &rhs_, &dv_, &dx_, &vsum_})
    if (*id < 0) *id = MechanicalOps::alloc_vec();
}

void BDFOdeSolver::reset() {
  // As SOFA: the times and the step count restart; the history slots are kept.
  times_.clear();
  times_.push_back(node()->time.value());
  solves_ = 0;
}

void BDFOdeSolver::solve(double dt, int x_result, int v_result) {
  if (state() != ComponentState::valid) return;
  MechanicalOps& ops = scope();
  if (!checked_states_) {
    // Residuals add positions to derivatives: one layout for both.
    for (MechanicalState* st : ops.independent_states())
      if (st->info().coord_width != st->info().deriv_width) {
        msg_error("only states whose positions and velocities have the same layout (Vec1d to Vec6d) are supported");
        set_state(ComponentState::invalid);
        return;
      }
    checked_states_ = true;
  }
  // Early steps lack history: the order grows with the steps done.
  const std::size_t s = std::max<std::size_t>(std::min<std::size_t>(order.value(), solves_ + 1), 1);
  times_.push_back(node()->time.value() + dt);
  while (times_.size() > s + 1) times_.pop_front();
  bdf_coefficients(times_, a_, b_);

  x_slots_.resize(s + 1, -1);
  v_slots_.resize(s + 1, -1);
  f_slots_.resize(s + 1, -1);
  x_slots_[s - 1] = x_result;
  v_slots_[s - 1] = v_result;
  f_slots_[s - 1] = kForce;
  for (std::size_t i = 0; i <= s; ++i) {
    for (int* id : {&v_slots_[i], &f_slots_[i]})
      if (*id < 0) *id = MechanicalOps::alloc_vec();
    if (x_slots_[i] < 0) x_slots_[i] = MechanicalOps::alloc_coord_vec();
  }

  // First guess: the previous velocity kept, positions moved by it.
  ops.v_eq(x_slots_[s], x_slots_[s - 1]);
  ops.v_eq(v_slots_[s], v_slots_[s - 1]);
  ops.v_peq(x_slots_[s], v_slots_[s], dt);
  ops.propagate_x_and_v(x_slots_[s], v_slots_[s]);

  BdfStep fn;
  fn.ops = &ops;
  fn.ls = linear_solver.get();
  fn.s = s;
  fn.a = &a_;
  fn.b = &b_;
  fn.h = dt;
  fn.rK = rayleigh_stiffness.value();
  fn.rM = rayleigh_mass.value();
  fn.time = node()->time.value();
  fn.x = &x_slots_;
  fn.v = &v_slots_;
  fn.f = &f_slots_;
  fn.r1 = r1_;
  fn.r2 = r2_;
  fn.rhs = rhs_;
  fn.dv = dv_;
  fn.dx = dx_;
  fn.vsum = vsum_;
  newton_solver->solve(fn);

  // Shift the history by one slot (slot s−1 is the state's own vectors).
  for (std::size_t i = 0; i < s; ++i) {
    ops.v_eq(v_slots_[i], v_slots_[i + 1]);
    ops.v_eq(x_slots_[i], x_slots_[i + 1]);
    ops.v_eq(f_slots_[i], f_slots_[i + 1]);
  }
  ++solves_;
}

void register_bdf_ode_solver(Registry& r) {
  ComponentInfo info;
  info.name = "BDFOdeSolver";
  info.category = "Solver/ODE";
  info.description = "backward differentiation formula of any order (velocity-based), solved by Newton-Raphson";
  info.create = creator<BDFOdeSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
