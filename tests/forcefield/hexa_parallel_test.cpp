// The parallel evaluation of the hexahedral kernel must give bit-identical
// results to the sequential one, whatever the thread count.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <random>

#include "forcefield/fem/hexa_fem.h"

namespace {

using sinew::Vec3;

struct Grid {
  std::vector<Vec3> x0;
  std::vector<std::array<int, 8>> hexa;
};

Grid make_grid(int nx, int ny, int nz) {
  Grid g;
  auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) g.x0.emplace_back(0.5 * i, 0.5 * j, 0.5 * k);
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
        g.hexa.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                          id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return g;
}

struct Result {
  std::vector<Vec3> f, df;
};

Result evaluate(const Grid& g, sinew::fem::HexaMethod m, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  sinew::fem::HexaFEM fem;
  std::vector<double> E(g.hexa.size(), 3000.0), nu(g.hexa.size(), 0.35);
  EXPECT_TRUE(fem.init(g.x0, g.hexa, E, nu, m).empty());
  EXPECT_EQ(fem.parallel(), threads > 1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3> x = g.x0, dx(g.x0.size());
  for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng));
  for (auto& d : dx) d = Vec3(u(rng), u(rng), u(rng));
  Result r;
  r.f.assign(x.size(), Vec3(1, 2, 3));
  r.df.assign(x.size(), Vec3(-1, 0.5, 0));
  fem.add_force(x, r.f);
  fem.add_dforce(dx, r.df, 0.37);
  return r;
}

TEST(HexaParallel, BitIdenticalToSequential) {
  const Grid g = make_grid(20, 12, 12);  // 2299 elements: above the parallel threshold
  ASSERT_GE(g.hexa.size(), sinew::fem::HexaFEM::kParallelMinElements);
  for (auto m : {sinew::fem::HexaMethod::large, sinew::fem::HexaMethod::polar, sinew::fem::HexaMethod::small}) {
    const Result seq = evaluate(g, m, 1);
    const Result par = evaluate(g, m, 2);
    for (std::size_t i = 0; i < seq.f.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(seq.f[i][c], par.f[i][c]) << "force, point " << i;
        ASSERT_EQ(seq.df[i][c], par.df[i][c]) << "dforce, point " << i;
      }
    }
  }
}

}  // namespace
