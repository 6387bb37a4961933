// SubsetTopology: splits a mesh in two by a region of interest (boxes, or
// spheres when `centers` is given): the points, edges, triangles, quads,
// tetrahedra and hexahedra inside (every vertex in one same region) and the
// rest, as topologies of their own. With localIndices, the elements are
// renumbered into the point lists they come with: the points of the region's
// border (vertices inside the region of a triangle — tetrahedron when there are
// tetrahedra — that also has vertices outside) come first in both point lists,
// then the inner points (pointsInROI) or the outer ones (pointsOutROI).
// With tetrahedraInput, the tetrahedra are chosen by index instead of by
// region and the point lists are rebuilt from them (SOFA's SubsetTopology).
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class SubsetTopology final : public Engine {
 public:
  explicit SubsetTopology(StateType type);

  // Regions.
  Field<std::vector<VecN<6>>> box{this, "box", {(VecN<6>() << 0, 0, 0, 1, 1, 1).finished()},
                                  "boxes: xmin ymin zmin xmax ymax zmax, ...", "Inputs"};
  Field<std::vector<Vec3>> centers{this, "centers", {}, "centre(s) of the sphere(s) (given: spheres replace boxes)",
                                   "Inputs"};
  Field<std::vector<double>> radii{this, "radii", {}, "radius of each sphere (one per centre)", "Inputs"};
  Field<Vec3> direction{this, "direction", Vec3::Zero(), "edge direction (unused by the selection)", "Inputs"};
  Field<Vec3> normal{this, "normal", Vec3::Zero(), "triangle normal direction (unused by the selection)", "Inputs"};
  Field<double> edge_angle{this, "edgeAngle", 0.0, "max edge angle to 'direction' (unused by the selection)",
                           "Inputs"};
  Field<double> tri_angle{this, "triAngle", 0.0, "max triangle normal angle to 'normal' (unused by the selection)",
                          "Inputs"};

  // Mesh.
  Field<FlatVec> rest_position;
  Field<std::vector<Edge>> edges{this, "edges", {}, "edge topology", "Inputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangle topology", "Inputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quad topology", "Inputs"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedron topology", "Inputs"};
  Field<std::vector<Hexa>> hexahedra{this, "hexahedra", {}, "hexahedron topology", "Inputs"};
  Field<std::vector<unsigned>> tetrahedra_input{this, "tetrahedraInput", {},
                                                "indices of the tetrahedra to keep (given: replaces the region test "
                                                "for tetrahedra)",
                                                "Inputs"};

  // Outputs.
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
  Field<FlatVec> points_out_roi;
  Field<std::vector<Edge>> edges_in_roi{this, "edgesInROI", {}, "edges in the ROI", "Outputs"};
  Field<std::vector<Edge>> edges_out_roi{this, "edgesOutROI", {}, "edges not in the ROI", "Outputs"};
  Field<std::vector<Triangle>> triangles_in_roi{this, "trianglesInROI", {}, "triangles in the ROI", "Outputs"};
  Field<std::vector<Triangle>> triangles_out_roi{this, "trianglesOutROI", {}, "triangles not in the ROI", "Outputs"};
  Field<std::vector<Quad>> quads_in_roi{this, "quadsInROI", {}, "quads in the ROI", "Outputs"};
  Field<std::vector<Quad>> quads_out_roi{this, "quadsOutROI", {}, "quads not in the ROI", "Outputs"};
  Field<std::vector<Tetra>> tetrahedra_in_roi{this, "tetrahedraInROI", {}, "tetrahedra in the ROI", "Outputs"};
  Field<std::vector<Tetra>> tetrahedra_out_roi{this, "tetrahedraOutROI", {}, "tetrahedra not in the ROI", "Outputs"};
  Field<std::vector<Hexa>> hexahedra_in_roi{this, "hexahedraInROI", {}, "hexahedra in the ROI", "Outputs"};
  Field<std::vector<Hexa>> hexahedra_out_roi{this, "hexahedraOutROI", {}, "hexahedra not in the ROI", "Outputs"};
  Field<unsigned> nbrborder{this, "nbrborder", 0,
                            "with localIndices: number of border points (the first points of both point lists)",
                            "Outputs"};

  // Parameters.
  Field<bool> local_indices{this, "localIndices", false,
                            "renumber the elements' vertices into the point lists they are output with",
                            "Parameters"};
  Field<bool> draw_roi{this, "drawROI", false, "draw the boxes (viewer)", "Visualization"};
  Field<bool> draw_points{this, "drawPoints", false, "draw the points in the ROI (viewer)", "Visualization"};
  Field<bool> draw_edges{this, "drawEdges", false, "draw the edges in the ROI (viewer)", "Visualization"};
  Field<bool> draw_triangles{this, "drawTriangle", false, "draw the triangles in the ROI (viewer)", "Visualization"};
  Field<bool> draw_tetrahedra{this, "drawTetrahedra", false, "draw the tetrahedra in the ROI (viewer)",
                              "Visualization"};
  Field<double> draw_size{this, "drawSize", 1.0, "size of the drawn items (viewer)", "Visualization"};

  void init() override;
  void reinit() override;

 protected:
  void do_update() override;

 private:
  bool point_in(const double* p, std::size_t roi) const;
  bool index_in(unsigned i, std::size_t roi) const;
  template <class Elem>
  bool elem_in(const Elem& e, std::size_t roi) const;
  template <class Elem>
  void select(const std::vector<Elem>& elems, Field<std::vector<unsigned>>& in_ids, Field<std::vector<Elem>>& in,
              Field<std::vector<Elem>>& out);
  template <class Elem>
  void mark_border(const std::vector<Elem>& elems);
  void select_tetrahedra_by_index();
  template <class Elem>
  void renumber(Elem& e, const std::vector<unsigned>& map) const;

  StateType type_;
  bool spheres_ = false;
  std::size_t n_roi_ = 0;
  const FlatVec* x_ = nullptr;
  std::vector<VecN<6>> boxes_;
  std::vector<unsigned> local_;       // point → its index in the point list it is output with
  std::vector<char> on_border_;       // per point, with localIndices
  mutable bool bad_index_ = false;
};

}  // namespace sinew
