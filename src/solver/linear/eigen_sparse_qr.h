// EigenSparseQR: Eigen's sparse QR direct solver (spec/solvers.md §3.6). Templates CompressedRowSparseMatrixd
// (default) and CompressedRowSparseMatrixMat3x3d.
#pragma once

#include "solver/linear/eigen_direct_solver.h"

namespace sinew {

class EigenSparseQR final : public EigenDirectSolver {
 public:
  bool supports_non_symmetric() const override { return true; }
 protected:
  std::unique_ptr<EigenFactorization> make(const std::string& ordering) const override;
};

}  // namespace sinew
