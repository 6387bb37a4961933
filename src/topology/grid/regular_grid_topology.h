// RegularGridTopology: an axis-aligned grid of nx·ny·nz points between
// `min` and `max`, with its hexahedra, quads, triangles and edges
// (spec/mechanics.md §5.2). Point (i,j,k) has index i + nx·(j + ny·k).
#pragma once

#include "topology/mesh_topology.h"

namespace sinew {

class RegularGridTopology : public MeshContainer {
 public:
  RegularGridTopology();

  Field<VecNi<3>> n{this, "n", VecNi<3>(2, 2, 2), "number of points along x, y, z", "Grid"};
  Field<Vec3> min{this, "min", Vec3::Zero(), "lower corner", "Grid"};
  Field<Vec3> max{this, "max", Vec3::Ones(), "upper corner", "Grid"};
  Field<Vec3> p0{this, "p0", Vec3::Zero(), "position of point 0 (default: min)", "Grid"};
  Field<double> cell_width{this, "cellWidth", 0.0, "if > 0, n is computed from the box size and this width", "Grid", "length"};
  Field<bool> compute_hexa_list{this, "computeHexaList", true, "generate the hexahedra", "Grid"};
  Field<bool> compute_quad_list{this, "computeQuadList", true, "generate the quads", "Grid"};
  Field<bool> compute_triangle_list{this, "computeTriangleList", true, "generate two triangles per quad", "Grid"};
  Field<bool> compute_edge_list{this, "computeEdgeList", true, "generate the edges", "Grid"};
  Field<bool> compute_point_list{this, "computePointList", true, "fill `position` with the grid points", "Grid"};
  Field<bool> create_tex_coords{this, "createTexCoords", false, "texture coordinates (viewer)", "Grid"};
  Field<bool> draw_edges{this, "drawEdges", false, "draw the grid (viewer)", "Visualization"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;

  // Geometry (valid after generation): spacing vectors and origin.
  Vec3 dx() const { return dx_; }
  Vec3 dy() const { return dy_; }
  Vec3 dz() const { return dz_; }
  Vec3 origin() const { return origin_; }
  VecNi<3> dims() const { return dims_; }
  std::size_t point_index(int i, int j, int k) const {
    return static_cast<std::size_t>(i + dims_[0] * (j + dims_[1] * k));
  }

 protected:
  void generate() override;
  // Position of grid point (i, j, k): origin + i·dx + j·dy + k·dz here; other
  // grids (CylinderGridTopology) place the same connectivity differently.
  virtual Vec3 grid_point(int i, int j, int k) const { return origin_ + dx_ * i + dy_ * j + dz_ * k; }

 private:
  VecNi<3> dims_{2, 2, 2};
  Vec3 dx_, dy_, dz_, origin_;
};

}  // namespace sinew
