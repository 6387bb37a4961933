// The packed (several elements per vector) force differential of the
// tetrahedral kernel must give bit-identical results to the plain scalar
// per-element loop kept here as the reference, for every method, thread count,
// element count (not a multiple of the lane count) and after the rotations or
// J changed (add_force with updateStiffnessMatrix).
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <random>

#include "forcefield/fem/tetra_fem.h"

namespace {

using sinew::Mat3;
using sinew::Vec3;
using sinew::fem::TetraFEM;
using M = sinew::fem::TetraMethod;

struct Mesh {
  std::vector<Vec3> x0;
  std::vector<std::array<int, 4>> tetra;
};

Mesh make_mesh(int nx, int ny, int nz, int drop) {
  Mesh m;
  auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) m.x0.emplace_back(0.5 * i, 0.5 * j + 0.01 * i, 0.5 * k);
  const int split[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        int c[8];
        for (int b = 0; b < 8; ++b) c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        for (const auto& s : split) m.tetra.push_back({c[s[0]], c[s[1]], c[s[2]], c[s[3]]});
      }
  m.tetra.resize(m.tetra.size() - drop);
  return m;
}

// Reference: SOFA's addDForce, one element after the other (the loop the
// packed path replaces), from the kernel's J, K and rot.
void reference_dforce(const TetraFEM& fem, std::span<const Vec3> dx, std::span<Vec3> df, double kfactor) {
  double X[12], F[12];
  for (std::size_t e = 0; e < fem.size(); ++e) {
    const auto& t = fem.tetra[e];
    const Mat3 r = fem.method == M::small ? Mat3::Identity() : fem.rot[e];
    const bool rotated = fem.method != M::small;
    for (int k = 0; k < 4; ++k) {
      const Vec3& v = dx[t[k]];
      if (!rotated) {
        for (int i = 0; i < 3; ++i) X[3 * k + i] = v[i];
      } else {
        X[3 * k + 0] = r(0, 0) * v[0] + r(1, 0) * v[1] + r(2, 0) * v[2];
        X[3 * k + 1] = r(0, 1) * v[0] + r(1, 1) * v[1] + r(2, 1) * v[2];
        X[3 * k + 2] = r(0, 2) * v[0] + r(1, 2) * v[1] + r(2, 2) * v[2];
      }
    }
    sinew::fem::tetra_force_scaled(fem.J[e], fem.K[e], X, kfactor, F);
    for (int k = 0; k < 4; ++k) {
      const double* Fk = F + 3 * k;
      Vec3& o = df[t[k]];
      if (!rotated) {
        o[0] -= Fk[0], o[1] -= Fk[1], o[2] -= Fk[2];
      } else {
        o[0] -= r(0, 0) * Fk[0] + r(0, 1) * Fk[1] + r(0, 2) * Fk[2];
        o[1] -= r(1, 0) * Fk[0] + r(1, 1) * Fk[1] + r(1, 2) * Fk[2];
        o[2] -= r(2, 0) * Fk[0] + r(2, 1) * Fk[1] + r(2, 2) * Fk[2];
      }
    }
  }
}

void check(const Mesh& m, M method, int threads, bool update_stiffness, bool symmetric) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  TetraFEM fem;
  std::vector<double> E(m.tetra.size()), nu(m.tetra.size());
  for (std::size_t e = 0; e < E.size(); ++e) E[e] = 3000.0 + 7.0 * (e % 13), nu[e] = 0.3 + 0.01 * (e % 5);
  fem.init(m.x0, m.tetra, E, nu, method);
  fem.update_stiffness_matrix = update_stiffness;
  fem.symmetric_update = symmetric;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3> dx(m.x0.size()), f(m.x0.size(), Vec3::Zero());
  // dforce before any add_force, then after two different deformations.
  for (int round = 0; round < 3; ++round) {
    if (round > 0) {
      std::vector<Vec3> x = m.x0;
      for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng)) * round;
      fem.add_force(x, f);
    }
    for (const double kfactor : {0.37, -1.25}) {
      for (auto& d : dx) d = Vec3(u(rng), u(rng), u(rng));
      std::vector<Vec3> got(m.x0.size(), Vec3(-1, 0.5, 0)), want = got;
      fem.add_dforce(dx, got, kfactor);
      reference_dforce(fem, dx, want, kfactor);
      for (std::size_t i = 0; i < got.size(); ++i)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(got[i][c], want[i][c]) << "point " << i << " method " << int(method) << " threads " << threads
                                           << " round " << round << " update " << update_stiffness << symmetric;
    }
  }
}

TEST(TetraSimd, DForceBitIdenticalToScalarReference) {
  const Mesh small_mesh = make_mesh(5, 4, 4, 3);  // 213 elements: sequential, tail block of 1
  const Mesh big_mesh = make_mesh(14, 10, 10, 1);  // 6317 elements: parallel above 1 thread
  for (const Mesh* m : {&small_mesh, &big_mesh})
    for (M method : {M::large, M::polar, M::small, M::svd})
      for (int threads : {1, 2}) {
        check(*m, method, threads, false, false);
        check(*m, method, threads, true, false);  // large: J loses its structure → scalar path
        check(*m, method, threads, true, true);
      }
}

// add_stiffness_blocks keeps JKJt between calls and reuses add_force's SR with
// computeGlobalMatrix: the blocks must equal the ones computed from scratch.
void check_blocks(const Mesh& m, M method, bool assembling, bool update_stiffness) {
  TetraFEM fem;
  std::vector<double> E(m.tetra.size(), 2500.0), nu(m.tetra.size(), 0.32);
  fem.init(m.x0, m.tetra, E, nu, method);
  fem.assembling = assembling;
  fem.update_stiffness_matrix = update_stiffness;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3> f(m.x0.size(), Vec3::Zero());
  for (int round = 0; round < 4; ++round) {
    if (round > 0 && round != 2) {  // round 2: two calls without add_force in between
      std::vector<Vec3> x = m.x0;
      for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng)) * round;
      fem.add_force(x, f);
    }
    std::vector<Mat3> got, want;
    fem.add_stiffness_blocks([&](int, int, const Mat3& b) { got.push_back(b); });
    sinew::fem::Mat12 jkjt, S, SR;
    for (std::size_t e = 0; e < fem.size(); ++e) {
      sinew::fem::tetra_jkjt(fem.J[e], fem.K[e], jkjt);
      sinew::fem::tetra_rotated_stiffness(jkjt, method == M::small ? Mat3::Identity() : fem.rot[e], S, SR);
      for (int n1 = 0; n1 < 4; ++n1)
        for (int n2 = 0; n2 < 4; ++n2) {
          Mat3 b;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) b(i, j) = -SR(3 * n1 + i, 3 * n2 + j);
          want.push_back(b);
        }
    }
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t k = 0; k < got.size(); ++k)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          ASSERT_EQ(got[k](i, j), want[k](i, j)) << "block " << k << " method " << int(method) << " round " << round;
  }
}

TEST(TetraSimd, StiffnessBlocksBitIdenticalToScratch) {
  const Mesh mesh = make_mesh(5, 4, 4, 3);
  for (M method : {M::large, M::small, M::polar})
    for (bool assembling : {false, true})
      for (bool upd : {false, true}) check_blocks(mesh, method, assembling, upd);
}

// Packed force of the large method against SOFA's scalar sequence (frame,
// rotated Δ, J·K·Jᵀ·Δ, rotation back), element after element.
TEST(TetraSimd, LargeForceBitIdenticalToScalarReference) {
  for (const Mesh& m : {make_mesh(5, 4, 4, 3), make_mesh(14, 10, 10, 1)})
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      TetraFEM fem, ref;
      std::vector<double> E(m.tetra.size()), nu(m.tetra.size());
      for (std::size_t e = 0; e < E.size(); ++e) E[e] = 3000.0 + 7.0 * (e % 13), nu[e] = 0.3 + 0.01 * (e % 5);
      fem.init(m.x0, m.tetra, E, nu, M::large);
      ref.init(m.x0, m.tetra, E, nu, M::large);
      std::mt19937 rng(13);
      std::uniform_real_distribution<double> u(-0.05, 0.05);
      for (int round = 1; round < 4; ++round) {
        std::vector<Vec3> x = m.x0;
        for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng)) * round;
        if (round == 3) x[m.tetra[0][1]] = x[m.tetra[0][0]];  // degenerate edge: no normalisation
        std::vector<Vec3> got(x.size(), Vec3(1, 2, 3)), want = got;
        fem.add_force(x, got);
        for (std::size_t e = 0; e < ref.size(); ++e) {
          const auto& t = ref.tetra[e];
          const Mat3 R = sinew::fem::tetra_frame_large(x[t[0]], x[t[1]], x[t[2]]);
          Vec3 p[4];
          for (int k = 0; k < 4; ++k)
            for (int i = 0; i < 3; ++i) p[k][i] = R(i, 0) * x[t[k]][0] + R(i, 1) * x[t[k]][1] + R(i, 2) * x[t[k]][2];
          p[1][0] -= p[0][0];
          p[2][0] -= p[0][0];
          p[2][1] -= p[0][1];
          for (int i = 0; i < 3; ++i) p[3][i] -= p[0][i];
          const auto& q = ref.rest[e];
          double D[12] = {0, 0, 0, q[1][0] - p[1][0], 0, 0, q[2][0] - p[2][0], q[2][1] - p[2][1], 0,
                          q[3][0] - p[3][0], q[3][1] - p[3][1], q[3][2] - p[3][2]};
          double F[12];
          sinew::fem::tetra_force(ref.J[e], ref.K[e], D, F);
          for (int k = 0; k < 4; ++k)
            for (int i = 0; i < 3; ++i)
              want[t[k]][i] += R(0, i) * F[3 * k] + R(1, i) * F[3 * k + 1] + R(2, i) * F[3 * k + 2];
          const Mat3 rt = R.transpose();
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) ASSERT_EQ(fem.rot[e](i, j), rt(i, j)) << "rot, element " << e;
        }
        for (std::size_t i = 0; i < got.size(); ++i)
          for (int c = 0; c < 3; ++c)
            ASSERT_EQ(got[i][c], want[i][c]) << "point " << i << " threads " << threads << " round " << round;
      }
    }
}

}  // namespace
