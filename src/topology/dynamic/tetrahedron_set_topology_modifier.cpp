#include "topology/dynamic/tetrahedron_set_topology_modifier.h"

#include <algorithm>
#include <functional>

#include "core/node.h"
#include "core/registry.h"
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
