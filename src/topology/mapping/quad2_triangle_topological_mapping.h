// Quad2TriangleTopologicalMapping: splits each quad of the input into two
// triangles, alternating the diagonal in a checkerboard when `swapping`
// (spec/mechanics.md §5.7).
#pragma once

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class Quad2TriangleTopologicalMapping final : public TopologicalMapping {
 public:
  Field<bool> swapping{this, "swapping", true,
                       "If true (default), alternate the diagonal orientation per quad in a checkerboard pattern to "
                       "avoid numerical bias",
                       "Mapping"};
  void init() override;
};

}  // namespace sinew
