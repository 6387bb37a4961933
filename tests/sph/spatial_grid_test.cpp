// The SPH neighbour grid finds exactly the pairs a brute-force search finds,
// each once, on random point sets (uniform, clustered, spread over many
// blocks and negative coordinates); once warm it allocates nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "alloc_counter.h"
#include "sph/spatial_grid.h"

namespace sinew::sph {
namespace {

using Pair = std::tuple<unsigned, unsigned, double>;

std::vector<Pair> brute_force(const std::vector<double>& x, double h) {
  std::vector<Pair> out;
  const std::size_t n = x.size() / 3;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      // Same difference order as the grid (later point minus visited point) does not matter
      // for r² up to the sign of each difference, which squares away exactly.
      const double dx = x[3 * j] - x[3 * i], dy = x[3 * j + 1] - x[3 * i + 1], dz = x[3 * j + 2] - x[3 * i + 2];
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < h * h) out.emplace_back(static_cast<unsigned>(i), static_cast<unsigned>(j), r2);
    }
  return out;
}

std::vector<Pair> from_grid(SpatialGrid& g, const std::vector<double>& x, double h) {
  g.update(x.data(), x.size() / 3);
  std::vector<Pair> out;
  g.for_each_pair(h, [&](unsigned a, unsigned b, double r2) { out.emplace_back(std::min(a, b), std::max(a, b), r2); });
  return out;
}

void expect_same_pairs(std::vector<Pair> grid, std::vector<Pair> brute) {
  const std::size_t found = grid.size();
  std::sort(grid.begin(), grid.end());
  std::sort(brute.begin(), brute.end());
  ASSERT_EQ(found, brute.size());
  EXPECT_TRUE(std::adjacent_find(grid.begin(), grid.end(), [](const Pair& a, const Pair& b) {
                return std::get<0>(a) == std::get<0>(b) && std::get<1>(a) == std::get<1>(b);
              }) == grid.end())
      << "a pair was reported twice";
  for (std::size_t k = 0; k < grid.size(); ++k) {
    ASSERT_EQ(std::get<0>(grid[k]), std::get<0>(brute[k]));
    ASSERT_EQ(std::get<1>(grid[k]), std::get<1>(brute[k]));
    EXPECT_EQ(std::get<2>(grid[k]), std::get<2>(brute[k]));  // bit-identical squared distance
  }
}

std::vector<double> uniform_points(std::size_t n, double lo, double hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> x(3 * n);
  for (double& c : x) c = u(rng);
  return x;
}

TEST(SpatialGrid, UniformCloudMatchesBruteForce) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto x = uniform_points(1500, -4.0, 5.0, seed);  // spans blocks on both sides of 0
    SpatialGrid g(0.75);
    const auto pairs = from_grid(g, x, 0.745);
    EXPECT_GT(pairs.size(), 1000u);
    expect_same_pairs(pairs, brute_force(x, 0.745));
  }
}

TEST(SpatialGrid, SearchDistanceEqualToCellWidth) {
  const auto x = uniform_points(2000, -3.0, 3.0, 11);
  SpatialGrid g(0.5);
  expect_same_pairs(from_grid(g, x, 0.5), brute_force(x, 0.5));
}

TEST(SpatialGrid, ClustersAndSparseOutliers) {
  // Dense clusters (many points per cell) plus isolated points far apart (many blocks).
  std::mt19937 rng(7);
  std::normal_distribution<double> nd(0.0, 0.3);
  std::uniform_real_distribution<double> far(-60.0, 60.0);
  std::vector<double> x;
  for (int c = 0; c < 6; ++c) {
    const double cx = far(rng), cy = far(rng), cz = far(rng);
    for (int k = 0; k < 200; ++k) {
      x.push_back(cx + nd(rng));
      x.push_back(cy + nd(rng));
      x.push_back(cz + nd(rng));
    }
  }
  for (int k = 0; k < 300; ++k)
    for (int d = 0; d < 3; ++d) x.push_back(far(rng));
  SpatialGrid g(0.4);
  const auto pairs = from_grid(g, x, 0.4);
  expect_same_pairs(pairs, brute_force(x, 0.4));
  EXPECT_GT(g.non_empty_block_count(), 300u);
}

TEST(SpatialGrid, PointsOnCellAndBlockBoundaries) {
  // A lattice whose coordinates fall exactly on cell faces (and block faces at multiples of 8 cells).
  std::vector<double> x;
  for (int i = -9; i <= 9; ++i)
    for (int j = -9; j <= 9; ++j)
      for (int k = -2; k <= 2; ++k) {
        x.push_back(0.5 * i);
        x.push_back(0.5 * j);
        x.push_back(0.5 * k);
      }
  SpatialGrid g(0.5);
  // Lattice neighbours at distance 0.5 exactly are excluded (r² < h² is strict), diagonals too.
  expect_same_pairs(from_grid(g, x, 0.5), brute_force(x, 0.5));
  expect_same_pairs(from_grid(g, x, 0.5000001), brute_force(x, 0.5000001));
}

TEST(SpatialGrid, SofaFloorRoundsToSixteenBitFixedPoint) {
  EXPECT_EQ(sofa_rfloor(2.5), 2);
  EXPECT_EQ(sofa_rfloor(-0.25), -1);
  EXPECT_EQ(sofa_rfloor(-3.0), -3);
  EXPECT_EQ(sofa_rfloor(7.0), 7);
  // Within 2⁻¹⁷ below an integer SOFA's floor rounds up; std::floor does not.
  EXPECT_EQ(sofa_rfloor(3.0 - 1e-7), 3);
  EXPECT_EQ(std::floor(3.0 - 1e-7), 2.0);
  EXPECT_EQ(sofa_rfloor(3.0 - 1e-4), 2);
}

// find_pairs (scalar and AVX2 kernels) gives for_each_pair's pairs in the same
// order: the order decides the digits of SPH's sums. Its r² is not kept but
// computed again from the points with the pair's indices swapped or not; both
// give for_each_pair's r² bit for bit (what SPHFluidForceField relies on).
TEST(SpatialGrid, FindPairsEqualsForEachPairInOrder) {
  for (unsigned seed : {1u, 2u, 3u}) {
    for (double h : {0.1, 0.3, 0.745}) {
      // Dense and sparse sets, spanning several blocks and negative coordinates.
      auto x = uniform_points(seed == 3 ? 4000 : 700, -3.0, 4.0 * h * seed, seed);
      SpatialGrid g(h);
      g.update(x.data(), x.size() / 3);
      std::vector<Pair> expected;
      g.for_each_pair(h, [&](unsigned a, unsigned b, double r2) { expected.emplace_back(a, b, r2); });
      ASSERT_GT(expected.size(), 0u);
      auto r2_of = [&](unsigned a, unsigned b) {
        const double dx = x[3 * b] - x[3 * a], dy = x[3 * b + 1] - x[3 * a + 1], dz = x[3 * b + 2] - x[3 * a + 2];
        return dx * dx + dy * dy + dz * dz;
      };
      for (PairKernel simd : {PairKernel::scalar, PairKernel::avx2, PairKernel::avx512}) {
        PairBuffer out;
        g.find_pairs(h, out, simd);
        ASSERT_EQ(out.size, expected.size()) << "kernel " << static_cast<int>(simd);
        ASSERT_EQ(out.runs, x.size() / 3) << "one run per point";
        for (std::size_t r = 0, k = 0; r < out.runs; ++r) {
          for (; k < out.run_end[r]; ++k) {
            ASSERT_EQ(out.run_first[r], std::get<0>(expected[k])) << "pair " << k <<  " kernel " << static_cast<int>(simd);
            ASSERT_EQ(out.second[k], std::get<1>(expected[k])) << "pair " << k <<  " kernel " << static_cast<int>(simd);
            ASSERT_EQ(r2_of(out.run_first[r], out.second[k]), std::get<2>(expected[k])) << "pair " << k;
            ASSERT_EQ(r2_of(out.second[k], out.run_first[r]), std::get<2>(expected[k])) << "pair " << k;
          }
        }
        ASSERT_EQ(out.run_end[out.runs - 1], out.size);
      }
    }
  }
}

TEST(SpatialGrid, MovingPointsAllocateNothingOnceWarm) {
  if (!SINEW_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counter not installed (sanitizer build)";
  auto x = uniform_points(3000, -2.0, 2.0, 3);
  SpatialGrid g(0.3);
  std::size_t count = 0;
  auto visit = [&](unsigned, unsigned, double) { ++count; };
  // Warm-up: a few updates over the same region so that every buffer reached its size.
  PairBuffer pairs;
  for (int s = 0; s < 3; ++s) {
    g.update(x.data(), x.size() / 3);
    g.for_each_pair(0.3, visit);
    g.find_pairs(0.3, pairs);
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  long before = test::g_allocations.load();
  for (int s = 0; s < 10; ++s) {
    for (double& c : x) c = std::clamp(c + jitter(rng), -2.0, 2.0);
    g.update(x.data(), x.size() / 3);
    g.for_each_pair(0.3, visit);
    g.find_pairs(0.3, pairs);
  }
  EXPECT_EQ(test::g_allocations.load() - before, 0);
  EXPECT_GT(count, 0u);
}

}  // namespace
}  // namespace sinew::sph
