// TetrahedronSetTopologyContainer: Topology container for tetrahedra (spec/mechanics.md §5.6).
#pragma once

#include "topology/dynamic/triangle_set_topology_container.h"

namespace sinew {

class TetrahedronSetTopologyContainer : public TriangleSetTopologyContainer {
 public:

  Level level() const override { return Level::tetrahedron; }

 protected:
  void create_lower_lists() override;
};

}  // namespace sinew
