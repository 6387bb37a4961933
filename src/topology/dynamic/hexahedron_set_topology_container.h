// HexahedronSetTopologyContainer: Topology container for hexahedra (spec/mechanics.md §5.6).
#pragma once

#include "topology/dynamic/quad_set_topology_container.h"

namespace sinew {

class HexahedronSetTopologyContainer : public QuadSetTopologyContainer {
 public:

  Level level() const override { return Level::hexahedron; }

 protected:
  void create_lower_lists() override;
};

}  // namespace sinew
