#include "solver/ode/newton_raphson_solver.h"

#include <algorithm>

#include "core/registry.h"

namespace sinew {

void NewtonRaphsonSolver::solve(NonlinearFunction& fn) {
  status.set("Running");
  auto& graph = residual_graph.edit();
  graph.clear();
  double r2 = fn.evaluate();
  const double r0 = r2;
  graph.push_back(r2);
  const double t_abs = absolute_residual.value();
  if (t_abs > 0 && r2 <= t_abs * t_abs) {
    status.set("ConvergedEquilibrium");
    return;
  }
  const double t_rs = relative_successive.value(), t_ri = relative_initial.value();
  const double t_red = relative_estimate.value(), t_aed = absolute_estimate.value();
  const bool estimate_measured = t_red > 0 || t_aed > 0;
  const unsigned L = std::max(max_line_search.value(), 1u);
  for (unsigned k = 0; k < max_iterations.value(); ++k) {
    const double r_prev = r2;
    const double x_prev2 = t_red > 0 ? fn.x_norm2() : 0.0;
    fn.solve_linear_step();
    double alpha = 1.0, alpha_prev = 0.0;
    bool success = false;
    for (unsigned j = 0; j < L; ++j) {
      fn.update(alpha - alpha_prev);
      r2 = fn.evaluate();
      if (r2 < r_prev) {
        success = true;
        break;
      }
      alpha_prev = alpha;
      alpha *= line_search_coefficient.value();
    }
    graph.push_back(r2);
    if (!success) {
      if (warn_line_search.value()) msg_warning("line search failed at Newton iteration " + std::to_string(k));
      status.set("DivergedLineSearch");
      if (L > 1) {
        fn.update(1.0 - alpha_prev);  // back to the full step
        r2 = fn.evaluate();
      }
    }
    if (t_rs > 0 && r2 < t_rs * t_rs * r_prev) return status.set("ConvergedResidualSuccessiveRatio");
    if (t_ri > 0 && r2 < t_ri * t_ri * r0) return status.set("ConvergedResidualInitialRatio");
    if (t_abs > 0 && r2 < t_abs * t_abs) return status.set("ConvergedAbsoluteResidual");
    if (estimate_measured) {
      const double dx2 = fn.dx_norm2();
      if (t_red > 0 && x_prev2 > 0 && dx2 < t_red * t_red * x_prev2)
        return status.set("ConvergedRelativeEstimateDifference");
      if (t_aed > 0 && dx2 < t_aed * t_aed) return status.set("ConvergedAbsoluteEstimateDifference");
    }
  }
  if (warn_diverge.value())
    msg_warning("Newton-Raphson did not converge in " + std::to_string(max_iterations.value()) + " iterations");
  status.set("DivergedMaxIterations");
}

void register_newton_raphson_solver(Registry& r) {
  ComponentInfo info;
  info.name = "NewtonRaphsonSolver";
  info.category = "Solver/Nonlinear";
  info.description = "Newton-Raphson iterations with line search (used by StaticSolver)";
  info.create = creator<NewtonRaphsonSolver>();
  r.add(std::move(info));
}

}  // namespace sinew
