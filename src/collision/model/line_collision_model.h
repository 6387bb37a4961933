// LineCollisionModel: one element per edge of the node's topology
// (spec/interaction.md §3.3), vertex order as the topology gives it.
#pragma once

#include "collision/collision_model.h"
#include "collision/intersect/elements.h"
#include "collision/intersect/local_min_distance_tests.h"

namespace sinew {

class PointCollisionModel;

class LineCollisionModel final : public CollisionModelBase {
 public:
  LineCollisionModel() : CollisionModelBase(Kind::line) {}

  Field<bool> both_side{this, "bothSide", false, "lines collide from both sides of the surface", "Collision"};
  Field<bool> display_free_position{this, "displayFreePosition", false, "draw the free positions (viewer)",
                                    "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the edges (default: the node's)"};

  std::size_t size() const override { return edges_.size(); }
  void compute_bounding_tree(int depth) override;
  bool element_can_collide(unsigned i, const CollisionModelBase& other, unsigned j) const override;
  void prepare_for_sharing(bool) const override {
    topology->edges_around_vertex();
    topology->triangles_around_edge();
  }

  LineElem elem(unsigned i) const {
    const Edge& e = edges_[i];
    return {x_[e[0]], x_[e[1]], {e[0], e[1]}, {i, edges_.size(), contact_distance.value(), this}};
  }
  const Edge& edge(unsigned i) const { return edges_[i]; }
  // LocalMinDistance's view of edge i: the two triangles along it, if it has exactly two.
  local_min_distance::LineNeighbourhood lmd_neighbourhood(unsigned i) const;
  const MeshTopologyBase* mesh() const { return topology.get(); }

 protected:
  bool init_model() override;

 private:
  bool update_from_topology();
  std::span<const Vec3> x_;
  std::vector<Edge> edges_;
  std::uint64_t edges_version_ = ~std::uint64_t{0};
  // The topology's lists the per-element filters read, fetched once per
  // detection (a topology list read goes through its field's link checks).
  const std::vector<Triangle>* tris_ = nullptr;
  const std::vector<MeshTopologyBase::IndexList>* tris_around_edge_ = nullptr;
  const std::vector<MeshTopologyBase::IndexList>* edges_around_vertex_ = nullptr;
  const PointCollisionModel* points_ = nullptr;  // the node's point model (self-collision filter)
};

}  // namespace sinew
