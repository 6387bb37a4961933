#include "constraint/correction/dense_compliance.h"

#include <algorithm>

namespace sinew::dense_compliance {

void prepare(const ConstraintMatrix& J, const double* C, std::size_t dofs, int w, Work& work) {
  const auto rows = J.rows();
  const auto entries = J.entries();
  work.slot.assign(dofs, -1);
  work.active.clear();
  for (const ConstraintMatrix::Row& r : rows)
    for (int e = r.begin; e < r.end; ++e) {
      const int d = entries[e].dof;
      if (work.slot[d] < 0) {
        work.slot[d] = 0;
        work.active.push_back(d);
      }
    }
  std::sort(work.active.begin(), work.active.end());
  for (std::size_t k = 0; k < work.active.size(); ++k) work.slot[work.active[k]] = static_cast<int>(k);

  // v(a, j) = Σ over the entries (b, n) of row j of C_ab·n, component by
  // component in SOFA's order (entries, then columns of the block).
  const std::size_t n = dofs * w, nr = rows.size();
  work.v.assign(work.active.size() * nr * w, 0.0);
  for (std::size_t k = 0; k < work.active.size(); ++k) {
    const std::size_t a = static_cast<std::size_t>(work.active[k]);
    for (std::size_t j = 0; j < nr; ++j) {
      double* vb = &work.v[(k * nr + j) * w];
      for (int e = rows[j].begin; e < rows[j].end; ++e) {
        const double* nv = J.value(e);
        const double* block = C + a * w * n + static_cast<std::size_t>(entries[e].dof) * w;
        for (int ii = 0; ii < w; ++ii) {
          const double* crow = block + static_cast<std::size_t>(ii) * n;
          for (int jj = 0; jj < w; ++jj) vb[ii] += crow[jj] * nv[jj];
        }
      }
    }
  }
}

void add_jcjt(const ConstraintMatrix& J, const Work& work, int w, double factor, double reg, double* W, int ld,
              bool by_id) {
  const auto rows = J.rows();
  const auto entries = J.entries();
  const std::size_t nr = rows.size();
  for (std::size_t i = 0; i < nr; ++i) {
    const std::size_t ri = by_id ? static_cast<std::size_t>(rows[i].id) : i;
    for (int e = rows[i].begin; e < rows[i].end; ++e) {
      const double* n1 = J.value(e);
      const std::size_t k = static_cast<std::size_t>(work.slot[entries[e].dof]);
      for (std::size_t j = i; j < nr; ++j) {
        const std::size_t rj = by_id ? static_cast<std::size_t>(rows[j].id) : j;
        const double* vb = &work.v[(k * nr + j) * w];
        double dot = vb[0] * n1[0];
        for (int c = 1; c < w; ++c) dot += vb[c] * n1[c];
        const double value = dot * factor;
        W[ri * ld + rj] += value;
        if (ri != rj) W[rj * ld + ri] += value;
        else W[ri * ld + ri] += reg;
      }
    }
  }
}

void jt_lambda(const ConstraintMatrix& J, const std::vector<double>& lambda, int w, bool skip_zero,
               std::vector<double>& out, std::vector<int>& active, std::vector<int>& mark) {
  std::fill(out.begin(), out.end(), 0.0);
  const std::size_t dofs = out.size() / static_cast<std::size_t>(w);
  mark.assign(dofs, 0);
  active.clear();
  const auto entries = J.entries();
  for (const ConstraintMatrix::Row& r : J.rows()) {
    const double l = static_cast<std::size_t>(r.id) < lambda.size() ? lambda[r.id] : 0.0;
    if (skip_zero && l == 0.0) continue;
    for (int e = r.begin; e < r.end; ++e) {
      const std::size_t d = static_cast<std::size_t>(entries[e].dof);
      if (d >= dofs) continue;
      const double* v = J.value(e);
      double* o = &out[d * w];
      for (int c = 0; c < w; ++c) o[c] += v[c] * l;
      if (!mark[d]) {
        mark[d] = 1;
        active.push_back(static_cast<int>(d));
      }
    }
  }
  std::sort(active.begin(), active.end());
}

void apply(const double* C, std::size_t dofs, int w, const std::vector<int>& active, const std::vector<double>& force,
           std::vector<double>& dx) {
  const std::size_t n = dofs * w;
  dx.assign(n, 0.0);
  for (int f : active) {
    const double* fb = &force[static_cast<std::size_t>(f) * w];
    for (std::size_t v = 0; v < dofs; ++v) {
      const double* block = C + v * w * n + static_cast<std::size_t>(f) * w;
      for (int j = 0; j < w; ++j) {
        const double* crow = block + static_cast<std::size_t>(j) * n;
        double s = 0.0;
        for (int i = 0; i < w; ++i) s += crow[i] * fb[i];
        dx[v * w + j] += s;
      }
    }
  }
}

}  // namespace sinew::dense_compliance
