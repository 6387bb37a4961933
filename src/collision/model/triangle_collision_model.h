// TriangleCollisionModel: one element per triangle of the node's topology,
// then two per quad (spec/interaction.md §3.3, flags §2.6).
#pragma once

#include "collision/collision_model.h"
#include "collision/intersect/elements.h"

namespace sinew {

class PointCollisionModel;

class TriangleCollisionModel : public CollisionModelBase {
 public:
  TriangleCollisionModel() : CollisionModelBase(Kind::triangle) {}

  Field<bool> both_side{this, "bothSide", false, "triangles collide from both sides", "Collision"};
  Field<bool> compute_normals{this, "computeNormals", true, "recompute the normals at every detection", "Collision"};
  Field<bool> use_curvature{this, "useCurvature", false, "use the curvature of the surface (cone data)", "Collision"};
  Link<MeshTopologyBase> topology{this, "topology", "topology giving the triangles (default: the node's)"};

  std::size_t size() const override { return tris_.size(); }
  void compute_bounding_tree(int depth) override;
  bool element_can_collide(unsigned i, const CollisionModelBase& other, unsigned j) const override;

  TriangleElem elem(unsigned i) const {
    const Triangle& t = tris_[i];
    return {x_[t[0]],
            x_[t[1]],
            x_[t[2]],
            normals_[i],
            {t[0], t[1], t[2]},
            flags_[i],
            {i, tris_.size(), contact_distance.value(), this}};
  }
  const Triangle& triangle(unsigned i) const { return tris_[i]; }
  // Number of the topology's own triangles (the elements after them come from quads).
  std::size_t topology_triangles() const { return n_topology_tris_; }
  const MeshTopologyBase* mesh() const { return topology.get(); }

  // Unit normal of triangle i as of the last detection (SOFA's t.n()).
  const Vec3& normal(unsigned i) const { return normals_[i]; }
  // Which of triangle i's vertices and edges it owns (kFlagP1 …, §2.6).
  int flags(unsigned i) const { return flags_[i]; }

 protected:
  bool init_model() override;
  // Follows the topology; true when the triangles were rebuilt (normals then zero).
  bool update_from_topology();
  // SOFA's updateNormals: every triangle's normal from the current positions.
  void update_normals();

  std::span<const Vec3> x_;
  std::vector<Triangle> tris_;
  std::vector<Vec3> normals_;
  // Normals recomputed at every detection even with computeNormals="false"
  // (TriangleOctreeCollisionModel, as SOFA's).
  bool always_compute_normals_ = false;

 private:
  void compute_flags();
  std::vector<int> flags_;
  std::size_t n_topology_tris_ = 0;
  std::uint64_t tris_version_ = ~std::uint64_t{0}, quads_version_ = ~std::uint64_t{0};
  const PointCollisionModel* points_ = nullptr;
};

}  // namespace sinew
