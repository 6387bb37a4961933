// BlockGaussSeidelConstraintSolver (ex ProjectedGaussSeidel,
// spec/interaction.md §5.4.1): projected block Gauss-Seidel on the assembled
// W, blocks swept in row order, each projected by its own law. NNCG derives
// from it (SOFA's hierarchy).
#pragma once

#include "constraint/solver/generic_constraint_solver.h"

namespace sinew {

class BlockGaussSeidelConstraintSolver : public GenericConstraintSolver {
 public:
  Field<bool> multithreading{this, "multithreading", false, "build the compliances concurrently (same result)",
                             "Solver"};
  Field<bool> use_svd_for_regularization{this, "useSVDForRegularization", false,
                                         "regularise only the rows in the null space of W (SVD)", "Solver"};
  Field<double> svd_value_factor{this, "svdSingularValueNullSpaceCriteriaFactor", 0.01,
                                 "singular values below this fraction of the largest are in the null space",
                                 "Solver"};
  Field<double> svd_vector_factor{this, "svdSingularVectorNullSpaceCriteriaFactor", 0.001,
                                  "components of null-space vectors above this mark their rows", "Solver"};

 protected:
  void build_system(const ConstraintParams& p) override;
  void solve_system() override;

 private:
  std::vector<double> sor_copy_;
};

}  // namespace sinew
