// TriangleSetTopologyModifier: Topology modifier dedicated to a triangular topology.
// No topological changes yet: it finds its container (same node) at init
// and accepts its attributes.
#pragma once

#include "topology/dynamic/edge_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class TriangleSetTopologyModifier : public EdgeSetTopologyModifier {
 public:
  Field<std::vector<unsigned>> list_out{this, "list_Out", {}, "degenerate triangles found (output)", "Topology"};

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "TriangleSetTopologyContainer"; }
};

}  // namespace sinew
