// QuadSetTopologyContainer: Topology container for quads (spec/mechanics.md §5.6).
#pragma once

#include "topology/dynamic/edge_set_topology_container.h"

namespace sinew {

class QuadSetTopologyContainer : public EdgeSetTopologyContainer {
 public:

  Level level() const override { return Level::quad; }

 protected:
  void create_lower_lists() override;
  // Clears the triangle and tetrahedron lists (not lists of this kind of container).
  void drop_foreign_lists();
};

}  // namespace sinew
