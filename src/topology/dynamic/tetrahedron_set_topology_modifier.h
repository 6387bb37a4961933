// TetrahedronSetTopologyModifier: Topology modifier dedicated to a tetrahedral topology.
// Adds tetrahedra (element_addition.h); removes them with SOFA's cascade: faces and edges left without a tetrahedron
// (one warn/propagate for both, then processed), then isolated points (when
// `removeIsolated`); see point_set_topology_modifier.h.
#pragma once

#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class TetrahedronSetTopologyModifier : public TriangleSetTopologyModifier {
 public:
  Field<bool> remove_isolated{this, "removeIsolated", true, "remove points left without elements", "Topology"};

 public:
  // SOFA's removeTetrahedra(ids, removeIsolatedItems).
  void remove_tetrahedra(std::vector<unsigned> ids, bool remove_isolated_items = true);
  // SOFA's addTetrahedra: process (each tetrahedron appended; its missing faces created in face
  // order, each after its own missing edges, with one edges-added event per edge and one
  // triangles-added event per face), then a tetrahedra-added event, then propagate.
  // `ancestors`/`coefficients` are empty or one row per tetrahedron.
  void add_tetrahedra(const std::vector<Tetra>& tetrahedra, std::vector<std::vector<unsigned>> ancestors = {},
                      std::vector<std::vector<double>> coefficients = {});
  bool remove_items(const std::vector<unsigned>& ids, std::string* why) override;

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "TetrahedronSetTopologyContainer"; }
};

}  // namespace sinew
