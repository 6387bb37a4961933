// Csr: patterns and in-place values against dense Eigen references on
// random matrices, and the "values only" refill path reusing a pattern.
#include "math/csr.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

using namespace sinew;

namespace {

// Random entries (with duplicates and a few out-of-range ones) as keys and values.
struct Entries {
  std::vector<std::uint64_t> keys;
  std::vector<double> values;
};

Entries random_entries(int rows, int cols, int count, std::mt19937& rng) {
  std::uniform_int_distribution<int> r(0, rows), c(0, cols);  // rows/cols themselves are out of range
  std::uniform_real_distribution<double> v(-1, 1);
  Entries e;
  for (int k = 0; k < count; ++k) {
    e.keys.push_back((static_cast<std::uint64_t>(r(rng)) << 32) | static_cast<std::uint32_t>(c(rng)));
    e.values.push_back(v(rng));
  }
  return e;
}

void fill(const Entries& e, const std::vector<int>& slot, Csr& m) {
  m.set_zero();
  for (std::size_t k = 0; k < slot.size(); ++k)
    if (slot[k] >= 0) m.val[slot[k]] += e.values[k];
}

Eigen::MatrixXd dense(const Entries& e, int rows, int cols) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(rows, cols);
  for (std::size_t k = 0; k < e.keys.size(); ++k) {
    const auto r = static_cast<int>(e.keys[k] >> 32), c = static_cast<int>(e.keys[k] & 0xffffffffu);
    if (r < rows && c < cols) d(r, c) += e.values[k];
  }
  return d;
}

Eigen::MatrixXd dense(const Csr& m) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(m.rows, m.cols);
  for (int i = 0; i < m.rows; ++i)
    for (int p = m.ptr[i]; p < m.ptr[i + 1]; ++p) {
      if (p > m.ptr[i]) {
        EXPECT_LT(m.idx[p - 1], m.idx[p]) << "columns must ascend";
      }
      d(i, m.idx[p]) += m.val[p];
    }
  return d;
}

}  // namespace

TEST(Csr, PatternSumsDuplicatesAndDropsOutOfRangeEntries) {
  std::mt19937 rng(1);
  const Entries e = random_entries(7, 5, 60, rng);
  Csr m;
  std::vector<int> slot;
  csr_pattern(7, 5, e.keys, m, slot);
  fill(e, slot, m);
  EXPECT_EQ(dense(m), dense(e, 7, 5));
  int dropped = 0;
  for (std::size_t k = 0; k < slot.size(); ++k) {
    const bool out = (e.keys[k] >> 32) >= 7 || (e.keys[k] & 0xffffffffu) >= 5;
    EXPECT_EQ(slot[k] < 0, out);
    dropped += out;
  }
  EXPECT_GT(dropped, 0);
}

TEST(Csr, ProductTransposeAndSumMatchDenseReferencesWhenRefilled) {
  std::mt19937 rng(2);
  for (auto [n, k, m] : {std::tuple{6, 9, 4}, std::tuple{30, 12, 30}, std::tuple{1, 1, 1}}) {
    Entries ea = random_entries(n, k, 3 * n, rng), eb = random_entries(k, m, 3 * k, rng);
    Csr a, b, c, t, s;
    std::vector<int> sa, sb, src;
    csr_pattern(n, k, ea.keys, a, sa);
    csr_pattern(k, m, eb.keys, b, sb);
    csr_multiply_pattern(a, b, c);
    csr_transpose_pattern(c, t, src);
    const std::vector<const Csr*> terms{&c, &c};
    csr_sum_pattern(terms, s);
    std::vector<double> work;
    // Same patterns, new values each round: the values-only path.
    for (int round = 0; round < 3; ++round) {
      std::uniform_real_distribution<double> v(-2, 2);
      for (double& x : ea.values) x = v(rng);
      for (double& x : eb.values) x = v(rng);
      fill(ea, sa, a);
      fill(eb, sb, b);
      csr_multiply_values(a, b, c, work);
      csr_transpose_values(c, src, t);
      csr_sum_values(terms, s, work);
      const Eigen::MatrixXd ref = dense(ea, n, k) * dense(eb, k, m);
      EXPECT_LT((dense(c) - ref).cwiseAbs().maxCoeff(), 1e-13);
      EXPECT_LT((dense(t) - ref.transpose()).cwiseAbs().maxCoeff(), 1e-13);
      EXPECT_LT((dense(s) - 2 * ref).cwiseAbs().maxCoeff(), 1e-13);
      for (double w : work) EXPECT_EQ(w, 0.0) << "the accumulator must be left zero";
    }
  }
}

TEST(Csr, IdentityIsANeutralFactor) {
  std::mt19937 rng(3);
  const Entries e = random_entries(5, 8, 25, rng);
  Csr a, id, c;
  std::vector<int> slot;
  std::vector<double> work;
  csr_pattern(5, 8, e.keys, a, slot);
  fill(e, slot, a);
  csr_identity(8, id);
  csr_multiply_pattern(a, id, c);
  csr_multiply_values(a, id, c, work);
  EXPECT_EQ(c.ptr, a.ptr);
  EXPECT_EQ(c.idx, a.idx);
  EXPECT_EQ(c.val, a.val);
}
