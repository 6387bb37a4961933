#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"

namespace sinew {

bool TetrahedronSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const TetrahedronSetTopologyContainer*>(&c) != nullptr; }

void register_tetrahedron_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedronSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a tetrahedral topology";
  info.create = creator<TetrahedronSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
