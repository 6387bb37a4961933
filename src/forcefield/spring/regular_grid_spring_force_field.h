// RegularGridSpringForceField: SpringForceField plus springs along the lines,
// face diagonals and cube diagonals of the RegularGridTopology of the state's
// node (its first topology), rest lengths from the grid spacing and
// stiffness/damping divided by them (spec/mechanics.md §3.3). The grid
// springs follow the explicit `spring` list, in SOFA's loop order.
#pragma once

#include "forcefield/spring/spring_force_field.h"

namespace sinew {

class RegularGridSpringForceField final : public SpringForceField {
 public:
  Field<double> lines_stiffness{this, "linesStiffness", 100.0, "stiffness of the grid-edge springs", "Spring", "force/length"};
  Field<double> lines_damping{this, "linesDamping", 5.0, "damping of the grid-edge springs", "Spring", "force·time/length"};
  Field<double> quads_stiffness{this, "quadsStiffness", 100.0, "stiffness of the quad-diagonal springs",
                                "Spring", "force/length"};
  Field<double> quads_damping{this, "quadsDamping", 5.0, "damping of the quad-diagonal springs", "Spring", "force·time/length"};
  Field<double> cubes_stiffness{this, "cubesStiffness", 100.0, "stiffness of the cube-diagonal springs",
                                "Spring", "force/length"};
  Field<double> cubes_damping{this, "cubesDamping", 5.0, "damping of the cube-diagonal springs", "Spring", "force·time/length"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
};

}  // namespace sinew
