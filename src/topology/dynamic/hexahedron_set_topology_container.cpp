#include "topology/dynamic/hexahedron_set_topology_container.h"

#include "core/registry.h"

namespace sinew {

void HexahedronSetTopologyContainer::create_lower_lists() {
  drop_foreign_lists();
  // Edges first (sorted pairs), then the faces.
  if (edges_f.get().empty()) {
    if (edges_f.parent()) edges_f.set_parent(nullptr);
    edges_f.edit() = topo::edges_of_volumes({}, hexahedra_f.get());
  }
  if (quads_f.get().empty()) {
    if (quads_f.parent()) quads_f.set_parent(nullptr);
    quads_f.edit() = topo::quads_of_hexahedra(hexahedra_f.get());
  }
}

void register_hexahedron_set_topology_container(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronSetTopologyContainer";
  info.category = "Topology";
  info.description = "Topology container for hexahedra";
  info.create = creator<HexahedronSetTopologyContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
