// TopologyBoundingTrasher (spec/interaction.md §7): after each step, removes the elements of a
// dynamic topology whose barycentre left a box — of the topology's highest kind (hexahedra,
// else tetrahedra, quads, triangles, edges), through that kind's modifier, with SOFA's
// isolated-item removal. Elements falling out of the scene stop costing anything.
#pragma once

#include <vector>

#include "core/roles.h"
#include "topology/mapping/topological_mapping.h"

namespace sinew {

class PointSetTopologyModifier;

class TopologyBoundingTrasher final : public Component {
 public:
  TopologyBoundingTrasher();

  Field<FlatVec> position;
  Field<std::vector<double>> box{this, "box", {-1000, -1000, -1000, 1000, 1000, 1000},
                                 "xmin ymin zmin xmax ymax zmax: elements whose barycentre leaves it are removed",
                                 "Topology", "length"};
  Field<bool> draw_box{this, "drawBox", false, "draw the box (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology whose elements are removed (default: the node's)"};

  void init() override;
  void handle_event(Event& e) override;
  // One pass: the elements outside the box are removed; returns how many.
  std::size_t trash();

 private:
  ElementType kind_ = ElementType::point;  // point: nothing to remove
  PointSetTopologyModifier* modifier_ = nullptr;
  std::vector<unsigned> outside_;  // capacity kept between steps
};

}  // namespace sinew
