// Hexa2TetraTopologicalMapping: splits each hexahedron of the input into 6
// tetrahedra of the output container (spec/mechanics.md §5.7, trap 15).
#pragma once

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class Hexa2TetraTopologicalMapping final : public TopologicalMapping {
 public:
  Field<bool> swapping{this, "swapping", false,
                       "alternate the split pattern per cell (checkerboard) to avoid a directional bias", "Mapping"};
  void init() override;

  // The 6 tetrahedra of hexahedron `h` (index `i` in a grid of nx × ny cells per layer).
  static void split(const Hexa& h, unsigned i, int nx, int ny, bool swapping, std::vector<Tetra>& out);
};

}  // namespace sinew
