// MeshTetraStuffing: a tetrahedral mesh of the inside of a closed surface by
// isosurface stuffing (Labelle & Shewchuk, SIGGRAPH 2007) as SOFA's
// Engine/Generate implements it. Two interleaved cubic grids (the second
// shifted by half a cell) cover the bounding box `vbbox` (default: the
// surface's box grown by 1 % on each side); each point is classified inside
// or outside by votes of rays cast along the 14 lattice directions (6 axis,
// 8 diagonal) against the surface, which also give the distance to the
// surface along each lattice edge. snapPoints moves points whose edges cut
// the surface closer than alphaLong / alphaShort onto the surface;
// splitTetrahedra cuts the tetrahedra crossing the surface at the cut points.
// Each pair of neighbouring points of the first grid with the four points of
// the second grid around their edge gives four tetrahedra (BCC lattice);
// unused points are removed and the tetrahedra oriented positively.
// size > 0: cell size; size < 0: −cells along the box's largest side.
// SOFA traces its rays through a triangle octree; Sinew tests every triangle,
// which finds the same intersections (only rays through a triangle edge, hit
// twice at equal distance, may list the two hits in another order).
#pragma once

#include <array>
#include <map>

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class MeshTetraStuffing final : public Engine {
 public:
  MeshTetraStuffing();

  Field<VecN<6>> vbbox{this, "vbbox", VecN<6>::Zero(), "box to fill: xmin ymin zmin xmax ymax zmax (default: the "
                                                       "surface's box grown by 1 %)",
                       "Inputs", "length"};
  Field<double> size{this, "size", -8.0, "cell size; negative: number of cells along the box's largest side",
                     "Inputs", "length"};
  Field<std::vector<Vec3>> input_points{this, "inputPoints", {}, "points of the surface", "Inputs", "length"};
  Field<std::vector<Triangle>> input_triangles{this, "inputTriangles", {}, "triangles of the surface", "Inputs"};
  Field<std::vector<Quad>> input_quads{this, "inputQuads", {}, "quads of the surface", "Inputs"};
  Field<std::vector<Vec3>> output_points{this, "outputPoints", {}, "points of the volume mesh", "Outputs", "length"};
  Field<std::vector<Tetra>> output_tetrahedra{this, "outputTetrahedra", {}, "tetrahedra of the volume mesh",
                                              "Outputs"};
  Field<double> alpha_long{this, "alphaLong", 0.24999, "snap threshold on long (axis) edges, fraction of the edge",
                           "Inputs"};
  Field<double> alpha_short{this, "alphaShort", 0.42978,
                            "snap threshold on short (diagonal) edges, fraction of the edge", "Inputs"};
  Field<bool> snap_points{this, "snapPoints", false, "snap points close to the surface onto it", "Inputs"};
  Field<bool> split_tetrahedra{this, "splitTetrahedra", false, "cut the tetrahedra crossing the surface", "Inputs"};
  Field<bool> draw{this, "draw", false, "draw the internal data (viewer)", "Visualization"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  static constexpr int kEdgeShell = 6 + 8;
  int edge_point(int p, int e) const;
  void add_tetra(std::vector<Tetra>& out, std::vector<Vec3>& x, int p1, int p2, int p3, int p4);
  void add_final_tetra(std::vector<Tetra>& out, const std::vector<Vec3>& x, int p1, int p2, int p3, int p4,
                       bool flip);
  bool flip_diag(const std::vector<Vec3>& x, int a, int b, int c, int d, int e) const;
  int split_point(int from, int to);

  double cellsize_ = 0;
  int gsize_[3] = {0, 0, 0}, hsize_[3] = {0, 0, 0};
  int ph0_ = 0;
  std::vector<int> inside_;
  std::vector<std::array<double, kEdgeShell>> dist_;
  std::map<std::pair<int, int>, int> split_points_;
};

}  // namespace sinew
