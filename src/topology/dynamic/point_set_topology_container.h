// PointSetTopologyContainer: base of SOFA's dynamic containers, used here
// statically (spec/mechanics.md §5.6). The family mirrors SOFA's hierarchy:
// Point ⊂ Edge ⊂ Triangle ⊂ Tetrahedron and Edge ⊂ Quad ⊂ Hexahedron.
//
// init(): the number of points is the size of `position` when it is set,
// else one past the largest index of the container's main list; when the
// main list is not empty the lower lists that are empty are created from it
// (edges first, then triangles or quads), in SOFA's order and orientation.
#pragma once

#include <memory>

#include "topology/dynamic/element_removal.h"
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

  // Removals (the modifier's process step) edit the lists through this view: the neighbourhood
  // arrays are built from the lists on first use (O(size) once), then kept up to date by the
  // removal processes, so a removal costs what it touches. The view stays live while nobody
  // else edits the lists; `end_edit()` records the new lists and point count.
  topo::DynamicMesh& begin_edit();
  // Moves the versions of the lists that changed (consumers comparing elements_version follow).
  void end_edit(bool edges_changed, bool triangles_changed, bool tetrahedra_changed, bool quads_changed = false,
                bool hexahedra_changed = false);

  // Neighbourhood queries: the live arrays while a removal view is live, else the cache.
  const std::vector<IndexList>& edges_around_vertex() const override;
  const std::vector<IndexList>& triangles_around_vertex() const override;
  const std::vector<IndexList>& triangles_around_edge() const override;
  const std::vector<IndexList>& tetrahedra_around_vertex() const override;
  const std::vector<IndexList>& tetrahedra_around_edge() const override;
  const std::vector<IndexList>& tetrahedra_around_triangle() const override;
  const std::vector<IndexList>& quads_around_vertex() const override;
  const std::vector<IndexList>& quads_around_edge() const override;
  const std::vector<IndexList>& hexahedra_around_vertex() const override;
  const std::vector<IndexList>& hexahedra_around_edge() const override;
  const std::vector<IndexList>& hexahedra_around_quad() const override;
  const std::vector<std::array<unsigned, 3>>& edges_in_triangle() const override;
  const std::vector<std::array<unsigned, 6>>& edges_in_tetrahedron() const override;
  const std::vector<std::array<unsigned, 4>>& triangles_in_tetrahedron() const override;
  const std::vector<std::array<unsigned, 4>>& edges_in_quad() const override;
  const std::vector<std::array<unsigned, 12>>& edges_in_hexahedron() const override;
  const std::vector<std::array<unsigned, 6>>& quads_in_hexahedron() const override;
  unsigned triangle_index(unsigned a, unsigned b, unsigned c) const override;
  unsigned quad_index(unsigned a, unsigned b, unsigned c, unsigned d) const override;

 protected:
  std::uint64_t points_stamp() const override { return (nb_points_f.version() << 1) | (initialised_ ? 1u : 0u); }
  // Creates the empty lower lists from the main list (SOFA's computeCrossElementBuffers).
  virtual void create_lower_lists() {}

 private:
  bool live() const;
  bool initialised_ = false;
  std::unique_ptr<topo::DynamicMesh> mesh_;
  std::uint64_t mesh_versions_[6] = {0, 0, 0, 0, 0, 0};
};

}  // namespace sinew
