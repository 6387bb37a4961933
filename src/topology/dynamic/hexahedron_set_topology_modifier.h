// HexahedronSetTopologyModifier: Topology modifier dedicated to an hexahedral topology.
// Adds hexahedra (element_addition.h); removes them with SOFA's cascade: quads and edges left
// without a hexahedron (one warn/propagate for both, then processed), then isolated points (when
// `removeIsolated`); see point_set_topology_modifier.h.
#pragma once

#include "topology/dynamic/quad_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class HexahedronSetTopologyModifier : public QuadSetTopologyModifier {
 public:
  Field<bool> remove_isolated{this, "removeIsolated", true, "remove points left without elements", "Topology"};

  // SOFA's removeHexahedra (removeIsolatedItems = true).
  void remove_hexahedra(std::vector<unsigned> ids);
  // SOFA's addHexahedra: process (each hexahedron appended; its missing faces created in face
  // order, each after its own missing edges, with one edges-added event per edge and one
  // quads-added event per face), then a hexahedra-added event, then propagate.
  // `ancestors`/`coefficients` are empty or one row per hexahedron.
  void add_hexahedra(const std::vector<Hexa>& hexahedra, std::vector<std::vector<unsigned>> ancestors = {},
                     std::vector<std::vector<double>> coefficients = {});
  bool remove_items(const std::vector<unsigned>& ids, std::string* why) override;

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "HexahedronSetTopologyContainer"; }
};

}  // namespace sinew
