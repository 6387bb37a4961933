// RungeKutta4Solver: classical explicit fourth-order Runge–Kutta (spec/solvers.md §1.3).
// Each stage projects and propagates its positions/velocities, computes
// forces and a = M⁻¹ f. No linear solver.
#pragma once

#include <memory>

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class RungeKutta4Solver final : public OdeSolver {
 public:
  void init() override;
  void solve(double dt, int x_result, int v_result) override;
  // SOFA's solution factors {0, dt/2, 1}: position, velocity.
  double position_integration_factor(double) const override { return 0.0; }
  double velocity_integration_factor(double dt) const override { return dt / 2; }

 private:
  // a = M⁻¹ f(X, V) at time t, with X and V projected in place first.
  void acceleration(double t, int X, int V, int a);

  int k1a_ = -1, k2a_ = -1, k3a_ = -1, k4a_ = -1, k2v_ = -1, k3v_ = -1, k4v_ = -1, X_ = -1;
};

}  // namespace sinew
