// BlockGaussSeidelConstraintSolver (ex ProjectedGaussSeidel,
// spec/interaction.md §5.4.1): projected block Gauss-Seidel on the assembled
// W, blocks swept in row order, each projected by its own law. NNCG derives
// from it (SOFA's hierarchy).
#pragma once

#include "constraint/solver/built_constraint_solver.h"

namespace sinew {

class BlockGaussSeidelConstraintSolver : public BuiltConstraintSolver {
 protected:
  void solve_system() override;

 private:
  std::vector<double> sor_copy_;
};

}  // namespace sinew
