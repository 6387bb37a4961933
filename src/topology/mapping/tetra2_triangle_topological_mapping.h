// Tetra2TriangleTopologicalMapping: the boundary triangles of a tetrahedral
// topology (triangles with a single adjacent tetrahedron), in input order
// (spec/mechanics.md §5.7). The output follows the input's changes
// (spec/interaction.md §7.3): faces uncovered by removed tetrahedra are added,
// faces removed from the input are removed, points follow.
#pragma once

#include "topology/mapping/topological_mapping.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {

class Tetra2TriangleTopologicalMapping final : public TopologicalMapping {
 public:
  Link<TriangleSetTopologyModifier> modifier{this, "modifier", "topology modifier of the output (optional)"};
  Field<bool> flip_normals{this, "flipNormals", false, "reverse the vertex order of the created faces", "Mapping"};
  Field<bool> no_new_triangles{this, "noNewTriangles", false, "do not add triangles on topology changes", "Mapping"};
  Field<bool> no_initial_triangles{this, "noInitialTriangles", false,
                                   "start with no triangles; only triangles created later are mapped", "Mapping"};
  void init() override;
  void update_top_down() override;
  // A boundary face stands for the one tetrahedron it bounds (none when it bounds no single one).
  bool input_elements(unsigned out, std::vector<unsigned>& in) const override;

  // Output triangle → input triangle, and back (kNoIndex when an input triangle is not mapped).
  const std::vector<unsigned>& loc2glob() const { return loc2glob_; }
  unsigned glob2loc(unsigned glob) const { return glob < glob2loc_.size() ? glob2loc_[glob] : kUnmapped; }
  static constexpr unsigned kUnmapped = ~0u;

 private:
  void set_glob2loc(unsigned glob, unsigned loc);
  void on_tetrahedra_removed(const std::vector<unsigned>& removed);
  void on_triangles_removed(const std::vector<unsigned>& removed);
  void on_tetrahedra_added(const std::vector<unsigned>& added);

  std::vector<unsigned> loc2glob_;
  // SOFA keeps a map; a flat array indexed by input triangle is the same relation.
  std::vector<unsigned> glob2loc_;
};

}  // namespace sinew
