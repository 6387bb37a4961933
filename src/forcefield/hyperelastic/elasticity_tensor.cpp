#include "forcefield/hyperelastic/elasticity_tensor.h"

#include <cmath>

namespace sinew::hyper {

namespace {

// The 6×6 building blocks of SOFA's closed forms, for C⁻¹ = c and C: rows i and columns j in
// storage order; ID = (1, 0, 1, 0, 0, 1), and X̄ a symmetric tensor with its off-diagonal
// entries doubled (its contraction with a storage direction).
struct Blocks {
  double chc[6][6];  // C⁻¹·H·C⁻¹ for the direction j (SOFA's C_H_C table)
  double a[6][6];    // c_i·c̄_j   (trC_HC_)
  double b[6][6];    // ID_i·c̄_j  (trID_HC_)
  double d[6][6];    // c_i·ID_j   (trC_HID)
  double e[6][6];    // C_i·c̄_j   (trCH_C)
  double g[6][6];    // c_i·C̄_j   (trC_HC)
  double h[6][6];    // ID_i·ID_j  (trIDHID)
  double id[6][6];   // identity   (IDHID)
};

void blocks(const Sym3& c, const Sym3& C, Blocks& B) {
  static constexpr double kId[6] = {1, 0, 1, 0, 0, 1};
  double cc[6], Cd[6];
  for (int k = 0; k < 6; ++k) {
    const bool off = k == 1 || k == 3 || k == 4;
    cc[k] = off ? c[k] + c[k] : c[k];
    Cd[k] = off ? C[k] + C[k] : C[k];
  }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      B.a[i][j] = c[i] * cc[j];
      B.b[i][j] = kId[i] * cc[j];
      B.d[i][j] = c[i] * kId[j];
      B.e[i][j] = C[i] * cc[j];
      B.g[i][j] = c[i] * Cd[j];
      B.h[i][j] = kId[i] * kId[j];
      B.id[i][j] = i == j ? 1.0 : 0.0;
    }
  double (&m)[6][6] = B.chc;
  m[0][0] = c[0] * c[0];
  m[1][1] = c[1] * c[1] + c[0] * c[2];
  m[2][2] = c[2] * c[2];
  m[3][3] = c[3] * c[3] + c[0] * c[5];
  m[4][4] = c[4] * c[4] + c[2] * c[5];
  m[5][5] = c[5] * c[5];
  m[1][0] = c[0] * c[1];
  m[0][1] = 2 * m[1][0];
  m[2][0] = m[0][2] = c[1] * c[1];
  m[5][0] = m[0][5] = c[3] * c[3];
  m[3][0] = c[0] * c[3];
  m[0][3] = 2 * m[3][0];
  m[4][0] = c[1] * c[3];
  m[0][4] = 2 * m[4][0];
  m[1][2] = c[2] * c[1];
  m[2][1] = 2 * m[1][2];
  m[1][5] = c[3] * c[4];
  m[5][1] = 2 * m[1][5];
  m[3][1] = m[1][3] = c[0] * c[4] + c[1] * c[3];
  m[1][4] = m[4][1] = c[1] * c[4] + c[2] * c[3];
  m[3][2] = c[4] * c[1];
  m[2][3] = 2 * m[3][2];
  m[4][2] = c[4] * c[2];
  m[2][4] = 2 * m[4][2];
  m[2][5] = m[5][2] = c[4] * c[4];
  m[3][5] = c[3] * c[5];
  m[5][3] = 2 * m[3][5];
  m[4][3] = m[3][4] = c[3] * c[4] + c[5] * c[1];
  m[4][5] = c[4] * c[5];
  m[5][4] = 2 * m[4][5];
}

void stvk(const double* p, double T[6][6]) {
  const double mu = p[0], lambda = p[1];
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double h = (i == 0 || i == 2 || i == 5) && (j == 0 || j == 2 || j == 5) ? 1.0 : 0.0;
      T[i][j] = lambda * h + (2 * mu) * (i == j ? 1.0 : 0.0);
    }
}

void neo_hookean(const Strain& s, const double* p, const Blocks& B, double T[6][6]) {
  const double mu = p[0], lambda = p[1];
  const double f = mu - lambda * std::log(s.J);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) T[i][j] = B.chc[i][j] * f * 2 + B.a[i][j] * lambda;
}

void mooney_rivlin(const Strain& s, const double* p, const Blocks& B, double T[6][6]) {
  const Sym3& C = s.C;
  const double I1 = s.I1;
  const double I1sq = C[0] * C[0] + C[2] * C[2] + C[5] * C[5] + 2 * (C[1] * C[1] + C[3] * C[3] + C[4] * C[4]);
  const double I2 = (std::pow(I1, 2.0) - I1sq) / 2;
  const double c1 = p[0], c2 = p[1], k0 = p[2];
  const double j23 = std::pow(s.J, -2.0 / 3.0), j43 = std::pow(s.J, -4.0 / 3.0), lj = std::log(s.J);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double a = B.a[i][j], b = B.b[i][j], chc = B.chc[i][j], d = B.d[i][j];
      const double t1 = ((a * I1 / 3.0 - b) / 3.0 + chc * I1 / 3.0 - d / 3.0) * 2.0 * c1 * j23;
      const double t2 = ((a * -2.0 * I2 / 3.0 + b * I1 - B.e[i][j]) * -2.0 / 3.0 + chc * 2.0 * I2 / 3.0 -
                         (d * I1 - B.g[i][j]) * 2.0 / 3.0 + B.h[i][j] - B.id[i][j]) *
                        2.0 * c2 * j43;
      T[i][j] = (t1 + t2 + a * k0 / 2.0 - chc * k0 * lj) * 2.0;
    }
}

void arruda_boyce(const Strain& s, const double* p, const Blocks& B, double T[6][6]) {
  const double I1 = s.I1, mu = p[0], k0 = p[1];
  const double i3 = std::pow(I1, 3.0), i4 = std::pow(I1, 4.0), i5 = std::pow(I1, 5.0);
  const double j23 = std::pow(s.J, -2.0 / 3.0), j43 = std::pow(s.J, -4.0 / 3.0), j2 = std::pow(s.J, -2.0);
  const double j83 = std::pow(s.J, -8.0 / 3.0), j103 = std::pow(s.J, -10.0 / 3.0), lj = std::log(s.J);
  constexpr double k13 = 1.0 / 3.0, k23 = 2.0 / 3.0, k43 = 4.0 / 3.0, k53 = 5.0 / 3.0;
  constexpr double k163 = 16.0 / 3.0, k253 = 25.0 / 3.0;
  // The five terms of the series, with their coefficients 1/2, 1/20, 11/1050, 19/7000,
  // 519/673750 over the powers of 8 of SOFA's λ_m² = 8.
  constexpr double w2 = 1.0 / 160.0, w3 = 11.0 / (1050.0 * 8.0 * 8.0), w4 = 19.0 / (7000.0 * 8.0 * 8.0 * 8.0);
  constexpr double w5 = 519.0 / (673750.0 * 8.0 * 8.0 * 8.0 * 8.0);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double a = B.a[i][j], b = B.b[i][j], chc = B.chc[i][j], d = B.d[i][j], h = B.h[i][j];
      const double t1 = (((a * k13 * I1 - b) * k13 - d * k13 + chc * k13 * I1) * (1.0 / 2.0)) * j23;
      const double t2 =
          (((a * k23 * I1 * I1 - b * 2.0 * I1) * k23 - d * k43 * I1 + chc * k23 * I1 * I1 + h * 2.0) * w2) * j43;
      const double t3 =
          ((a * I1 * I1 * I1 - b * 3.0 * I1 * I1 - d * 3.0 * I1 * I1 + chc * I1 * I1 * I1 + h * 6.0 * I1) * w3) * j2;
      const double t4 =
          (((a * k43 * i4 - b * 4.0 * i3) * k43 - d * k163 * i3 + chc * k43 * i4 + h * 12.0 * I1 * I1) * w4) * j83;
      const double t5 =
          (((a * k53 * i5 - b * 5 * i4) * k53 - d * k253 * i4 + chc * k53 * i5 + h * 20.0 * i3) * w5) * j103;
      T[i][j] = ((t1 + t2 + t3 + t4 + t5) * 2.0 * mu + a * k0 / 2.0 - chc * k0 * lj) * 2.0;
    }
}

}  // namespace

bool elasticity_tensor(Material m, const Strain& s, const double* p, TangentCache& cache, double T[6][6]) {
  if (m == Material::stvenant_kirchhoff) {
    stvk(p, T);
    return true;
  }
  if (m == Material::neo_hookean || m == Material::mooney_rivlin || m == Material::arruda_boyce) {
    Sym3 inv;
    if (!invert(s.C, inv)) return false;
    Blocks B;
    blocks(inv, s.C, B);
    if (m == Material::neo_hookean) neo_hookean(s, p, B, T);
    else if (m == Material::mooney_rivlin) mooney_rivlin(s, p, B, T);
    else arruda_boyce(s, p, B, T);
    return true;
  }
  if (!prepare_tangent(m, s, p, cache)) return false;
  for (int col = 0; col < 6; ++col) {
    Sym3 H, out;
    H[col] = 1.0;
    switch (m) {
      case Material::veronda_westman: veronda_westman_dstress(s, p, cache, H, out); break;
      case Material::costa: costa_dstress(s, p, cache, H, out); break;
      case Material::ogden: ogden_dstress(s, p, cache, H, out); break;
      case Material::stable_neo_hookean: stable_neo_hookean_dstress(s, p, cache, H, out); break;
      default: break;
    }
    for (int row = 0; row < 6; ++row) T[row][col] = 2.0 * out[row];
  }
  return true;
}

}  // namespace sinew::hyper
