#include "topology/dynamic/edge_set_topology_container.h"

#include "core/registry.h"

namespace sinew {

void EdgeSetTopologyContainer::create_lower_lists() {
  // Nothing below edges but the vertex shells, built on demand.
}

void register_edge_set_topology_container(Registry& r) {
  ComponentInfo info;
  info.name = "EdgeSetTopologyContainer";
  info.category = "Topology";
  info.description = "Topology container for edges";
  info.create = creator<EdgeSetTopologyContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
