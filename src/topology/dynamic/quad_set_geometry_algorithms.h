// QuadSetGeometryAlgorithms: Geometry algorithms dedicated to a quad topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/dynamic/edge_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class QuadSetGeometryAlgorithms : public EdgeSetGeometryAlgorithms {
 public:
  Field<bool> show_quad_indices{this, "showQuadIndices", false, "draw quad indices (viewer)", "Visualization"};
  Field<bool> draw_quads{this, "drawQuads", false, "draw the quads (viewer)", "Visualization"};
  Field<std::string> draw_color_quads{this, "drawColorQuads", "0 0.4 0.4 1", "quad colour (viewer)", "Visualization"};
};

}  // namespace sinew
