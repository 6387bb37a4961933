// TetrahedronSetTopologyModifier: Topology modifier dedicated to a tetrahedral topology.
// No topological changes yet: it finds its container (same node) at init
// and accepts its attributes.
#pragma once

#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class TetrahedronSetTopologyModifier : public TriangleSetTopologyModifier {
 public:
  Field<bool> remove_isolated{this, "removeIsolated", true, "remove points left without elements", "Topology"};

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "TetrahedronSetTopologyContainer"; }
};

}  // namespace sinew
