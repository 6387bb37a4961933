// Tetra2TriangleTopologicalMapping: the boundary triangles of a tetrahedral
// topology (triangles with a single adjacent tetrahedron), in input order
// (spec/mechanics.md §5.7).
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
};

}  // namespace sinew
