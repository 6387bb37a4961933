// OBBCollisionModel (SOFA's CollisionOBBCapsule plugin): one oriented box per
// frame of the node's Rigid3d state. The frame gives the box's centre and
// axes; `extents` its half-sizes, one triple per frame (missing triples take
// `defaultExtent` on all three axes and are written back, as SOFA does).
// Contacts on a box are mapped to its frame by a RigidMapping (ContactMapper).
#pragma once

#include <cstdint>
#include <vector>

#include "collision/collision_model.h"
#include "collision/intersect/elements.h"

namespace sinew {

class ObbCollisionModel final : public CollisionModelBase {
 public:
  ObbCollisionModel() : CollisionModelBase(Kind::obb) {}

  Field<std::vector<Vec3>> extents{this, "extents", {}, "half-extents of each box along its frame's x, y and z axes",
                                   "Collision", "length"};
  Field<double> default_extent{this, "defaultExtent", 1.0, "half-extent of the boxes that extents does not give",
                               "Collision", "length"};

  std::size_t size() const override { return boxes_.size(); }
  void compute_bounding_tree(int depth) override;

  // The boxes as of the last compute_bounding_tree (positions and velocities read then).
  const ObbElem& elem(unsigned i) const { return boxes_[i]; }

 protected:
  bool accepts_rigid3() const override { return true; }
  bool accepts_vec3() const override { return false; }
  bool init_model() override;

 private:
  // Extents padded to the state's size (SOFA's resize); false after an error on a bad extent.
  bool update_extents(std::size_t n);
  void read_boxes();
  std::vector<ObbElem> boxes_;
  std::uint64_t extents_seen_ = 0;  // version of `extents` last checked
};

// The eight corners of a box in SOFA's OBB numbering (c ± a0 ± a1 ± a2, a_i = axis_i·ext_i).
std::array<Vec3, 8> obb_vertices(const ObbElem& b);

}  // namespace sinew
