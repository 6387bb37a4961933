// SphereCollisionModel: one sphere per point of the node's state, radius
// from listRadius or radius (spec/interaction.md §3.3). Vec3d: centred on the
// points, contacts at the centres. Rigid3d: centred on the frames, contacts on
// the surface (c − n·r), mapped to the frames by a RigidMapping (ContactMapper).
#pragma once

#include "collision/collision_model.h"
#include "collision/intersect/elements.h"

namespace sinew {

class SphereCollisionModel final : public CollisionModelBase {
 public:
  SphereCollisionModel() : CollisionModelBase(Kind::sphere) {}

  Field<double> radius{this, "radius", 1.0, "radius of the spheres not given by listRadius", "Collision", "length"};
  Field<std::vector<double>> list_radius{this, "listRadius", {}, "radius of each sphere", "Collision", "length"};
  Field<bool> show_impostors{this, "showImpostors", true, "draw spheres as impostors (viewer)", "Visualization"};

  std::size_t size() const override { return x_.size(); }
  void compute_bounding_tree(int depth) override;

  SphereElem elem(unsigned i) const { return {x_[i], r_[i], rigid_, {i, x_.size(), contact_distance.value(), this}}; }
  double radius_of(unsigned i) const { return r_[i]; }
  bool rigid() const { return rigid_; }
  bool accepts_rigid3() const override { return true; }

 protected:
  bool init_model() override;

 private:
  void update_radii();
  std::span<const Vec3> x_;
  std::vector<double> r_;
  bool rigid_ = false;
};

}  // namespace sinew
