#include "mapping/linear/barycentric_table.h"

#include <algorithm>

#include "core/assert.h"

namespace sinew {

void BaryTable::clear() {
  start_.assign(1, 0);
  idx_.clear();
  w_.clear();
  element_.clear();
}

std::size_t BaryTable::vertices_needed() const {
  std::size_t n = 0;
  for (unsigned v : idx_) n = std::max<std::size_t>(n, std::size_t{v} + 1);
  return n;
}

void BaryTable::gather(const std::vector<double>& in, std::vector<double>& out) const {
  const std::size_t n = points();
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    double s0 = 0, s1 = 0, s2 = 0;
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
      SINEW_ASSERT(idx_[k] * std::size_t{3} + 2 < in.size(), "barycentric table: vertex index within the input");
      const double* p = &in[idx_[k] * 3];
      const double w = w_[k];
      s0 += p[0] * w;
      s1 += p[1] * w;
      s2 += p[2] * w;
    }
    out[i * 3] = s0;
    out[i * 3 + 1] = s1;
    out[i * 3 + 2] = s2;
  }
}

void BaryTable::scatter_add(const std::vector<double>& out, std::vector<double>& in) const {
  const std::size_t n = std::min(points(), out.size() / 3);
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = &out[i * 3];
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
      SINEW_ASSERT(idx_[k] * std::size_t{3} + 2 < in.size(), "barycentric table: vertex index within the input");
      double* p = &in[idx_[k] * 3];
      const double w = w_[k];
      p[0] += v[0] * w;
      p[1] += v[1] * w;
      p[2] += v[2] * w;
    }
  }
}

void BaryTable::jacobian(std::vector<JacobianEntry>& out) const {
  const std::size_t n = points();
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k)
      for (std::uint32_t c = 0; c < 3; ++c)
        out.push_back({0, static_cast<std::uint32_t>(i * 3 + c), idx_[k] * 3 + c, w_[k]});
}

}  // namespace sinew
