// DiagonalVelocityDampingForceField: f_i −= c_i ∘ v_i, a damping coefficient
// per DoF component, SOFA's DiagonalVelocityDampingForceField (templates
// Vec1d, Vec2d, Vec3d, Vec6d, Rigid2d, Rigid3d). `dampingCoefficient` holds
// one derivative-sized vector per DoF; DoFs past the last one use the last.
// Its damping matrix −diag(c) enters implicit solves through the b factor
// (SOFA's addDForce/addBToMatrix); it has no stiffness and no energy.
#pragma once

#include <optional>
#include <vector>

#include "core/roles.h"

namespace sinew {

class DiagonalVelocityDampingForceField final : public ForceField {
 public:
  Field<std::vector<double>> damping_coefficient{
      this, "dampingCoefficient", {}, "velocity damping coefficients, one derivative-sized vector per DoF", "Damping"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink&) override { return true; }
  bool build_damping(MatrixSink& B) override;
  std::optional<double> potential_energy() const override { return 0.0; }

 private:
  // Coefficient of scalar component j of DoF i.
  double coef(std::size_t i, unsigned j) const;
  unsigned w_ = 3;
  std::size_t count_ = 0;  // coefficient vectors given
};

}  // namespace sinew
