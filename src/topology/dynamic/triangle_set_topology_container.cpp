#include "topology/dynamic/triangle_set_topology_container.h"

#include "core/registry.h"

namespace sinew {

void TriangleSetTopologyContainer::create_lower_lists() {
  // SOFA's triangle container has no quad or hexahedron list (getNbQuads() is 0): what
  // src=@grid brings there is not its own (AreaMapping refuses a topology with quads).
  auto drop = [](auto& f) {
    if (f.get().empty()) return;
    if (f.parent()) f.set_parent(nullptr);
    f.edit().clear();
  };
  drop(quads_f);
  drop(hexahedra_f);
  // Edges of the triangles, stored as found (oriented like their first triangle).
  if (edges_f.get().empty()) {
    if (edges_f.parent()) edges_f.set_parent(nullptr);
    edges_f.edit() = topo::edges_of_surfaces(triangles_f.get(), {});
  }
}

void register_triangle_set_topology_container(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleSetTopologyContainer";
  info.category = "Topology";
  info.description = "Topology container for triangles";
  info.create = creator<TriangleSetTopologyContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
