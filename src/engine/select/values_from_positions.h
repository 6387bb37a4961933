// ValuesFromPositions: a value (or vector) per point, edge, triangle and
// tetrahedron from its position along a direction (SOFA's Engine/Select).
// Scalar field: with the element's centre c, s = (c·direction − bmin) /
// (bmax − bmin)·(n − 1) interpolates linearly between the n inputValues
// (clamped at both ends; 0 without values, the value itself with one). SOFA
// takes bmin and bmax from the x coordinates of the scene's bounding box;
// Sinew uses the root's `bbox` when given, else the bounds of the x
// coordinates of every mechanical state's positions (SOFA's box also grows
// with visual models). Vector field: every element gets `direction`.
// Positions default to the state's rest_position (else a mesh loader's
// position), elements to the node's topology's. Vec3d and Rigid3d (centres).
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class ValuesFromPositions final : public Engine {
 public:
  explicit ValuesFromPositions(StateType type);

  Field<std::vector<double>> input_values{this, "inputValues", {}, "values interpolated along the direction",
                                          "Inputs"};
  Field<Vec3> direction{this, "direction", Vec3(0, 1, 0), "direction of the interpolation", "Inputs"};
  Field<FlatVec> position;
  Field<std::vector<Edge>> edges{this, "edges", {}, "edges", "Inputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles", "Inputs"};
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedra", "Inputs"};
  Field<std::vector<double>> values{this, "values", {}, "value of each point", "Outputs"};
  Field<std::vector<double>> edge_values{this, "edgeValues", {}, "value of each edge", "Outputs"};
  Field<std::vector<double>> triangle_values{this, "triangleValues", {}, "value of each triangle", "Outputs"};
  Field<std::vector<double>> tetrahedron_values{this, "tetrahedronValues", {}, "value of each tetrahedron",
                                                "Outputs"};
  Field<std::vector<Vec3>> point_vectors{this, "pointVectors", {}, "vector of each point", "Outputs"};
  Field<std::vector<Vec3>> edge_vectors{this, "edgeVectors", {}, "vector of each edge", "Outputs"};
  Field<std::vector<Vec3>> triangle_vectors{this, "triangleVectors", {}, "vector of each triangle", "Outputs"};
  Field<std::vector<Vec3>> tetrahedron_vectors{this, "tetrahedronVectors", {}, "vector of each tetrahedron",
                                               "Outputs"};
  Field<std::string> field_type{this, "fieldType", "Scalar", "output kind: Scalar or Vector", "Inputs"};
  Field<bool> draw_vectors{this, "drawVectors", false, "draw the vectors (viewer)", "Visualization"};
  Field<float> draw_vector_length{this, "drawVectorLength", 10.0f, "length of the drawn vectors (viewer)",
                                  "Visualization"};

  void init() override;
  void reinit() override { update(); }

 protected:
  void do_update() override;
};

}  // namespace sinew
