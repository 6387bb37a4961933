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
  if (mstate_->state_type() != StateType::vec3) {
    msg_error(std::string("needs a Vec3d MechanicalState; ") + mstate_->describe() + " is " + mstate_->info().name);
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

void CollisionModelBase::compute_continuous_bounding_tree(double dt, Motion motion, int depth) {
  const auto x = positions();
  x_end_.resize(x.size());
  if (motion == Motion::free_motion) {
    const auto xf = as_vec3(mstate_->read(kFreePosition));
    for (std::size_t i = 0; i < x.size(); ++i) x_end_[i] = i < xf.size() ? xf[i] : x[i];
  } else if (motion == Motion::inertia) {
    const auto v = as_vec3(mstate_->read(kVelocity));
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
