// StandardTetrahedralFEMForceField: SOFA's second hyperelastic force field on
// linear tetrahedra, with the materials of TetrahedronHyperelasticityFEMForceField
// but StableNeoHookean. The same elements computed with the strain-displacement
// matrices and the 6×6 elasticity tensor (hyper::Formulation::standard): forces
// and tangent agree with TetrahedronHyperelasticityFEMForceField's to round-off.
// spec/mechanics.md §2.8; SOFA's Sofa/Component/SolidMechanics/FEM/HyperElastic.
#pragma once

#include "forcefield/hyperelastic/tetrahedron_hyperelasticity_fem_force_field.h"

namespace sinew {

class StandardTetrahedralFEMForceField final : public HyperelasticTetraForceField {
 public:
  Field<std::string> parameter_file{this, "ParameterFile", "myFile.param",
                                    "file of per-tetrahedron parameters (never read, as in SOFA)", "Material"};

  StandardTetrahedralFEMForceField() : HyperelasticTetraForceField(hyper::Formulation::standard) {}
};

}  // namespace sinew
