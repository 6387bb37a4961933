// TetrahedronSetGeometryAlgorithms: Geometry algorithms dedicated to a tetrahedral topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/dynamic/triangle_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class TetrahedronSetGeometryAlgorithms : public TriangleSetGeometryAlgorithms {
 public:
  Field<bool> show_tetrahedra_indices{this, "showTetrahedraIndices", false, "draw tetrahedron indices (viewer)",
                                      "Visualization"};
  Field<bool> draw_tetrahedra{this, "drawTetrahedra", false, "draw the tetrahedra (viewer)", "Visualization"};
  Field<float> draw_scale_tetrahedra{this, "drawScaleTetrahedra", 1.0f,
                                     "shrink factor of drawn tetrahedra in [0, 1] (viewer)", "Visualization"};
  Field<std::string> draw_color_tetrahedra{this, "drawColorTetrahedra", "1 1 0 1", "tetrahedron colour (viewer)",
                                           "Visualization"};
};

}  // namespace sinew
