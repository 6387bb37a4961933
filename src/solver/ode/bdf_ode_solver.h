// BDFOdeSolver: SOFA's velocity-based backward differentiation formula of any
// order, steps of any size, each step a nonlinear system solved by the
// node's NewtonRaphsonSolver (spec/solvers.md §1.5).
//
// Linear multistep form over the last s+1 times t_0 … t_s (s = the order in
// use, t_s = end of this step, h = t_s − t_{s−1}):
//   r1 = Σ a_j x_j − h Σ b_j v_j                       (positions)
//   r2 = Σ a_j M v_j − h Σ b_j f_j,  f_j = f(x_j, v_j) − rM·M v_j + rK·K v_j
// with a, b from bdf_coefficients (a_s = 1, b_j = 0 for j < s). A Newton step
// solves  [(a_s + h b_s rM)·M − h b_s·B − h b_s (rK + h b_s / a_s)·K] Δv
//          = −r2 − (h b_s / a_s)·K·r1,
// then v_s += α Δv and x_s += (h b_s / a_s) Δv − r1 / a_s. The first guess is
// x_s = x + h v, v_s = v. The order used is min(order, steps done + 1).
//
// History, as SOFA keeps it: slot s−1 is the state's position / velocity /
// force vector, other slots are vectors of their own, allocated on first use
// and kept; after the solve, slot j takes slot j+1 for j < s. With order ≥ 2
// the slot lists keep growing from the front, so every slot below s ends up
// naming the state's own vectors: the older samples all equal the current
// state. SOFA then computes x' − x = h·b_s·v', M(v' − v) = h·b_s·f' (a_0 + … +
// a_{s−1} = −1): backward Euler with the step scaled by b_s (2/3 at order 2,
// 6/11 at order 3) from the second step on. This is reproduced, not corrected.
#pragma once

#include <deque>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/roles.h"
#include "solver/ode/newton_raphson_solver.h"

namespace sinew {

// Coefficients of the BDF formula on the sample times t (size s+1 ≥ 2):
// a_j = h·L_j'(t_s) / (h·L_s'(t_s)) with L_j the Lagrange polynomials of the
// samples, then a_s = 1, b_s = 1 / (h·L_s'(t_s)), b_j = 0 (SOFA's arithmetic).
void bdf_coefficients(const std::deque<double>& t, std::vector<double>& a, std::vector<double>& b);

class BDFOdeSolver final : public OdeSolver {
 public:
  Field<unsigned> order{this, "order", 1u, "order of the method (1 to 6 are zero-stable; 0 is read as 1)", "Solver"};
  Field<double> rayleigh_stiffness{this, "rayleighStiffness", 0.0, "Rayleigh damping related to stiffness (rK)",
                                   "Solver", "time"};
  Field<double> rayleigh_mass{this, "rayleighMass", 0.0, "Rayleigh damping related to mass (rM)", "Solver", "1/time"};
  Link<NewtonRaphsonSolver> newton_solver{this, "newtonSolver",
                                          "Newton solver of each step (default: first one in this node or below)"};
  Link<LinearSolver> linear_solver{this, "linearSolver", "linear solver (default: first one in this node or below)"};

  void init() override;
  void reset() override;
  void solve(double dt, int x_result, int v_result) override;

  // Coefficients of the last step (tests).
  const std::vector<double>& a_coefficients() const { return a_; }
  const std::vector<double>& b_coefficients() const { return b_; }

 private:
  std::deque<double> times_;   // end times of the last steps, the current one last
  std::size_t solves_ = 0;     // steps done since init / reset
  std::vector<double> a_, b_;
  std::vector<int> x_slots_, v_slots_, f_slots_;  // vector ids per history slot, −1 = not allocated
  int r1_ = -1, r2_ = -1, rhs_ = -1, dv_ = -1, dx_ = -1, vsum_ = -1;
  bool checked_states_ = false;
};

}  // namespace sinew
