#include "collision/model/tetrahedron_collision_model.h"

#include "collision/model/element_checks.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

bool TetrahedronCollisionModel::init_model() {
  topology.set(model_topology(*this, topology.get()));
  if (!topology.get()) {
    msg_error("needs a topology (a mesh topology in its node or above, or the 'topology' link) to give its tetrahedra");
    return false;
  }
  x_ = positions();
  update_from_topology();
  return true;
}

bool TetrahedronCollisionModel::update_from_topology() {
  const MeshTopologyBase& t = *topology;
  const auto v = t.elements_version(MeshTopologyBase::Elements::tetrahedra);
  if (v == version_ && tets_.size() == t.tetrahedra().size()) return false;
  version_ = v;
  tets_ = t.tetrahedra();
  return true;
}

void TetrahedronCollisionModel::compute_bounding_tree(int depth) {
  x_ = positions();
  const bool changed = update_from_topology();
  if (changed || tree_.size() != tets_.size()) tree_.resize(0);
  if (!moving.value() && tree_.built() && !changed) return;
  tree_.resize(tets_.size());
  if (tets_.empty()) return;
  const std::size_t n = x_.size();
  for (unsigned i = 0; i < tets_.size(); ++i) {
    const Tetra& t = tets_[i];
    Aabb box;
    if (std::max({t[0], t[1], t[2], t[3]}) >= n) {
      box = skipped_box(*this, "tetrahedron", i, "a point index beyond the state's size");
    } else {
      box.min = x_[t[0]].cwiseMin(x_[t[1]]).cwiseMin(x_[t[2]]).cwiseMin(x_[t[3]]);
      box.max = x_[t[0]].cwiseMax(x_[t[1]]).cwiseMax(x_[t[2]]).cwiseMax(x_[t[3]]);
      widen_to_end(box, {t[0], t[1], t[2], t[3]}, 0.0);
      const double vol6 = (x_[t[1]] - x_[t[0]]).cross(x_[t[2]] - x_[t[0]]).dot(x_[t[3]] - x_[t[0]]);
      if (!finite_box(box)) box = skipped_box(*this, "tetrahedron", i, "a non-finite position");
      else if (vol6 == 0.0) box = skipped_box(*this, "tetrahedron", i, "zero volume (degenerate)");
    }
    tree_.set_box(i, box);
  }
  tree_.update(depth);
}

void register_tetrahedron_collision_model(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedronCollisionModel";
  info.category = "Collision/Geometry";
  info.description = "collision model of the tetrahedra of a topology over a Vec3d state";
  info.create = creator<TetrahedronCollisionModel>();
  r.add(std::move(info));
}

}  // namespace sinew
