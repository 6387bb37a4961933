// PointSetTopologyModifier: Topology modifier dedicated to a point topology.
// No topological changes yet: it finds its container (same node) at init
// and accepts its attributes.
#pragma once

#include "core/roles.h"

namespace sinew {

class MeshContainer;

class PointSetTopologyModifier : public TopologyObject {
 public:
  Field<bool> propagate_to_dof{this, "propagateToDOF", true, "apply point additions/removals to the node's state",
                               "Topology"};

  void init() override;
  // The container this modifier edits (first of the node, else of its ancestors).
  MeshContainer* container() const { return container_; }

 protected:
  // Whether `c` is a container this modifier can edit.
  virtual bool accepts(const Component& c) const;
  virtual const char* container_kind() const { return "PointSetTopologyContainer"; }

 private:
  MeshContainer* container_ = nullptr;
};

}  // namespace sinew
