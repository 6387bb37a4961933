// PointSetTopologyContainer: base of SOFA's dynamic containers, used here
// statically (spec/mechanics.md §5.6). The family mirrors SOFA's hierarchy:
// Point ⊂ Edge ⊂ Triangle ⊂ Tetrahedron and Edge ⊂ Quad ⊂ Hexahedron.
//
// init(): the number of points is the size of `position` when it is set,
// else one past the largest index of the container's main list; when the
// main list is not empty the lower lists that are empty are created from it
// (edges first, then triangles or quads), in SOFA's order and orientation.
#pragma once

#include "topology/mesh_topology.h"

namespace sinew {

class PointSetTopologyContainer : public MeshContainer {
 public:
  // Which element list is the container's own (its "topology type").
  enum class Level { point, edge, triangle, quad, tetrahedron, hexahedron };

  PointSetTopologyContainer();

  Field<unsigned> nb_points_f{this, "nbPoints", 0u, "point count (when no positions are given)", "Topology"};
  Field<bool> check_topology{this, "checkTopology", false, "run consistency checks on the topology (slow)", "Topology"};

  virtual Level level() const { return Level::point; }

  std::size_t nb_points() const override;
  void init() override;
  void clear_topology() override;
  void set_nb_points(std::size_t n) override;

 protected:
  std::uint64_t points_stamp() const override { return (nb_points_f.version() << 1) | (initialised_ ? 1u : 0u); }
  // Creates the empty lower lists from the main list (SOFA's computeCrossElementBuffers).
  virtual void create_lower_lists() {}

 private:
  bool initialised_ = false;
};

}  // namespace sinew
