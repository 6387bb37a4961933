#include "solver/ode/runge_kutta4_solver.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void RungeKutta4Solver::init() {
  for (int* id : {&k1a_, &k2a_, &k3a_, &k4a_, &k2v_, &k3v_, &k4v_}) *id = MechanicalOps::alloc_vec();
  X_ = MechanicalOps::alloc_coord_vec();
}

void RungeKutta4Solver::acceleration(double t, int X, int V, int a) {
  MechanicalOps& ops = scope();
  ops.project_position(X, t);
  ops.project_velocity(V, t);
  ops.propagate_x_and_v(X, V);
  ops.compute_force(kForce, true, true, X, V);
  ops.acc_from_f(a, kForce);
  ops.project_response(a);
}

void RungeKutta4Solver::solve(double dt, int x_result, int v_result) {
  MechanicalOps& ops = scope();
  const double h = dt, t0 = node()->time.value();
  const double h2 = h / 2.0, h3 = h / 3.0, h6 = h / 6.0;
  const int pos = kPosition, vel = kVelocity;

  ops.add_separate_gravity(h, vel);
  // X is a coordinate vector: positions of each stage, x + s·v.
  auto stage_position = [&](int v, double s) {
    for (MechanicalState* st : ops.independent_states()) st->add_deriv_to_coord(X_, pos, v, s);
  };
  acceleration(t0, pos, vel, k1a_);  // k1v is vel itself
  stage_position(vel, h2);
  ops.v_op(k2v_, vel, k1a_, h2);
  acceleration(t0 + h2, X_, k2v_, k2a_);
  stage_position(k2v_, h2);
  ops.v_op(k3v_, vel, k2a_, h2);
  acceleration(t0 + h2, X_, k3v_, k3a_);
  stage_position(k3v_, h);
  ops.v_op(k4v_, vel, k3a_, h);
  acceleration(t0 + h, X_, k4v_, k4a_);

  // x_new = x + h/6 k1v + h/3 k2v + h/3 k3v + h/6 k4v (left to right), before v_new.
  for (MechanicalState* st : ops.independent_states()) {
    st->add_deriv_to_coord(x_result, pos, vel, h6);
    st->add_deriv_to_coord(x_result, x_result, k2v_, h3);
    st->add_deriv_to_coord(x_result, x_result, k3v_, h3);
    st->add_deriv_to_coord(x_result, x_result, k4v_, h6);
  }
  if (v_result != vel) ops.v_eq(v_result, vel);
  ops.v_peq(v_result, k1a_, h6);
  ops.v_peq(v_result, k2a_, h3);
  ops.v_peq(v_result, k3a_, h3);
  ops.v_peq(v_result, k4a_, h6);
}

void register_runge_kutta4_solver(Registry& r) {
  ComponentInfo info;
  info.name = "RungeKutta4Solver";
  info.category = "Solver/ODE";
  info.description = "explicit fourth-order Runge-Kutta time integration";
  info.create = creator<RungeKutta4Solver>();
  r.add(std::move(info));
}

}  // namespace sinew
