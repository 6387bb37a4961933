// EdgeSetTopologyContainer: Topology container for edges (spec/mechanics.md §5.6).
#pragma once

#include "topology/dynamic/point_set_topology_container.h"

namespace sinew {

class EdgeSetTopologyContainer : public PointSetTopologyContainer {
 public:
  Field<bool> check_connexity{this, "checkConnexity", false, "check that the mesh is connected at init", "Topology"};

  Level level() const override { return Level::edge; }

 protected:
  void create_lower_lists() override;
};

}  // namespace sinew
