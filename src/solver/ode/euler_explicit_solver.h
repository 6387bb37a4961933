// EulerExplicitSolver: forward Euler, symplectic by default (spec/solvers.md §1.2).
//   a = M⁻¹ f (diagonal masses) or solve M·a = P·f with a linear solver;
//   symplectic: v += h·a, x += h·v;  otherwise: x += h·v (old v), v += h·a.
#pragma once

#include <memory>

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class EulerExplicitSolver final : public OdeSolver {
 public:
  Field<bool> symplectic{this, "symplectic", true, "update velocities first, then positions with the new velocities",
                         "Solver"};
  Field<bool> thread_safe_visitor{this, "threadSafeVisitor", false, "no effect (SOFA allocation detail)", "Solver"};
  Link<LinearSolver> linear_solver{this, "linearSolver",
                                   "linear solver for non-diagonal masses (default: first one up the graph)"};

  void init() override;
  void solve(double dt, int x_result, int v_result) override;
  // SOFA's solution factors {symplectic·dt², dt, 1}: position, velocity.
  double position_integration_factor(double dt) const override { return symplectic.value() ? dt * dt : 0.0; }
  double velocity_integration_factor(double dt) const override { return dt; }

 private:
  int acc_ = -1;
};

}  // namespace sinew
