// NewtonRaphsonSolver: Newton iterations with backtracking line search for a
// nonlinear function supplied by an ODE solver (spec/solvers.md §1.4).
// All criteria compare squared quantities with squared thresholds (strict <);
// a threshold ≤ 0 is not measured.
#pragma once

#include <string>
#include <vector>

#include "core/roles.h"

namespace sinew {

// What StaticSolver (or another user) provides to the Newton loop.
struct NonlinearFunction {
  virtual ~NonlinearFunction() = default;
  virtual double evaluate() = 0;               // F(x); returns F·F
  virtual void solve_linear_step() = 0;        // dx = (∂F/∂x)⁻¹ F
  virtual void update(double alpha) = 0;       // x += alpha·dx
  virtual double dx_norm2() = 0;               // dx·dx
  virtual double x_norm2() = 0;                // x·x
};

class NewtonRaphsonSolver final : public Component {
 public:
  Field<unsigned> max_iterations{this, "maxNbIterationsNewton", 1, "maximum Newton iterations", "Newton"};
  Field<double> relative_successive{this, "relativeSuccessiveStoppingThreshold", 1e-5,
                                    "stop when |r_k| < t·|r_k-1|", "Newton"};
  Field<double> relative_initial{this, "relativeInitialStoppingThreshold", 1e-5, "stop when |r_k| < t·|r_0|",
                                 "Newton"};
  Field<double> absolute_residual{this, "absoluteResidualStoppingThreshold", 1e-5, "stop when |r_k| < t",
                                  "Newton"};
  Field<double> relative_estimate{this, "relativeEstimateDifferenceThreshold", 0.0, "stop when |dx| < t·|x|",
                                  "Newton"};
  Field<double> absolute_estimate{this, "absoluteEstimateDifferenceThreshold", 0.0, "stop when |dx| < t",
                                  "Newton"};
  Field<unsigned> max_line_search{this, "maxNbIterationsLineSearch", 1, "line search iterations", "Newton"};
  Field<double> line_search_coefficient{this, "lineSearchCoefficient", 0.5, "step reduction factor", "Newton"};
  Field<bool> update_state_when_diverged{this, "updateStateWhenDiverged", true, "unused", "Newton"};
  Field<std::string> status{this, "status", "Undefined", "outcome of the last solve (output)", "Newton"};
  Field<std::vector<double>> residual_graph{this, "residualGraph", {}, "squared residuals (output)", "Newton"};
  Field<bool> warn_line_search{this, "warnWhenLineSearchFails", true, "warn when the line search fails", "Newton"};
  Field<bool> warn_diverge{this, "warnWhenDiverge", true, "warn when Newton does not converge", "Newton"};

  void solve(NonlinearFunction& f);
};

}  // namespace sinew
