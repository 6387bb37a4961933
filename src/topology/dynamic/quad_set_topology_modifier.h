// QuadSetTopologyModifier: Topology modifier dedicated to a quad topology.
// Adds quads (element_addition.h); removes quads with their isolated edges and
// points (SOFA's removeQuads); see point_set_topology_modifier.h.
#pragma once

#include "topology/dynamic/edge_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class QuadSetTopologyModifier : public EdgeSetTopologyModifier {
 public:
  // SOFA's removeQuads: warn, propagate, process; then the edges left without a quad (warn,
  // propagate, process) and the points left without a quad, when asked.
  void remove_quads(std::vector<unsigned> ids, bool remove_isolated_edges, bool remove_isolated_points);
  // SOFA's addQuads: process (each quad appended, its missing edges created, one edges-added
  // event per created edge), then a quads-added event, then propagate. `ancestors` /
  // `coefficients` are empty or one row per quad.
  void add_quads(const std::vector<Quad>& quads, std::vector<std::vector<unsigned>> ancestors = {},
                 std::vector<std::vector<double>> coefficients = {});
  // removeItems: removeQuads(ids, true, true).
  bool remove_items(const std::vector<unsigned>& ids, std::string* why) override;

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "QuadSetTopologyContainer"; }
};

}  // namespace sinew
