#include "forcefield/hyperelastic/hyperelastic_materials.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace sinew::hyper {

Mat3 Sym3::full() const {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = (*this)(i, j);
  return m;
}

Vec3 mul(const Sym3& s, const Vec3& w) {
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    double a = s(i, 0) * w[0];
    a += s(i, 1) * w[1];
    a += s(i, 2) * w[2];
    r[i] = a;
  }
  return r;
}

bool invert(const Sym3& m, Sym3& out) {
  const double det = m(0, 0) * m(1, 1) * m(2, 2) + m(1, 0) * m(2, 1) * m(0, 2) + m(2, 0) * m(0, 1) * m(1, 2) -
                     m(0, 0) * m(2, 1) * m(1, 2) - m(1, 0) * m(0, 1) * m(2, 2) - m(2, 0) * m(1, 1) * m(0, 2);
  if (-1e-100 <= det && det <= 1e-100) return false;
  out(0, 0) = (m(1, 1) * m(2, 2) - m(2, 1) * m(1, 2)) / det;
  out(1, 0) = (m(1, 2) * m(2, 0) - m(2, 2) * m(1, 0)) / det;
  out(2, 0) = (m(1, 0) * m(2, 1) - m(2, 0) * m(1, 1)) / det;
  out(1, 1) = (m(2, 2) * m(0, 0) - m(0, 2) * m(2, 0)) / det;
  out(2, 1) = (m(2, 0) * m(0, 1) - m(0, 0) * m(2, 1)) / det;
  out(2, 2) = (m(0, 0) * m(1, 1) - m(1, 0) * m(0, 1)) / det;
  return true;
}

namespace {

// Plain 3×3 product with sums left to right (SOFA's Mat/MatSym products).
template <class A, class B>
Mat3 product(const A& a, const B& b) {
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = a(i, 0) * b(0, j);
      s += a(i, 1) * b(1, j);
      s += a(i, 2) * b(2, j);
      r(i, j) = s;
    }
  return r;
}

Sym3 symmetric_part(const Mat3& m) {
  Sym3 w;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i <= j; ++i) w(i, j) = (m(i, j) + m(j, i)) / 2;
  return w;
}

const Sym3 kId = Sym3::identity();

// tr(C²) from the stored values (off-diagonal terms twice).
double trace_c2(const Sym3& C) { return C[0] * C[0] + C[2] * C[2] + C[5] * C[5] + 2 * (C[1] * C[1] + C[3] * C[3] + C[4] * C[4]); }

// Coefficients of the Arruda–Boyce series (λ_m² = 8 in SOFA's expansion).
constexpr double kAB1 = 1.0 / 2.0;
constexpr double kAB2 = 1.0 / 160.0;
constexpr double kAB3 = 11.0 / (1050.0 * 8 * 8);
constexpr double kAB4 = 19.0 / (7000.0 * 8.0 * 8.0 * 8.0);
constexpr double kAB5 = 519.0 / (673750.0 * 8.0 * 8.0 * 8.0 * 8.0);

}  // namespace

Sym3 sandwich(const Sym3& a, const Sym3& h) { return symmetric_part(product(a, product(h, a))); }

double contract(const Sym3& a, const Sym3& h) {
  return h[0] * a[0] + h[2] * a[2] + h[5] * a[5] + 2 * h[1] * a[1] + 2 * h[3] * a[3] + 2 * h[4] * a[4];
}

const std::array<MaterialName, 8>& material_names() {
  static const std::array<MaterialName, 8> names = {{
      {"ArrudaBoyce", true, Material::arruda_boyce, 2, "mu k0"},
      {"StVenantKirchhoff", true, Material::stvenant_kirchhoff, 2, "mu lambda"},
      {"NeoHookean", true, Material::neo_hookean, 2, "mu lambda"},
      {"MooneyRivlin", true, Material::mooney_rivlin, 3, "c1 c2 k0"},
      {"VerondaWestman", true, Material::veronda_westman, 3, "c1 c2 k0"},
      {"Costa", true, Material::costa, 8, "a k0 bff bfs bss bfn bsn bnn"},
      {"Ogden", true, Material::ogden, 3, "mu1 alpha1 k0"},
      {"StableNeoHookean", true, Material::stable_neo_hookean, 2, "mu lambda"},
  }};
  return names;
}

const MaterialName* find_material(std::string_view name) {
  for (const auto& m : material_names())
    if (m.name == name) return &m;
  return nullptr;
}

// ------------------------------------------------------------ St Venant–Kirchhoff
// W = λ/2 (tr E)² + μ tr(E²), E = (C − I)/2.
double stvk_energy(const Strain& s, const double* p) {
  const double mu = p[0], lambda = p[1];
  const double trE = 0.5 * (s.I1 - 3);
  const double trE2 = 0.25 * (trace_c2(s.C) - 2 * s.I1 + 3);
  return 0.5 * lambda * trE * trE + mu * trE2;
}

void stvk_stress(const Strain& s, const double* p, Sym3& S) {
  const double mu = p[0], lambda = p[1];
  const double trE = 0.5 * (s.I1 - 3);
  S = kId * (lambda * trE - mu) + s.C * mu;
}

void stvk_dstress(const Strain&, const double* p, const TangentCache&, const Sym3& H, Sym3& out) {
  const double mu = p[0], lambda = p[1];
  out = kId * (H.trace() * lambda / 2.0) + H * mu;
}

// ------------------------------------------------------------ neo-Hookean (Bonet & Wood)
// W = μ/2 (I1 − 3) − μ ln J + λ/2 (ln J)².
double neo_hookean_energy(const Strain& s, const double* p) {
  const double mu = p[0], lambda = p[1];
  const double lj = std::log(s.J);
  return 0.5 * mu * (s.I1 - 3) - mu * lj + 0.5 * lambda * std::pow(lj, 2);
}

void neo_hookean_stress(const Strain& s, const double* p, Sym3& S) {
  Sym3 ic;
  invert(s.C, ic);
  const double mu = p[0], lambda = p[1];
  S = kId * mu + ic * (lambda * std::log(s.J) - mu);
}

void neo_hookean_dstress(const Strain&, const double* p, const TangentCache& c, const Sym3& H, Sym3& out) {
  const double mu = p[0], lambda = p[1];
  const double tr_hc = contract(c.inv_c, H);
  out = sandwich(c.inv_c, H) * (mu - lambda * c.log_j) + c.inv_c * (lambda * tr_hc / 2);
}

// ------------------------------------------------------------ Arruda–Boyce
// W = μ Σ_i c_i (J^{-2i/3} I1^i − 3^i) + k0/2 (ln J)², i = 1..5.
double arruda_boyce_energy(const Strain& s, const double* p) {
  const double mu = p[0], k0 = p[1], I1 = s.I1, J = s.J;
  const double c[5] = {kAB1, kAB2, kAB3, kAB4, kAB5};
  double w = 0;
  for (int i = 1; i <= 5; ++i) w += c[i - 1] * (std::pow(J, -2.0 * i / 3.0) * std::pow(I1, i) - std::pow(3.0, i));
  const double lj = std::log(J);
  return mu * w + k0 * lj * lj / 2;
}

void arruda_boyce_stress(const Strain& s, const double* p, Sym3& S) {
  Sym3 ic;
  invert(s.C, ic);
  const double I1 = s.I1, J = s.J, mu = p[0], k0 = p[1];
  // Term i: c_i J^{-2i/3} (i I1^{i-1} Id − (i/3) I1^i C⁻¹), written as SOFA groups it.
  const Sym3 t1 = (ic * (-1.0 / 3.0) * I1 + kId) * kAB1 * std::pow(J, -2.0 / 3.0);
  const Sym3 t2 = (ic * (-2.0 / 3.0) * I1 * I1 + kId * 2.0 * I1) * kAB2 * std::pow(J, -4.0 / 3.0);
  const Sym3 t3 = (kId * 3.0 * I1 * I1 - ic * I1 * I1 * I1) * kAB3 * std::pow(J, -2.0);
  const Sym3 t4 = (ic * (-4.0 / 3.0) * std::pow(I1, 4.0) + kId * 4.0 * std::pow(I1, 3.0)) * kAB4 * std::pow(J, -8.0 / 3.0);
  const Sym3 t5 =
      (ic * (-5.0 / 3.0) * std::pow(I1, 5.0) + kId * 5.0 * std::pow(I1, 4.0)) * kAB5 * std::pow(J, -10.0 / 3.0);
  S = (t1 + t2 + t3 + t4 + t5) * 2.0 * mu + ic * k0 * std::log(J);
}

void arruda_boyce_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out) {
  const Sym3& ic = c.inv_c;
  const double I1 = s.I1, mu = p[0], k0 = p[1];
  const double tr_hc = contract(ic, H);  // C⁻¹:H = 2 d(ln J)
  const Sym3 chc = sandwich(ic, H);      // C⁻¹ H C⁻¹ = −dC⁻¹
  const double trH = H[0] + H[2] + H[5];
  // Derivative of each term: d(J^{-2i/3}) = −(i/3) J^{-2i/3} C⁻¹:H, dI1 = tr H, dC⁻¹ = −C⁻¹HC⁻¹.
  const Sym3 d1 = ((ic * (-1.0 / 3.0) * I1 + kId) * (-1.0 / 3.0) * tr_hc - ic * (1.0 / 3.0) * trH +
                   chc * (1.0 / 3.0) * I1) *
                  kAB1 * c.pj[0];
  const Sym3 d2 = ((ic * (-2.0 / 3.0) * I1 * I1 + kId * 2.0 * I1) * (-2.0 / 3.0) * tr_hc -
                   ic * (4.0 / 3.0) * I1 * trH + chc * (2.0 / 3.0) * I1 * I1 + kId * 2.0 * trH) *
                  kAB2 * c.pj[1];
  const Sym3 d3 = ((ic * (-I1) * I1 * I1 + kId * 3.0 * I1 * I1) * (-tr_hc) - ic * 3.0 * I1 * I1 * trH +
                   chc * I1 * I1 * I1 + kId * 6.0 * I1 * trH) *
                  kAB3 * c.pj[2];
  const Sym3 d4 = ((ic * (-4.0 / 3.0) * c.pi4 + kId * 4.0 * c.pi3) * (-4.0 / 3.0) * tr_hc -
                   ic * (16.0 / 3.0) * c.pi3 * trH + chc * (4.0 / 3.0) * c.pi4 +
                   kId * 12.0 * I1 * I1 * trH) *
                  kAB4 * c.pj[3];
  const Sym3 d5 = ((ic * (-5.0 / 3.0) * c.pi5 + kId * 5.0 * c.pi4) * (-5.0 / 3.0) * tr_hc -
                   ic * (25.0 / 3.0) * c.pi4 * trH + chc * (5.0 / 3.0) * c.pi5 +
                   kId * 20.0 * c.pi3 * trH) *
                  kAB5 * c.pj[4];
  out = (d1 + d2 + d3 + d4 + d5) * 2.0 * mu + ic * (k0 / 2.0) * tr_hc - chc * (k0 * c.log_j);
}

// ------------------------------------------------------------ Mooney–Rivlin
// W = c1 (J^{-2/3} I1 − 3) + c2 (J^{-4/3} I2 − 3) + k0/2 (ln J)², I2 = (I1² − tr C²)/2.
// (SOFA's own energy has integer exponents -2/3 = 0; this is the energy of its stress.)
double mooney_rivlin_energy(const Strain& s, const double* p) {
  const double I1 = s.I1, J = s.J;
  const double I2 = (I1 * I1 - trace_c2(s.C)) / 2;
  const double lj = std::log(J);
  return p[0] * (I1 * std::pow(J, -2.0 / 3.0) - 3) + p[1] * (I2 * std::pow(J, -4.0 / 3.0) - 3) + p[2] * lj * lj / 2;
}

void mooney_rivlin_stress(const Strain& s, const double* p, Sym3& S) {
  Sym3 ic;
  invert(s.C, ic);
  const double I1 = s.I1, J = s.J, c1 = p[0], c2 = p[1], k0 = p[2];
  const double I2 = (std::pow(I1, 2.0) - trace_c2(s.C)) / 2;
  S = (ic * -1.0 * I1 / 3.0 + kId) * (2 * c1 * std::pow(J, -2.0 / 3.0)) +
      (ic * -1.0 * 2.0 * I2 / 3.0 + kId * I1 - s.C) * (2 * c2 * std::pow(J, -4.0 / 3.0)) + ic * k0 * std::log(J);
}

void mooney_rivlin_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out) {
  const Sym3& ic = c.inv_c;
  const Sym3& C = s.C;
  const double I1 = s.I1, c1 = p[0], c2 = p[1], k0 = p[2];
  const double I2 = (std::pow(I1, 2.0) - trace_c2(C)) / 2;
  const double tr_ich = contract(ic, H);  // C⁻¹:H
  const Sym3 chc = sandwich(ic, H);
  const double tr_ch = contract(C, H);  // C:H
  const double trH = H[0] + H[2] + H[5];
  out = ((kId - ic * I1 / 3.0) * (-tr_ich) / 3.0 + chc * I1 / 3.0 - ic * trH / 3.0) * 2.0 * c1 * c.pj[0] +
        ((ic * -2.0 * I2 / 3.0 + kId * I1 - C) * -2.0 * tr_ich / 3.0 + chc * 2.0 * I2 / 3.0 -
         ic * 2.0 * (I1 * trH - tr_ch) / 3.0 + kId * trH - H) *
            2.0 * c2 * c.pj[1] +
        ic * tr_ich * k0 / 2.0 - chc * k0 * c.log_j;
}

// ------------------------------------------------------------ Ogden (one term)
// W = μ1/α1² (J^{-α1/3} Σ λ_n^{α1} − 3) + k0/2 (ln J)², λ_n² the eigenvalues of C.
namespace {

struct OgdenSpectral {
  Eigen::Matrix3d evec;
  Eigen::Vector3d eval;
  Sym3 c_pow;  // C^{α/2 − 1}
  Sym3 inv_c;
  double tr_c_pow = 0;  // Σ λ_n^{α}  (= tr C^{α/2})
  double fj = 0;        // J^{-α/3}
  double log_j = 0;
};

bool ogden_spectral(const Strain& s, double alpha, OgdenSpectral& o) {
  o.fj = std::pow(s.J, -alpha / 3.0);
  o.log_j = std::log(s.J);
  Eigen::Matrix3d c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c(i, j) = s.C(i, j);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(c, Eigen::ComputeEigenvectors);
  if (solver.info() != Eigen::Success) return false;
  o.eval = solver.eigenvalues();
  o.evec = solver.eigenvectors();
  const double half = alpha / 2.0;
  o.tr_c_pow = 0;
  for (int n = 0; n < 3; ++n) o.tr_c_pow += std::pow(o.eval[n], half);
  // V·diag(λ^{α/2−1})·Vᵀ as plain products, then symmetrised.
  const double e = half - 1.0;
  Sym3 d;
  d(0, 0) = std::pow(o.eval[0], e);
  d(1, 1) = std::pow(o.eval[1], e);
  d(2, 2) = std::pow(o.eval[2], e);
  const Mat3 vt = o.evec.transpose();
  o.c_pow = symmetric_part(product(o.evec, product(d, vt)));
  invert(s.C, o.inv_c);
  return true;
}

}  // namespace

double ogden_energy(const Strain& s, const double* p) {
  OgdenSpectral o;
  ogden_spectral(s, p[1], o);
  const double mu1 = p[0], alpha1 = p[1], k0 = p[2];
  const double m = mu1 / std::pow(alpha1, 2.0);
  return o.fj * m * o.tr_c_pow - 3.0 * m + k0 * o.log_j * o.log_j / 2.0;
}

void ogden_stress(const Strain& s, const double* p, Sym3& S) {
  OgdenSpectral o;
  if (!ogden_spectral(s, p[1], o)) return;  // SOFA leaves the stress at zero
  const double mu1 = p[0], alpha1 = p[1], k0 = p[2];
  const Sym3 iso = o.c_pow * o.fj * mu1 / alpha1 - o.inv_c * o.fj * mu1 / (3.0 * alpha1) * o.tr_c_pow;
  const Sym3 vol = o.inv_c * k0 * o.log_j;
  S = iso + vol;
}

bool ogden_prepare(const Strain& s, const double* p, TangentCache& c) {
  OgdenSpectral o;
  if (!ogden_spectral(s, p[1], o)) return false;
  const double mu1 = p[0], alpha1 = p[1], k0 = p[2];
  const double h = alpha1 / 2.0;
  const double h1 = h - 1.0, h2 = h - 2.0;
  const auto& V = o.evec;
  const auto& ev = o.eval;
  const Sym3& ca = o.c_pow;
  const Sym3& ic = o.inv_c;
  static constexpr int kPair[6][2] = {{0, 0}, {0, 1}, {1, 1}, {0, 2}, {1, 2}, {2, 2}};
  // Powers of the eigenvalues and the rotation coefficients depend only on the
  // eigen pair: computed once (same values as recomputing them per entry).
  double pw2[3], rot[3][3] = {};
  for (int a = 0; a < 3; ++a) pw2[a] = std::pow(ev[a], h2);
  for (int a = 0; a < 3; ++a) {
    const double pa1 = std::pow(ev[a], h1);
    for (int b = 0; b < 3; ++b) {
      if (b == a) continue;
      // Divided difference of λ^{α/2−1}, or its limit for (numerically) equal eigenvalues.
      const double big = std::max(std::fabs(ev[a]), std::fabs(ev[b]));
      const bool equal = std::fabs(ev[a] - ev[b]) < big * 1e-8;
      rot[a][b] = equal ? h1 * pw2[a] : (pa1 - std::pow(ev[b], h1)) / (ev[a] - ev[b]);
    }
  }
  double T[6][6] = {};
  for (int m = 0; m < 6; ++m) {
    const int i = kPair[m][0], j = kPair[m][1];
    for (int n = 0; n < 6; ++n) {
      const int k = kPair[n][0], l = kPair[n][1];
      // ∂C^{α/2−1}/∂C by the spectral decomposition: eigenvalue variations, then
      // eigenvector rotations.
      for (int a = 0; a < 3; ++a) {
        T[m][n] += o.fj * mu1 / alpha1 * h1 * pw2[a] * V(i, a) * V(j, a) * V(k, a) * V(l, a);
        for (int b = 0; b < 3; ++b) {
          if (b == a) continue;
          T[m][n] += 0.5 * o.fj * mu1 / alpha1 * rot[a][b] *
                     (V(i, a) * V(j, b) * V(k, b) * V(l, a) + V(i, a) * V(j, b) * V(k, a) * V(l, b));
        }
      }
      // Derivatives of J^{-α/3}, of tr C^{α/2} and of C⁻¹ in the isochoric stress.
      T[m][n] += -o.fj * mu1 / 6.0 * (ca(i, j) * ic(l, k) + ca(k, l) * ic(j, i)) +
                 o.fj * mu1 * o.tr_c_pow / 18.0 * ic(j, i) * ic(l, k) +
                 o.fj * mu1 / (6.0 * alpha1) * o.tr_c_pow * (ic(k, i) * ic(l, j) + ic(l, i) * ic(k, j));
      // Volumetric stress k0 ln J C⁻¹.
      T[m][n] += 0.5 * k0 * ic(j, i) * ic(l, k) - 0.5 * k0 * o.log_j * (ic(j, k) * ic(l, i) + ic(j, l) * ic(k, i));
    }
  }
  // SOFA's tensor is 2T with off-diagonal columns doubled (H is stored once),
  // and applying it halves the product again.
  for (int m = 0; m < 6; ++m)
    for (int n = 0; n < 6; ++n) {
      double t = 2.0 * T[m][n];
      if (n == 1 || n == 3 || n == 4) t *= 2.0;
      c.ogden[m][n] = t;
    }
  return true;
}

void ogden_dstress(const Strain&, const double*, const TangentCache& c, const Sym3& H, Sym3& out) {
  for (int m = 0; m < 6; ++m) {
    double r = c.ogden[m][0] * H[0];
    for (int n = 1; n < 6; ++n) r += c.ogden[m][n] * H[n];
    out[m] = r / 2.0;
  }
}

// ------------------------------------------------------------ Veronda–Westman
double veronda_westman_energy(const Strain& s, const double* p) {
  const double I1 = s.I1, J = s.J, c1 = p[0], c2 = p[1], k0 = p[2];
  const double I2 = (std::pow(I1, 2.0) - trace_c2(s.C)) / 2;
  return c1 * (std::exp(c2 * (std::pow(J, -2.0 / 3.0) * I1 - 3)) - 1) -
         c1 * c2 * (std::pow(J, -4.0 / 3.0) * I2 - 3) / 2 + k0 * std::log(J) * std::log(J) / 2;
}

void veronda_westman_stress(const Strain& s, const double* p, Sym3& S) {
  Sym3 ic;
  invert(s.C, ic);
  const double I1 = s.I1, J = s.J, c1 = p[0], c2 = p[1], k0 = p[2];
  const double I2 = (std::pow(I1, 2.0) - trace_c2(s.C)) / 2;
  // Exponential isochoric I1 term, then the (negative) I2 term that cancels
  // the initial shear stiffness excess, then the volumetric term.
  S = (kId - ic * I1 / 3.0) * 2.0 * c1 * c2 * std::pow(J, -2.0 / 3.0) *
          std::exp(c2 * (std::pow(J, -2.0 / 3.0) * I1 - 3)) +
      (kId * I1 - s.C - ic * I2 * 2.0 / 3.0) * (-c1 * c2 * std::pow(J, -4.0 / 3.0)) + ic * k0 * std::log(J);
}

void veronda_westman_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out) {
  const Sym3& ic = c.inv_c;
  const Sym3& C = s.C;
  const double I1 = s.I1, I2 = c.i2, c1 = p[0], c2 = p[1], k0 = p[2];
  const double tr_ich = contract(ic, H);  // C⁻¹:H
  const Sym3 chc = sandwich(ic, H);       // C⁻¹HC⁻¹
  const double tr_ch = contract(C, H);    // C:H
  const double trH = H[0] + H[2] + H[5];
  // Three parts: the exponential term at fixed exponent, the variation of its
  // exponent, and the I2 term; then the volumetric term.
  out = (ic * I1 * tr_ich / 9.0 - ic * trH / 3.0 + chc / 3.0 * I1 - kId * tr_ich / 3.0) * 2.0 * c1 * c2 * c.pj[0] *
            c.ex +
        (kId - ic * I1 / 3.0) * c.ex * 2.0 * c1 * c2 * c2 * c.pj[1] * (-I1 * tr_ich / 3.0 + trH) +
        (ic * -4.0 * tr_ich * I2 / 9.0 + ic * 2.0 * I1 * trH / 3.0 - ic * 2.0 * tr_ch / 3.0 - chc * 2.0 * I2 / 3.0 +
         kId * tr_ich * I1 * (2.0 / 3.0) - kId * trH - C * tr_ich * (2.0 / 3.0) + H) *
            c1 * c2 * c.pj[1] +
        chc * -k0 * c.log_j + ic * k0 * tr_ich / 2.0;
}

// ------------------------------------------------------------ Costa
namespace {

// E = (C − I)/2, Q = Σ b_ij E_ij² and U∘E (each stored entry of E times its b).
void costa_strain(const Strain& s, const double* p, double& Q, Sym3& ue) {
  const double bff = p[2], bfs = p[3], bss = p[4], bfn = p[5], bsn = p[6], bnn = p[7];
  const Sym3 E = (s.C - kId) / 2.0;
  Q = bff * E[0] * E[0] + 2 * bfs * E[1] * E[1] + bss * E[2] * E[2] + 2 * bfn * E[3] * E[3] +
      2 * bsn * E[4] * E[4] + bnn * E[5] * E[5];
  ue = Sym3{{bff * E[0], bfs * E[1], bss * E[2], bfn * E[3], bsn * E[4], bnn * E[5]}};
}

}  // namespace

double costa_energy(const Strain& s, const double* p) {
  const double a = p[0], k0 = p[1], J = s.J;
  double Q;
  Sym3 ue;
  costa_strain(s, p, Q, ue);
  const double qbar = std::pow(J, -4.0 / 3.0) * Q;
  return a * (std::exp(qbar) - 1) / 2 + k0 * (J * std::log(J) - J - 1);
}

void costa_stress(const Strain& s, const double* p, Sym3& S) {
  Sym3 ic;
  invert(s.C, ic);
  const double a = p[0], k0 = p[1], J = s.J;
  double Q;
  Sym3 ue;
  costa_strain(s, p, Q, ue);
  const double qbar = std::pow(J, -4.0 / 3.0) * Q;
  S = (ue - ic * (2.0 / 3.0) * Q) * (a * std::exp(qbar) * std::pow(J, -4.0 / 3.0)) + ic * k0 * J * std::log(J);
}

// SOFA's tangent drops k0 from the −J ln J C⁻¹HC⁻¹ volumetric term; kept so
// that results match SOFA (exact derivative of the stress only when k0 = 1).
void costa_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out) {
  const Sym3& ic = c.inv_c;
  const double a = p[0], k0 = p[1], J = s.J, Q = c.q;
  const double bff = p[2], bfs = p[3], bss = p[4], bfn = p[5], bsn = p[6], bnn = p[7];
  const Sym3 uh{{bff * H[0], bfs * H[1], bss * H[2], bfn * H[3], bsn * H[4], bnn * H[5]}};
  const double tr_hue = contract(c.ue, H);  // dQ = (U∘E):H
  const double tr_ich = contract(ic, H);    // C⁻¹:H
  const Sym3 chc = sandwich(ic, H);
  out = ((c.ue - ic * (2.0 / 3.0) * Q) * ((-2.0 / 3.0) * tr_ich) + uh / 2.0 + chc * (2.0 / 3.0) * Q -
         ic * (2.0 / 3.0) * tr_hue) *
            (a * c.pj[1] * c.ex) +
        (c.ue - ic * (2.0 / 3.0) * Q) * (a * c.pj[3] * (tr_hue - (2.0 / 3.0) * Q * tr_ich) * c.ex) +
        ic * k0 / 2.0 * J * (c.log_j + 1) * tr_ich - chc * J * c.log_j;
}

// ------------------------------------------------------------ stable neo-Hookean
double stable_neo_hookean_energy(const Strain& s, const double* p) {
  const double mu = p[0], lambda = p[1];
  const double alpha = 1 + mu / (lambda + mu);  // makes the rest state stress free
  return 0.5 * (mu * (s.I1 - 3) + (lambda + mu) * std::pow(s.J - alpha, 2));
}

void stable_neo_hookean_stress(const Strain& s, const double* p, Sym3& S) {
  Sym3 ic;
  invert(s.C, ic);
  const double mu = p[0], lambda = p[1], J = s.J;
  const double alpha = 1 + mu / (lambda + mu);
  S = kId * mu + ic * ((lambda + mu) * J * (J - alpha));
}

void stable_neo_hookean_dstress(const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out) {
  const Sym3& ic = c.inv_c;
  const double mu = p[0], lambda = p[1], J = s.J;
  const double alpha = 1 + mu / (lambda + mu);
  const double tr_ich = contract(ic, H);
  const Sym3 chc = sandwich(ic, H);
  out = (chc * (-2 * J * (J - alpha)) + ic * (J * (2 * J - alpha) * tr_ich)) * (0.5 * (lambda + mu));
}

bool prepare_tangent(Material m, const Strain& s, const double* p, TangentCache& c) {
  if (m == Material::stvenant_kirchhoff) return true;
  // A singular C (J = 0, reachable only by the stable neo-Hookean, which keeps
  // such elements) leaves a zero inverse rather than the previous element's.
  c.inv_c = Sym3{};
  invert(s.C, c.inv_c);
  if (m == Material::stable_neo_hookean) return true;
  c.log_j = std::log(s.J);
  // The same powers SOFA recomputes at each application of the tensor.
  if (m == Material::arruda_boyce || m == Material::mooney_rivlin || m == Material::veronda_westman ||
      m == Material::costa) {
    c.pj[0] = std::pow(s.J, -2.0 / 3.0);
    c.pj[1] = std::pow(s.J, -4.0 / 3.0);
  }
  if (m == Material::veronda_westman) {
    c.i2 = (std::pow(s.I1, 2.0) - trace_c2(s.C)) / 2;
    c.ex = std::exp(p[1] * (s.I1 * c.pj[0] - 3.0));
  }
  if (m == Material::costa) {
    c.pj[3] = std::pow(s.J, -8.0 / 3.0);
    costa_strain(s, p, c.q, c.ue);
    c.ex = std::exp(std::pow(s.J, -4.0 / 3.0) * c.q);
  }
  if (m == Material::arruda_boyce) {
    c.pj[2] = std::pow(s.J, -2.0);
    c.pj[3] = std::pow(s.J, -8.0 / 3.0);
    c.pj[4] = std::pow(s.J, -10.0 / 3.0);
    c.pi3 = std::pow(s.I1, 3.0);
    c.pi4 = std::pow(s.I1, 4.0);
    c.pi5 = std::pow(s.I1, 5.0);
  }
  if (m == Material::ogden) return ogden_prepare(s, p, c);
  return true;
}

}  // namespace sinew::hyper
