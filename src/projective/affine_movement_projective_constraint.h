// AffineMovementProjectiveConstraint (old name AffineMovementConstraint): moves
// listed DoFs from their first positions x0 to an affine image xf of them,
// linearly in time between beginConstraintTime and endConstraintTime (as
// SOFA's component of that name).
//
//   xf = R·x0 + t (Vec3d: R = `rotation`; Rigid3d: R = the matrix of
//        `quaternion`, and the orientation becomes quaternion + x0's, SOFA's
//        quaternion "sum" = product, renormalised).
// The time law, the capture of x0/xf and the projections are MovementToFinalPositions'.
#pragma once

#include <vector>

#include "projective/movement_to_final_positions.h"

namespace sinew {

class AffineMovementProjectiveConstraint final : public MovementToFinalPositions {
 public:
  explicit AffineMovementProjectiveConstraint(StateType t) : MovementToFinalPositions(t) {}

  // SOFA's Mat3x3 default is the zero matrix: without `rotation`, Vec3d points go to `translation`.
  Field<Mat3> rotation{this, "rotation", Mat3::Zero(), "rotation applied to the points (Vec3d)", "Constraint"};
  Field<VecN<4>> quaternion{this, "quaternion", VecN<4>(0, 0, 0, 1),
                            "rotation applied to the points, x y z w (Rigid3d)", "Constraint"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation applied to the points", "Constraint",
                          "length"};

 protected:
  void final_of(const std::vector<unsigned>& idx, const std::vector<double>& x, const std::vector<double>& x0,
                std::vector<double>& xf) const override;
};

}  // namespace sinew
