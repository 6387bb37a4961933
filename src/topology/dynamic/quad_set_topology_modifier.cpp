#include "topology/dynamic/quad_set_topology_modifier.h"

#include <algorithm>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/element_addition.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/quad_set_topology_container.h"

namespace sinew {

bool QuadSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const QuadSetTopologyContainer*>(&c) != nullptr; }

void QuadSetTopologyModifier::remove_quads(std::vector<unsigned> ids, bool remove_isolated_edges,
                                           bool remove_isolated_points) {
  if (!container()) return;
  const std::vector<unsigned> d = checked_ids(std::move(ids), container()->quads().size(), "quad");
  if (d.empty()) return;
  warn(TopologyChangeType::quads_removed, d);
  propagate_topological_changes();
  PointSetTopologyContainer& c = *dynamic_container();
  topo::Isolated iso = topo::remove_quads_process(c.begin_edit(), d, remove_isolated_edges, remove_isolated_points);
  c.end_edit(false, false, false, true, false);
  if (!iso.edges.empty()) {
    std::sort(iso.edges.begin(), iso.edges.end(), std::greater<unsigned>());
    warn(TopologyChangeType::edges_removed, iso.edges);
    propagate_topological_changes();
    topo::remove_edges_process(c.begin_edit(), iso.edges, false);
    c.end_edit(true, false, false);
  }
  cascade_isolated_points(std::move(iso.points));
}

void QuadSetTopologyModifier::add_quads(const std::vector<Quad>& quads, std::vector<std::vector<unsigned>> ancestors,
                                        std::vector<std::vector<double>> coefficients) {
  if (!container() || quads.empty()) return;
  PointSetTopologyContainer& c = *dynamic_container();
  topo::DynamicMesh& m = c.begin_edit();
  const unsigned first = static_cast<unsigned>(m.quads->size());
  const std::size_t edges_before = m.edges->size();
  for (const Quad& q : quads)
    for (unsigned e : topo::add_quad_process(m, q)) warn(TopologyChangeType::edges_added, {e});
  c.end_edit(m.edges->size() != edges_before, false, false, true, false);
  TopologyChange added{TopologyChangeType::quads_added, {}, std::move(ancestors), std::move(coefficients)};
  for (unsigned i = 0; i < quads.size(); ++i) added.indices.push_back(first + i);
  warn(std::move(added));
  propagate_topological_changes();
}

bool QuadSetTopologyModifier::remove_items(const std::vector<unsigned>& ids, std::string* why) {
  if (!container()) {
    if (why) *why = "the modifier has no container";
    return false;
  }
  remove_quads(ids, true, true);
  return true;
}

void register_quad_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "QuadSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a quad topology";
  info.create = creator<QuadSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
