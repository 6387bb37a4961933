// TriangleSetTopologyContainer: Topology container for triangles (spec/mechanics.md §5.6).
#pragma once

#include "topology/dynamic/edge_set_topology_container.h"

namespace sinew {

class TriangleSetTopologyContainer : public EdgeSetTopologyContainer {
 public:

  Level level() const override { return Level::triangle; }

 protected:
  void create_lower_lists() override;
};

}  // namespace sinew
