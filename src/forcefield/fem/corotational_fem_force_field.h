// CorotationalFEMForceField: linear elasticity in a per-element rotated frame
// (SOFA's new element-generic FEM; spec/mechanics.md §2.5, trap 14).
// R = Fcurᵀ·F0 from the 3-node frame (tetrahedra, "triangle") or the
// averaged-edge frame (hexahedra, "hexahedron"); the SVD polar factor of the
// deformation about the centroids ("stable_polar", the default for prisms and
// pyramids); also "polar" (Higham's iteration) and "identity". Displacements
// are measured about the element centroids.
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
