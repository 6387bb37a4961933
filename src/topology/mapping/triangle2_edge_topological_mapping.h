// Triangle2EdgeTopologicalMapping: the boundary edges of a triangular
// topology (edges with a single adjacent triangle), in input order.
#pragma once

#include "topology/mapping/topological_mapping.h"

namespace sinew {

class Triangle2EdgeTopologicalMapping final : public TopologicalMapping {
 public:
  void init() override;
};

}  // namespace sinew
