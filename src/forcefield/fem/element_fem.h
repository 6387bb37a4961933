// Numerical kernel of SOFA's element-generic linear FEM
// (LinearSmallStrainFEMForceField, CorotationalFEMForceField) on linear
// tetrahedra, trilinear hexahedra, linear prisms and pyramids, as plain
// per-element arrays.
// Spec: shared/spec/mechanics.md §2.5 (traps 6 and 14).
//
// Element stiffness K_e = Σ_q w_q |det J_q| Bᵀ C B from rest positions, with
// SOFA's Voigt order (xx, yy, zz, yz, xz, xy), engineering shear and the
// reference elements of math/finite_element.h; every sum is evaluated in
// SOFA's order (dense Mat products, first term first).
//
// Forces are computed per element into a per-element buffer (optionally in
// parallel with oneTBB: elements are independent) and then scattered to the
// nodes sequentially in element order, exactly as SOFA does, so the
// "parallel" and "sequenced" strategies give bit-identical results.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "math/finite_element.h"
#include "math/types.h"

namespace sinew::fem {

// How the corotational element rotation is obtained (SOFA rotationMethod).
enum class RotationMethod {
  none,        // linear small strain: no rotation at all
  identity,    // R = I
  triangle,    // frame of nodes 0,1,2 (default for tetrahedra)
  hexahedron,  // frame of the averaged x and y edges (default for hexahedra)
  polar,       // orthogonal factor of Σ (x−t)(X0−t0)ᵀ (Higham's iteration)
  stable_polar,  // the same by SVD, always a rotation (SOFA's StablePolarDecomposition)
};

// A problem found while preparing the elements (element = −1: whole input).
struct ElementIssue {
  int element = -1;
  bool fatal = true;
  std::string message;
};

// Lamé parameters as SOFA computes them (3D): μ = E/(2(1+ν)), λ = Eν/((1+ν)(1−2ν)).
void lame_parameters(double young, double poisson, double& lambda, double& mu);

// Element stiffness of element type E (fe::Tetra4, Hexa8, Prism6, Pyramid5) from its rest
// nodes, dof order (node0 x,y,z, node1 x,y,z, ...), row-major D×D with
// D = 3·E::kNodes. Returns false when the Jacobian is singular at some
// quadrature point (degenerate element); K is then left unspecified.
// *inverted (if given) is set when det J < 0 at some quadrature point
// (SOFA integrates with |det J| anyway).
template <class E>
bool element_stiffness(const std::array<Vec3, E::kNodes>& X, double lambda, double mu, double* K,
                       bool* inverted = nullptr);

// Frames (rows = axes, world → local) used by the triangle and hexahedron rotation methods.
Mat3 frame_from_3_points(const Vec3& p0, const Vec3& p1, const Vec3& p2);
Mat3 frame_from_hexahedron(const std::array<Vec3, 8>& n);

template <class E>
struct ElementFEM {
  static constexpr int N = E::kNodes;
  static constexpr int D = 3 * N;
  using Stiffness = std::array<double, D * D>;  // row-major
  using ElementVector = std::array<double, D>;

  RotationMethod rotation = RotationMethod::none;
  bool parallel_force = false;   // computeForceStrategy="parallel"
  bool parallel_dforce = false;  // computeForceDerivStrategy="parallel"

  std::vector<std::array<unsigned, N>> elements;
  std::vector<Stiffness> K;
  std::vector<Mat3> F0;  // rest frames (SOFA's "initial rotations transposed")
  std::vector<Mat3> R;   // rotation of each element at the last add_force
  std::vector<ElementVector> fe;   // element forces of the last add_force
  std::vector<ElementVector> dfe;  // element force derivatives of the last add_force

  // Precomputes stiffnesses (and rest frames) from rest positions X0.
  // E_, nu: per element (already broadcast and checked by the caller).
  std::vector<ElementIssue> init(std::span<const Vec3> X0, std::span<const std::array<unsigned, N>> elems,
                                 std::span<const double> young, std::span<const double> poisson,
                                 RotationMethod method);

  std::size_t size() const { return elements.size(); }

  // f_k −= fe_k with fe = K·(x − X0) (linear) or R·K·(Rᵀ(x−t) − (X0−t0)) (corotational).
  void add_force(std::span<const Vec3> x, std::span<const Vec3> X0, std::span<Vec3> f);
  // df_k −= kfactor · (K·dx)_k, rotated with the R of the last add_force when corotational.
  void add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double kfactor);

  // Calls sink(row_node, col_node, block) with block = ∂f/∂x block −K_ij
  // (linear) or −R K_ij Rᵀ (corotational), element by element, i outer.
  template <class Sink>
  void stiffness_blocks(Sink&& sink) const {
    for (std::size_t e = 0; e < elements.size(); ++e) {
      const auto& k = K[e];
      const bool rot = rotation != RotationMethod::none;
      const Mat3& r = R[e];
      for (int a = 0; a < N; ++a)
        for (int b = 0; b < N; ++b) {
          Mat3 local;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) local(i, j) = k[(3 * a + i) * D + 3 * b + j];
          Mat3 block;
          if (!rot) {
            block = -local;
          } else {
            // ((−R)·K_ab)·Rᵀ, each 3×3 product summed in SOFA's order
            const Mat3 mr = -r;
            Mat3 t;
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j)
                t(i, j) = mr(i, 0) * local(0, j) + mr(i, 1) * local(1, j) + mr(i, 2) * local(2, j);
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j)
                block(i, j) = t(i, 0) * r(j, 0) + t(i, 1) * r(j, 1) + t(i, 2) * r(j, 2);
          }
          sink(elements[e][a], elements[e][b], block);
        }
    }
  }

 private:
  void element_force(std::size_t e, std::span<const Vec3> x, std::span<const Vec3> X0);
  void element_dforce(std::size_t e, std::span<const Vec3> dx);
};

extern template struct ElementFEM<fe::Tetra4>;
extern template struct ElementFEM<fe::Hexa8>;
extern template struct ElementFEM<fe::Prism6>;
extern template struct ElementFEM<fe::Pyramid5>;

}  // namespace sinew::fem
