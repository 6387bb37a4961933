// PointCollisionModel: one element per point of the node's Vec3d state
// (spec/interaction.md §3.3).
#pragma once

#include "collision/collision_model.h"
#include "collision/intersect/elements.h"

namespace sinew {

class PointCollisionModel final : public CollisionModelBase {
 public:
  PointCollisionModel() : CollisionModelBase(Kind::point) {}

  Field<bool> both_side{this, "bothSide", false, "points collide from both sides of the surface", "Collision"};
  Field<bool> compute_normals{this, "computeNormals", false,
                              "compute vertex normals from the triangles (or tetrahedra faces) around each point",
                              "Collision"};
  Field<bool> display_free_position{this, "displayFreePosition", false, "draw the free positions (viewer)",
                                    "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the neighbourhood of each point (default: the node's)"};

  std::size_t size() const override { return x_.size(); }
  void compute_bounding_tree(int depth) override;
  bool element_can_collide(unsigned i, const CollisionModelBase& other, unsigned j) const override;

  PointElem elem(unsigned i) const { return {x_[i], {i, x_.size(), contact_distance.value(), this}}; }
  const MeshTopologyBase* mesh() const { return topology.get(); }
  // Vertex normals (computeNormals), one per point; empty otherwise.
  const std::vector<Vec3>& normals() const { return normals_; }

 protected:
  bool init_model() override;

 private:
  void update_normals();
  std::span<const Vec3> x_;
  std::vector<Vec3> normals_;
};

}  // namespace sinew
