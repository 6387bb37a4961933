#include "collision/model/obb_collision_model.h"

#include <cmath>

#include "collision/model/element_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "math/quat.h"

namespace sinew {

std::array<Vec3, 8> obb_vertices(const ObbElem& b) {
  const Vec3 a0 = b.axis[0] * b.ext[0], a1 = b.axis[1] * b.ext[1], a2 = b.axis[2] * b.ext[2];
  const Vec3& c = b.c;
  return {c + a0 - a1 - a2, c + a0 + a1 - a2, c + a0 + a1 + a2, c + a0 - a1 + a2,
          c - a0 - a1 - a2, c - a0 + a1 - a2, c - a0 + a1 + a2, c - a0 - a1 + a2};
}

bool ObbCollisionModel::init_model() {
  const double d = default_extent.value();
  if (!(d > 0) || !std::isfinite(d)) {
    msg_error("defaultExtent must be a finite value > 0 (got " + std::to_string(d) + ")");
    return false;
  }
  if (!update_extents(mstate_->size())) return false;
  read_boxes();
  return true;
}

bool ObbCollisionModel::update_extents(std::size_t n) {
  const std::vector<Vec3>& given = extents.get();
  for (std::size_t i = 0; i < given.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!(given[i][k] > 0) || !std::isfinite(given[i][k])) {
        msg_error("extents of box " + std::to_string(i) + " must be finite values > 0 (got " +
                  std::to_string(given[i][0]) + " " + std::to_string(given[i][1]) + " " +
                  std::to_string(given[i][2]) + ")");
        return false;
      }
  if (given.size() < n) {
    std::vector<Vec3> padded = given;
    padded.resize(n, Vec3::Constant(default_extent.value()));
    extents.set(std::move(padded));
  }
  extents_seen_ = extents.version();
  return true;
}

// Centre, axes (the frame's rotation of the unit vectors, as SOFA's axis()) and linear velocity.
void ObbCollisionModel::read_boxes() {
  const std::vector<double>& x = mstate_->read(kPosition);
  const std::vector<double>& v = mstate_->read(kVelocity);
  const std::vector<Vec3>& ext = extents.get();
  const std::size_t n = x.size() / 7;
  boxes_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    ObbElem& b = boxes_[i];
    const double* xi = &x[i * 7];
    const Quat q = Quat::from(xi + 3);
    b.c = Vec3(xi[0], xi[1], xi[2]);
    b.axis = {quat_rotate(q, Vec3(1, 0, 0)), quat_rotate(q, Vec3(0, 1, 0)), quat_rotate(q, Vec3(0, 0, 1))};
    b.ext = ext[i];
    b.v = v.size() >= (i + 1) * 6 ? Vec3(v[i * 6], v[i * 6 + 1], v[i * 6 + 2]) : Vec3::Zero();
    b.info = {static_cast<unsigned>(i), n, contact_distance.value(), this};
  }
}

void ObbCollisionModel::compute_bounding_tree(int depth) {
  const std::size_t n = mstate_->size();
  const bool resized = tree_.size() != n;
  if (resized) tree_.resize(0);
  // Extents checked again when the state grew or someone wrote them since.
  const bool reshaped = resized || extents.version() != extents_seen_;
  if (reshaped && !update_extents(n)) {
    boxes_.clear();
    set_state(ComponentState::invalid);
    return;
  }
  read_boxes();
  if (!moving.value() && tree_.built() && !reshaped) return;
  tree_.resize(n);
  if (n == 0) return;
  const double d = contact_distance.value();
  for (unsigned i = 0; i < n; ++i) {
    const auto vs = obb_vertices(boxes_[i]);
    Aabb box{vs[0], vs[0]};
    for (int j = 1; j < 8; ++j) box.min = box.min.cwiseMin(vs[j]), box.max = box.max.cwiseMax(vs[j]);
    box.min -= Vec3::Constant(d);
    box.max += Vec3::Constant(d);
    if (!finite_box(box)) box = skipped_box(*this, "box", i, "a non-finite position or orientation");
    tree_.set_box(i, box);
  }
  tree_.update(depth);
}

void register_obb_collision_model(Registry& r) {
  ComponentInfo info;
  info.name = "OBBCollisionModel";
  info.category = "Collision/Geometry";
  info.description = "collision model of oriented boxes, one per frame of a Rigid3d state (half-extents per frame)";
  info.templates = {"Rigid3d"};
  info.default_template = "Rigid3d";
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t != "Rigid3d") return nullptr;
    return std::make_unique<ObbCollisionModel>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
