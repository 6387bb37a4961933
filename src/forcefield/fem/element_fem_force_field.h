// Common base of SOFA's element-generic linear FEM force fields
// (LinearSmallStrainFEMForceField, CorotationalFEMForceField; SOFA's
// FEMForceField + BaseElementLinearFEMForceField), templates
// "Vec3d,Tetrahedron", "Vec3d,Hexahedron", "Vec3d,Prism" and "Vec3d,Pyramid"
// (spec/mechanics.md §2.5); prisms and pyramids come from a MeshTopology.
// Not a component by itself; the kernel lives in forcefield/element_fem.h.
#pragma once

#include "core/roles.h"
#include "forcefield/fem/element_fem.h"

namespace sinew {

enum class FemElementKind { tetrahedron, hexahedron, prism, pyramid };

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
  // Calls f(kernel) with the kernel of this force field's element kind.
  template <class F>
  void visit_kernel(F&& f) const {
    switch (kind_) {
      case FemElementKind::tetrahedron: f(tetra_); break;
      case FemElementKind::hexahedron: f(hexa_); break;
      case FemElementKind::prism: f(prism_); break;
      case FemElementKind::pyramid: f(pyramid_); break;
    }
  }

 protected:
  // The rotation method of the element kernels (none for the linear field);
  // false (with an error already raised) when it cannot be used.
  virtual bool rotation_method(fem::RotationMethod& out) = 0;

 private:
  bool read_strategy(const Field<std::string>& f, bool& parallel);

  FemElementKind kind_;
  fem::ElementFEM<fe::Tetra4> tetra_;
  fem::ElementFEM<fe::Hexa8> hexa_;
  fem::ElementFEM<fe::Prism6> prism_;
  fem::ElementFEM<fe::Pyramid5> pyramid_;
  template <class F>
  void visit_kernel(F&& f) {
    switch (kind_) {
      case FemElementKind::tetrahedron: f(tetra_); break;
      case FemElementKind::hexahedron: f(hexa_); break;
      case FemElementKind::prism: f(prism_); break;
      case FemElementKind::pyramid: f(pyramid_); break;
    }
  }
};

// "Vec3d,Tetrahedron" → tetrahedron, "Vec3d,Hexahedron" → hexahedron, "…,Prism", "…,Pyramid".
FemElementKind fem_element_kind_from_template(const std::string& tmpl);
// The element name of a kind ("tetrahedra", ...), for messages.
const char* fem_element_plural(FemElementKind kind);

}  // namespace sinew
