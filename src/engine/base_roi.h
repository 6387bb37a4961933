// BaseROI: shared machinery of the region-of-interest engines (BoxROI,
// SphereROI; spec/mechanics.md §7.7): finds the positions (local
// MechanicalObject rest_position, else local MeshLoader position, else the
// first MechanicalObject up the tree) and the element lists (first local
// topology), then selects points and elements, producing every output SOFA
// provides: indices/elements in and out of the ROI, points in and out.
// Subclasses say whether a point is inside.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class BaseROI : public Engine {
 public:
  explicit BaseROI(StateType type);

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
  Field<bool> do_update_field{this, "doUpdate", true, "recompute when inputs change (else only at init)",
                              "Parameters"};

  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the points in the ROI", "Outputs"};
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
  Field<FlatVec> points_out_roi;
  Field<std::vector<Edge>> edges_out_roi{this, "edgesOutROI", {}, "edges not in the ROI", "Outputs"};
  Field<std::vector<Triangle>> triangles_out_roi{this, "trianglesOutROI", {}, "triangles not in the ROI", "Outputs"};
  Field<std::vector<Quad>> quads_out_roi{this, "quadsOutROI", {}, "quads not in the ROI", "Outputs"};
  Field<std::vector<Tetra>> tetrahedra_out_roi{this, "tetrahedraOutROI", {}, "tetrahedra not in the ROI", "Outputs"};
  Field<std::vector<Hexa>> hexahedra_out_roi{this, "hexahedraOutROI", {}, "hexahedra not in the ROI", "Outputs"};
  Field<std::vector<unsigned>> indices_out{this, "indicesOut", {}, "indices of the points not in the ROI",
                                           "Outputs"};
  Field<std::vector<unsigned>> edge_out_indices{this, "edgeOutIndices", {}, "indices of the edges not in the ROI",
                                                "Outputs"};
  Field<std::vector<unsigned>> triangle_out_indices{this, "triangleOutIndices", {},
                                                    "indices of the triangles not in the ROI", "Outputs"};
  Field<std::vector<unsigned>> quad_out_indices{this, "quadOutIndices", {}, "indices of the quads not in the ROI",
                                                "Outputs"};
  Field<std::vector<unsigned>> tetrahedron_out_indices{this, "tetrahedronOutIndices", {},
                                                       "indices of the tetrahedra not in the ROI", "Outputs"};
  Field<std::vector<unsigned>> hexahedron_out_indices{this, "hexahedronOutIndices", {},
                                                      "indices of the hexahedra not in the ROI", "Outputs"};

  // Viewer-only.
  Field<bool> draw_roi{this, "drawROI", false, "draw the region (viewer)", "Visualization"};
  Field<bool> draw_points{this, "drawPoints", false, "draw the selected points (viewer)", "Visualization"};
  Field<bool> draw_edges{this, "drawEdges", false, "draw the selected edges (viewer)", "Visualization"};
  Field<bool> draw_triangles{this, "drawTriangles", false, "draw the selected triangles (viewer)", "Visualization"};
  Field<bool> draw_quads{this, "drawQuads", false, "draw the selected quads (viewer)", "Visualization"};
  Field<bool> draw_tetrahedra{this, "drawTetrahedra", false, "draw the selected tetrahedra (viewer)",
                              "Visualization"};
  Field<bool> draw_hexahedra{this, "drawHexahedra", false, "draw the selected hexahedra (viewer)", "Visualization"};
  Field<double> draw_size{this, "drawSize", 1.0, "size of the drawn items (viewer)", "Visualization"};

  void init() override;
  void reinit() override;

  int spatial_dim() const { return dim_; }

 protected:
  // Prepares the region from the subclass's fields (called at init, before the first update).
  virtual void roi_init() {}
  // Called at each update before the selection; false skips the selection (outputs stay empty).
  virtual bool roi_do_update() { return true; }
  // Whether the point (spatial_dim() coordinates) is in the region.
  virtual bool point_in_roi(const double* p) const = 0;
  // Extra element tests (SphereROI's angle criteria).
  virtual bool edge_extra(const Edge&) const { return true; }
  virtual bool triangle_extra(const Triangle&) const { return true; }
  // Non-strict mode: an element whose vertices are all in the ROI is in it,
  // before the centroid test (SOFA's MeshROI, through its indices).
  virtual bool inside_vertices_suffice() const { return false; }

  void do_update() override;
  // Coordinates of point i of the current positions (valid during do_update).
  const double* point(unsigned i) const { return &pos_->data[static_cast<std::size_t>(i) * pos_->width]; }

 private:
  template <class Elem>
  bool elem_in(const Elem& e, bool strict_mode) const;
  template <class Elem, class Extra>
  void select(const std::vector<Elem>& elems, bool strict_mode, Field<std::vector<unsigned>>& in_ids,
              Field<std::vector<Elem>>& in_elems, Field<std::vector<unsigned>>& out_ids,
              Field<std::vector<Elem>>& out_elems, Extra extra);

  int dim_ = 3;
  bool initialized_ = false;
  bool force_ = false;
  const FlatVec* pos_ = nullptr;
  mutable bool bad_index_ = false;
};

}  // namespace sinew
