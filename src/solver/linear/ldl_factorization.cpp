#include "solver/linear/ldl_factorization.h"

#include <algorithm>
#include <cmath>

extern "C" {
#include <ldl.h>
}

#include "math/block_csr.h"
#include "solver/linear/ordering_method.h"

namespace sinew {

void ldl_load(LdlFactorization& f, const BlockCsrMatrix& A) {
  f.factorized = false;
  A.to_filtered_csr(f.rb, f.ci, f.vals);
  f.n = static_cast<int>(A.size());
}

LdlOutcome ldl_factorize(LdlFactorization& f, OrderingMethod* ordering, bool reuse_symbolic) {
  LdlOutcome out;
  f.factorized = false;
  if (f.n == 0) {
    out.status = LdlStatus::empty;
    return out;
  }
  const bool new_pattern = !f.have_symbolic || f.rb != f.prev_rb || f.ci != f.prev_ci;
  if (new_pattern || !reuse_symbolic) {
    if (ordering) {
      ordering->compute_permutation(f.n, f.rb.data(), f.ci.data(), f.perm);
    } else {
      f.perm.resize(static_cast<std::size_t>(f.n));
      for (int i = 0; i < f.n; ++i) f.perm[static_cast<std::size_t>(i)] = i;
    }
    const std::size_t n = static_cast<std::size_t>(f.n);
    f.invperm.assign(n, 0);
    f.lp.assign(n + 1, 0);
    f.parent.assign(n, 0);
    f.lnz.assign(n, 0);
    f.flag.assign(n, 0);
    ldl_symbolic(f.n, f.rb.data(), f.ci.data(), f.lp.data(), f.parent.data(), f.lnz.data(), f.flag.data(),
                 f.perm.data(), f.invperm.data());
    const int nnz = f.lp[n];
    f.li.assign(static_cast<std::size_t>(nnz), 0);
    f.lx.assign(static_cast<std::size_t>(nnz), 0.0);
    f.d.assign(n, 0.0);
    f.inv_d.assign(n, 0.0);
    f.y.assign(n, 0.0);
    f.t.assign(n, 0.0);
    f.pattern.assign(n, 0);
    f.prev_rb = f.rb;
    f.prev_ci = f.ci;
    f.have_symbolic = true;
    ++f.symbolic_count;
  }
  const int k = ldl_numeric(f.n, f.rb.data(), f.ci.data(), f.vals.data(), f.lp.data(), f.parent.data(), f.lnz.data(),
                            f.li.data(), f.lx.data(), f.d.data(), f.y.data(), f.pattern.data(), f.flag.data(),
                            f.perm.data(), f.invperm.data());
  if (k != f.n) {
    out.status = LdlStatus::zero_pivot;
    out.row = k;
    return out;
  }
  for (int i = 0; i < f.n; ++i) {
    const double d = f.d[static_cast<std::size_t>(i)];
    if (!std::isfinite(d)) {
      out.status = LdlStatus::non_finite_pivot;
      out.row = i;
      return out;
    }
    if (d < 0) out.negative_pivot = true;
    f.inv_d[static_cast<std::size_t>(i)] = 1.0 / d;
  }
  f.factorized = true;
  return out;
}

void ldl_solve(LdlFactorization& f, double* x, const double* b) {
  double* t = f.t.data();
  const int* perm = f.perm.data();
  for (int i = 0; i < f.n; ++i) t[i] = b[perm[i]];
  ldl_lsolve(f.n, t, f.lp.data(), f.li.data(), f.lx.data());
  for (int i = 0; i < f.n; ++i) t[i] *= f.inv_d[static_cast<std::size_t>(i)];
  ldl_ltsolve(f.n, t, f.lp.data(), f.li.data(), f.lx.data());
  for (int i = 0; i < f.n; ++i) x[perm[i]] = t[i];
}

void ldl_add_jminvjt(const LdlFactorization& f, LdlJminvjtScratch& s, Eigen::MatrixXd& result,
                     const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& J, double fact) {
  using RowIt = Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator;
  const Eigen::Index m = J.rows();
  const std::size_t n = static_cast<std::size_t>(f.n);
  s.reach_mark.assign(n, -1);
  s.dense.assign(n, 0.0);
  s.y_start.assign(1, 0);
  s.y_idx.clear();
  s.y_val.clear();
  for (Eigen::Index row = 0; row < m; ++row) {
    // Pattern of L⁻¹·b: the etree paths from b's non-zeros to the root.
    s.reach.clear();
    for (RowIt it(J, row); it; ++it) {
      for (int k = f.invperm[static_cast<std::size_t>(it.col())]; k != -1 && s.reach_mark[static_cast<std::size_t>(k)] != row;
           k = f.parent[static_cast<std::size_t>(k)]) {
        s.reach_mark[static_cast<std::size_t>(k)] = static_cast<int>(row);
        s.reach.push_back(k);
      }
    }
    std::sort(s.reach.begin(), s.reach.end());  // children before parents
    for (RowIt it(J, row); it; ++it)
      s.dense[static_cast<std::size_t>(f.invperm[static_cast<std::size_t>(it.col())])] += it.value();
    // Forward solve on the pattern (ldl_lsolve restricted to it).
    for (int k : s.reach) {
      const double yk = s.dense[static_cast<std::size_t>(k)];
      if (yk == 0.0) continue;
      for (int p = f.lp[static_cast<std::size_t>(k)]; p < f.lp[static_cast<std::size_t>(k) + 1]; ++p)
        s.dense[static_cast<std::size_t>(f.li[static_cast<std::size_t>(p)])] -= f.lx[static_cast<std::size_t>(p)] * yk;
    }
    for (int k : s.reach) {
      s.y_idx.push_back(k);
      s.y_val.push_back(s.dense[static_cast<std::size_t>(k)]);
      s.dense[static_cast<std::size_t>(k)] = 0.0;
    }
    s.y_start.push_back(static_cast<int>(s.y_idx.size()));
  }
  // result(r1, r2) += fact · Σ_k y_r1[k] · y_r2[k] / d_k (symmetric).
  for (Eigen::Index r1 = 0; r1 < m; ++r1) {
    const int b1 = s.y_start[static_cast<std::size_t>(r1)], e1 = s.y_start[static_cast<std::size_t>(r1) + 1];
    if (b1 == e1) continue;
    for (int p = b1; p < e1; ++p) {
      const std::size_t k = static_cast<std::size_t>(s.y_idx[static_cast<std::size_t>(p)]);
      s.dense[k] = s.y_val[static_cast<std::size_t>(p)] * f.inv_d[k];
    }
    for (Eigen::Index r2 = r1; r2 < m; ++r2) {
      double acc = 0.0;
      for (int p = s.y_start[static_cast<std::size_t>(r2)]; p < s.y_start[static_cast<std::size_t>(r2) + 1]; ++p)
        acc += s.y_val[static_cast<std::size_t>(p)] * s.dense[static_cast<std::size_t>(s.y_idx[static_cast<std::size_t>(p)])];
      if (acc == 0.0) continue;
      result(r1, r2) += fact * acc;
      if (r2 != r1) result(r2, r1) += fact * acc;
    }
    for (int p = b1; p < e1; ++p) s.dense[static_cast<std::size_t>(s.y_idx[static_cast<std::size_t>(p)])] = 0.0;
  }
}

}  // namespace sinew
