// PlaneROI: the points (and edges, triangles, tetrahedra with all their
// points) inside one of several slabs, each given by three points p0, p1, p2
// (a rectangle p0-p1-p2-p3 with p3 = p0 + p2 − p1) and a depth across it
// (SOFA's PlaneROI: its own Data, not BoxROI's). The viewer draws it
// (render/draw_roi.cpp).
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class PlaneROI final : public Engine {
 public:
  explicit PlaneROI(StateType type);

  Field<std::vector<double>> plane{this, "plane", std::vector<double>(10, 0.0),
                                   "slabs: 3 points and a depth each (10 values per slab)", "Parameters", "length"};
  Field<FlatVec> position;
  Field<std::vector<Edge>> edges{this, "edges", {}, "edge topology", "Inputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangle topology", "Inputs"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedron topology", "Inputs"};
  Field<bool> compute_edges{this, "computeEdges", true, "select the edges", "Parameters"};
  Field<bool> compute_triangles{this, "computeTriangles", true, "select the triangles", "Parameters"};
  Field<bool> compute_tetrahedra{this, "computeTetrahedra", true, "select the tetrahedra", "Parameters"};
  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the points in the ROI", "Outputs"};
  Field<std::vector<unsigned>> edge_indices{this, "edgeIndices", {}, "indices of the edges in the ROI", "Outputs"};
  Field<std::vector<unsigned>> triangle_indices{this, "triangleIndices", {}, "indices of the triangles in the ROI",
                                                "Outputs"};
  Field<std::vector<unsigned>> tetrahedron_indices{this, "tetrahedronIndices", {},
                                                   "indices of the tetrahedra in the ROI", "Outputs"};
  Field<FlatVec> points_in_roi;
  Field<std::vector<Edge>> edges_in_roi{this, "edgesInROI", {}, "edges in the ROI", "Outputs"};
  Field<std::vector<Triangle>> triangles_in_roi{this, "trianglesInROI", {}, "triangles in the ROI", "Outputs"};
  Field<std::vector<Tetra>> tetrahedra_in_roi{this, "tetrahedraInROI", {}, "tetrahedra in the ROI", "Outputs"};
  Field<bool> draw_boxes{this, "drawBoxes", false, "draw the slabs (viewer)", "Visualization"};
  Field<bool> draw_points{this, "drawPoints", false, "draw the points (viewer)", "Visualization"};
  Field<bool> draw_edges{this, "drawEdges", false, "draw the edges (viewer)", "Visualization"};
  Field<bool> draw_triangles{this, "drawTriangles", false, "draw the triangles (viewer)", "Visualization"};
  Field<bool> draw_tetrahedra{this, "drawTetrahedra", false, "draw the tetrahedra (viewer)", "Visualization"};
  Field<double> draw_size{this, "drawSize", 1.0, "size of the drawn items (viewer)", "Visualization"};

  void init() override;

 private:
  void do_update() override;
};

}  // namespace sinew
