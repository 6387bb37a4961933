#include "topology/dynamic/tetrahedron_set_topology_container.h"

#include "core/registry.h"

namespace sinew {

void TetrahedronSetTopologyContainer::create_lower_lists() {
  // Edges first (sorted pairs), then the faces (outward for positively oriented tetrahedra).
  if (edges_f.get().empty()) {
    if (edges_f.parent()) edges_f.set_parent(nullptr);
    edges_f.edit() = topo::edges_of_volumes(tetrahedra_f.get(), {});
  }
  if (triangles_f.get().empty()) {
    if (triangles_f.parent()) triangles_f.set_parent(nullptr);
    triangles_f.edit() = topo::triangles_of_tetrahedra(tetrahedra_f.get(), true);
  }
}

void register_tetrahedron_set_topology_container(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedronSetTopologyContainer";
  info.category = "Topology";
  info.description = "Topology container for tetrahedra";
  info.create = creator<TetrahedronSetTopologyContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
