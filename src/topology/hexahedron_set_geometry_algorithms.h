// HexahedronSetGeometryAlgorithms: Geometry algorithms dedicated to an hexahedral topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/quad_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class HexahedronSetGeometryAlgorithms : public QuadSetGeometryAlgorithms {
 public:
  Field<bool> show_hexa_indices{this, "showHexaIndices", false, "Debug : view Hexa indices", "Visualization"};
  Field<bool> draw_hexahedra{this, "drawHexahedra", false, "if true, draw the Hexahedron in the topology",
                             "Visualization"};
  Field<float> draw_scale_hexahedra{this, "drawScaleHexahedra", 1.0f,
                                    "Scale of the hexahedra (between 0 and 1; if <1.0, it produces gaps between the hexahedra)",
                                    "Visualization"};
  Field<std::string> draw_color_hexahedra{this, "drawColorHexahedra", "1 0.5 0 1",
                                          "RGB code color used to draw hexahedra.", "Visualization"};

};

}  // namespace sinew
