#include "collision/model/sphere_collision_model.h"

#include "collision/model/element_checks.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool SphereCollisionModel::init_model() {
  rigid_ = mstate_->state_type() == StateType::rigid3;
  x_ = positions();
  update_radii();
  return true;
}

// listRadius sized to the state: missing entries take `radius`, extra ones are dropped (SOFA).
void SphereCollisionModel::update_radii() {
  const std::vector<double>& list = list_radius.get();
  r_.assign(x_.size(), radius.value());
  for (std::size_t i = 0; i < std::min(list.size(), r_.size()); ++i) r_[i] = list[i];
}

void SphereCollisionModel::compute_bounding_tree(int depth) {
  x_ = positions();
  const bool resized = tree_.size() != x_.size();
  if (resized) {
    tree_.resize(0);
    update_radii();
  }
  if (!moving.value() && tree_.built() && !resized) return;
  tree_.resize(x_.size());
  if (x_.empty()) return;
  const double d = contact_distance.value();
  for (unsigned i = 0; i < x_.size(); ++i) {
    const double r = r_[i];
    Aabb box{x_[i] - Vec3::Constant(r + d), x_[i] + Vec3::Constant(r + d)};
    widen_to_end(box, {i}, r + d);
    if (!(r > 0) || !std::isfinite(r))
      box = skipped_box(*this, "sphere", i, "a radius that is not a finite value > 0");
    else if (!finite_box(box))
      box = skipped_box(*this, "sphere", i, "a non-finite position");
    tree_.set_box(i, box);
  }
  tree_.update(depth);
}

void register_sphere_collision_model(Registry& r) {
  ComponentInfo info;
  info.name = "SphereCollisionModel";
  info.category = "Collision/Geometry";
  info.description = "collision model of spheres centred on the points of a Vec3d state or the frames of a Rigid3d one";
  info.templates = {"Vec3d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;  // the template follows the node's state
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t != "Vec3d" && t != "Rigid3d") return nullptr;
    return std::make_unique<SphereCollisionModel>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
