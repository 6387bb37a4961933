// EulerImplicitSolver: backward Euler with Rayleigh damping (spec/solvers.md §1.1).
//
// Second order (default), h = dt, tr = 0.5 with the trapezoidal scheme else 1:
//   b = h·(f − rM·M·v + (tr·h + rK)·K·v),  projected
//   A = (1 + tr·h·rM)·M − tr·h·B − tr·h·(tr·h + rK)·K
//   solve A·Δv = b;  v += Δv;  x += h·v
// First order: b = f, A = M − tr·h·K, v = Δv, x += h·v.
#pragma once

#include <memory>

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class EulerImplicitSolver final : public OdeSolver {
 public:
  Field<double> rayleigh_stiffness{this, "rayleighStiffness", 0.0, "Rayleigh damping related to stiffness (rK)",
                                   "Solver", "time"};
  Field<double> rayleigh_mass{this, "rayleighMass", 0.0, "Rayleigh damping related to mass (rM)", "Solver", "1/time"};
  Field<double> vdamping{this, "vdamping", 0.0, "velocity decay rate: v *= exp(−dt·vdamping) after each step",
                         "Solver", "1/time"};
  Field<bool> first_order{this, "firstOrder", false, "use the first-order variant (velocity = solution)", "Solver"};
  Field<bool> trapezoidal_scheme{this, "trapezoidalScheme", false, "use 0.5 instead of 1 in the factors",
                                 "Solver"};
  Field<bool> solve_constraint{this, "solveConstraint", false, "apply constraint solvers of this node", "Solver"};
  Field<bool> thread_safe_visitor{this, "threadSafeVisitor", false, "no effect (SOFA allocation detail)", "Solver"};
  Field<bool> compute_residual{this, "computeResidual", false,
                               "compute the squared residual after the step (extra force evaluation)", "Solver"};
  Field<double> residual{this, "residual", 1.7976931348623157e308, "squared residual of the last step (output)",
                         "Solver"};
  Link<LinearSolver> linear_solver{this, "linearSolver", "linear solver (default: first one below this node)"};

  void init() override;
  void solve(double dt, int x_result, int v_result) override;

 private:
  int x_ = -1, b_ = -1;  // solution (kept between steps) and right-hand side
};

}  // namespace sinew
