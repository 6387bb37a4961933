// Hexa2QuadTopologicalMapping: the boundary quads of a hexahedral topology
// (quads with a single adjacent hexahedron), in input order (spec/mechanics.md §5.7).
// The output follows the input's changes as SOFA's updateTopologicalMappingTopDown
// does (spec/interaction.md §7.3): faces uncovered by removed hexahedra are added,
// input quads removed are removed one at a time, points follow. Additions of
// hexahedra or quads are not followed (SOFA ignores them too).
#pragma once

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class QuadSetTopologyModifier;

class Hexa2QuadTopologicalMapping final : public TopologicalMapping {
 public:
  Field<bool> flip_normals{this, "flipNormals", false, "reverse the vertex order of the created faces", "Mapping"};
  void init() override;
  void update_top_down() override;

  // Output quad → input quad, and back (kUnmapped when an input quad is not mapped).
  const std::vector<unsigned>& loc2glob() const { return loc2glob_; }
  unsigned glob2loc(unsigned glob) const { return glob < glob2loc_.size() ? glob2loc_[glob] : kUnmapped; }
  static constexpr unsigned kUnmapped = ~0u;

 private:
  void set_glob2loc(unsigned glob, unsigned loc);
  void on_hexahedra_removed(const std::vector<unsigned>& removed);
  void on_quads_removed(const std::vector<unsigned>& removed);

  QuadSetTopologyModifier* modifier_ = nullptr;
  std::vector<unsigned> loc2glob_;
  // SOFA keeps a map; a flat array indexed by input quad is the same relation.
  std::vector<unsigned> glob2loc_;
};

}  // namespace sinew
