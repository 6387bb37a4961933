// RungeKutta2Solver: explicit midpoint method, as SOFA computes it (spec/solvers.md §1.5).
//   v += h·g (separate gravity);  a0 = M⁻¹ f(x, v) at t (x, v projected in place first)
//   X = x + h/2·v,  V = v + h/2·a0;  a1 = M⁻¹ f(X, V) at t + h/2 (X, V projected first)
//   x_new = x + h·V,  v_new = v + h·a1
// No Data, no linear solver.
#pragma once

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class RungeKutta2Solver final : public OdeSolver {
 public:
  void init() override;
  void solve(double dt, int x_result, int v_result) override;
  // SOFA's solution factors {0, dt/2, 1}: position, velocity.
  double position_integration_factor(double) const override { return 0.0; }
  double velocity_integration_factor(double dt) const override { return dt / 2; }

 private:
  // a = M⁻¹ f(X, V) at time t, with X and V projected in place first (SOFA's computeAcc).
  void acceleration(double t, int X, int V, int a);

  int acc_ = -1, new_x_ = -1, new_v_ = -1;
};

}  // namespace sinew
