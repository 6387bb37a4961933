#include "forcefield/hyperelastic/hyperelastic_tetra.h"

#include <cmath>

#include "forcefield/hyperelastic/elasticity_tensor.h"
#include "math/sofa_vec.h"

namespace sinew::hyper {

namespace {

// Local edges of a tetrahedron, SOFA's order.
constexpr unsigned kLocalEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// StVK and the stable neo-Hookean are defined for J <= 0 (the latter is made for it).
bool needs_log_j(Material m) { return m != Material::stvenant_kirchhoff && m != Material::stable_neo_hookean; }

void stress(Material m, const Strain& s, const double* p, Sym3& S) {
  switch (m) {
    case Material::arruda_boyce: arruda_boyce_stress(s, p, S); break;
    case Material::stvenant_kirchhoff: stvk_stress(s, p, S); break;
    case Material::neo_hookean: neo_hookean_stress(s, p, S); break;
    case Material::mooney_rivlin: mooney_rivlin_stress(s, p, S); break;
    case Material::veronda_westman: veronda_westman_stress(s, p, S); break;
    case Material::costa: costa_stress(s, p, S); break;
    case Material::ogden: ogden_stress(s, p, S); break;
    case Material::stable_neo_hookean: stable_neo_hookean_stress(s, p, S); break;
  }
}

void dstress(Material m, const Strain& s, const double* p, const TangentCache& c, const Sym3& H, Sym3& out) {
  switch (m) {
    case Material::arruda_boyce: arruda_boyce_dstress(s, p, c, H, out); break;
    case Material::stvenant_kirchhoff: stvk_dstress(s, p, c, H, out); break;
    case Material::neo_hookean: neo_hookean_dstress(s, p, c, H, out); break;
    case Material::mooney_rivlin: mooney_rivlin_dstress(s, p, c, H, out); break;
    case Material::veronda_westman: veronda_westman_dstress(s, p, c, H, out); break;
    case Material::costa: costa_dstress(s, p, c, H, out); break;
    case Material::ogden: ogden_dstress(s, p, c, H, out); break;
    case Material::stable_neo_hookean: stable_neo_hookean_dstress(s, p, c, H, out); break;
  }
}

// SOFA's strain-displacement matrix of a vertex with shape vector s (6×3, rows in the storage
// order of C: 00, 01, 11, 02, 12, 22): δC = Σ_a B_a·δx_a, shear rows counting both terms.
void strain_displacement(const Mat3& F, const Vec3& s, double B[6][3]) {
  for (int c = 0; c < 3; ++c) {
    B[0][c] = F(c, 0) * s[0];
    B[2][c] = F(c, 1) * s[1];
    B[5][c] = F(c, 2) * s[2];
    B[1][c] = F(c, 0) * s[1] + F(c, 1) * s[0];
    B[3][c] = F(c, 2) * s[0] + F(c, 0) * s[2];
    B[4][c] = F(c, 1) * s[2] + F(c, 2) * s[1];
  }
}

double energy_density(Material m, const Strain& s, const double* p) {
  switch (m) {
    case Material::arruda_boyce: return arruda_boyce_energy(s, p);
    case Material::stvenant_kirchhoff: return stvk_energy(s, p);
    case Material::neo_hookean: return neo_hookean_energy(s, p);
    case Material::mooney_rivlin: return mooney_rivlin_energy(s, p);
    case Material::veronda_westman: return veronda_westman_energy(s, p);
    case Material::costa: return costa_energy(s, p);
    case Material::ogden: return ogden_energy(s, p);
    case Material::stable_neo_hookean: return stable_neo_hookean_energy(s, p);
  }
  return 0;
}

}  // namespace

std::vector<TetraHyperelasticity::Issue> TetraHyperelasticity::init(
    std::span<const Vec3> rest, const std::vector<std::array<unsigned, 4>>& tets,
    const std::vector<std::array<unsigned, 2>>& edges, const std::vector<std::array<unsigned, 6>>& edges_in_tet,
    Material material, const std::vector<double>& params, Formulation form) {
  std::vector<Issue> issues;
  material_ = material;
  form_ = form;
  for (int k = 0; k < kMaxParams; ++k) p_[k] = k < static_cast<int>(params.size()) ? params[k] : 0.0;
  tets_ = tets;
  edges_ = edges;
  edges_in_tet_ = edges_in_tet;
  rest_.assign(tets.size(), Rest{});
  cur_.assign(tets.size(), Current{});
  dfdx_.assign(edges.size(), Mat3::Zero());
  dirty_ = true;
  bad_element_ = -1;
  if (edges_in_tet.size() != tets.size()) {
    issues.push_back({-1, "the topology gives no edges for the tetrahedra"});
    return issues;
  }
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const auto& t = tets[i];
    bool ok = true;
    for (unsigned v : t)
      if (v >= rest.size()) {
        issues.push_back({static_cast<int>(i), "uses point " + std::to_string(v) + " but the state has " +
                                                   std::to_string(rest.size()) + " points"});
        ok = false;
        break;
      }
    for (int j = 0; j < 6 && ok; ++j) {
      const unsigned e = edges_in_tet[i][j];
      const unsigned a = t[kLocalEdges[j][0]], b = t[kLocalEdges[j][1]];
      if (e >= edges.size() || !((edges[e][0] == a && edges[e][1] == b) || (edges[e][0] == b && edges[e][1] == a))) {
        issues.push_back({static_cast<int>(i), "edge (" + std::to_string(a) + ", " + std::to_string(b) +
                                                   ") is missing from the topology's edge list"});
        ok = false;
      }
    }
    if (!ok) continue;
    Vec3 p[4];
    for (int j = 0; j < 4; ++j) p[j] = rest[t[j]];
    const double vol6 = sofa_dot(sofa_cross(p[2] - p[0], p[3] - p[0]), p[1] - p[0]);
    if (vol6 == 0 || !std::isfinite(vol6)) {
      issues.push_back({static_cast<int>(i), "degenerate tetrahedron (" + std::to_string(t[0]) + ", " +
                                                 std::to_string(t[1]) + ", " + std::to_string(t[2]) + ", " +
                                                 std::to_string(t[3]) + "): zero rest volume"});
      continue;
    }
    Rest& r = rest_[i];
    r.vol_scale = 1.0 / vol6;
    r.volume = std::fabs(vol6 / 6);
    for (int j = 0; j < 4; ++j) {
      const double sign = j % 2 ? 1 : -1;
      const Vec3 c = sofa_cross(p[(j + 2) % 4] - p[(j + 1) % 4], p[(j + 3) % 4] - p[(j + 1) % 4]);
      const Vec3 sc(sign * c[0], sign * c[1], sign * c[2]);
      r.sv[j] = Vec3(sc[0] / vol6, sc[1] / vol6, sc[2] / vol6);
    }
  }
  return issues;
}

// F = Σ_{j=1..3} (x_j − x_0) ⊗ s_j, C = FᵀF (upper triangle), J = det F, I1 = tr C.
void TetraHyperelasticity::deformation(std::size_t i, std::span<const Vec3> x, Current& c, Vec3 dp[3]) const {
  const auto& t = tets_[i];
  const Rest& r = rest_[i];
  const Vec3& x0 = x[t[0]];
  Mat3& F = c.F;
  dp[0] = x[t[1]] - x0;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) F(k, l) = dp[0][k] * r.sv[1][l];
  for (int j = 1; j < 3; ++j) {
    dp[j] = x[t[j + 1]] - x0;
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) F(k, l) += dp[j][k] * r.sv[j + 1][l];
  }
  Sym3& C = c.strain.C;
  for (int k = 0; k < 3; ++k)
    for (int l = k; l < 3; ++l) C(k, l) = F(0, k) * F(0, l) + F(1, k) * F(1, l) + F(2, k) * F(2, l);
  c.strain.J = sofa_dot(sofa_cross(dp[1], dp[2]), dp[0]) * r.vol_scale;
  c.strain.I1 = C(0, 0) + C(1, 1) + C(2, 2);
}

void TetraHyperelasticity::add_force(std::span<const Vec3> x, std::span<Vec3> f) {
  bad_element_ = -1;
  const bool log_j = needs_log_j(material_);
  Vec3 dp[3];
  for (std::size_t i = 0; i < tets_.size(); ++i) {
    Current& c = cur_[i];
    deformation(i, x, c, dp);
    c.skip = log_j && !(c.strain.J > 0);
    if (c.skip) {
      if (bad_element_ < 0) {
        bad_element_ = static_cast<int>(i);
        bad_j_ = c.strain.J;
      }
      continue;
    }
    c.S = Sym3{};
    stress(material_, c.strain, p_, c.S);
    const Rest& r = rest_[i];
    const auto& t = tets_[i];
    if (form_ == Formulation::standard) {
      for (int l = 0; l < 4; ++l) {
        double B[6][3];
        strain_displacement(c.F, r.sv[l], B);
        Vec3 fl;
        for (int a = 0; a < 3; ++a) {
          double v = B[0][a] * c.S[0];
          for (int q = 1; q < 6; ++q) v += B[q][a] * c.S[q];
          fl[a] = v;
        }
        f[t[l]] -= Vec3(fl[0] * r.volume, fl[1] * r.volume, fl[2] * r.volume);
      }
      continue;
    }
    for (int l = 0; l < 4; ++l) {
      const Vec3 fl = sofa_mul(c.F, mul(c.S, r.sv[l]));
      f[t[l]] -= Vec3(fl[0] * r.volume, fl[1] * r.volume, fl[2] * r.volume);
    }
  }
  dirty_ = true;
}

void TetraHyperelasticity::update_tangent() {
  if (form_ == Formulation::standard) {
    update_tangent_standard();
    return;
  }
  for (auto& b : dfdx_) b.setZero();
  TangentCache cache;
  Sym3 H[3], out;
  for (std::size_t i = 0; i < tets_.size(); ++i) {
    const Current& c = cur_[i];
    if (c.skip) continue;
    const Rest& r = rest_[i];
    const auto& t = tets_[i];
    const Mat3& F = c.F;
    if (!prepare_tangent(material_, c.strain, p_, cache)) continue;
    for (int j = 0; j < 6; ++j) {
      const unsigned e = edges_in_tet_[i][j];
      int k = kLocalEdges[j][0], l = kLocalEdges[j][1];
      if (edges_[e][0] != t[k]) std::swap(k, l);  // k: the edge's first point
      const Vec3& svl = r.sv[l];
      const Vec3& svk = r.sv[k];
      // H_m = δC for a unit move of point l along axis m: s_l ⊗ F_m + F_m ⊗ s_l (F_m: row m).
      for (int a = 0; a < 3; ++a)
        for (int b = a; b < 3; ++b)
          for (int m = 0; m < 3; ++m) H[m](a, b) = svl[a] * F(m, b) + F(m, a) * svl[b];
      Mat3 N;
      for (int m = 0; m < 3; ++m) {
        dstress(material_, c.strain, p_, cache, H[m], out);
        const Vec3 v = sofa_mul(F, mul(out, svk));
        N(m, 0) = v[0];
        N(m, 1) = v[1];
        N(m, 2) = v[2];
      }
      const double sd = sofa_dot(mul(c.S, svk), svl);  // geometric part s_k·S·s_l
      Mat3& B = dfdx_[e];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) B(a, b) += ((a == b ? sd : 0.0) + N(a, b)) * r.volume;
    }
  }
  dirty_ = false;
}

// SOFA's StandardTetrahedralFEMForceField: per edge (k its first point, l the other)
// DfDx += V·(s_k·S·s_l·I + Nᵀ), N = (B_kᵀ·T)·B̃_l with T the 6×6 elasticity tensor and B̃_l the
// strain-displacement matrix with its shear rows halved.
void TetraHyperelasticity::update_tangent_standard() {
  for (auto& b : dfdx_) b.setZero();
  TangentCache cache;
  for (std::size_t i = 0; i < tets_.size(); ++i) {
    const Current& c = cur_[i];
    if (c.skip) continue;
    const Rest& r = rest_[i];
    const auto& t = tets_[i];
    double T[6][6];
    if (!elasticity_tensor(material_, c.strain, p_, cache, T)) continue;
    double B[4][6][3];
    for (int a = 0; a < 4; ++a) strain_displacement(c.F, r.sv[a], B[a]);
    for (int j = 0; j < 6; ++j) {
      const unsigned e = edges_in_tet_[i][j];
      int k = kLocalEdges[j][0], l = kLocalEdges[j][1];
      if (edges_[e][0] != t[k]) std::swap(k, l);  // k: the edge's first point
      double Bl[6][3];
      for (int q = 0; q < 6; ++q)
        for (int b = 0; b < 3; ++b) Bl[q][b] = (q == 1 || q == 3 || q == 4) ? B[l][q][b] / 2 : B[l][q][b];
      double P[3][6];  // B_kᵀ·T
      for (int a = 0; a < 3; ++a)
        for (int q = 0; q < 6; ++q) {
          double v = B[k][0][a] * T[0][q];
          for (int m = 1; m < 6; ++m) v += B[k][m][a] * T[m][q];
          P[a][q] = v;
        }
      Mat3 N;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          double v = P[a][0] * Bl[0][b];
          for (int q = 1; q < 6; ++q) v += P[a][q] * Bl[q][b];
          N(a, b) = v;
        }
      const double sd = sofa_dot(mul(c.S, r.sv[k]), r.sv[l]);
      Mat3& D = dfdx_[e];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) D(a, b) += ((a == b ? sd : 0.0) + N(b, a)) * r.volume;
    }
  }
  dirty_ = false;
}

void TetraHyperelasticity::add_dforce(std::span<const Vec3> dx, std::span<Vec3> df, double k) {
  if (dirty_) update_tangent();
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const Mat3& B = dfdx_[e];
    const unsigned v0 = edges_[e][0], v1 = edges_[e][1];
    const Vec3 d = dx[v0] - dx[v1];
    const Vec3 dv0 = sofa_mul(B, d);
    Vec3 dv1;
    for (int i = 0; i < 3; ++i) dv1[i] = d[0] * B(0, i) + d[1] * B(1, i) + d[2] * B(2, i);
    df[v0] += Vec3(dv1[0] * k, dv1[1] * k, dv1[2] * k);
    df[v1] -= Vec3(dv0[0] * k, dv0[1] * k, dv0[2] * k);
  }
}

double TetraHyperelasticity::energy(std::span<const Vec3> x) const {
  double w = 0;
  Current c;
  Vec3 dp[3];
  for (std::size_t i = 0; i < tets_.size(); ++i) {
    deformation(i, x, c, dp);
    if (needs_log_j(material_) && !(c.strain.J > 0)) continue;
    w += rest_[i].volume * energy_density(material_, c.strain, p_);
  }
  return w;
}

}  // namespace sinew::hyper
