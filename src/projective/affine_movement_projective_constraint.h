// AffineMovementProjectiveConstraint (old name AffineMovementConstraint): moves
// listed DoFs from their first positions x0 to an affine image xf of them,
// linearly in time between beginConstraintTime and endConstraintTime (as
// SOFA's component of that name).
//
//   xf = R·x0 + t (Vec3d: R = `rotation`; Rigid3d: R = the matrix of
//        `quaternion`, and the orientation becomes quaternion + x0's, SOFA's
//        quaternion "sum" = product, renormalised);
//   begin < time ≤ end: x = ((xf − x0)·time + (x0·end − xf·begin)) / (end − begin)
//        (centres only for rigids); time > end: x = xf (whole coordinate);
//   velocities and responses of the listed DoFs are always zeroed.
// x0 and xf (and the same for `meshIndices`, kept as SOFA keeps them) are taken
// at the first position projection and never again: not on reset, not when
// points are removed — after a removal a renumbered DoF reads the x0/xf slot
// of its new index, as in SOFA. `indices` follows point removals.
// Assembled systems and constraint rows are not projected (SOFA implements
// neither; both report it).
#pragma once

#include <vector>

#include "core/roles.h"
#include "projective/subset_indices.h"

namespace sinew {

class AffineMovementProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit AffineMovementProjectiveConstraint(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> mesh_indices{this, "meshIndices", {}, "indices of the mesh", "Constraint"};
  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the constrained points", "Constraint"};
  Field<double> begin_time{this, "beginConstraintTime", 0.0, "time the movement starts", "Constraint", "time"};
  Field<double> end_time{this, "endConstraintTime", 20.0, "time the movement ends", "Constraint", "time"};
  // SOFA's Mat3x3 default is the zero matrix: without `rotation`, Vec3d points go to `translation`.
  Field<Mat3> rotation{this, "rotation", Mat3::Zero(), "rotation applied to the points (Vec3d)", "Constraint"};
  Field<VecN<4>> quaternion{this, "quaternion", VecN<4>(0, 0, 0, 1),
                            "rotation applied to the points, x y z w (Rigid3d)", "Constraint"};
  Field<Vec3> translation{this, "translation", Vec3::Zero(), "translation applied to the points", "Constraint",
                          "length"};
  Field<bool> draw_constrained_points{this, "drawConstrainedPoints", false, "draw the constrained points (viewer)",
                                      "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override;
  void project_response(int dx) override;
  void project_jacobian(ConstraintMatrix& J) override;
  void project_velocity(int v, double t) override;
  void project_position(int x, double t) override;

  // Positions taken at the first projection and their images (coordinate width per DoF,
  // sized to the state at that time).
  const std::vector<double>& initial_positions() const { return x0_; }
  const std::vector<double>& final_positions() const { return xf_; }

 private:
  void zero(int id);
  void take_initial(const std::vector<unsigned>& idx, const std::vector<double>& x, std::vector<double>& x0) const;
  void take_final(const std::vector<unsigned>& idx, const std::vector<double>& x, std::vector<double>& x0,
                  std::vector<double>& xf) const;
  void transform(const std::vector<unsigned>& idx, const std::vector<double>& x0, std::vector<double>& xf) const;

  StateType type_;
  int cw_ = 3, w_ = 3;
  std::vector<double> x0_, xf_, mesh_x0_, mesh_xf_;
  bool warned_rows_ = false;
  SubsetIndicesFollower follow_;
};

}  // namespace sinew
