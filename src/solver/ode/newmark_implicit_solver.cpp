#include "solver/ode/newmark_implicit_solver.h"

#include <cmath>

#include "core/node.h"
#include "core/profile.h"
#include "core/registry.h"

namespace sinew {

LinearSolver* NewmarkImplicitSolver::linear_solver() const { return node()->find_down<LinearSolver>(); }

void NewmarkImplicitSolver::init() {
  if (!linear_solver()) {
    msg_error("no linear solver found in this node or below it");
    set_state(ComponentState::invalid);
    return;
  }
  for (int* id : {&a_, &a_result_, &b_}) *id = MechanicalOps::alloc_vec();
}

void NewmarkImplicitSolver::solve(double dt, int x_result, int v_result) {
  MechanicalOps& ops = scope();
  StepProfile& profile = node()->root()->profile();
  LinearSolver* ls = linear_solver();
  if (!ls) {
    msg_error("no linear solver found in this node or below it");
    set_state(ComponentState::invalid);
    return;
  }
  const double h = dt, g = gamma.value(), be = beta.value();
  const double rM = rayleigh_mass.value(), rK = rayleigh_stiffness.value();
  const int pos = kPosition, vel = kVelocity;

  // The stored acceleration: computed on the first step (projections at time 0, as SOFA does);
  // a later step starting at time 0 (after a reset) gets a fresh zero vector, as in SOFA.
  if (steps_ == 0) {
    ops.v_clear(a_);
    ops.project_position(pos, 0.0);
    ops.project_velocity(vel, 0.0);
    ops.propagate_x_and_v(pos, vel);
    ops.compute_force(kForce);
    ops.acc_from_f(a_, kForce);
    ops.project_response(a_);
  } else if (node()->time.value() == 0.0) {
    ops.v_clear(a_);
  }
  ++steps_;

  // Right-hand side.
  {
    SINEW_TIMED(profile, "solve/forces");
    ops.compute_force(b_);
  }
  if (rM != 0.0 || rK != 0.0 || be != 0.5) {
    ops.propagate_dx(a_);
    ops.add_mbk_dx(b_, -h * (1 - g) * rM, h * (1 - g), h * (1 - g) * rK + h * h * (1 - 2 * be) / 2.0, a_);
  }
  ops.add_mbk_v(b_, -rM, 1.0, rK + h);
  ops.project_response(b_);

  // Solve for the acceleration at the end of the step (a fresh vector each step in SOFA).
  ops.v_clear(a_result_);
  {
    SINEW_TIMED(profile, "solve/build system");
    ls->build_system(ops, 1 + h * g * rM, -h * g, -h * h * be - h * rK * g);
  }
  {
    SINEW_TIMED(profile, "solve/linear solve");
    ls->solve_system(ops, a_result_, b_);
  }

  // x₁ = x + h·v + h²(½−β)·a + h²β·a₁ (term by term), then v₁ = v + h(1−γ)·a + hγ·a₁.
  for (MechanicalState* st : ops.independent_states()) {
    st->add_deriv_to_coord(x_result, pos, vel, h);
    st->add_deriv_to_coord(x_result, x_result, a_, h * h * (0.5 - be));
    st->add_deriv_to_coord(x_result, x_result, a_result_, h * h * be);
  }
  ops.v_op(v_result, vel, a_, h * (1 - g));
  ops.v_peq(v_result, a_result_, h * g);

  ops.add_separate_gravity(h, v_result);
  if (vdamping.value() != 0.0) ops.v_teq(v_result, std::exp(-h * vdamping.value()));

  ops.v_eq(a_, a_result_);
}

void register_newmark_implicit_solver(Registry& r) {
  ComponentInfo info;
  info.name = "NewmarkImplicitSolver";
  info.category = "Solver/ODE";
  info.description = "implicit Newmark time integration (gamma, beta) with Rayleigh damping";
  info.create = creator<NewmarkImplicitSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
