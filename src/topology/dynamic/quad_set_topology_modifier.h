// QuadSetTopologyModifier: Topology modifier dedicated to a quad topology.
// No topological changes yet: it finds its container (same node) at init
// and accepts its attributes.
#pragma once

#include "topology/dynamic/edge_set_topology_modifier.h"

namespace sinew {

class MeshContainer;

class QuadSetTopologyModifier : public EdgeSetTopologyModifier {
 public:

  // Quad (and hexahedron) removal is not implemented yet: refused with a message, never ignored.
  bool remove_items(const std::vector<unsigned>&, std::string* why) override {
    if (why) *why = std::string("removing elements of a ") + container_kind() + " is not supported yet";
    return false;
  }

 protected:
  bool accepts(const Component& c) const override;
  const char* container_kind() const override { return "QuadSetTopologyContainer"; }
};

}  // namespace sinew
