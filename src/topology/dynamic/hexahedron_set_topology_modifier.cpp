#include "topology/dynamic/hexahedron_set_topology_modifier.h"

#include <algorithm>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/element_addition.h"
#include "topology/dynamic/hexahedron_set_topology_container.h"
#include "topology/dynamic/point_set_topology_container.h"

namespace sinew {

bool HexahedronSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const HexahedronSetTopologyContainer*>(&c) != nullptr; }

void HexahedronSetTopologyModifier::remove_hexahedra(std::vector<unsigned> ids) {
  if (!container()) return;
  const std::vector<unsigned> d = checked_ids(std::move(ids), container()->hexahedra().size(), "hexahedron");
  if (d.empty()) return;
  warn(TopologyChangeType::hexahedra_removed, d);
  propagate_topological_changes();
  PointSetTopologyContainer& c = *dynamic_container();
  topo::Isolated iso = topo::remove_hexahedra_process(c.begin_edit(), d, true, remove_isolated.value());
  c.end_edit(false, false, false, false, true);
  if (!iso.quads.empty() || !iso.edges.empty()) {
    // Quads then edges are warned, one propagation carries both, then both are processed.
    std::sort(iso.quads.begin(), iso.quads.end(), std::greater<unsigned>());
    std::sort(iso.edges.begin(), iso.edges.end(), std::greater<unsigned>());
    if (!iso.quads.empty()) warn(TopologyChangeType::quads_removed, iso.quads);
    if (!iso.edges.empty()) warn(TopologyChangeType::edges_removed, iso.edges);
    propagate_topological_changes();
    if (!iso.quads.empty()) {
      topo::remove_quads_process(c.begin_edit(), iso.quads, false, false);
      c.end_edit(false, false, false, true, false);
    }
    if (!iso.edges.empty()) {
      topo::remove_edges_process(c.begin_edit(), iso.edges, false);
      c.end_edit(true, false, false);
    }
  }
  cascade_isolated_points(std::move(iso.points));
}

void HexahedronSetTopologyModifier::add_hexahedra(const std::vector<Hexa>& hexahedra,
                                                  std::vector<std::vector<unsigned>> ancestors,
                                                  std::vector<std::vector<double>> coefficients) {
  if (!container() || hexahedra.empty()) return;
  PointSetTopologyContainer& c = *dynamic_container();
  topo::DynamicMesh& m = c.begin_edit();
  const unsigned first = static_cast<unsigned>(m.hexahedra->size());
  bool edges_changed = false, quads_changed = false;
  for (const Hexa& h : hexahedra)
    for (const topo::Created& k : topo::add_hexahedron_process(m, h)) {
      const bool edge = k.kind == topo::Created::Kind::edge;
      (edge ? edges_changed : quads_changed) = true;
      warn(edge ? TopologyChangeType::edges_added : TopologyChangeType::quads_added, {k.index});
    }
  c.end_edit(edges_changed, false, false, quads_changed, true);
  TopologyChange added{TopologyChangeType::hexahedra_added, {}, std::move(ancestors), std::move(coefficients)};
  for (unsigned i = 0; i < hexahedra.size(); ++i) added.indices.push_back(first + i);
  warn(std::move(added));
  propagate_topological_changes();
}

bool HexahedronSetTopologyModifier::remove_items(const std::vector<unsigned>& ids, std::string* why) {
  if (!container()) {
    if (why) *why = "the modifier has no container";
    return false;
  }
  remove_hexahedra(ids);
  return true;
}

void register_hexahedron_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "HexahedronSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to an hexahedral topology";
  info.create = creator<HexahedronSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
