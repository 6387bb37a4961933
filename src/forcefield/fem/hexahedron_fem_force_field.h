// HexahedronFEMForceField: linear elasticity on hexahedra, corotational
// (method large or polar) or linear (small) (spec/mechanics.md §2.3), and
// HexahedronFEMForceFieldAndMass, the same force field acting as the mass
// of its object (§2.4). The numerical kernel lives in forcefield/hexa_fem.h.
#pragma once

#include "core/roles.h"
#include "core/rotation_finder.h"
#include "forcefield/fem/hexa_fem.h"

#include <vector>

namespace sinew {

// Per-element Young's modulus and Poisson ratio from the two fields, with
// SOFA's broadcast (value i, else value 0) and its replacement of
// out-of-range values (E < 0 → 5000, ν ∉ [0, 0.5) → 0.45), each reported on `c`.
void hexa_element_materials(const Component& c, const std::vector<double>& young,
                            const std::vector<double>& poisson, std::size_t ne, std::vector<double>& E,
                            std::vector<double>& nu);

// SOFA's integrateMass: the entry every node pair of a hexahedron gets per unit volume (its
// closed form with all corner signs squared, 8/27 of the density), evaluated in its order.
double hexa_mass_integral(double density);

// The force field on top of either role: ForceField, or Mass for the "AndMass" variant.
template <class Role>
class HexahedronFEMBase : public Role, public RotationFinder {
 public:
  Field<std::vector<double>> young_modulus{this, "youngModulus", {5000.0},
                                           "Young's modulus, one value or one per element", "Material", "pressure (force/length²)"};
  Field<std::vector<double>> poisson_ratio{this, "poissonRatio", {0.45},
                                           "Poisson's ratio in [0, 0.5), one value or one per element", "Material", "dimensionless"};
  Field<std::string> method{this, "method", "large", "large (corotational), polar or small (linear)", "Material"};
  Field<bool> update_stiffness_matrix{this, "updateStiffnessMatrix", false,
                                      "recompute element stiffness from current positions each step", "Material"};
  Field<std::string> gather_pt{this, "gatherPt", " ", "unused (kept for SOFA compatibility)", "Material"};
  Field<std::string> gather_bsize{this, "gatherBsize", " ", "unused (kept for SOFA compatibility)", "Material"};
  Field<bool> drawing{this, "drawing", true, "draw the elements (viewer)", "Visualization"};
  Field<double> draw_percentage_offset{this, "drawPercentageOffset", 0.15, "element shrink factor (viewer)",
                                       "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the hexahedra (default: the node's)"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_dforce(const MechParams& p, double kfactor) override;
  bool build_stiffness(MatrixSink& K) override;

  const fem::HexaFEM& kernel() const { return fem_; }
  // Per-point rotations for the Warp/PrecomputedWarp preconditioners (SOFA getRotations).
  void node_rotations(std::span<Mat3> out) const override { fem_.node_rotations(out); }
  MechanicalState* rotation_state() const override { return this->mstate.get(); }

 protected:
  // SOFA reads the container's live hexahedra every step while its per-element data (rest
  // shape, stiffness, rotations) keeps the order of init: after removals, element i takes the
  // live hexahedron i with the data computed for the i-th one at init. Reproduced: the node
  // indices follow the live list, the rest of the data stays.
  void follow_topology();

  fem::HexaFEM fem_;
  std::vector<Vec3> rest_;  // initial points (rest positions at init)
  std::uint64_t hexa_version_ = 0;
  bool warned_growth_ = false;
};

class HexahedronFEMForceField : public HexahedronFEMBase<ForceField> {
 public:
  // SOFA's m_potentialEnergy: ½·Σ ΔᵀKΔ over the elements (in their frames for
  // large/polar), computed by the last add_force.
  std::optional<double> potential_energy() const override { return fem_.potential_energy; }
};

// Element mass matrices (SOFA's closed form: every node pair gets
// (8/27)·ρ·vol on its 3×3 identity block, vol from the rotated rest element)
// and gravity on the physical lumped masses ρ·vol/8 per element corner.
// NonUniformHexahedronFEMForceFieldAndMass derives from it with full nodal matrices.
class HexahedronFEMForceFieldAndMass : public HexahedronFEMBase<Mass> {
 public:
  Field<double> density{this, "density", 1.0, "volumetric mass (kg/m³)", "Mass"};
  Field<bool> lumped_mass{this, "lumpedMass", false, "use row-summed (lumped) element masses", "Mass"};

  void init() override;
  void add_force(const MechParams& p) override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;
  void acc_from_f(const MechParams& p, int a, int f) override;
  void add_gravity_to_v(int v, double dt) override;
  bool build_mass(MatrixSink& M) override;
  double total() const override;
  bool is_diagonal() const override { return false; }

 protected:
  // An element's 24×24 mass is N ⊗ I3 for an 8×8 nodal matrix N. SOFA's closed form makes every
  // entry of N the same: one value per element. A derived component may set full nodal matrices
  // (row-major), which are then used instead.
  std::vector<double> element_mass_;                 // per element
  std::vector<std::array<double, 64>> nodal_mass_;   // per element, or empty
  // Per element and component (x, y, z), an 8×8 nodal matrix each: masses homogenized with
  // weights that differ by component (HexahedronCompositeFEMForceFieldAndMass); used first.
  std::vector<std::array<std::array<double, 64>, 3>> component_mass_;
  std::vector<double> particle_mass_;  // lumped physical mass per point (gravity)
  std::vector<Vec3> lumped_;           // row sums per point and component (lumpedMass)
};

}  // namespace sinew
