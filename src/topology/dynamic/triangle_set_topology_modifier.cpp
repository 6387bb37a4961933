#include "topology/dynamic/triangle_set_topology_modifier.h"

#include <algorithm>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/element_addition.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/triangle_set_topology_container.h"

namespace sinew {

bool TriangleSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const TriangleSetTopologyContainer*>(&c) != nullptr; }

void TriangleSetTopologyModifier::remove_triangles(std::vector<unsigned> ids, bool remove_isolated_edges,
                                                   bool remove_isolated_points) {
  if (!container()) return;
  const std::vector<unsigned> d = checked_ids(std::move(ids), container()->triangles().size(), "triangle");
  if (d.empty()) return;
  warn(TopologyChangeType::triangles_removed, d);
  propagate_topological_changes();
  PointSetTopologyContainer& c = *dynamic_container();
  topo::Isolated iso = topo::remove_triangles_process(c.begin_edit(), d, remove_isolated_edges, remove_isolated_points);
  c.end_edit(false, true, false);
  if (!iso.edges.empty()) {
    std::sort(iso.edges.begin(), iso.edges.end(), std::greater<unsigned>());
    warn(TopologyChangeType::edges_removed, iso.edges);
    propagate_topological_changes();
    topo::remove_edges_process(c.begin_edit(), iso.edges, false);
    c.end_edit(true, false, false);
  }
  cascade_isolated_points(std::move(iso.points));
}

void TriangleSetTopologyModifier::add_triangles(const std::vector<Triangle>& triangles,
                                                std::vector<std::vector<unsigned>> ancestors,
                                                std::vector<std::vector<double>> coefficients) {
  if (!container() || triangles.empty()) return;
  PointSetTopologyContainer& c = *dynamic_container();
  topo::DynamicMesh& m = c.begin_edit();
  const unsigned first = static_cast<unsigned>(m.triangles->size());
  const std::size_t edges_before = m.edges->size();
  for (const Triangle& t : triangles)
    for (unsigned e : topo::add_triangle_process(m, t)) warn(TopologyChangeType::edges_added, {e});
  c.end_edit(m.edges->size() != edges_before, true, false);
  TopologyChange added{TopologyChangeType::triangles_added, {}, std::move(ancestors), std::move(coefficients)};
  for (unsigned i = 0; i < triangles.size(); ++i) added.indices.push_back(first + i);
  warn(std::move(added));
  propagate_topological_changes();
}

bool TriangleSetTopologyModifier::remove_items(const std::vector<unsigned>& ids, std::string* why) {
  if (!container()) {
    if (why) *why = "the modifier has no container";
    return false;
  }
  remove_triangles(ids, true, true);
  return true;
}

void register_triangle_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "TriangleSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a triangular topology";
  info.create = creator<TriangleSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
