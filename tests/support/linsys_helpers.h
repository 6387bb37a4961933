// Helpers for the linear-solver tests: random sparse SPD systems and filling
// a BlockCsrMatrix from a dense matrix.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <random>
#include <vector>

#include "math/block_csr.h"

namespace sinew::test {

// Random sparse SPD matrix of size n: a few random couplings between scalar
// rows, made diagonally dominant.
inline Eigen::MatrixXd random_spd(int n, unsigned seed, double density = 0.15) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pick(0.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j)
      if (pick(rng) < density) A(i, j) = A(j, i) = u(rng);
  for (int i = 0; i < n; ++i) A(i, i) = A.row(i).cwiseAbs().sum() + 0.5 + pick(rng);
  return A;
}

// Fills a BlockCsrMatrix (block size bs) with the non-zero entries of a dense matrix.
inline void fill(BlockCsrMatrix& M, const Eigen::MatrixXd& A, int bs) {
  const std::size_t n = static_cast<std::size_t>(A.rows());
  M.reset(n, bs);
  std::vector<std::uint64_t> keys;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (A(i, j) != 0.0) keys.push_back((static_cast<std::uint64_t>(i) << 32) | j);
  M.build_pattern(keys);
  for (std::uint64_t k : keys) M.values()[M.slot(k >> 32, k & 0xffffffffu)] += A(k >> 32, k & 0xffffffffu);
}

}  // namespace sinew::test
