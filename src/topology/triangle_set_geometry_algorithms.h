// TriangleSetGeometryAlgorithms: Geometry algorithms dedicated to a triangular topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/edge_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class TriangleSetGeometryAlgorithms : public EdgeSetGeometryAlgorithms {
 public:
  Field<bool> show_triangle_indices{this, "showTriangleIndices", false, "Debug : view Triangle indices",
                                    "Visualization"};
  Field<bool> draw_triangles{this, "drawTriangles", false, "if true, draw the triangles in the topology",
                             "Visualization"};
  Field<std::string> draw_color_triangles{this, "drawColorTriangles", "0.3 0.5 0.8 1",
                                          "RGBA code color used to draw triangles", "Visualization"};
  Field<bool> draw_normals{this, "drawNormals", false, "if true, draw the triangles in the topology",
                           "Visualization"};
  Field<double> draw_normal_length{this, "drawNormalLength", 10.0, "Fiber length visualisation.", "Visualization"};
  Field<bool> recompute_triangles_orientation{this, "recomputeTrianglesOrientation", false,
                                              "if true, will recompute triangles orientation according to normals",
                                              "Topology"};
  Field<bool> flip_normals{this, "flipNormals", false,
                           "if true, will flip normal of the first triangle used to recompute triangle orientation.",
                           "Topology"};

  void init() override;
};

}  // namespace sinew
