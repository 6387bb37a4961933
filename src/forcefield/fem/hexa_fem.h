// Numerical kernel of SOFA's HexahedronFEMForceField (methods small, large,
// polar), as plain per-element arrays and free functions. A scene component
// wraps HexaFEM; nothing here knows about scenes or topologies.
//
// Everything must reproduce SOFA to round-off (regression scenes compare at
// 1e-8 after 100 steps), so every sum is written out in SOFA's evaluation
// order and Eigen is used only as storage: Eigen's own reductions (dot, norm,
// matrix products) group terms differently and are avoided in this kernel.
// Spec: shared/spec/mechanics.md §2.0 and §2.3.
//
// Node order of a hexahedron (cell axes): 0:(0,0,0) 1:(1,0,0) 2:(1,1,0)
// 3:(0,1,0) 4:(0,0,1) 5:(1,0,1) 6:(1,1,1) 7:(0,1,1).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Geometry>  // math/types.h names Eigen::Quaterniond but only includes Eigen/Core

#include "math/types.h"

namespace sinew::fem {

enum class HexaMethod { small, large, polar };

// Element stiffness, 24×24, dof order (node0 x,y,z, node1 x,y,z, ...).
// Row-major so that the hot K·D loop reads rows contiguously.
using Mat24 = Eigen::Matrix<double, 24, 24, Eigen::RowMajor>;

// The three distinct entries of SOFA's isotropic material matrix (Voigt,
// engineering shear): u = D(0,0), v = D(0,1), w = D(3,3), in Pa.
struct HexaMaterial {
  double u = 0, v = 0, w = 0;
};

// Material entries as SOFA computes them: the matrix with unit diagonal,
// ν/(1−ν) off-diagonal and (1−2ν)/(2(1−ν)) shear, scaled entry-wise by
// E(1−ν)/((1+ν)(1−2ν)). young in Pa; poisson in [0, 0.5) (not checked).
HexaMaterial hexa_material(double young, double poisson);

// What the Jacobian looked like while integrating one element.
struct HexaJacobianInfo {
  double min_det = 0;      // smallest detJ over the Gauss points used (m³/8 for a unit cell)
  bool singular = false;   // some |detJ| ≤ DBL_EPSILON: SOFA keeps the previous J⁻¹ (garbage K)
  bool parallelepiped = false;  // the constant-Jacobian shortcut was taken
};

// Element stiffness from 8 nodes given in the element frame (rotated rest
// nodes R0·X0_k, or rotated current nodes when the stiffness is updated).
// 2×2×2 Gauss quadrature with signed detJ (an inverted element contributes
// negatively, as in SOFA); K is finally multiplied entry-wise by `coef`
// (SparseGridTopology stiffness coefficient, 1 otherwise). Never throws.
HexaJacobianInfo hexa_element_stiffness(const std::array<Vec3, 8>& nodes, const HexaMaterial& mat,
                                        double coef, Mat24& K);
inline HexaJacobianInfo hexa_element_stiffness(const std::array<Vec3, 8>& nodes, double young,
                                               double poisson, Mat24& K) {
  return hexa_element_stiffness(nodes, hexa_material(young, poisson), 1.0, K);
}

// Element frames, rows = local axes (world → local). Positions in any unit.
// large: x axis along the averaged x edges h, z ⟂ (h, averaged y edges w).
// polar: orthogonal factor of the matrix with rows (h, w, averaged z edges).
Mat3 hexa_frame_large(const std::array<Vec3, 8>& n);
Mat3 hexa_frame_polar(const std::array<Vec3, 8>& n);

// A problem found by HexaFEM::init; element = −1 for problems of the whole
// input (size mismatch). fatal: the element's stiffness is meaningless (zero
// detJ at a Gauss point, non-finite values) or it cannot be computed at all
// (node index out of range: such an element is marked inactive and skipped
// everywhere); the caller should refuse the scene. Not fatal: SOFA computes
// the element anyway (inverted element, negative detJ) and so do we.
// The message does not repeat the element index.
struct HexaIssue {
  int element = -1;
  bool fatal = true;
  std::string message;
};

// Hot data of one HexahedronFEMForceField. All vectors are indexed by element.
struct HexaFEM {
  HexaMethod method = HexaMethod::large;
  bool update_stiffness = false;  // SOFA updateStiffnessMatrix: K from current nodes in add_force
  std::vector<std::array<int, 8>> hexa;      // node indices per element
  std::vector<std::array<Vec3, 8>> rest;     // rotated rest nodes R0·X0_k
  std::vector<Mat3> R0, R;                   // rest and current frames (R = R0 until add_force)
  std::vector<Mat24> K;                      // element stiffness (N/m)
  std::vector<HexaMaterial> material;        // per element, kept for update_stiffness
  std::vector<double> coef;                  // per element stiffness factor (1 unless sparse grid)
  std::vector<unsigned char> active;         // 0 for elements with out-of-range node indices
  std::vector<int> node_hexa_count;          // incident elements per point (with multiplicity)
  double potential_energy = 0;               // ½ Σ ΔᵀKΔ of the last add_force (J), as SOFA reports it

  // Stiffnesses shared by bitwise-equal elements (regular grids: a handful of
  // distinct K instead of one 4.6 kB matrix per element), read by add_dforce
  // so the K·x products stream far less memory. Same values, so the same
  // results bit for bit. Rebuilt when k_gen changed (init, add_force with
  // update_stiffness); call touch_stiffness() after writing K directly.
  void touch_stiffness() { ++k_gen; }
  // True when the last add_dforce used the shared stiffnesses (tests).
  bool shares_stiffness() const { return !k_index.empty(); }
 private:
  std::uint64_t k_gen = 1;
  mutable std::uint64_t shared_gen = 0;
  mutable std::vector<std::uint32_t> k_index;  // element → k_shared (empty: use K)
  // Distinct stiffnesses with rows reordered x of the 8 nodes, then y, then z
  // (rows are independent sums: the order of each row's terms is unchanged).
  mutable std::vector<std::array<double, 24 * 24>> k_shared;
  mutable std::vector<std::uint32_t> k_rep;   // an element having k_shared[u]
  void refresh_shared_stiffness() const;
 public:

  // Precompute frames, rotated rest nodes and stiffnesses from rest positions
  // X0 (n points) and per-element E (Pa), ν (already broadcast: element i
  // uses E[i], nu[i]). stiffness_coef: per-element factor, empty = all 1.
  // Problems come back as a list instead of exceptions; see HexaIssue.
  std::vector<HexaIssue> init(std::span<const Vec3> X0, std::span<const std::array<int, 8>> hexa,
                              std::span<const double> E, std::span<const double> nu, HexaMethod m,
                              std::span<const double> stiffness_coef = {});

  std::size_t size() const { return hexa.size(); }

  // f += Σ_e Rᵀ K (R0·X0 − R·x) per element, in element order; updates R
  // (large/polar), K (if update_stiffness) and potential_energy.
  // Precondition: init succeeded, x.size() and f.size() ≥ number of points.
  void add_force(std::span<const Vec3> x, std::span<Vec3> f);

  // df −= kfactor · Rᵀ K R dx per element, with R from the last add_force.
  // (SOFA's tangent: the derivative of R is ignored.)
  void add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double kfactor) const;

  // Calls sink(row_node, col_node, block) with block = −kfactor·Rᵀ K_ij R for
  // every element and every node pair (i, j) of it, i outer, j inner; blocks of
  // shared nodes arrive once per element and must be summed by the sink.
  template <class Sink>
  void add_stiffness_blocks(double kfactor, Sink&& sink) const;

  // Per-point rotation used by WarpPreconditioner (SOFA getRotations):
  // polar((I + Σ_e R_e·R0_eᵀ) / n_e) over the n_e incident elements — the
  // identity seed is SOFA's. out.size() = number of points. A point with no
  // element gets the identity (SOFA would divide by zero).
  void node_rotations(std::span<Mat3> out) const;

  // ---- parallel evaluation (bit-identical to the sequential loops)
  // Elements are processed concurrently into per-element slots; each point
  // then sums its slots in element order, as the sequential loop would.
  static constexpr std::size_t kParallelMinElements = 2048;
  std::vector<std::uint32_t> node_start, node_slot;     // point → (element·8 + corner) slots, CSR
  mutable std::vector<std::array<Vec3, 8>> scratch;     // per-element nodal contributions
  std::vector<double> element_energy;
  void build_incidence(std::size_t n_points);
  bool parallel() const;

 private:
  void element_force(std::size_t e, std::span<const Vec3> x, Vec3* out, double& energy);
  void element_dforce(std::size_t e, std::span<const Vec3> dx, double kfactor, Vec3* out) const;
  void gather(std::span<Vec3> f, double sign) const;
};

// Block −kfactor·Rᵀ·K_ij·R, in SOFA's order: (RᵀK_ij) first, then ·R, then
// scaled entry-wise.
inline Mat3 hexa_rotated_block(const Mat24& K, const Mat3& R, int i, int j, double kfactor) {
  Mat3 kb, t, out;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) kb(a, b) = K(3 * i + a, 3 * j + b);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) t(a, b) = R(0, a) * kb(0, b) + R(1, a) * kb(1, b) + R(2, a) * kb(2, b);
  const double s = -kfactor;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) out(a, b) = (t(a, 0) * R(0, b) + t(a, 1) * R(1, b) + t(a, 2) * R(2, b)) * s;
  return out;
}

template <class Sink>
void HexaFEM::add_stiffness_blocks(double kfactor, Sink&& sink) const {
  for (std::size_t e = 0; e < hexa.size(); ++e) {
    if (!active[e]) continue;
    const auto& h = hexa[e];
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) sink(h[i], h[j], hexa_rotated_block(K[e], R[e], i, j, kfactor));
  }
}

}  // namespace sinew::fem
