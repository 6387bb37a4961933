// EdgeSetTopologyModifier: Topology modifier dedicated to an edge topology.
// Adds edges; removes edges (with their isolated points); see point_set_topology_modifier.h.
#pragma once

#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class EdgeSetTopologyModifier : public PointSetTopologyModifier {
 public:

 public:
  // SOFA's removeEdges: warn, propagate, process; points left without an edge follow when asked.
  void remove_edges(std::vector<unsigned> ids, bool remove_isolated_points);
  // SOFA's addEdges: process (each edge appended, in the given vertex order), then one
  // edges-added event for all of them, then propagate. `ancestors`/`coefficients` are empty or
  // one row per edge.
  void add_edges(const std::vector<Edge>& edges, std::vector<std::vector<unsigned>> ancestors = {},
                 std::vector<std::vector<double>> coefficients = {});
  bool remove_items(const std::vector<unsigned>& ids, std::string* why) override;

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "EdgeSetTopologyContainer"; }
};

}  // namespace sinew
