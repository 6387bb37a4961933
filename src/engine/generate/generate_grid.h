// GenerateGrid: a regular grid of resolution[0] × resolution[1] ×
// resolution[2] cells between min and max (SOFA's Engine/Generate). With
// resolution z = 0 the grid is flat: quads and two triangles per quad;
// otherwise hexahedra and six tetrahedra per hexahedron. Points are numbered
// x fastest, then y, then z; cells are visited x, then y, then z innermost,
// as SOFA does. Vec2d keeps the first two coordinates.
#pragma once

#include "core/engine.h"
#include "core/roles.h"

namespace sinew {

class GenerateGrid final : public Engine {
 public:
  explicit GenerateGrid(int dim);

  Field<FlatVec> output_position;
  Field<std::vector<Tetra>> tetrahedra{this, "tetrahedra", {}, "tetrahedra of the grid (3D)", "Outputs"};
  Field<std::vector<Quad>> quads{this, "quads", {}, "quads of the grid (2D)", "Outputs"};
  Field<std::vector<Triangle>> triangles{this, "triangles", {}, "triangles of the grid (2D)", "Outputs"};
  Field<std::vector<Hexa>> hexahedra{this, "hexahedra", {}, "hexahedra of the grid (3D)", "Outputs"};
  Field<Vec3> min{this, "min", Vec3::Zero(), "minimum corner", "Inputs", "length"};
  Field<Vec3> max{this, "max", Vec3::Zero(), "maximum corner", "Inputs", "length"};
  Field<VecNi<3>> resolution{this, "resolution", VecNi<3>(3, 3, 3),
                             "cells along x, y, z; z = 0 makes a 2D grid", "Inputs"};

  void init() override { set_dirty(); }
  void reinit() override { update(); }

 protected:
  void do_update() override;

 private:
  int dim_;
};

}  // namespace sinew
