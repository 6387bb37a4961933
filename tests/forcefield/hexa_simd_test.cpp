// HexaFEM::add_dforce (stiffnesses shared between bitwise-equal elements,
// register-blocked and runtime-dispatched K·x product) must give bit-identical
// results to the plain scalar per-element loop kept here as the reference.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <random>

#include "forcefield/fem/hexa_fem.h"

namespace {

using sinew::Mat3;
using sinew::Vec3;
using sinew::fem::HexaFEM;
using HM = sinew::fem::HexaMethod;

struct Grid {
  std::vector<Vec3> x0;
  std::vector<std::array<int, 8>> hexa;
};

// Spacing 16/39 as in the benchmark beams (round-off makes a few dozen
// distinct element stiffnesses); `jitter` makes every element different.
Grid make_grid(int nx, int ny, int nz, double jitter) {
  Grid g;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  const double h = 16.0 / 39.0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        g.x0.emplace_back(h * i + jitter * u(rng), 6 + h * j + jitter * u(rng), -2 + h * k + jitter * u(rng));
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
        g.hexa.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                          id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return g;
}

void reference_dforce(const HexaFEM& fem, std::span<const Vec3> dx, std::span<Vec3> df, double kfactor) {
  const bool rotate = fem.method != HM::small;
  for (std::size_t e = 0; e < fem.size(); ++e) {
    if (!fem.active[e]) continue;
    const auto& h = fem.hexa[e];
    const Mat3& R = fem.R[e];
    double X[24], F[24];
    for (int k = 0; k < 8; ++k) {
      const Vec3& v = dx[h[k]];
      for (int i = 0; i < 3; ++i)
        X[3 * k + i] = rotate ? R(i, 0) * v[0] + R(i, 1) * v[1] + R(i, 2) * v[2] : v[i];
    }
    const double* K = fem.K[e].data();  // column-major 24×24
    for (int i = 0; i < 24; ++i) F[i] = K[i] * X[0];
    for (int c = 1; c < 24; ++c)
      for (int i = 0; i < 24; ++i) F[i] += K[24 * c + i] * X[c];
    for (int k = 0; k < 8; ++k) {
      const double* f = F + 3 * k;
      for (int i = 0; i < 3; ++i) {
        const double t = rotate ? R(0, i) * f[0] + R(1, i) * f[1] + R(2, i) * f[2] : f[i];
        df[h[k]][i] -= t * kfactor;
      }
    }
  }
}

void check(const Grid& g, HM method, int threads, bool update_stiffness, bool expect_shared) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  HexaFEM fem;
  std::vector<double> E(g.hexa.size(), 2000.0), nu(g.hexa.size(), 0.3);
  ASSERT_TRUE(fem.init(g.x0, g.hexa, E, nu, method).empty());
  fem.update_stiffness = update_stiffness;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3> dx(g.x0.size()), f(g.x0.size(), Vec3::Zero());
  for (int round = 0; round < 3; ++round) {
    if (round > 0) {
      std::vector<Vec3> x = g.x0;
      for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng)) * round;
      fem.add_force(x, f);
    }
    for (const double kfactor : {0.37, -1.25}) {
      for (auto& d : dx) d = Vec3(u(rng), u(rng), u(rng));
      std::vector<Vec3> got(g.x0.size(), Vec3(-1, 0.5, 0)), want = got;
      fem.add_dforce(dx, got, kfactor);
      if (!update_stiffness) {
        EXPECT_EQ(fem.shares_stiffness(), expect_shared);
      }
      reference_dforce(fem, dx, want, kfactor);
      for (std::size_t i = 0; i < got.size(); ++i)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(got[i][c], want[i][c]) << "point " << i << " method " << int(method) << " threads " << threads
                                           << " round " << round << " update " << update_stiffness;
    }
  }
}

TEST(HexaSimd, DForceBitIdenticalToScalarReference) {
  const Grid regular = make_grid(20, 12, 12, 0.0);   // 2299 elements, shared stiffnesses
  const Grid jittered = make_grid(9, 6, 5, 0.02);    // all stiffnesses distinct
  for (const Grid* g : {&regular, &jittered})
    for (HM m : {HM::large, HM::polar, HM::small})
      for (int threads : {1, 2})
        for (bool upd : {false, true}) check(*g, m, threads, upd, g == &regular);
}

}  // namespace
