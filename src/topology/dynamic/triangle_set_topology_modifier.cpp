#include "topology/dynamic/triangle_set_topology_modifier.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/triangle_set_topology_container.h"

namespace sinew {

bool TriangleSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const TriangleSetTopologyContainer*>(&c) != nullptr; }

void register_triangle_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a triangular topology";
  info.create = creator<TriangleSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
