// ExtrudeSurface: a closed shell grown from a patch of a triangle surface
// (SOFA's Engine/Generate). Each vertex of the patch (`surfaceTriangles`,
// indices into `triangles`) gives two output vertices: itself (index 2k) and
// itself moved by heightFactor along its normal (2k+1), the normal being the
// normalised sum of its triangles' unit normals. Each patch triangle gives the
// flipped bottom triangle and the top one; each border edge of the patch
// (an edge used once) gives two side triangles, in the edges' sorted order.
// Vec3d.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class ExtrudeSurface final : public Engine {
 public:
  ExtrudeSurface();

  Field<bool> is_visible{this, "isVisible", true, "draw the extrusion (viewer)", "Visualization"};
  Field<double> height_factor{this, "heightFactor", 1.0, "height of the extrusion along the normals", "Inputs",
                              "length"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the surface", "Inputs"};
  Field<FlatVec> surface_vertices;
  Field<std::vector<unsigned>> surface_triangles{this, "surfaceTriangles", {},
                                                 "indices of the triangles to extrude", "Inputs"};
  Field<FlatVec> extrusion_vertices;
  Field<std::vector<Triangle>> extrusion_triangles{this, "extrusionTriangles", {}, "triangles of the extrusion",
                                                   "Outputs"};

  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
