// StaticSolver: finds the equilibrium f(x) = 0 with Newton-Raphson
// (spec/solvers.md §1.4). Velocities are untouched. Each Newton step solves
// −K·dx = F with the node's linear solver (matrix factors m = 0, b = 0, k = −1).
#pragma once

#include <memory>

#include "core/mechanical_ops.h"
#include "core/roles.h"
#include "solver/ode/newton_raphson_solver.h"

namespace sinew {

class StaticSolver final : public OdeSolver {
 public:
  Link<NewtonRaphsonSolver> newton_solver{this, "newtonSolver", "Newton solver (default: first one below)"};
  Link<LinearSolver> linear_solver{this, "linearSolver", "linear solver (default: first one below)"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
  void solve(double dt, int x_result, int v_result) override;
  const char* divergence_hint() const override { return "singular or indefinite stiffness?"; }

 private:
  int dx_ = -1;
  // Deprecated attributes forwarded to the Newton solver it creates.
  std::vector<std::pair<std::string, std::string>> forwarded_;
};

}  // namespace sinew
