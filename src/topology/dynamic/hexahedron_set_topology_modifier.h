// HexahedronSetTopologyModifier: Topology modifier dedicated to an hexahedral topology.
// No topological changes yet: it finds its container (same node) at init
// and accepts its attributes.
#pragma once

#include "topology/dynamic/quad_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class HexahedronSetTopologyModifier : public QuadSetTopologyModifier {
 public:
  Field<bool> remove_isolated{this, "removeIsolated", true, "remove points left without elements", "Topology"};

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "HexahedronSetTopologyContainer"; }
};

}  // namespace sinew
