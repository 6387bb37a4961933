// EdgeSetGeometryAlgorithms: Geometry algorithms dedicated to an edge topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/dynamic/point_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class EdgeSetGeometryAlgorithms : public PointSetGeometryAlgorithms {
 public:
  Field<bool> show_edge_indices{this, "showEdgeIndices", false, "draw edge indices (viewer)", "Visualization"};
  Field<bool> draw_edges{this, "drawEdges", false, "draw the edges (viewer)", "Visualization"};
  Field<std::string> draw_color_edges{this, "drawColorEdges", "0.4 1 0.3 1", "edge colour (viewer)", "Visualization"};
};

}  // namespace sinew
