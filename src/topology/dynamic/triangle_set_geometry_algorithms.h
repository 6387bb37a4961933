// TriangleSetGeometryAlgorithms: Geometry algorithms dedicated to a triangular topology.
// Drawing options and the link to the container; the regression scenes use
// no geometric query of it (they matter for topological changes only).
#pragma once

#include "topology/dynamic/edge_set_geometry_algorithms.h"

namespace sinew {

class MeshContainer;

class TriangleSetGeometryAlgorithms : public EdgeSetGeometryAlgorithms {
 public:
  Field<bool> show_triangle_indices{this, "showTriangleIndices", false, "draw triangle indices (viewer)",
                                    "Visualization"};
  Field<bool> draw_triangles{this, "drawTriangles", false, "draw the triangles (viewer)", "Visualization"};
  Field<std::string> draw_color_triangles{this, "drawColorTriangles", "0.3 0.5 0.8 1", "triangle colour (viewer)",
                                          "Visualization"};
  Field<bool> draw_normals{this, "drawNormals", false, "draw the triangle normals (viewer)", "Visualization"};
  Field<double> draw_normal_length{this, "drawNormalLength", 10.0, "length of drawn normals (viewer)", "Visualization"};
  Field<bool> recompute_triangles_orientation{this, "recomputeTrianglesOrientation", false,
                                              "reorient the triangles consistently at init", "Topology"};
  Field<bool> flip_normals{this, "flipNormals", false,
                           "flip the reference triangle used by recomputeTrianglesOrientation", "Topology"};

  void init() override;
};

}  // namespace sinew
