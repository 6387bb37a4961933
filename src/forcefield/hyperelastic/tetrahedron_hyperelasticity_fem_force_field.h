// TetrahedronHyperelasticityFEMForceField: hyperelastic linear tetrahedra
// (total Lagrangian) with one of SOFA's materials: ArrudaBoyce (default),
// StVenantKirchhoff, NeoHookean, MooneyRivlin, VerondaWestman, Costa, Ogden,
// StableNeoHookean (spec/mechanics.md §2.8). StandardTetrahedralFEMForceField
// (standard_tetrahedral_fem_force_field.h) shares all but its arithmetic.
// The kernel lives in forcefield/hyperelastic_tetra.h, the materials in
// forcefield/hyperelastic_materials.h.
#pragma once

#include "core/roles.h"
#include "forcefield/hyperelastic/hyperelastic_tetra.h"

namespace sinew {

// What SOFA's two hyperelastic tetrahedron force fields share: the material and its
// parameters, the topology, and the kernel, which each runs in its own formulation.
class HyperelasticTetraForceField : public ForceField {
 public:
  Field<std::string> material_name{
      this, "materialName", "ArrudaBoyce",
      "material: ArrudaBoyce (mu k0), StVenantKirchhoff (mu lambda), NeoHookean (mu lambda), MooneyRivlin "
      "(c1 c2 k0), VerondaWestman (c1 c2 k0), Costa (a k0 bff bfs bss bfn bsn bnn), Ogden (mu1 alpha1 k0) or "
      "StableNeoHookean (mu lambda; TetrahedronHyperelasticityFEMForceField only)",
      "Material"};
  Field<std::vector<double>> parameter_set{this, "ParameterSet", {},
                                           "the material parameters (see materialName)", "Material"};
  Field<std::vector<Vec3>> anisotropy_directions{
      this, "AnisotropyDirections", {},
      "directions of anisotropy; as in SOFA no material uses them (Costa's fibre, sheet and normal axes are the "
      "global x, y, z axes)",
      "Material"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the tetrahedra (default: the node's)"};

  void init() override;
  void reinit() override { init(); }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const hyper::TetraHyperelasticity& kernel() const { return fem_; }
  // Σ V0·W(C) over the elements (SOFA implements it in neither force field).
  std::optional<double> potential_energy() const override;

 protected:
  explicit HyperelasticTetraForceField(hyper::Formulation form) : form_(form) {}

 private:
  hyper::Formulation form_;
  hyper::TetraHyperelasticity fem_;
  bool reported_inversion_ = false;
};

class TetrahedronHyperelasticityFEMForceField final : public HyperelasticTetraForceField {
 public:
  Field<bool> matrix_regularization{this, "matrixRegularization", false,
                                    "regularisation of the stiffness matrix (unused, as in SOFA)", "Material"};

  TetrahedronHyperelasticityFEMForceField() : HyperelasticTetraForceField(hyper::Formulation::hyperelasticity) {}
};

}  // namespace sinew
