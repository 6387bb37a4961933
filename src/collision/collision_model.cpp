#include "collision/collision_model.h"

#include "core/node.h"

namespace sinew {

const char* kind_name(CollisionModelBase::Kind k) {
  switch (k) {
    case CollisionModelBase::Kind::point:
      return "Point";
    case CollisionModelBase::Kind::line:
      return "Line";
    case CollisionModelBase::Kind::triangle:
      return "Triangle";
    case CollisionModelBase::Kind::sphere:
      return "Sphere";
    case CollisionModelBase::Kind::tetrahedron:
      return "Tetrahedron";
    case CollisionModelBase::Kind::obb:
      return "OBB";
  }
  return "?";
}

CollisionModelBase::CollisionModelBase(Kind kind) : kind_(kind) { contact_distance.add_alias("proximity"); }

void CollisionModelBase::init() {
  mstate_ = node()->get_mechanical_state();  // the node's, else the nearest ancestor's (SOFA's context lookup)
  if (!mstate_) {
    msg_error("needs a MechanicalState in its node " + node()->describe() + " or above");
    set_state(ComponentState::invalid);
    return;
  }
  const StateType t = mstate_->state_type();
  if (!(t == StateType::vec3 && accepts_vec3()) && !(t == StateType::rigid3 && accepts_rigid3())) {
    const char* need = !accepts_vec3()    ? "needs a Rigid3d MechanicalState; "
                       : accepts_rigid3() ? "needs a Vec3d or Rigid3d MechanicalState; "
                                          : "needs a Vec3d MechanicalState; ";
    msg_error(need + mstate_->describe() + " is " + mstate_->info().name);
    set_state(ComponentState::invalid);
    return;
  }
  if (contact_distance.value() < 0 || !std::isfinite(contact_distance.value())) {
    msg_error("contactDistance must be a finite value >= 0 (got " + std::to_string(contact_distance.value()) + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (!init_model()) set_state(ComponentState::invalid);
}

std::span<const Vec3> CollisionModelBase::points_of(int vec, int role) const {
  const std::vector<double>& a = mstate_->read(vec);
  if (mstate_->state_type() == StateType::vec3) return as_vec3(a);
  // Rigid3d: coordinates are (centre, quaternion), derivatives (linear, angular).
  const std::size_t stride = role == kPosition ? 7 : 6;
  std::vector<Vec3>& out = gathered_[vec == kPosition ? 0 : role == kPosition ? 1 : 2];
  out.resize(a.size() / stride);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(a[i * stride], a[i * stride + 1], a[i * stride + 2]);
  return out;
}

void CollisionModelBase::compute_continuous_bounding_tree(double dt, Motion motion, int depth) {
  const auto x = positions();
  x_end_.resize(x.size());
  if (motion == Motion::free_motion) {
    const auto xf = points_of(kFreePosition, kPosition);
    for (std::size_t i = 0; i < x.size(); ++i) x_end_[i] = i < xf.size() ? xf[i] : x[i];
  } else if (motion == Motion::inertia) {
    const auto v = points_of(kVelocity, kVelocity);
    for (std::size_t i = 0; i < x.size(); ++i) x_end_[i] = x[i] + v[i] * dt;
  } else {
    std::copy(x.begin(), x.end(), x_end_.begin());
  }
  compute_bounding_tree(depth);
}

bool CollisionModelBase::is_active() const {
  if (!active.value() || state() != ComponentState::valid) return false;
  for (const Node* n = node(); n; n = n->parent())
    if (!n->activated.value()) return false;
  return true;
}

bool CollisionModelBase::can_collide_with(const CollisionModelBase& other) const {
  if (node() == other.node()) return self_collision.value();
  const auto& g1 = group.value();
  const auto& g2 = other.group.value();
  if (g1.empty() || g2.empty()) return true;
  for (int a : g1)
    for (int b : g2)
      if (a == b) return false;
  return true;
}

}  // namespace sinew
