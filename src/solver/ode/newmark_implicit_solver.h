// NewmarkImplicitSolver: implicit Newmark scheme in SOFA's formulation
// (spec/solvers.md §1.5), solving for the acceleration at the end of the step.
// The acceleration a of the previous step is kept between steps; on the first
// step it is computed as M⁻¹ f(x, v), x and v projected at time 0.
//   b = f(x, v) + [−h(1−γ)rM·M + h(1−γ)·B + (h(1−γ)rK + h²(1−2β)/2)·K]·a   (the bracket only
//       when rM ≠ 0, rK ≠ 0 or β ≠ 0.5, as in SOFA)
//     + [−rM·M + B + (rK + h)·K]·v,  projected
//   A = (1 + hγ·rM)·M − hγ·B − (h²β + hγ·rK)·K;  solve A·a₁ = b
//   x₁ = x + h·v + h²(½ − β)·a + h²β·a₁;  v₁ = v + h(1−γ)·a + hγ·a₁
//   v₁ += h·g (separate gravity);  v₁ *= exp(−h·vdamping) when vdamping ≠ 0;  a = a₁
#pragma once

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class NewmarkImplicitSolver final : public OdeSolver {
 public:
  Field<double> rayleigh_stiffness{this, "rayleighStiffness", 0.0, "Rayleigh damping related to stiffness (rK)",
                                   "Solver", "time"};
  Field<double> rayleigh_mass{this, "rayleighMass", 0.0, "Rayleigh damping related to mass (rM)", "Solver", "1/time"};
  Field<double> vdamping{this, "vdamping", 0.0, "velocity decay rate: v *= exp(−dt·vdamping) after each step",
                         "Solver", "1/time"};
  Field<double> gamma{this, "gamma", 0.5, "Newmark γ coefficient", "Solver"};
  Field<double> beta{this, "beta", 0.25, "Newmark β coefficient", "Solver"};
  Field<bool> thread_safe_visitor{this, "threadSafeVisitor", false, "no effect (SOFA allocation detail)", "Solver"};

  void init() override;
  void solve(double dt, int x_result, int v_result) override;

 private:
  // The linear solver SOFA's mechanical operations use: the first one in this node or below.
  LinearSolver* linear_solver() const;

  int a_ = -1;        // acceleration of the previous step (kept)
  int a_result_ = -1, b_ = -1;
  long steps_ = 0;    // SOFA's step counter: the acceleration is computed on the first step only
};

}  // namespace sinew
