// LinearSmallStrainFEMForceField: Hooke's law assuming small strain, on
// tetrahedra or hexahedra (SOFA's new element-generic FEM;
// spec/mechanics.md §2.5). Element force fe = K_e·(x_e − X0_e).
#pragma once

#include "forcefield/fem/element_fem_force_field.h"

namespace sinew {

class LinearSmallStrainFEMForceField final : public ElementFEMForceFieldBase {
 public:
  explicit LinearSmallStrainFEMForceField(FemElementKind kind) : ElementFEMForceFieldBase(kind) {}
  // ½·uᵀ·K·u with u = x − x_rest (SOFA returns 0).
  std::optional<double> potential_energy() const override;

 protected:
  bool rotation_method(fem::RotationMethod& out) override {
    out = fem::RotationMethod::none;
    return true;
  }
};

}  // namespace sinew
