// PointCollisionModel: one element per point of the node's Vec3d state
// (spec/interaction.md §3.3).
#pragma once

#include "collision/collision_model.h"
#include "collision/intersect/elements.h"
#include "collision/intersect/local_min_distance_tests.h"

namespace sinew {

class PointCollisionModel : public CollisionModelBase {
 public:
  PointCollisionModel() : CollisionModelBase(Kind::point) {}

  Field<bool> both_side{this, "bothSide", false, "points collide from both sides of the surface", "Collision"};
  Field<bool> compute_normals{this, "computeNormals", false,
                              "compute vertex normals from the triangles (or tetrahedra faces) around each point",
                              "Collision"};
  Field<bool> display_free_position{this, "displayFreePosition", false, "draw the free positions (viewer)",
                                    "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology",
                                  "topology giving the neighbourhood of each point (default: the node's)"};

  std::size_t size() const override { return x_.size(); }
  void compute_bounding_tree(int depth) override;
  bool element_can_collide(unsigned i, const CollisionModelBase& other, unsigned j) const override;
  void prepare_for_sharing(bool neighbourhoods) const override;

  PointElem elem(unsigned i) const {
    return {x_[i], {i, x_.size(), contact_distance.value(), this}, i < normals_.size() ? normals_[i] : Vec3::Zero()};
  }
  const MeshTopologyBase* mesh() const { return topology.get(); }
  // LocalMinDistance's view of point i (triangles and edges around it), at
  // the positions of the current detection; built once per detection on first use.
  local_min_distance::PointNeighbourhood lmd_neighbourhood(unsigned i) const;
  // Vertex normals (computeNormals), one per point; empty otherwise.
  const std::vector<Vec3>& normals() const { return normals_; }

 protected:
  bool init_model() override;

 private:
  void update_normals();
  void build_lmd() const;
  std::span<const Vec3> x_;
  std::vector<Vec3> normals_;
  std::uint64_t stamp_ = 1;  // moves at every detection
  // LocalMinDistance neighbourhoods, one range per point in each array.
  mutable std::uint64_t lmd_stamp_ = 0;
  mutable bool lmd_line_above_ = false;
  mutable std::vector<Vec3> lmd_normals_, lmd_others_;
  mutable std::vector<unsigned> lmd_normal_start_, lmd_other_start_;
};

}  // namespace sinew
