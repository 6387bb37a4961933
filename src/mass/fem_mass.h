// FEMMass: consistent finite-element mass on tetrahedra, hexahedra, prisms
// or pyramids (SOFA's FEMMass, spec/mechanics.md §1.4). Templates
// "Vec3d,Tetrahedron", "Vec3d,Hexahedron", "Vec3d,Prism", "Vec3d,Pyramid"
// (prisms and pyramids come from a MeshTopology).
//
// M_e(i,j) = Σ_q w_q ρ(q) |det J(q)| N_i(q) N_j(q) on rest positions, with
// ρ(q) = Σ_k N_k(q) ρ_k interpolated from a NodalMassDensity. The global
// matrix is one scalar per node pair (the same on x, y, z), stored as CSR
// with sorted columns; addForce adds Σ_j M_ij·g, accFromF is not available.
#pragma once

#include "core/roles.h"
#include "mass/nodal_mass_density.h"

namespace sinew {

class FEMMass final : public Mass {
 public:
  enum class ElementKind { tetrahedron, hexahedron, prism, pyramid };

  Link<NodalMassDensity> nodal_mass_density{this, "nodalMassDensity",
                                            "NodalMassDensity component (default: first one found in the context)"};
  Link<MeshTopologyBase> topology{this, "topology", "topology holding the elements (default: the node's)"};

  explicit FEMMass(ElementKind kind) : kind_(kind) {}

  void init() override;
  void reinit() override { init(); }
  void add_force(const MechParams& p) override;
  void add_mdx(const MechParams& p, int res, int dx, double factor) override;
  void acc_from_f(const MechParams& p, int a, int f) override;
  void add_gravity_to_v(int v, double dt) override;
  double total() const override { return total_; }
  bool build_mass(MatrixSink& M) override;
  bool is_diagonal() const override { return false; }  // consistent mass matrix (SOFA: isDiagonal() false)
  // SOFA's getPotentialEnergy: −Σ_ij x_i·g·M_ij.
  std::optional<double> potential_energy() const override;

  // Scalar node×node mass matrix (CSR, rows in increasing order, sorted columns).
  const std::vector<std::size_t>& row_begin() const { return row_begin_; }
  const std::vector<unsigned>& columns() const { return cols_; }
  const std::vector<double>& values() const { return vals_; }

  // Element mass matrix (N×N row-major) of one element from its rest nodes
  // and nodal densities, as SOFA integrates it. false: degenerate element.
  static bool tetra_mass(const std::array<Vec3, 4>& X, const std::array<double, 4>& rho, double* M);
  static bool hexa_mass(const std::array<Vec3, 8>& X, const std::array<double, 8>& rho, double* M);
  static bool prism_mass(const std::array<Vec3, 6>& X, const std::array<double, 6>& rho, double* M);
  static bool pyramid_mass(const std::array<Vec3, 5>& X, const std::array<double, 5>& rho, double* M);

 private:
  ElementKind kind_;
  std::vector<std::size_t> row_begin_;  // size n+1
  std::vector<unsigned> cols_;
  std::vector<double> vals_;
  double total_ = 0;
  bool acc_warned_ = false;
};

}  // namespace sinew
