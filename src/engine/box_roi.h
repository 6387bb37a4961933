// BoxROI: selects the points (and elements) lying in axis-aligned boxes
// (spec/mechanics.md §7.7). An engine: outputs are recomputed lazily when
// an input (boxes, positions, element lists) changed.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class BoxROI final : public Engine {
 public:
  explicit BoxROI(StateType type);

  Field<std::vector<VecN<6>>> box{this, "box", {}, "boxes: xmin ymin zmin xmax ymax zmax, ...", "Inputs"};
  Field<std::vector<VecN<10>>> oriented_box{this, "orientedBox", {}, "oriented boxes (p0 p1 p2 depth)", "Inputs"};
  Field<FlatVec> position;
  Field<std::vector<Edge>> edges{this, "edges", {}, "edge topology", "Inputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangle topology", "Inputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quad topology", "Inputs"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedron topology", "Inputs"};
  Field<std::vector<Hexa>> hexahedra{this, "hexahedra", {}, "hexahedron topology", "Inputs"};
  Field<bool> compute_edges{this, "computeEdges", true, "select edges", "Parameters"};
  Field<bool> compute_triangles{this, "computeTriangles", true, "select triangles", "Parameters"};
  Field<bool> compute_quads{this, "computeQuads", true, "select quads", "Parameters"};
  Field<bool> compute_tetrahedra{this, "computeTetrahedra", true, "select tetrahedra", "Parameters"};
  Field<bool> compute_hexahedra{this, "computeHexahedra", true, "select hexahedra", "Parameters"};
  Field<bool> strict{this, "strict", true, "elements: all vertices inside (else: centroid inside)", "Parameters"};
  Field<bool> do_update_field{this, "doUpdate", true, "recompute when inputs change", "Parameters"};

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the points in the ROI", "Outputs"};
  Field<std::vector<unsigned>> edge_indices{this, "edgeIndices", {}, "indices of the edges in the ROI", "Outputs"};
  Field<std::vector<unsigned>> triangle_indices{this, "triangleIndices", {}, "indices of the triangles in the ROI",
                                                "Outputs"};
  Field<std::vector<unsigned>> quad_indices{this, "quadIndices", {}, "indices of the quads in the ROI", "Outputs"};
  Field<std::vector<unsigned>> tetrahedron_indices{this, "tetrahedronIndices", {},
                                                   "indices of the tetrahedra in the ROI", "Outputs"};
  Field<std::vector<unsigned>> hexahedron_indices{this, "hexahedronIndices", {},
                                                  "indices of the hexahedra in the ROI", "Outputs"};
  Field<FlatVec> points_in_roi;
  Field<std::vector<Edge>> edges_in_roi{this, "edgesInROI", {}, "edges in the ROI", "Outputs"};
  Field<std::vector<Triangle>> triangles_in_roi{this, "trianglesInROI", {}, "triangles in the ROI", "Outputs"};
  Field<std::vector<Quad>> quads_in_roi{this, "quadsInROI", {}, "quads in the ROI", "Outputs"};
  Field<std::vector<Tetra>> tetrahedra_in_roi{this, "tetrahedraInROI", {}, "tetrahedra in the ROI", "Outputs"};
  Field<std::vector<Hexa>> hexahedra_in_roi{this, "hexahedraInROI", {}, "hexahedra in the ROI", "Outputs"};
  Field<unsigned> nb_indices{this, "nbIndices", 0, "number of points in the ROI", "Outputs"};
  Field<std::vector<unsigned>> indices_out{this, "indicesOut", {}, "indices of the points outside the ROI",
                                           "Outputs"};
  // Viewer-only.
  Field<bool> draw_boxes{this, "drawBoxes", false, "draw the boxes (viewer)", "Visualization"};
  Field<bool> draw_points{this, "drawPoints", false, "draw the selected points (viewer)", "Visualization"};
  Field<bool> draw_edges{this, "drawEdges", false, "viewer", "Visualization"};
  Field<bool> draw_triangles{this, "drawTriangles", false, "viewer", "Visualization"};
  Field<bool> draw_quads{this, "drawQuads", false, "viewer", "Visualization"};
  Field<bool> draw_tetrahedra{this, "drawTetrahedra", false, "viewer", "Visualization"};
  Field<bool> draw_hexahedra{this, "drawHexahedra", false, "viewer", "Visualization"};
  Field<double> draw_size{this, "drawSize", 1.0, "viewer", "Visualization"};

  void init() override;

 protected:
  void do_update() override;

 private:
  bool inside(const double* p) const;
  template <class Elem>
  void select(const std::vector<Elem>& elems, const std::vector<double>& x, int w, Field<std::vector<unsigned>>& ids,
              Field<std::vector<Elem>>& out);
  std::vector<VecN<6>> boxes_;  // normalised (min ≤ max per axis)
};

}  // namespace sinew
