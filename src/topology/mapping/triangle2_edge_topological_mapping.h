// Triangle2EdgeTopologicalMapping: the boundary edges of a triangular
// topology (edges with a single adjacent triangle), in input order
// (spec/mechanics.md §5.7). The output follows the input's changes
// (spec/interaction.md §7.3, SOFA's updateTopologicalMappingTopDown): edges
// uncovered by removed triangles are added, removed input edges leave the
// output, new triangles bring their boundary edges and retire the edges they
// cover, points follow (removed and added, without DoFs).
#pragma once

#include "topology/dynamic/edge_set_topology_modifier.h"
#include "topology/mapping/topological_mapping.h"

namespace sinew {

class Triangle2EdgeTopologicalMapping final : public TopologicalMapping {
 public:
  void init() override;
  void update_top_down() override;

  // Output edge → input edge, and back (kUnmapped when an input edge is not mapped).
  const std::vector<unsigned>& loc2glob() const { return loc2glob_; }
  unsigned glob2loc(unsigned glob) const { return glob < glob2loc_.size() ? glob2loc_[glob] : kUnmapped; }
  static constexpr unsigned kUnmapped = ~0u;

 private:
  void set_glob2loc(unsigned glob, unsigned loc);
  void on_edges_removed(const std::vector<unsigned>& removed);
  void on_triangles_removed(const std::vector<unsigned>& removed);
  void on_triangles_added(const std::vector<unsigned>& added);

  EdgeSetTopologyModifier* modifier_ = nullptr;
  std::vector<unsigned> loc2glob_;
  // SOFA keeps a map; a flat array indexed by input edge is the same relation.
  std::vector<unsigned> glob2loc_;
};

}  // namespace sinew
