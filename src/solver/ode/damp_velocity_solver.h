// DampVelocitySolver: reduces the velocities (spec/solvers.md §1.5). Usually
// placed after another ODE solver in the same node (every solver of a node
// runs, in declaration order):
//   v *= exp(−rate·dt);  if threshold ≠ 0, each DOF with |v_i|² < threshold² is zeroed.
// Positions are not touched.
#pragma once

#include "core/mechanical_ops.h"
#include "core/roles.h"

namespace sinew {

class DampVelocitySolver final : public OdeSolver {
 public:
  Field<double> rate{this, "rate", 0.99, "velocity decay rate: v *= exp(−rate·dt) (typically between 0 and 1)",
                     "Solver", "1/time"};
  Field<double> threshold{this, "threshold", 0.0, "velocities of norm below it are set to zero (0: none)", "Solver",
                          "length/time"};

  void solve(double dt, int x_result, int v_result) override;
};

}  // namespace sinew
