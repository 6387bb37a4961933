// EdgeSetTopologyModifier: Topology modifier dedicated to an edge topology.
// No topological changes yet: it finds its container (same node) at init
// and accepts its attributes.
#pragma once

#include "topology/dynamic/point_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class EdgeSetTopologyModifier : public PointSetTopologyModifier {
 public:

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "EdgeSetTopologyContainer"; }
};

}  // namespace sinew
