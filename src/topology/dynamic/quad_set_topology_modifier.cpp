#include "topology/dynamic/quad_set_topology_modifier.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/quad_set_topology_container.h"

namespace sinew {

bool QuadSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const QuadSetTopologyContainer*>(&c) != nullptr; }

void register_quad_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "QuadSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a quad topology";
  info.create = creator<QuadSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
