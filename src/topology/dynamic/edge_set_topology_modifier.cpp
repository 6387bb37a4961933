#include "topology/dynamic/edge_set_topology_modifier.h"

#include <algorithm>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/edge_set_topology_container.h"
#include "topology/dynamic/element_addition.h"

namespace sinew {

bool EdgeSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const EdgeSetTopologyContainer*>(&c) != nullptr; }

void EdgeSetTopologyModifier::remove_edges(std::vector<unsigned> ids, bool remove_isolated_points) {
  if (!container()) return;
  const std::vector<unsigned> d = checked_ids(std::move(ids), container()->edges().size(), "edge");
  if (d.empty()) return;
  warn(TopologyChangeType::edges_removed, d);
  propagate_topological_changes();
  PointSetTopologyContainer& c = *dynamic_container();
  topo::Isolated iso = topo::remove_edges_process(c.begin_edit(), d, remove_isolated_points);
  c.end_edit(true, false, false);
  cascade_isolated_points(std::move(iso.points));
}

void EdgeSetTopologyModifier::add_edges(const std::vector<Edge>& edges, std::vector<std::vector<unsigned>> ancestors,
                                        std::vector<std::vector<double>> coefficients) {
  if (!container() || edges.empty()) return;
  PointSetTopologyContainer& c = *dynamic_container();
  topo::DynamicMesh& m = c.begin_edit();
  const unsigned first = static_cast<unsigned>(m.edges->size());
  for (const Edge& e : edges) topo::add_edge_process(m, e);
  c.end_edit(true, false, false);
  TopologyChange added{TopologyChangeType::edges_added, {}, std::move(ancestors), std::move(coefficients)};
  for (unsigned i = 0; i < edges.size(); ++i) added.indices.push_back(first + i);
  warn(std::move(added));
  propagate_topological_changes();
}

bool EdgeSetTopologyModifier::remove_items(const std::vector<unsigned>& ids, std::string* why) {
  if (!container()) {
    if (why) *why = "the modifier has no container";
    return false;
  }
  remove_edges(ids, true);
  return true;
}

void register_edge_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "EdgeSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to an edge topology";
  info.create = creator<EdgeSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
