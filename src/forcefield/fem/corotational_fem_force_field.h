// CorotationalFEMForceField: linear elasticity in a per-element rotated frame
// (SOFA's new element-generic FEM; spec/mechanics.md §2.5, trap 14).
// R = Fcurᵀ·F0 from the 3-node frame (tetrahedra, "triangle") or the
// averaged-edge frame (hexahedra, "hexahedron"); also "polar" and
// "identity". Displacements are measured about the element centroids.
#pragma once

#include "forcefield/fem/element_fem_force_field.h"

namespace sinew {

class CorotationalFEMForceField final : public ElementFEMForceFieldBase {
 public:
  Field<std::string> rotation_method_f;

  explicit CorotationalFEMForceField(FemElementKind kind);

 protected:
  bool rotation_method(fem::RotationMethod& out) override;
};

}  // namespace sinew
