#include "solver/ode/euler_implicit_solver.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "core/timer.h"

namespace sinew {

void EulerImplicitSolver::init() {
  if (!linear_solver) linear_solver.set(node()->find_down<LinearSolver>());
  if (!linear_solver) {
    msg_error("no linear solver found in this node or below it");
    state_ = ComponentState::invalid;
    return;
  }
  x_ = MechanicalOps::alloc_vec();
  b_ = MechanicalOps::alloc_vec();
}

void EulerImplicitSolver::solve(double dt, int x_result, int v_result) {
  if (!ops_) ops_ = std::make_unique<MechanicalOps>(*node());
  MechanicalOps& ops = *ops_;
  const double h = dt;
  const double tr = trapezoidal_scheme.value() ? 0.5 : 1.0;
  const double rM = rayleigh_mass.value(), rK = rayleigh_stiffness.value();
  const bool first = first_order.value();

  // Force at the start of the step.
  {
    SINEW_TIMED("solve/forces");
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
    SINEW_TIMED("solve/build system");
    linear_solver->build_system(ops, m_fact, b_fact, k_fact);
  }
  {
    SINEW_TIMED("solve/linear solve");
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
  if (!ops.all_finite(x_result) || !ops.all_finite(v_result)) {
    // Stop here rather than let NaNs spread: report once, then this solver is off.
    msg_error("the simulation diverged at step " + std::to_string(node()->root()->step_index) +
              ", t = " + parse::format_double(node()->time.value() + h) +
              " (non-finite positions or velocities); reduce dt or check the material parameters");
    state_ = ComponentState::invalid;
    return;
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
