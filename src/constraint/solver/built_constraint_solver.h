// Base of the solvers that assemble the whole compliance W (SOFA's
// BuiltConstraintSolver, spec/interaction.md §5.2 step 7): every correction
// adds its compliance, then the regularisation goes on the diagonal (all
// rows, or with useSVDForRegularization only the rows in W's null space).
// BlockGaussSeidel (and NNCG through it) and ImprovedJacobi derive from it.
#pragma once

#include "constraint/solver/generic_constraint_solver.h"

namespace sinew {

class BuiltConstraintSolver : public GenericConstraintSolver {
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
};

}  // namespace sinew
