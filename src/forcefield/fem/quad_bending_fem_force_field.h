// QuadBendingFEMForceField: Mindlin-style quad plate elements, method "small"
// (the only one SOFA implements: `method` is read but ignored).
//
// What SOFA computes (QuadBendingFEMForceField.inl), with no element frame:
// the quad's edges are taken as aligned with the world axes, so
//  * membrane: world x, y displacements, plane-stress C·thickness, 2×2 Gauss
//    points (±1/√3), shape-function derivatives from the half lengths
//    l = |q1 − q0|/2 and h = |q3 − q0|/2;
//  * transverse shear: world z displacements, κ = 5/6, 1 Gauss point (weight 2×2).
// Nodal rotations are taken as zero, so the bending (curvature) terms never
// reach the translational forces and are not computed here. l and h come from
// the *current* positions (as SOFA does), so K changes with the shape; the
// displacement is taken relative to the centroid (q0 + q2)/2, at rest and now.
// The element stiffness is kept from the last add_force: add_dforce and
// build_stiffness use it. SOFA's own buildStiffnessMatrix reads its 20×20 K
// with a 3-row stride instead of 5 (a bug); Sinew assembles the K that
// add_dforce applies.
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"

namespace sinew {

class QuadBendingFEMForceField final : public ForceField {
 public:
  Field<std::string> method{this, "method", "small", "\"small\" displacements (the only method SOFA implements)",
                            "Material"};
  Field<std::vector<double>> poisson_ratio{
      this, "poissonRatio", {0.45}, "Poisson's ratio: one value, or one per element", "Material", "dimensionless"};
  Field<std::vector<double>> young_modulus{
      this, "youngModulus", {1000.0}, "Young's modulus: one value, or one per element", "Material", "pressure (force/length²)"};
  Field<double> thickness{this, "thickness", 1.0, "thickness of the plate elements", "Material", "length"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the quads (default: the node's)"};

  struct Element {
    std::array<unsigned, 4> v{};
    std::array<double, 12> rest{};  // rest positions minus the rest centroid (q0 + q2)/2
    double c00 = 0, c01 = 0, c22 = 0;  // membrane material (× thickness); c11 = c00, c10 = c01
    double cs = 0;                     // transverse shear material κ·G·thickness
    std::array<double, 64> kxy{};      // membrane K over (x0 y0 x1 y1 x2 y2 x3 y3), row-major
    std::array<double, 16> kz{};       // shear K over (z0 z1 z2 z3), row-major
  };

  void init() override;
  void reinit() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const std::vector<Element>& elements() const { return el_; }

 private:
  bool rebuild();
  bool update_stiffness(const double* x);  // K of every element from positions x; false on a degenerate quad
  void fail(const std::string& why);
  std::vector<Element> el_;
  std::uint64_t quads_version_ = 0;  // of the list the elements were built from
};

}  // namespace sinew
