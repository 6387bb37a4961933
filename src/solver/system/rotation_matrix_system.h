// RotationMatrixSystem: the linear system of WarpPreconditioner (template
// RotationMatrixd; spec/solvers.md §2.7). Its matrix R is block diagonal
// with one 3×3 rotation per point.
//
// build: every `assemblingRate` calls (the first one included) the main
// assembled system is assembled with the same factors and R is reset to the
// identity; on the other calls R is refilled with the current per-point
// rotations of the rotation finder (a corotational force field).
#pragma once

#include "core/rotation_finder.h"
#include "solver/system/matrix_linear_system.h"

namespace sinew {

class RotationMatrixSystem final : public MatrixLinearSystem {
 public:
  Field<unsigned> assembling_rate{this, "assemblingRate", 1u, "refresh the rotations every N steps", "LinearSystem"};
  Link<MatrixLinearSystem> main_system{this, "mainSystem", "assembled system to rotate"};
  Link<Component> rotation_finder{this, "rotationFinder", "component providing the rotations"};

  void init() override;
  void reset() override { counter_ = assembling_rate.value(); }
  void build_system_matrix(MechanicalOps& ops, double m, double b, double k) override;

  RotationFinder* finder() const { return finder_; }
  // Whether the last build assembled the main system (R = identity).
  bool main_assembled_last() const { return main_assembled_last_; }

  // The 3×3 block of point block `k` (row-major, 9 values), or nullptr when R
  // is not stored as 3×3 blocks (then it is the identity).
  const double* block(std::size_t k) const;

 private:
  void set_identity();
  void fill_rotations();

  RotationFinder* finder_ = nullptr;
  unsigned counter_ = 1;
  bool main_assembled_last_ = false;
};

}  // namespace sinew
