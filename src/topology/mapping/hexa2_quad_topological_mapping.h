// Hexa2QuadTopologicalMapping: the boundary quads of a hexahedral topology
// (quads with a single adjacent hexahedron), in input order (spec/mechanics.md §5.7).
#pragma once

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class Hexa2QuadTopologicalMapping final : public TopologicalMapping {
 public:
  Field<bool> flip_normals{this, "flipNormals", false, "reverse the vertex order of the created faces", "Mapping"};
  void init() override;
};

}  // namespace sinew
