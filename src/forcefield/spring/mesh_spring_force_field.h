// MeshSpringForceField: SpringForceField whose springs are generated at init
// from the topology's lines, triangles, quads, tetrahedra and hexahedra
// (spec/mechanics.md §3.2). `stiffness`/`damping` set all five per-element
// values (SOFA aliases) as well as the base lists.
#pragma once

#include "forcefield/spring/spring_force_field.h"

namespace sinew {

class MeshSpringForceField final : public SpringForceField {
 public:
  MeshSpringForceField();

  Field<double> lines_stiffness{this, "linesStiffness", 0.0, "stiffness of the edge springs", "Spring", "force/length"};
  Field<double> lines_damping{this, "linesDamping", 0.0, "damping of the edge springs", "Spring", "force·time/length"};
  Field<double> triangles_stiffness{this, "trianglesStiffness", 0.0, "stiffness of the springs inside triangles",
                                    "Spring", "force/length"};
  Field<double> triangles_damping{this, "trianglesDamping", 0.0, "damping of the springs inside triangles", "Spring", "force·time/length"};
  Field<double> quads_stiffness{this, "quadsStiffness", 0.0, "stiffness of the springs inside quads", "Spring", "force/length"};
  Field<double> quads_damping{this, "quadsDamping", 0.0, "damping of the springs inside quads", "Spring", "force·time/length"};
  Field<double> tetrahedra_stiffness{this, "tetrahedraStiffness", 0.0,
                                     "stiffness of the springs inside tetrahedra", "Spring", "force/length"};
  Field<double> tetrahedra_damping{this, "tetrahedraDamping", 0.0, "damping of the springs inside tetrahedra",
                                   "Spring", "force·time/length"};
  Field<double> cubes_stiffness{this, "cubesStiffness", 0.0, "stiffness of the springs inside hexahedra",
                                "Spring", "force/length"};
  Field<double> cubes_damping{this, "cubesDamping", 0.0, "damping of the springs inside hexahedra", "Spring", "force·time/length"};
  Field<bool> no_compression{this, "noCompression", false, "springs resist stretching only", "Spring"};
  Field<double> draw_min_elongation_range{this, "drawMinElongationRange", 8.0, "min elongation range (viewer)",
                                          "Visualization"};
  Field<double> draw_max_elongation_range{this, "drawMaxElongationRange", 15.0, "max elongation range (viewer)",
                                          "Visualization"};
  Field<double> draw_spring_size{this, "drawSpringSize", 8.0, "size of drawn lines (viewer)", "Visualization"};
  Field<VecNi<2>> local_range{this, "localRange", VecNi<2>(-1, -1),
                              "[first, last] DoF range; springs outside it are ignored (-1: open end)", "Spring"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the springs are built from (default: the node's)"};

  void parse(AttributeMap& attrs, Diagnostics& diag) override;
  void init() override;
};

}  // namespace sinew
