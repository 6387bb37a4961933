#include "topology/dynamic/quad_set_topology_container.h"

#include "core/registry.h"

namespace sinew {

void QuadSetTopologyContainer::create_lower_lists() {
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
