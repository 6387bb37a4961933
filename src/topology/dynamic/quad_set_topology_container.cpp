#include "topology/dynamic/quad_set_topology_container.h"

#include "core/registry.h"

namespace sinew {

void QuadSetTopologyContainer::drop_foreign_lists() {
  // SOFA's quad and hexahedron containers have no triangle or tetrahedron lists: what src=@grid
  // brings there is not theirs, and no change would keep it up to date (its points could be
  // removed under it).
  auto drop = [](auto& f) {
    if (f.get().empty()) return;
    if (f.parent()) f.set_parent(nullptr);
    f.edit().clear();
  };
  drop(triangles_f);
  drop(tetrahedra_f);
}

void QuadSetTopologyContainer::create_lower_lists() {
  drop_foreign_lists();
  // Edges of the quads, (q[j+1], q[j+2]) stored with the smaller index first.
  if (edges_f.get().empty()) {
    if (edges_f.parent()) edges_f.set_parent(nullptr);
    edges_f.edit() = topo::edges_of_surfaces({}, quads_f.get());
  }
}

void register_quad_set_topology_container(Registry& r) {
  ComponentInfo info;
  info.name = "QuadSetTopologyContainer";
  info.category = "Topology";
  info.description = "Topology container for quads";
  info.create = creator<QuadSetTopologyContainer>();
  r.add(std::move(info));
}

}  // namespace sinew
