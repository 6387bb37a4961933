// EdgeSetTopologyModifier: Topology modifier dedicated to an edge topology.
// Removes edges (with their isolated points); see point_set_topology_modifier.h.
#pragma once

#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class EdgeSetTopologyModifier : public PointSetTopologyModifier {
 public:

 public:
  // SOFA's removeEdges: warn, propagate, process; points left without an edge follow when asked.
  void remove_edges(std::vector<unsigned> ids, bool remove_isolated_points);
  bool remove_items(const std::vector<unsigned>& ids, std::string* why) override;

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "EdgeSetTopologyContainer"; }
};

}  // namespace sinew
