// SurfacePressureForceField: a scalar pressure on a closed surface (its
// triangles and quads), SOFA's SurfacePressureForceField (template Vec3d).
//
// Each triangle (a, b, c) adds p·(ab × ac)/6 to each of its vertices (scaled
// by |n·mainDirection| when a main direction is given); a quad (a, b, c, d)
// adds p·(ab × ac)/6 + p·(ac × ad)/6 to a and c, the first part to b, the
// second to d. The elements are `triangleIndices`/`quadIndices`, else every
// element of the topology whose vertices lie in the box [min, max] (no box:
// all). The pressure is
//   - `pressure`, or in `pulseMode` a value ramping at `pressureSpeed` (Pa/s)
//     between `pressureLowerBound` and `pressure`, one dt per force
//     evaluation (SOFA's rule: it advances at every addForce);
//   - with `volumeConservationMode`, scaled by V0/V (V the enclosed volume
//     by the divergence theorem, V0 `defaultVolume`, taken at the first
//     evaluation when −1).
// With `useTangentStiffness` the triangles' tangent (the derivative of the
// cross product, not symmetric) enters implicit solves; quads have none
// (SOFA's).
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class SurfacePressureForceField final : public ForceField {
 public:
  Field<double> pressure{this, "pressure", 0.0, "pressure (force per unit area)", "Pressure", "force/length²"};
  Field<Vec3> min{this, "min", Vec3::Zero(), "lower corner of the selection box (both corners 0: no box)",
                  "Pressure", "length"};
  Field<Vec3> max{this, "max", Vec3::Zero(), "upper corner of the selection box", "Pressure", "length"};
  Field<std::vector<unsigned>> triangle_indices{this, "triangleIndices", {}, "indices of the pressed triangles",
                                                "Pressure"};
  Field<std::vector<unsigned>> quad_indices{this, "quadIndices", {}, "indices of the pressed quads", "Pressure"};
  Field<bool> pulse_mode{this, "pulseMode", false, "cyclic pressure between pressureLowerBound and pressure",
                         "Pressure"};
  Field<double> pressure_lower_bound{this, "pressureLowerBound", 0.0, "lower bound of the pulse", "Pressure",
                                     "force/length²"};
  Field<double> pressure_speed{this, "pressureSpeed", 0.0, "rate of the pulse (pressure per second)", "Pressure"};
  Field<bool> volume_conservation_mode{this, "volumeConservationMode", false,
                                       "scale the pressure by the inverse of the volume change", "Pressure"};
  Field<bool> use_tangent_stiffness{this, "useTangentStiffness", true,
                                    "use the (non-symmetric) tangent of the triangle forces", "Pressure"};
  Field<double> default_volume{this, "defaultVolume", -1.0, "reference volume (-1: the first one computed)",
                               "Pressure", "length³"};
  Field<Vec3> main_direction{this, "mainDirection", Vec3::Zero(),
                             "scale each triangle's force by |normal·mainDirection| (0: off)", "Pressure"};
  Field<double> draw_force_scale{this, "drawForceScale", 0.0, "scale of the drawn forces (viewer)", "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the surface (default: the node's)"};

  void init() override;
  void reset() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  // Volume enclosed by the pressed elements at x (divergence theorem).
  double mesh_volume(const std::vector<double>& x) const;
  double last_pressure() const { return last_pressure_; }

 private:
  double pulse_pressure();
  bool in_box(const double* x) const;
  // Tangent blocks of the last add_force: df_row += K_block·dx_col.
  struct Block {
    unsigned row, col;
    double k[3][3];
  };
  std::vector<Block> blocks_;
  bool increasing_ = true;
  double pulse_ = 0, last_pressure_ = 0;
};

}  // namespace sinew
