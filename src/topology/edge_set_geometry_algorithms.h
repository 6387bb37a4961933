// EdgeSetGeometryAlgorithms: Geometry algorithms dedicated to an edge topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/point_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class EdgeSetGeometryAlgorithms : public PointSetGeometryAlgorithms {
 public:
  Field<bool> show_edge_indices{this, "showEdgeIndices", false, "Debug : view Edge indices.", "Visualization"};
  Field<bool> draw_edges{this, "drawEdges", false, "if true, draw the edges in the topology.", "Visualization"};
  Field<std::string> draw_color_edges{this, "drawColorEdges", "0.4 1 0.3 1", "RGB code color used to draw edges.",
                                      "Visualization"};

};

}  // namespace sinew
