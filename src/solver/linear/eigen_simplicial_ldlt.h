// EigenSimplicialLDLT: Eigen's simplicial LDLᵀ direct solver (lower triangle) (spec/solvers.md §3.6). Templates CompressedRowSparseMatrixd
// (default) and CompressedRowSparseMatrixMat3x3d.
#pragma once

#include "solver/linear/eigen_direct_solver.h"

namespace sinew {

class EigenSimplicialLDLT final : public EigenDirectSolver {
 public:

 protected:
  std::unique_ptr<EigenFactorization> make(const std::string& ordering) const override;
};

}  // namespace sinew
