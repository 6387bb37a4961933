// TriangleSetTopologyModifier: Topology modifier dedicated to a triangular topology.
// Removes triangles (with their isolated edges and points); see point_set_topology_modifier.h.
#pragma once

#include "topology/dynamic/edge_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class TriangleSetTopologyModifier : public EdgeSetTopologyModifier {
 public:
  Field<std::vector<unsigned>> list_out{this, "list_Out", {}, "degenerate triangles found (output)", "Topology"};

 public:
  // SOFA's removeTriangles: warn, propagate, process; then the edges left without a triangle
  // (warn, propagate, process) and the points left without a triangle, when asked.
  void remove_triangles(std::vector<unsigned> ids, bool remove_isolated_edges, bool remove_isolated_points);
  // SOFA's addTriangles: process (each triangle appended, its missing edges created, one
  // edges-added event per created edge), then a triangles-added event, then propagate.
  // `ancestors`/`coefficients` are empty or one row per triangle.
  void add_triangles(const std::vector<Triangle>& triangles, std::vector<std::vector<unsigned>> ancestors = {},
                     std::vector<std::vector<double>> coefficients = {});
  // removeItems: removeTriangles(ids, true, true).
  bool remove_items(const std::vector<unsigned>& ids, std::string* why) override;

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "TriangleSetTopologyContainer"; }
};

}  // namespace sinew
