#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

#include <algorithm>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
#include "topology/dynamic/element_addition.h"
#include "topology/dynamic/point_set_topology_container.h"
#include "topology/dynamic/tetrahedron_set_topology_container.h"

namespace sinew {

bool TetrahedronSetTopologyModifier::accepts(const Component& c) const { return dynamic_cast<const TetrahedronSetTopologyContainer*>(&c) != nullptr; }

void TetrahedronSetTopologyModifier::remove_tetrahedra(std::vector<unsigned> ids, bool remove_isolated_items) {
  if (!container()) return;
  const std::vector<unsigned> d = checked_ids(std::move(ids), container()->tetrahedra().size(), "tetrahedron");
  if (d.empty()) return;
  warn(TopologyChangeType::tetrahedra_removed, d);
  propagate_topological_changes();
  PointSetTopologyContainer& c = *dynamic_container();
  topo::Isolated iso =
      topo::remove_tetrahedra_process(c.begin_edit(), d, remove_isolated_items, remove_isolated.value());
  c.end_edit(false, false, true);
  if (!iso.triangles.empty() || !iso.edges.empty()) {
    std::sort(iso.triangles.begin(), iso.triangles.end(), std::greater<unsigned>());
    std::sort(iso.edges.begin(), iso.edges.end(), std::greater<unsigned>());
    if (!iso.triangles.empty()) warn(TopologyChangeType::triangles_removed, iso.triangles);
    if (!iso.edges.empty()) warn(TopologyChangeType::edges_removed, iso.edges);
    propagate_topological_changes();
    if (!iso.triangles.empty()) {
      topo::remove_triangles_process(c.begin_edit(), iso.triangles, false, false);
      c.end_edit(false, true, false);
    }
    if (!iso.edges.empty()) {
      topo::remove_edges_process(c.begin_edit(), iso.edges, false);
      c.end_edit(true, false, false);
    }
  }
  cascade_isolated_points(std::move(iso.points));
}

void TetrahedronSetTopologyModifier::add_tetrahedra(const std::vector<Tetra>& tetrahedra,
                                                    std::vector<std::vector<unsigned>> ancestors,
                                                    std::vector<std::vector<double>> coefficients) {
  if (!container() || tetrahedra.empty()) return;
  PointSetTopologyContainer& c = *dynamic_container();
  topo::DynamicMesh& m = c.begin_edit();
  const unsigned first = static_cast<unsigned>(m.tetrahedra->size());
  bool edges_changed = false, triangles_changed = false;
  for (const Tetra& t : tetrahedra)
    for (const topo::Created& k : topo::add_tetrahedron_process(m, t)) {
      const bool edge = k.kind == topo::Created::Kind::edge;
      (edge ? edges_changed : triangles_changed) = true;
      warn(edge ? TopologyChangeType::edges_added : TopologyChangeType::triangles_added, {k.index});
    }
  c.end_edit(edges_changed, triangles_changed, true);
  TopologyChange added{TopologyChangeType::tetrahedra_added, {}, std::move(ancestors), std::move(coefficients)};
  for (unsigned i = 0; i < tetrahedra.size(); ++i) added.indices.push_back(first + i);
  warn(std::move(added));
  propagate_topological_changes();
}

bool TetrahedronSetTopologyModifier::remove_items(const std::vector<unsigned>& ids, std::string* why) {
  if (!container()) {
    if (why) *why = "the modifier has no container";
    return false;
  }
  remove_tetrahedra(ids, true);
  return true;
}

void register_tetrahedron_set_topology_modifier(Registry& r) {
  ComponentInfo info;
  info.name = "TetrahedronSetTopologyModifier";
  info.category = "Topology";
  info.description = "Topology modifier dedicated to a tetrahedral topology";
  info.create = creator<TetrahedronSetTopologyModifier>();
  r.add(std::move(info));
}

}  // namespace sinew
