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

class HexahedralFEMForceField final : public ForceField {
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

 private:
  // Hexahedra removed or added since the elements were built: rebuilt from the rest positions
  // (SOFA's per-hexahedron data is computed from them on creation and moved with swap-last on
  // removal, so a rebuild gives the same elements in the container's order).
  void follow_topology();

  fem::HexaFEM fem_;  // K replaced by hexahedral_element_stiffness after init
  std::uint64_t hexa_version_ = 0;
};

}  // namespace sinew
