// HexahedralFEMForceField: SOFA's topology-container sibling of
// HexahedronFEMForceField (corotational hexahedra, methods large and polar
// only). Frames, rest shape, force and tangent are those of the Hexahedron
// kernel (forcefield/hexa_fem.h, reused as is); two things differ in SOFA and
// are reproduced here:
//  - the element stiffness is a closed form for axis-aligned boxes, built from
//    the unrotated rest nodes, rounded to float, whose diagonal 3×3 entries
//    scale every term by the same axis length (exact for cubes only);
//  - the assembled stiffness blocks are −R·K_ij·Rᵀ (R: world → element
//    frame), whereas add_dforce applies −Rᵀ·K·R: the two agree only when the
//    element frames are symmetric (no rotation, or half-turns).
// HexahedralFEMForceFieldAndMass is the same force field acting as the mass
// of its object, with SOFA's element masses (below).
#pragma once

#include <array>
#include <vector>

#include "core/roles.h"
#include "forcefield/fem/hexa_fem.h"

namespace sinew {

namespace fem {

// SOFA HexahedralFEM element stiffness from the 8 rest nodes as given (world
// frame, no rotation): J⁻¹ = diag(2/l) with l = n6 − n0, detJ taken as
// |n1−n0|·|n3−n0|·|n4−n0|/8; each 3×3 block entry is integrated exactly over
// the reference cube, rounded to float, then multiplied by detJ. Diagonal
// entries (m, m) use (2/l_m)² on all their terms. Lower triangle copied from
// the upper one. Non-finite output for flat boxes (a zero component of l).
// float_entries = false skips the float rounding (tests: on cubes the result
// is then HexahedronFEMForceField's Gauss stiffness to round-off).
void hexahedral_element_stiffness(const std::array<Vec3, 8>& nodes, const HexaMaterial& mat, Mat24& K,
                                  bool float_entries = true);

}  // namespace fem

// The force field on top of either role: ForceField, or Mass for the "AndMass" variant.
template <class Role>
class HexahedralFEMBase : public Role {
 public:
  Field<std::vector<double>> young_modulus{this, "youngModulus", {5000.0},
                                           "Young's modulus, one value or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> poisson_ratio{this, "poissonRatio", {0.45},
                                           "Poisson's ratio in [0, 0.5), one value or one per element", "Material", "dimensionless"};
  Field<std::string> method{this, "method", "large", "\"large\" or \"polar\" displacements", "Material"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the hexahedra (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const fem::HexaFEM& kernel() const { return fem_; }

 protected:
  // Hexahedra removed or added since the elements were built: rebuilt from the rest positions
  // (SOFA's per-hexahedron data is computed from them on creation and moved with swap-last on
  // removal, so a rebuild gives the same elements in the container's order).
  void follow_topology();

  fem::HexaFEM fem_;  // K replaced by hexahedral_element_stiffness after init
  std::uint64_t hexa_version_ = 0;
};

class HexahedralFEMForceField final : public HexahedralFEMBase<ForceField> {};

// SOFA's element masses, from the rotated rest element of volume
// V = |n1−n0|·|n3−n0|·|n4−n0|: every node pair (i, j) of the element gets
// (ρV)·(8/27) on its 3×3 identity block (SOFA integrates each pair with the
// first node's corner signs, squared: a constant), so M_e·dx couples all 8
// nodes; gravity acts on ρV/8 per corner (unless separateGravity). Kept from
// SOFA: the assembled mass (compatibility path of addMToMatrix) has the
// diagonal blocks only, lumpedMass sums each row of M_e, and accFromF does not
// exist (a warning, the acceleration is left as it is).
class HexahedralFEMForceFieldAndMass final : public HexahedralFEMBase<Mass> {
 public:
  Field<double> density{this, "density", 1.0, "volumetric mass", "Mass", "mass/length³"};
  Field<bool> lumped_mass{this, "lumpedMass", false, "use lumped masses (row sums of the element mass matrices)",
                          "Mass"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;
  void acc_from_f(const MechParams& p, int a, int f) override;
  void add_gravity_to_v(int v, double dt) override;
  bool build_mass(MatrixSink& M) override;
  double total() const override;
  bool is_diagonal() const override { return lumped_mass.value(); }

  // Per element: the value of every diagonal entry of its 3×3 blocks (SOFA's M_e).
  const std::vector<double>& element_masses() const { return element_mass_; }
  const std::vector<double>& particle_masses() const { return particle_mass_; }

 private:
  std::vector<double> element_mass_;
  std::vector<double> particle_mass_;  // ρV/8 per element corner, summed per point (gravity, total)
  std::vector<Vec3> lumped_;           // row sums per point and component (lumpedMass)
};

}  // namespace sinew
