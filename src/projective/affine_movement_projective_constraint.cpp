#include "projective/affine_movement_projective_constraint.h"

#include <string>

#include "core/node.h"
#include "core/registry.h"
#include "core/state_creator.h"
#include "io/sofa_quat.h"
#include "projective/indices_in_state.h"

namespace sinew {

void AffineMovementProjectiveConstraint::final_of(const std::vector<unsigned>& idx, const std::vector<double>&,
                                                  const std::vector<double>& x0, std::vector<double>& xf) const {
  const Vec3& t = translation.get();
  Mat3 R;
  io::SQuat quat;
  if (type_ == StateType::rigid3) {
    const VecN<4>& q = quaternion.get();
    quat.q = {q[0], q[1], q[2], q[3]};
    const auto m = quat.matrix();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) R(r, c) = m[r * 3 + c];
  } else {
    R = rotation.get();
  }
  const std::size_t n = std::min(x0.size(), xf.size()) / cw_;
  for (unsigned i : idx) {
    if (i >= n) continue;
    const double* a = &x0[i * cw_];
    double* b = &xf[i * cw_];
    // SOFA's Mat·Vec: each row summed left to right, then the translation added.
    for (int r = 0; r < 3; ++r) {
      double s = R(r, 0) * a[0];
      s += R(r, 1) * a[1];
      s += R(r, 2) * a[2];
      b[r] = s + t[r];
    }
    if (type_ == StateType::rigid3) {
      io::SQuat q0;
      q0.q = {a[3], a[4], a[5], a[6]};
      const io::SQuat r = io::sofa_add(quat, q0);
      for (int c = 0; c < 4; ++c) b[3 + c] = r.q[c];
    }
  }
}

void register_affine_movement_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "AffineMovementProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "moves points to an affine image of their first positions, linearly in time";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<AffineMovementProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
