// NNCGConstraintSolver (spec/interaction.md §5.4.2): block Gauss-Seidel
// sweeps accelerated as a nonsmooth nonlinear conjugate gradient: each sweep's
// change of forces Δ gives β = |Δ_new|²/|Δ|², the forces move by β·p along the
// previous direction p, restarting (p = 0) when β > 1. Derives from
// BlockGaussSeidel as in SOFA (same Data, same build).
#pragma once

#include <vector>

#include "constraint/solver/block_gauss_seidel_constraint_solver.h"

namespace sinew {

class NNCGConstraintSolver : public BlockGaussSeidelConstraintSolver {
 protected:
  void solve_system() override;

 private:
  std::vector<double> lam_, delta_, delta_new_, p_;  // reused from step to step
};

}  // namespace sinew
