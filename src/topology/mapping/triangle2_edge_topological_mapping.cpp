#include "topology/mapping/triangle2_edge_topological_mapping.h"

#include "core/registry.h"
#include "topology/dynamic/edge_set_topology_modifier.h"

namespace sinew {

void Triangle2EdgeTopologicalMapping::init() {
  if (!check_links(true, ElementType::triangle, ElementType::edge)) return;
  if (!find_from_output<EdgeSetTopologyModifier>()) {
    msg_error("No EdgeSetTopologyModifier found in the Edge topology Node.");
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<Edge> edges = input->edges();
  const auto& around = input->triangles_around_edge();
  const std::size_t np = input->nb_points();
  output->clear_topology();
  output->set_nb_points(np);
  std::vector<Edge> out;
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (i < around.size() && around[i].size() == 1) out.push_back(edges[i]);
  output->edges_f.set(std::move(out));
  output->init();
}

void register_triangle2_edge_topological_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "Triangle2EdgeTopologicalMapping";
  info.category = "TopologyMapping";
  info.description = "Topological mapping where TriangleSetTopology is converted to EdgeSetTopology";
  info.create = creator<Triangle2EdgeTopologicalMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
