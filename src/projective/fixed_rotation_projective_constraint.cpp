#include "projective/fixed_rotation_projective_constraint.h"

#include "core/registry.h"

namespace sinew {

namespace {

// Twist of q about the unit `axis` and the remaining swing (q = swing·twist).
void swing_twist(const Quat& q, const Vec3& axis, Quat& twist, Quat& swing) {
  const double d = q.x * axis[0] + q.y * axis[1] + q.z * axis[2];
  twist = {d * axis[0], d * axis[1], d * axis[2], q.w};
  // A rotation by π about an axis perpendicular to `axis` has no twist: identity.
  if (twist.x == 0. && twist.y == 0. && twist.z == 0. && twist.w == 0.) twist = Quat{};
  twist = quat_normalized(twist);
  swing = quat_normalized(quat_mul(q, quat_inverse(twist)));
}

}  // namespace

Quat fix_rotation(const Quat& q, const Quat& initial, bool x, bool y, bool z) {
  Quat rest = q, rest_initial = initial, keep;
  auto remove = [&](const Vec3& axis) {
    Quat twist, swing;
    swing_twist(rest, axis, twist, swing);
    rest = swing;
    swing_twist(rest_initial, axis, twist, swing);
    rest_initial = swing;
    keep = quat_mul(twist, keep);
  };
  if (x) remove(Vec3(1, 0, 0));
  if (y) remove(Vec3(0, 1, 0));
  if (z) remove(Vec3(0, 0, 1));
  return quat_mul(rest, keep);
}

void FixedRotationProjectiveConstraint::init() {
  ProjectiveConstraint::init();
  if (state() != ComponentState::valid) return;
  const std::vector<double>& x = mstate->read(kPosition);
  initial_.resize(mstate->size());
  for (std::size_t i = 0; i < initial_.size(); ++i) initial_[i] = Quat::from(&x[7 * i + 3]);
}

void FixedRotationProjectiveConstraint::project_position(int xid, double) {
  std::vector<double>& x = mstate->write(xid);
  const bool fx = fixed_x.value(), fy = fixed_y.value(), fz = fixed_z.value();
  // Frames added after init have no initial orientation: left alone.
  const std::size_t n = std::min(initial_.size(), x.size() / 7);
  for (std::size_t i = 0; i < n; ++i)
    fix_rotation(Quat::from(&x[7 * i + 3]), initial_[i], fx, fy, fz).store(&x[7 * i + 3]);
}

void register_fixed_rotation_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "FixedRotationProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "keeps the rotations of rigid frames about chosen world axes at their initial values";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  info.requirement = Requirement::state;
  info.create = creator<FixedRotationProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
