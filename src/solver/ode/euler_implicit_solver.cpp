#include "solver/ode/euler_implicit_solver.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "core/profile.h"

namespace sinew {

void EulerImplicitSolver::init() {
  if (!linear_solver) linear_solver.set(node()->find_down<LinearSolver>());
  if (!linear_solver) {
    msg_error("no linear solver found in this node or below it");
    set_state(ComponentState::invalid);
    return;
  }
  x_ = MechanicalOps::alloc_vec();
  b_ = MechanicalOps::alloc_vec();
}

void EulerImplicitSolver::solve(double dt, int x_result, int v_result) {
  MechanicalOps& ops = scope();
  StepProfile& profile = node()->root()->profile();
  const double h = dt;
  const double tr = trapezoidal_scheme.value() ? 0.5 : 1.0;
  const double rM = rayleigh_mass.value(), rK = rayleigh_stiffness.value();
  const bool first = first_order.value();

  // Force at the start of the step.
  {
    SINEW_TIMED(profile, "solve/forces");
    ops.compute_force(kForce);
  }

  // Right-hand side.
  ops.v_eq(b_, kForce);
  if (!first) {
    ops.add_mbk_v(b_, -rM, 0.0, h * tr + rK);  // clears b on mapped states first (SOFA default clear=true)
    ops.v_teq(b_, h);
  }
  ops.project_response(b_);

  // System matrix factors.
  double m_fact, b_fact, k_fact;
  if (first) {
    m_fact = 1.0;
    b_fact = 0.0;
    k_fact = -tr * h;
  } else {
    m_fact = 1.0 + tr * h * rM;
    b_fact = -tr * h;
    k_fact = -tr * h * (tr * h + rK);
  }
  {
    SINEW_TIMED(profile, "solve/build system");
    linear_solver->build_system(ops, m_fact, b_fact, k_fact);
  }
  {
    SINEW_TIMED(profile, "solve/linear solve");
    linear_solver->solve_system(ops, x_, b_);
  }

  // v_new = v + Δv (or Δv), x_new = x + h·v_new, in one loop per DOF.
  if (first) {
    ops.v_eq(v_result, x_);
    ops.v_integrate(v_result, x_, 0.0, x_result, kPosition, h);
  } else {
    if (v_result != kVelocity) ops.v_eq(v_result, kVelocity);
    ops.v_integrate(v_result, x_, 1.0, x_result, kPosition, h);
  }
  ops.add_separate_gravity(h, v_result);
  if (vdamping.value() != 0.0) ops.v_teq(v_result, std::exp(-h * vdamping.value()));

  if (compute_residual.value()) {
    // r = M·(v_new − v) − h·f(current state); with v_new and v the same vector the first term vanishes.
    ops.compute_force(kForce);
    ops.project_response(kForce);
    const double ff = ops.v_dot(kForce, kForce);
    residual.set(h * h * ff);
  }
}

void register_euler_implicit_solver(Registry& r) {
  ComponentInfo info;
  info.name = "EulerImplicitSolver";
  info.category = "Solver/ODE";
  info.description = "implicit (backward) Euler time integration with Rayleigh damping";
  info.create = creator<EulerImplicitSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
