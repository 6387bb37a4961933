// Hyperelastic materials of SOFA's TetrahedronHyperelasticityFEMForceField
// (spec/mechanics.md §2.8), as plain free functions per material:
//   energy  W(C)          strain energy density (not used by SOFA, for tests)
//   stress  S = 2 ∂W/∂C   second Piola–Kirchhoff stress
//   dstress dS = ∂S/∂C : H  for a symmetric variation H of C (SOFA's
//                         applyElasticityTensor)
// The tangent needs quantities that only depend on C (C⁻¹, ln J, Ogden's
// spectral tensor); they are gathered once per element in a TangentCache by
// `prepare`, then dstress is applied 18 times per element.
//
// Every expression keeps SOFA's evaluation order (element-wise operations on
// the 6 stored values, left to right) so that results agree to round-off.
#pragma once

#include <array>
#include <string_view>

#include "math/types.h"

namespace sinew::hyper {

// Symmetric 3×3 matrix stored as SOFA's MatSym: (0,0) (0,1) (1,1) (0,2) (1,2) (2,2).
struct Sym3 {
  std::array<double, 6> v{};

  static constexpr int index(int i, int j) { return i >= j ? i * (i + 1) / 2 + j : j * (j + 1) / 2 + i; }
  double operator()(int i, int j) const { return v[index(i, j)]; }
  double& operator()(int i, int j) { return v[index(i, j)]; }
  double operator[](int k) const { return v[k]; }
  double& operator[](int k) { return v[k]; }
  static Sym3 identity() { return Sym3{{1, 0, 1, 0, 0, 1}}; }
  double trace() const { return v[0] + v[2] + v[5]; }
  Mat3 full() const;
};
inline Sym3 operator+(const Sym3& a, const Sym3& b) {
  Sym3 r;
  for (int k = 0; k < 6; ++k) r.v[k] = a.v[k] + b.v[k];
  return r;
}
inline Sym3 operator-(const Sym3& a, const Sym3& b) {
  Sym3 r;
  for (int k = 0; k < 6; ++k) r.v[k] = a.v[k] - b.v[k];
  return r;
}
inline Sym3 operator*(const Sym3& a, double f) {
  Sym3 r;
  for (int k = 0; k < 6; ++k) r.v[k] = a.v[k] * f;
  return r;
}
inline Sym3 operator/(const Sym3& a, double f) {
  Sym3 r;
  for (int k = 0; k < 6; ++k) r.v[k] = a.v[k] / f;
  return r;
}

// S·w with each row summed left to right.
Vec3 mul(const Sym3& s, const Vec3& w);
// SOFA's closed-form inverse (cofactors over the determinant); false when |det| <= 1e-100
// (then `out` is left unchanged, as SOFA does).
bool invert(const Sym3& m, Sym3& out);
// Symmetric part of A·H·A (both symmetric), products evaluated as SOFA's A·(H·A).
Sym3 sandwich(const Sym3& a, const Sym3& h);
// A:H counting off-diagonal entries twice, in SOFA's order.
double contract(const Sym3& a, const Sym3& h);

enum class Material {
  arruda_boyce,
  stvenant_kirchhoff,
  neo_hookean,
  mooney_rivlin,
  veronda_westman,
  costa,
  ogden,
  stable_neo_hookean
};
// Largest ParameterSet (Costa).
inline constexpr int kMaxParams = 8;

// SOFA's option names, in the order of its OptionsGroup.
struct MaterialName {
  std::string_view name;
  bool supported;  // all of SOFA's materials are; kept so a refused one gets a precise error
  Material material;
  int nb_params;  // required ParameterSet size
  std::string_view params;  // meaning of the parameters
};
const std::array<MaterialName, 8>& material_names();
const MaterialName* find_material(std::string_view name);

// Strain state of an element: C = FᵀF, J = det F, I1 = tr C.
struct Strain {
  Sym3 C;
  double J = 1, I1 = 3;
};

// Quantities of the tangent depending only on C (computed once per element).
struct TangentCache {
  Sym3 inv_c;
  double log_j = 0;
  // Powers of J and I1 used by the tangent (Arruda–Boyce, Mooney–Rivlin):
  // J^{-2/3}, J^{-4/3}, J^{-2}, J^{-8/3}, J^{-10/3}, I1³, I1⁴, I1⁵.
  double pj[5] = {}, pi3 = 0, pi4 = 0, pi5 = 0;
  double ogden[6][6] = {};  // Ogden: elasticity tensor acting on stored H values (already halved)
  // Veronda–Westman: ex = exp(c2 (J^{-2/3} I1 − 3)), i2 = I2.
  // Costa: ex = exp(Q̄), q = Q, ue = the stiffness-weighted Green strain U∘E.
  double ex = 0, i2 = 0, q = 0;
  Sym3 ue;
};

// ---- per material (p = ParameterSet)
// St Venant–Kirchhoff: μ = p0, λ = p1.
double stvk_energy(const Strain& s, const double* p);
void stvk_stress(const Strain& s, const double* p, Sym3& S);
void stvk_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);

// Compressible neo-Hookean: μ = p0, λ = p1.
double neo_hookean_energy(const Strain& s, const double* p);
void neo_hookean_stress(const Strain& s, const double* p, Sym3& S);
void neo_hookean_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);

// Arruda–Boyce (5-term series): μ = p0, bulk k0 = p1.
double arruda_boyce_energy(const Strain& s, const double* p);
void arruda_boyce_stress(const Strain& s, const double* p, Sym3& S);
void arruda_boyce_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);

// Mooney–Rivlin: c1 = p0, c2 = p1, bulk k0 = p2.
double mooney_rivlin_energy(const Strain& s, const double* p);
void mooney_rivlin_stress(const Strain& s, const double* p, Sym3& S);
void mooney_rivlin_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);

// One-term Ogden: μ1 = p0, α1 = p1, bulk k0 = p2.
double ogden_energy(const Strain& s, const double* p);
void ogden_stress(const Strain& s, const double* p, Sym3& S);
void ogden_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);
// Fills c.ogden (the spectral elasticity tensor); false when the eigen solver fails.
bool ogden_prepare(const Strain& s, const double* p, TangentCache& c);

// Veronda–Westman: c1 = p0, c2 = p1, bulk k0 = p2.
// W = c1 (exp(c2 (J^{-2/3} I1 − 3)) − 1) − c1 c2/2 (J^{-4/3} I2 − 3) + k0/2 (ln J)².
double veronda_westman_energy(const Strain& s, const double* p);
void veronda_westman_stress(const Strain& s, const double* p, Sym3& S);
void veronda_westman_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);

// Costa (orthotropic exponential, fibre/sheet/normal axes = global x/y/z as in
// SOFA): a = p0, bulk k0 = p1, b_ff b_fs b_ss b_fn b_sn b_nn = p2..p7.
// E = (C − I)/2, Q = Σ b_ij E_ij² (off-diagonal terms twice), Q̄ = J^{-4/3} Q,
// W = a/2 (exp(Q̄) − 1) + k0 (J ln J − J − 1).
double costa_energy(const Strain& s, const double* p);
void costa_stress(const Strain& s, const double* p, Sym3& S);
void costa_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);

// Stable neo-Hookean (Smith, de Goes, Kim 2018): μ = p0, λ = p1, α = 1 + μ/(λ + μ).
// W = ½ (μ (I1 − 3) + (λ + μ)(J − α)²); needs no ln J, so inverted elements keep their force.
double stable_neo_hookean_energy(const Strain& s, const double* p);
void stable_neo_hookean_stress(const Strain& s, const double* p, Sym3& S);
void stable_neo_hookean_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out);

// Fills the cache for any material (inverse of C, ln J, powers of J, Ogden's tensor).
bool prepare_tangent(Material m, const Strain& s, const double* p, TangentCache& c);

}  // namespace sinew::hyper
