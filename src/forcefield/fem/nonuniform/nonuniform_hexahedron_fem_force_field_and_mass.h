// NonUniformHexahedronFEMForceFieldAndMass: HexahedronFEMForceFieldAndMass on a
// sparse grid whose element matrices are condensed from the grid's virtual finer
// levels (Nesme, Payan, Faure, VRIPHYS 2006): a coarse cell half filled by the
// object is as stiff and heavy as the fine cells it holds, not as a full or
// half cell. spec/mechanics.md §2.4; SOFA's
// Sofa/Component/SolidMechanics/FEM/NonUniform.
//
// Each mechanical cell's stiffness and mass are built at the finest level used
// (classical 2×2×2-Gauss stiffness and SOFA's closed-form mass, both scaled by
// that fine cell's stiffness coefficient, as SOFA does for the mass too) and
// carried up one level at a time: K_coarse = Σ_octants Tᵀ·K_fine·T, T the
// trilinear weights of the coarse corners at the fine corners.
#pragma once

#include <array>
#include <vector>

#include "forcefield/fem/hexahedron_fem_force_field.h"

namespace sinew {

class SparseGridTopology;

class NonUniformHexahedronFEMForceFieldAndMass : public HexahedronFEMForceFieldAndMass {
 public:
  Field<int> nb_virtual_finer_levels{this, "nbVirtualFinerLevels", 0,
                                     "virtual finer levels of the sparse grid the matrices are condensed from",
                                     "Mass"};
  Field<bool> use_mass{this, "useMass", true,
                       "the condensed element masses are the object's mass (else totalMass spread over the points)",
                       "Mass"};
  Field<double> total_mass{this, "totalMass", 0.0,
                           "without useMass: every point weighs totalMass / number of elements (SOFA's rule)", "Mass",
                           "mass"};

  void init() override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;

  // kernel().K holds each condensed stiffness transposed (symmetric to round-off): the kernel
  // reads it by columns, so its products are SOFA's K·x bit for bit; the assembled matrix
  // (build_stiffness) gets Kᵀ's blocks, equal to K's to round-off.
  // Condensed 8×8 nodal mass of element e (the 24×24 matrix is this ⊗ I3), row-major.
  const std::array<double, 64>& element_mass(std::size_t e) const { return nodal_mass_[e]; }

 protected:
  // Fills fem_.K (each element's stiffness, transposed: see kernel()) and the element masses
  // (nodal_mass_ or component_mass_) from the grid; false after an error. `levels` is
  // nbVirtualFinerLevels, already checked to be >= 0.
  virtual bool compute_element_matrices(const SparseGridTopology& grid, int levels);
  // The classical stiffness and mass of hexahedron `nodes` (before the state's scale3d), both
  // scaled by `coef` (SOFA passes the stiffness coefficient for the mass too), with the first
  // element's material: SOFA's computeClassicalMechanicalMatrices. False when its Jacobian is singular.
  bool classical_matrices(std::array<Vec3, 8> nodes, double coef, fem::Mat24& K, std::array<double, 64>& M) const;
};

namespace fem {
// Adds Tᵀ·fine·T to `coarse` (24×24, dof order node-major), T the trilinear weights of the 8
// corners of a cell at the corners of its octant `octant` (x + 2y + 4z), in SOFA's order of
// operations (addFineToCoarse). Exposed for tests.
void hexa_fine_to_coarse(Mat24& coarse, const Mat24& fine, int octant);
// The same on 8×8 nodal matrices (a mass M ⊗ I3 condenses component by component).
void hexa_fine_to_coarse(std::array<double, 64>& coarse, const std::array<double, 64>& fine, int octant);
// Weight of coarse corner j at fine corner k of octant c, as SOFA's single-precision table.
float hexa_octant_weight(int c, int k, int j);
}  // namespace fem

}  // namespace sinew
