// Tetra2TriangleTopologicalMapping: the boundary triangles of a tetrahedral
// topology (triangles with a single adjacent tetrahedron), in input order
// (spec/mechanics.md §5.7).
#pragma once

#include "topology/topological_mapping.h"
#include "topology/triangle_set_topology_modifier.h"

namespace sinew {

class Tetra2TriangleTopologicalMapping final : public TopologicalMapping {
 public:
  Link<TriangleSetTopologyModifier> modifier{this, "modifier", "Optional link to a topology modifier"};
  Field<bool> flip_normals{this, "flipNormals", false,
                           "Flip Normal ? (Inverse point order when creating triangle)", "Mapping"};
  Field<bool> no_new_triangles{this, "noNewTriangles", false, "If true no new triangles are being created",
                               "Mapping"};
  Field<bool> no_initial_triangles{this, "noInitialTriangles", false,
                                   "If true the list of initial triangles is initially empty. Only additional "
                                   "triangles will be added in the list",
                                   "Mapping"};
  void init() override;
};

}  // namespace sinew
