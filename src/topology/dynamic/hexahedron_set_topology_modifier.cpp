#include "topology/dynamic/hexahedron_set_topology_modifier.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/hexahedron_set_topology_container.h"

namespace sinew {

bool HexahedronSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const HexahedronSetTopologyContainer*>(&c) != nullptr; }

void register_hexahedron_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to an hexahedral topology";
  info.create = creator<HexahedronSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
