// Common base of SOFA's element-generic linear FEM force fields
// (LinearSmallStrainFEMForceField, CorotationalFEMForceField; SOFA's
// FEMForceField + BaseElementLinearFEMForceField), templates
// "Vec3d,Tetrahedron" and "Vec3d,Hexahedron" (spec/mechanics.md §2.5).
// Not a component by itself; the kernel lives in forcefield/element_fem.h.
#pragma once

#include "core/roles.h"
#include "forcefield/fem/element_fem.h"

namespace sinew {

enum class FemElementKind { tetrahedron, hexahedron };

class ElementFEMForceFieldBase : public ForceField {
 public:
  Field<std::vector<double>> young_modulus{
      this, "youngModulus", {5000.0}, "Young's modulus: one value, or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> poisson_ratio{
      this, "poissonRatio", {0.45}, "Poisson's ratio in [0, 0.5): one value, or one per element", "Material", "dimensionless"};
  Field<std::string> compute_force_strategy{
      this, "computeForceStrategy", "parallel",
      "execution policy of the force evaluation: \"parallel\" or \"sequenced\" (identical results)", "Multithreading"};
  Field<std::string> compute_force_deriv_strategy{
      this, "computeForceDerivStrategy", "parallel",
      "execution policy of the force-derivative evaluation: \"parallel\" or \"sequenced\" (identical results)",
      "Multithreading"};
  Field<double> element_space{this, "elementSpace", 0.125, "gap between drawn elements (viewer)", "Visualization"};
  Field<std::vector<double>> element_stiffness{
      this, "elementStiffness", {}, "stiffness matrix of each element (output, row-major, flattened)"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the elements (default: the node's)"};

  explicit ElementFEMForceFieldBase(FemElementKind kind) : kind_(kind) {}

  void init() override;
  // Material or rest shape changed: recompute the element stiffnesses (SOFA's update callback).
  void reinit() override { init(); }
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  FemElementKind element_kind() const { return kind_; }
  const fem::ElementFEM<fe::Tetra4>& tetra_kernel() const { return tetra_; }
  const fem::ElementFEM<fe::Hexa8>& hexa_kernel() const { return hexa_; }

 protected:
  // The rotation method of the element kernels (none for the linear field);
  // false (with an error already raised) when it cannot be used.
  virtual bool rotation_method(fem::RotationMethod& out) = 0;

 private:
  bool read_strategy(const Field<std::string>& f, bool& parallel);

  FemElementKind kind_;
  fem::ElementFEM<fe::Tetra4> tetra_;
  fem::ElementFEM<fe::Hexa8> hexa_;
};

// "Vec3d,Tetrahedron" → tetrahedron, "Vec3d,Hexahedron" → hexahedron.
FemElementKind fem_element_kind_from_template(const std::string& tmpl);

}  // namespace sinew
