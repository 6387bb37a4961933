// PointSetGeometryAlgorithms: Geometry algorithms dedicated to a point topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "core/roles.h"

namespace sinew {

class MeshContainer;

class PointSetGeometryAlgorithms : public TopologyObject {
 public:
  Field<float> show_indices_scale{this, "showIndicesScale", 1.0f, "size of drawn indices (viewer)", "Visualization"};
  Field<bool> show_point_indices{this, "showPointIndices", false, "draw point indices (viewer)", "Visualization"};
  Field<std::string> tag_mechanics{this, "tagMechanics", "", "tag of the state holding the positions", "Topology"};

  Link<MeshTopologyBase> topology{this, "topology", "topology used by this component (default: the node's)"};

  void init() override;
  // The state whose positions the geometric queries read.
  MechanicalState* mechanical_state() const { return state_ptr_; }

 private:
  MechanicalState* state_ptr_ = nullptr;
};

}  // namespace sinew
