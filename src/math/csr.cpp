#include "math/csr.h"

#include <algorithm>

namespace sinew {

void Csr::set_zero() { std::fill(val.begin(), val.end(), 0.0); }

namespace {

// Fills c.ptr/c.idx from per-row column lists produced by `row_cols(i, out)`;
// `mark` (c.cols ints, all -1 on entry) deduplicates.
template <class RowCols>
void build_rows(Csr& c, RowCols&& row_cols) {
  c.ptr.assign(c.rows + 1, 0);
  c.idx.clear();
  std::vector<int> mark(c.cols, -1);
  std::vector<int> row;
  for (int i = 0; i < c.rows; ++i) {
    row.clear();
    row_cols(i, [&](int j) {
      if (mark[j] != i) {
        mark[j] = i;
        row.push_back(j);
      }
    });
    std::sort(row.begin(), row.end());
    c.idx.insert(c.idx.end(), row.begin(), row.end());
    c.ptr[i + 1] = static_cast<int>(c.idx.size());
  }
  c.val.assign(c.idx.size(), 0.0);
}

// Value index of (i, j) in c, -1 if absent (binary search in the row).
int find(const Csr& c, int i, int j) {
  const auto b = c.idx.begin() + c.ptr[i];
  const auto e = c.idx.begin() + c.ptr[i + 1];
  const auto it = std::lower_bound(b, e, j);
  return it != e && *it == j ? static_cast<int>(it - c.idx.begin()) : -1;
}

}  // namespace

void csr_pattern(int rows, int cols, const std::vector<std::uint64_t>& keys, Csr& out, std::vector<int>& slot) {
  auto row_of = [](std::uint64_t k) { return static_cast<std::uint32_t>(k >> 32); };
  auto col_of = [](std::uint64_t k) { return static_cast<std::uint32_t>(k & 0xffffffffu); };
  auto kept = [&](std::uint64_t k) {
    return row_of(k) < static_cast<std::uint32_t>(rows) && col_of(k) < static_cast<std::uint32_t>(cols);
  };
  out.rows = rows;
  out.cols = cols;
  // Bucket the kept entries by row, then let build_rows sort and deduplicate.
  std::vector<int> begin(rows + 1, 0);
  for (std::uint64_t k : keys)
    if (kept(k)) ++begin[row_of(k) + 1];
  for (int i = 0; i < rows; ++i) begin[i + 1] += begin[i];
  std::vector<int> bucket(begin.back());
  std::vector<int> fill(begin.begin(), begin.end() - 1);
  for (std::uint64_t k : keys)
    if (kept(k)) bucket[fill[row_of(k)]++] = static_cast<int>(col_of(k));
  build_rows(out, [&](int i, auto&& add) {
    for (int k = begin[i]; k < begin[i + 1]; ++k) add(bucket[k]);
  });
  slot.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k)
    slot[k] = kept(keys[k]) ? find(out, static_cast<int>(row_of(keys[k])), static_cast<int>(col_of(keys[k]))) : -1;
}

void csr_identity(int n, Csr& out) {
  out.rows = out.cols = n;
  out.ptr.resize(n + 1);
  out.idx.resize(n);
  for (int i = 0; i <= n; ++i) out.ptr[i] = i;
  for (int i = 0; i < n; ++i) out.idx[i] = i;
  out.val.assign(n, 1.0);
}

void csr_multiply_pattern(const Csr& a, const Csr& b, Csr& c) {
  c.rows = a.rows;
  c.cols = b.cols;
  build_rows(c, [&](int i, auto&& add) {
    for (int p = a.ptr[i]; p < a.ptr[i + 1]; ++p) {
      const int k = a.idx[p];
      for (int q = b.ptr[k]; q < b.ptr[k + 1]; ++q)
        add(b.idx[q]);
    }
  });
}

void csr_multiply_values(const Csr& a, const Csr& b, Csr& c, std::vector<double>& work) {
  if (work.size() < static_cast<std::size_t>(c.cols)) work.resize(c.cols, 0.0);
  for (int i = 0; i < a.rows; ++i) {
    for (int p = a.ptr[i]; p < a.ptr[i + 1]; ++p) {
      const int k = a.idx[p];
      const double v = a.val[p];
      for (int q = b.ptr[k]; q < b.ptr[k + 1]; ++q)
        work[b.idx[q]] += v * b.val[q];
    }
    for (int p = c.ptr[i]; p < c.ptr[i + 1]; ++p) {
      double& w = work[c.idx[p]];
      c.val[p] = w;
      w = 0.0;
    }
  }
}

void csr_transpose_pattern(const Csr& a, Csr& t, std::vector<int>& src) {
  t.rows = a.cols;
  t.cols = a.rows;
  t.ptr.assign(t.rows + 1, 0);
  for (int p = 0; p < a.nnz(); ++p) ++t.ptr[a.idx[p] + 1];
  for (int i = 0; i < t.rows; ++i) t.ptr[i + 1] += t.ptr[i];
  t.idx.resize(a.nnz());
  src.resize(a.nnz());
  std::vector<int> fill(t.ptr.begin(), t.ptr.end() - 1);
  // Rows of A in ascending order keep the columns of T ascending.
  for (int i = 0; i < a.rows; ++i)
    for (int p = a.ptr[i]; p < a.ptr[i + 1]; ++p) {
      const int k = fill[a.idx[p]]++;
      t.idx[k] = i;
      src[k] = p;
    }
  t.val.assign(t.idx.size(), 0.0);
}

void csr_transpose_values(const Csr& a, const std::vector<int>& src, Csr& t) {
  for (std::size_t k = 0; k < src.size(); ++k) t.val[k] = a.val[src[k]];
}

void csr_sum_pattern(const std::vector<const Csr*>& terms, Csr& s) {
  s.rows = terms.empty() ? 0 : terms.front()->rows;
  s.cols = terms.empty() ? 0 : terms.front()->cols;
  build_rows(s, [&](int i, auto&& add) {
    for (const Csr* t : terms)
      for (int p = t->ptr[i]; p < t->ptr[i + 1]; ++p)
        add(t->idx[p]);
  });
}

void csr_sum_values(const std::vector<const Csr*>& terms, Csr& s, std::vector<double>& work) {
  if (work.size() < static_cast<std::size_t>(s.cols)) work.resize(s.cols, 0.0);
  for (int i = 0; i < s.rows; ++i) {
    for (const Csr* t : terms)
      for (int p = t->ptr[i]; p < t->ptr[i + 1]; ++p)
        work[t->idx[p]] += t->val[p];
    for (int p = s.ptr[i]; p < s.ptr[i + 1]; ++p) {
      double& w = work[s.idx[p]];
      s.val[p] = w;
      w = 0.0;
    }
  }
}

}  // namespace sinew
