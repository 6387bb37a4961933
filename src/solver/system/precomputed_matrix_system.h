// PrecomputedMatrixSystem: the linear system of PrecomputedWarpPreconditioner
// (template CompressedRowSparseMatrixd; spec/solvers.md §2.8). It never
// assembles nor resizes its matrix (which stays 0×0); only its right-hand
// side and solution vectors are filled by set_rhs / set_system_solution.
#pragma once

#include "solver/system/matrix_linear_system.h"

namespace sinew {

class PrecomputedMatrixSystem final : public MatrixLinearSystem {
 public:
  void build_system_matrix(MechanicalOps&, double, double, double) override {}
};

}  // namespace sinew
