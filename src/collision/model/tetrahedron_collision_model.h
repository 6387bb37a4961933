// TetrahedronCollisionModel: one element per tetrahedron of the topology
// (SOFA's TetrahedronCollisionModel). Boxes are the tetrahedra's own (SOFA
// adds no contactDistance here).
#pragma once

#include "collision/collision_model.h"
#include "collision/intersect/elements.h"

namespace sinew {

class TetrahedronCollisionModel final : public CollisionModelBase {
 public:
  TetrahedronCollisionModel() : CollisionModelBase(Kind::tetrahedron) {}

  Link<MeshTopologyBase> topology{this, "topology", "topology giving the tetrahedra (default: the node's)"};

  std::size_t size() const override { return tets_.size(); }
  void compute_bounding_tree(int depth) override;

  TetrahedronElem elem(unsigned i) const {
    const Tetra& t = tets_[i];
    return {{x_[t[0]], x_[t[1]], x_[t[2]], x_[t[3]]},
            {t[0], t[1], t[2], t[3]},
            {i, tets_.size(), contact_distance.value(), this}};
  }
  const Tetra& tetrahedron(unsigned i) const { return tets_[i]; }

 protected:
  bool init_model() override;

 private:
  bool update_from_topology();
  std::span<const Vec3> x_;
  std::vector<Tetra> tets_;
  std::uint64_t version_ = ~std::uint64_t{0};
};

}  // namespace sinew
