// FixedRotationProjectiveConstraint (Rigid3d): removes from every frame's
// orientation its rotation about the chosen world axes (FixedXRotation,
// FixedYRotation, FixedZRotation), and puts back the rotation about those axes
// that the frame had at init. As SOFA's component of that name:
// - only positions are projected (project_position); velocities, responses
//   and constraint Jacobians are left alone, and assembled systems get no
//   Dirichlet rows;
// - each axis is removed by a swing–twist split, x then y then z, on the
//   current orientation and (for the twist to keep) on the initial one:
//   twist = normalised (axis·(axis·q⃗), q_w) (identity if that is all zeros),
//   swing = normalised q·twist⁻¹; result = swing_xyz · (twist_z·twist_y·twist_x
//   of the initial orientation), not renormalised.
#pragma once

#include <vector>

#include "core/roles.h"
#include "math/quat.h"

namespace sinew {

class FixedRotationProjectiveConstraint final : public ProjectiveConstraint {
 public:
  Field<bool> fixed_x{this, "FixedXRotation", false, "prevent rotation around the x axis", "Constraint"};
  Field<bool> fixed_y{this, "FixedYRotation", false, "prevent rotation around the y axis", "Constraint"};
  Field<bool> fixed_z{this, "FixedZRotation", false, "prevent rotation around the z axis", "Constraint"};

  void init() override;
  void project_response(int) override {}
  void project_jacobian(ConstraintMatrix&) override {}
  void project_velocity(int, double) override {}
  void project_position(int x, double t) override;
  bool dirichlet_indices(std::vector<std::size_t>&) override { return true; }  // nothing, as SOFA

 private:
  std::vector<Quat> initial_;  // orientation of each frame at init (SOFA's previousOrientation)
};

// The orientation q with its rotations about the flagged world axes (x, y, z)
// replaced by those of `initial` (the projection above, for one frame).
Quat fix_rotation(const Quat& q, const Quat& initial, bool x, bool y, bool z);

}  // namespace sinew
