#include "topology/dynamic/edge_set_topology_modifier.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/edge_set_topology_container.h"

namespace sinew {

bool EdgeSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const EdgeSetTopologyContainer*>(&c) != nullptr; }

void register_edge_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "EdgeSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to an edge topology";
  info.create = creator<EdgeSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
