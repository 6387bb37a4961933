// GenerateCylinder: a tetrahedral cylinder and its triangulated surface
// (SOFA's Engine/Generate). Points on rings: per height level, the axis point
// then resRadial rings of resCircumferential points; each level pair is cut
// into prisms around the axis (3 tetrahedra each) and hexahedra between rings
// (6 tetrahedra each), in SOFA's order and orientation. The surface mesh is
// the outer wall (two triangles per quad) and, when openSurface is false, the
// two caps. Rational Bézier control points (BezierTetrahedronDegree,
// BezierTriangleDegree > 1) are not computed: such a request is an error.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class GenerateCylinder final : public Engine {
 public:
  GenerateCylinder();

  Field<std::vector<Vec3>> tetra_positions{this, "output_TetrahedraPosition", {},
                                           "points of the tetrahedral mesh", "Outputs", "length"};
  Field<std::vector<Vec3>> triangle_positions{this, "output_TrianglesPosition", {},
                                              "points of the triangular surface mesh", "Outputs", "length"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedra of the cylinder", "Outputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the cylinder's surface", "Outputs"};
  Field<std::vector<double>> bezier_triangle_weights{this, "BezierTriangleWeights", {},
                                                     "weights of rational Bézier triangles (not computed)", "Outputs"};
  Field<std::vector<int>> is_bezier_triangle_rational{this, "isBezierTriangleRational", {},
                                                      "whether each Bézier triangle is rational (not computed)",
                                                      "Outputs"};
  Field<unsigned> bezier_triangle_degree{this, "BezierTriangleDegree", 0,
                                         "order of the Bézier triangles (> 1 is not supported)", "Inputs"};
  Field<std::vector<double>> bezier_tetra_weights{this, "BezierTetrahedronWeights", {},
                                                  "weights of rational Bézier tetrahedra (not computed)", "Outputs"};
  Field<std::vector<int>> is_bezier_tetra_rational{this, "isBezierTetrahedronRational", {},
                                                   "whether each Bézier tetrahedron is rational (not computed)",
                                                   "Outputs"};
  Field<unsigned> bezier_tetra_degree{this, "BezierTetrahedronDegree", 0,
                                      "order of the Bézier tetrahedra (> 1 is not supported)", "Inputs"};
  Field<double> radius{this, "radius", 0.2, "radius of the cylinder", "Inputs", "length"};
  Field<double> height{this, "height", 1.0, "height of the cylinder (along z)", "Inputs", "length"};
  Field<Vec3> origin{this, "origin", Vec3::Zero(), "centre of the bottom cap", "Inputs", "length"};
  Field<bool> open_surface{this, "openSurface", true, "the surface mesh has no caps", "Inputs"};
  Field<unsigned> res_circumferential{this, "resCircumferential", 6, "points on each ring", "Inputs"};
  Field<unsigned> res_radial{this, "resRadial", 3, "rings around the axis", "Inputs"};
  Field<unsigned> res_height{this, "resHeight", 5, "levels along the height", "Inputs"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
