// HexahedronSetGeometryAlgorithms: Geometry algorithms dedicated to an hexahedral topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/dynamic/quad_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class HexahedronSetGeometryAlgorithms : public QuadSetGeometryAlgorithms {
 public:
  Field<bool> show_hexa_indices{this, "showHexaIndices", false, "draw hexahedron indices (viewer)", "Visualization"};
  Field<bool> draw_hexahedra{this, "drawHexahedra", false, "draw the hexahedra (viewer)", "Visualization"};
  Field<float> draw_scale_hexahedra{this, "drawScaleHexahedra", 1.0f,
                                    "shrink factor of drawn hexahedra in [0, 1] (viewer)", "Visualization"};
  Field<std::string> draw_color_hexahedra{this, "drawColorHexahedra", "1 0.5 0 1", "hexahedron colour (viewer)",
                                          "Visualization"};
};

}  // namespace sinew
