#include "solver/ode/runge_kutta2_solver.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void RungeKutta2Solver::init() {
  for (int* id : {&acc_, &new_v_}) *id = MechanicalOps::alloc_vec();
  new_x_ = MechanicalOps::alloc_coord_vec();
}

void RungeKutta2Solver::acceleration(double t, int X, int V, int a) {
  MechanicalOps& ops = scope();
  ops.project_position(X, t);
  ops.project_velocity(V, t);
  ops.propagate_x_and_v(X, V);
  ops.compute_force(kForce, true, true, X, V);
  ops.acc_from_f(a, kForce);
  ops.project_response(a);
}

void RungeKutta2Solver::solve(double dt, int x_result, int v_result) {
  MechanicalOps& ops = scope();
  const double h = dt, t0 = node()->time.value();
  const int pos = kPosition, vel = kVelocity;

  ops.add_separate_gravity(h, vel);
  acceleration(t0, pos, vel, acc_);

  // Half step along the derivative: X = x + h/2·v, V = v + h/2·a (one pass per state, x first).
  for (MechanicalState* st : ops.independent_states()) st->add_deriv_to_coord(new_x_, pos, vel, h / 2.0);
  ops.v_op(new_v_, vel, acc_, h / 2.0);
  acceleration(t0 + h / 2.0, new_x_, new_v_, acc_);

  // Full step with the midpoint derivative; positions first (they read the old v when v_result is v).
  for (MechanicalState* st : ops.independent_states()) st->add_deriv_to_coord(x_result, pos, new_v_, h);
  ops.v_op(v_result, vel, acc_, h);
}

void register_runge_kutta2_solver(Registry& r) {
  ComponentInfo info;
  info.name = "RungeKutta2Solver";
  info.category = "Solver/ODE";
  info.description = "explicit second-order Runge-Kutta (midpoint) time integration";
  info.create = creator<RungeKutta2Solver>();
  r.add(std::move(info));
}

}  // namespace sinew
