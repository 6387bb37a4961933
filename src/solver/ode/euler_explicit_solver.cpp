#include "solver/ode/euler_explicit_solver.h"

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void EulerExplicitSolver::init() {
  if (!linear_solver) linear_solver.set(node()->find_up<LinearSolver>());
  acc_ = MechanicalOps::alloc_vec();
}

void EulerExplicitSolver::solve(double dt, int x_result, int v_result) {
  MechanicalOps& ops = scope();
  const double h = dt;

  if (v_result != kVelocity) ops.v_eq(v_result, kVelocity);
  ops.add_separate_gravity(h, v_result);  // before the forces (trap 16)
  ops.compute_force(kForce);

  // The mass can be inverted directly when every mass is diagonal and none sits on a mapped state.
  bool diagonal = true;
  for (Mass* m : ops.masses())
    if (!m->is_diagonal() || !m->mstate->independent()) diagonal = false;
  if (diagonal) {
    ops.acc_from_f(acc_, kForce);
    ops.project_response(acc_);
  } else {
    ops.project_response(kForce);
    if (!linear_solver) {
      msg_error("the mass is not diagonal: a linear solver is needed (none found in this node or above)");
      set_state(ComponentState::invalid);
      return;
    }
    linear_solver->build_system(ops, 1.0, 0.0, 0.0);
    linear_solver->solve_system(ops, acc_, kForce);
  }

  if (symplectic.value()) {
    ops.v_integrate(v_result, acc_, h, x_result, kPosition, h);
  } else {
    // Positions move with the velocity of the start of the step.
    for (MechanicalState* s : ops.independent_states()) s->add_deriv_to_coord(x_result, kPosition, v_result, h);
    ops.v_peq(v_result, acc_, h);
  }
}

void register_euler_explicit_solver(Registry& r) {
  ComponentInfo info;
  info.name = "EulerExplicitSolver";
  info.category = "Solver/ODE";
  info.description = "explicit (forward) Euler time integration, symplectic by default";
  info.create = creator<EulerExplicitSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
