// Numerical kernel of SOFA's TetrahedronHyperelasticityFEMForceField
// (spec/mechanics.md §2.8): linear tetrahedra, total Lagrangian, one
// hyperelastic material (forcefield/hyperelastic_materials.h) for all elements.
//
// add_force stores each element's deformation gradient F, C = FᵀF, J and the
// stress S; the tangent is then rebuilt lazily (at the next add_dforce or
// stiffness request) as one 3×3 block B_e per topology edge, exactly as SOFA
// keeps it, so that add_dforce is a loop over edges:
//   δ = dx_v0 − dx_v1;  df_v0 += k·B_eᵀ·δ;  df_v1 −= k·B_e·δ.
// Nothing here knows about scenes or topologies.
#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "forcefield/hyperelastic/hyperelastic_materials.h"
#include "math/types.h"

namespace sinew::hyper {

// SOFA computes these elements in two force fields that differ in their arithmetic only:
// TetrahedronHyperelasticityFEMForceField takes f_l = −V·F·S·s_l and the tangent through the
// material's applyElasticityTensor; StandardTetrahedralFEMForceField takes f_l = −V·B_lᵀ·S with
// the 6×3 strain-displacement matrices B_l and the tangent through the 6×6 elasticity tensor
// (forcefield/hyperelastic/elasticity_tensor.h).
enum class Formulation { hyperelasticity, standard };

class TetraHyperelasticity {
 public:
  struct Issue {
    int element;  // -1: not tied to an element
    std::string message;
  };

  // Builds the rest information. `edges_in_tet[i][j]` is the index in `edges`
  // of local edge j ({0,1},{0,2},{0,3},{1,2},{1,3},{2,3}) of tetrahedron i.
  // Degenerate elements (zero rest volume) are reported and make init fail.
  std::vector<Issue> init(std::span<const Vec3> rest, const std::vector<std::array<unsigned, 4>>& tets,
                          const std::vector<std::array<unsigned, 2>>& edges,
                          const std::vector<std::array<unsigned, 6>>& edges_in_tet, Material material,
                          const std::vector<double>& params, Formulation form = Formulation::hyperelasticity);

  // f += forces at x. Elements with J <= 0 (inverted or flat) are skipped for
  // materials that need ln J (all but StVenantKirchhoff and StableNeoHookean);
  // the first one is kept in bad_element().
  void add_force(std::span<const Vec3> x, std::span<Vec3> f);
  // df += k·K·dx with K = ∂f/∂x at the positions of the last add_force.
  void add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double k);
  // Raw blocks of K = ∂f/∂x (point i, point j, 3×3), edge by edge as SOFA.
  template <class Sink>
  void stiffness_blocks(Sink&& sink) {
    if (dirty_) update_tangent();
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      const Mat3& B = dfdx_[e];
      const unsigned a = edges_[e][0], b = edges_[e][1];
      const Mat3 Bt = B.transpose();
      sink(a, a, Bt);
      sink(a, b, Mat3(-Bt));
      sink(b, a, Mat3(-B));
      sink(b, b, B);
    }
  }
  // Total strain energy at x (Σ V0·W; SOFA provides none, used by tests).
  double energy(std::span<const Vec3> x) const;

  std::size_t nb_elements() const { return tets_.size(); }
  // First element with J <= 0 met by the last add_force, or -1.
  int bad_element() const { return bad_element_; }
  double bad_j() const { return bad_j_; }

 private:
  struct Rest {
    Vec3 sv[4];  // shape vectors ∇N_j (rest)
    double vol_scale = 0;  // 1 / (6·signed volume)
    double volume = 0;     // |rest volume|
  };
  struct Current {
    Mat3 F;
    Strain strain;
    Sym3 S;
    bool skip = false;
  };
  void deformation(std::size_t i, std::span<const Vec3> x, Current& c, Vec3 dp[3]) const;
  void update_tangent();
  void update_tangent_standard();

  Material material_ = Material::arruda_boyce;
  Formulation form_ = Formulation::hyperelasticity;
  double p_[kMaxParams] = {};
  std::vector<std::array<unsigned, 4>> tets_;
  std::vector<std::array<unsigned, 2>> edges_;
  std::vector<std::array<unsigned, 6>> edges_in_tet_;
  std::vector<Rest> rest_;
  std::vector<Current> cur_;
  std::vector<Mat3> dfdx_;  // per edge
  bool dirty_ = true;
  int bad_element_ = -1;
  double bad_j_ = 0;
};

}  // namespace sinew::hyper
