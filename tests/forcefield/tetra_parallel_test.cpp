// The parallel evaluation of the tetrahedral kernel must give bit-identical
// results to the sequential one, whatever the thread count.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <random>

#include "forcefield/fem/tetra_fem.h"

namespace {

using sinew::Vec3;

struct Mesh {
  std::vector<Vec3> x0;
  std::vector<std::array<int, 4>> tetra;
};

// A grid of cubes, each split in six tetrahedra around its main diagonal.
Mesh make_mesh(int nx, int ny, int nz) {
  Mesh m;
  auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) m.x0.emplace_back(0.5 * i, 0.5 * j, 0.5 * k);
  const int split[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        int c[8];
        for (int b = 0; b < 8; ++b) c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        for (const auto& s : split) m.tetra.push_back({c[s[0]], c[s[1]], c[s[2]], c[s[3]]});
      }
  return m;
}

struct Result {
  std::vector<Vec3> f, df;
};

Result evaluate(const Mesh& m, sinew::fem::TetraMethod method, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  sinew::fem::TetraFEM fem;
  std::vector<double> E(m.tetra.size(), 3000.0), nu(m.tetra.size(), 0.35);
  fem.init(m.x0, m.tetra, E, nu, method);
  EXPECT_EQ(fem.parallel(), threads > 1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3> x = m.x0, dx(m.x0.size());
  for (auto& p : x) p += Vec3(u(rng), u(rng), u(rng));
  for (auto& d : dx) d = Vec3(u(rng), u(rng), u(rng));
  Result r;
  r.f.assign(x.size(), Vec3(1, 2, 3));
  r.df.assign(x.size(), Vec3(-1, 0.5, 0));
  fem.add_force(x, r.f);
  fem.add_dforce(dx, r.df, 0.37);
  return r;
}

TEST(TetraParallel, BitIdenticalToSequential) {
  const Mesh m = make_mesh(14, 10, 10);  // 6318 tetrahedra: above the parallel threshold
  ASSERT_GE(m.tetra.size(), sinew::fem::TetraFEM::kParallelMinElements);
  using M = sinew::fem::TetraMethod;
  for (M method : {M::large, M::polar, M::small, M::svd}) {
    const Result seq = evaluate(m, method, 1);
    const Result par = evaluate(m, method, 2);
    for (std::size_t i = 0; i < seq.f.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(seq.f[i][c], par.f[i][c]) << "force, point " << i << ", method " << int(method);
        ASSERT_EQ(seq.df[i][c], par.df[i][c]) << "dforce, point " << i << ", method " << int(method);
      }
  }
}

}  // namespace
