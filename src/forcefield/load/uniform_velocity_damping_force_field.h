// UniformVelocityDampingForceField: f −= c·v on every DoF; when `implicit`,
// the damping matrix −c·I enters the implicit system through the b factor
// (spec/mechanics.md §3.11).
#pragma once

#include "core/roles.h"

namespace sinew {

class UniformVelocityDampingForceField final : public ForceField {
 public:
  UniformVelocityDampingForceField() { damping_coefficient.add_alias("damping"); }

  Field<double> damping_coefficient{this, "dampingCoefficient", 0.1, "velocity damping coefficient", "Damping"};
  Field<bool> implicit{this, "implicit", false, "include the damping matrix in the implicit system", "Damping"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink&) override { return true; }
  bool build_damping(MatrixSink& B) override;
};

}  // namespace sinew
