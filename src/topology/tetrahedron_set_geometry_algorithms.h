// TetrahedronSetGeometryAlgorithms: Geometry algorithms dedicated to a tetrahedral topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/triangle_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class TetrahedronSetGeometryAlgorithms : public TriangleSetGeometryAlgorithms {
 public:
  Field<bool> show_tetrahedra_indices{this, "showTetrahedraIndices", false, "Debug : view Tetrahedrons indices",
                                      "Visualization"};
  Field<bool> draw_tetrahedra{this, "drawTetrahedra", false, "if true, draw the tetrahedra in the topology",
                              "Visualization"};
  Field<float> draw_scale_tetrahedra{this, "drawScaleTetrahedra", 1.0f,
                                     "Scale of the terahedra (between 0 and 1; if <1.0, it produces gaps between the tetrahedra)",
                                     "Visualization"};
  Field<std::string> draw_color_tetrahedra{this, "drawColorTetrahedra", "1 1 0 1",
                                           "RGBA code color used to draw tetrahedra.", "Visualization"};

};

}  // namespace sinew
