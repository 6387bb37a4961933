#include "mapping/linear/skinning_mapping.h"

#include <limits>
#include <string>

#include "core/registry.h"
#include "math/quat.h"

namespace sinew {

bool SkinningMapping::init_mapping() {
  if (!indices.value().empty() || !weight.value().empty()) {
    msg_error("explicit 'indices' and 'weight' lists are not supported (leave them out: they are computed)");
    return false;
  }
  const std::vector<unsigned>& nb = nb_ref.get();
  if (nb.empty() || nb[0] == 0) {
    msg_error("nbRef must give at least one frame per point");
    return false;
  }
  slots_ = nb[0];
  const std::vector<double>& out = initial_output_positions();
  const std::size_t n = out.size() / 3;
  // initPos: kept when it has one point per output point, else the output's positions.
  std::vector<double> p0 = init_pos.get();
  if (p0.size() != n * 3) {
    p0.assign(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n * 3));
    init_pos.set(p0);
  }
  const std::vector<double>& xf = in_coord(compute_from_position.value() ? kPosition : kRestPosition);
  const std::size_t nf = xf.size() / 7;

  // The slots_ nearest frames by 1/d², sorted by decreasing weight (insertion
  // as SOFA: a frame goes before the first smaller-or-equal weight), normalised.
  index_.assign(n * slots_, 0u);
  w_.assign(n * slots_, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double* w = &w_[i * slots_];
    unsigned* id = &index_[i * slots_];
    const double* p = &p0[i * 3];
    for (std::size_t j = 0; j < nf; ++j) {
      const double* c = &xf[j * 7];
      const double d0 = p[0] - c[0], d1 = p[1] - c[1], d2 = p[2] - c[2];
      double wj = d0 * d0 + d1 * d1 + d2 * d2;
      if (wj != 0) wj = 1.0 / wj;
      else wj = std::numeric_limits<double>::max();
      std::size_t m = 0;
      while (m != slots_ && w[m] > wj) ++m;
      if (m == slots_) continue;
      for (std::size_t k = slots_ - 1; k > m; --k) {
        w[k] = w[k - 1];
        id[k] = id[k - 1];
      }
      w[m] = wj;
      id[m] = static_cast<unsigned>(j);
    }
    double sum = 0;
    for (std::size_t j = 0; j < slots_; ++j) sum += w[j];
    if (sum != 0)
      for (std::size_t j = 0; j < slots_; ++j) w[j] /= sum;
  }

  // Frames per point: nbRef per point when it has one value per point.
  count_.assign(n, static_cast<unsigned>(slots_));
  if (nb.size() == n && n != 0)
    for (std::size_t i = 0; i < n; ++i) {
      if (nb[i] > slots_) {
        msg_error("nbRef of point " + std::to_string(i) + " (" + std::to_string(nb[i]) +
                  ") exceeds the first value (" + std::to_string(slots_) + "), the number of weights kept per point");
        return false;
      }
      count_[i] = nb[i];
    }
  // Normalised again over each point's own count (SOFA's reinit), then cut at the first zero weight.
  for (std::size_t i = 0; i < n; ++i) {
    double* w = &w_[i * slots_];
    double sum = 0;
    for (unsigned j = 0; j < count_[i]; ++j) sum += w[j];
    if (sum != 0)
      for (unsigned j = 0; j < count_[i]; ++j) w[j] /= sum;
    unsigned c = 0;
    while (c < count_[i] && w[c] > 0.) ++c;
    count_[i] = c;
  }

  // Weighted local points and lever arms at init.
  local_.assign(n * slots_ * 3, 0.0);
  rotated_.assign(n * slots_ * 3, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (unsigned j = 0; j < count_[i]; ++j) {
      const std::size_t s = i * slots_ + j;
      const double* c = &xf[index_[s] * 7];
      const double* p = &p0[i * 3];
      const Vec3 d(p[0] - c[0], p[1] - c[1], p[2] - c[2]);
      const Vec3 l = quat_inverse_rotate(Quat::from(c + 3), d);
      for (int k = 0; k < 3; ++k) {
        local_[s * 3 + k] = l[k] * w_[s];
        rotated_[s * 3 + k] = d[k] * w_[s];
      }
    }
  resize_output(n);
  return true;
}

void SkinningMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const std::vector<double>& in = in_coord(x);
  std::vector<double>& out = *outp;
  const std::size_t n = count_.size();
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    double* o = &out[i * 3];
    o[0] = o[1] = o[2] = 0.0;
    for (unsigned j = 0; j < count_[i]; ++j) {
      const std::size_t s = i * slots_ + j;
      const double* c = &in[index_[s] * 7];
      const Vec3 r = quat_rotate(Quat::from(c + 3), Vec3(local_[s * 3], local_[s * 3 + 1], local_[s * 3 + 2]));
      double* rp = &rotated_[s * 3];
      for (int k = 0; k < 3; ++k) {
        rp[k] = r[k];
        o[k] += c[k] * w_[s] + r[k];
      }
    }
  }
}

void SkinningMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  const std::vector<double>& in = in_deriv(v, role);
  std::vector<double>& out = *outp;
  const std::size_t n = count_.size();
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    double* o = &out[i * 3];
    o[0] = o[1] = o[2] = 0.0;
    for (unsigned j = 0; j < count_[i]; ++j) {
      const std::size_t s = i * slots_ + j;
      const double* d = &in[index_[s] * 6];
      const double* p = &rotated_[s * 3];
      const double w = w_[s];
      // v·w + ω × r
      o[0] += d[0] * w + (d[4] * p[2] - d[5] * p[1]);
      o[1] += d[1] * w + (d[5] * p[0] - d[3] * p[2]);
      o[2] += d[2] * w + (d[3] * p[1] - d[4] * p[0]);
    }
  }
}

void SkinningMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min(count_.size(), out.size() / 3);
  for (std::size_t i = 0; i < n; ++i) {
    const double* fi = &out[i * 3];
    for (unsigned j = 0; j < count_[i]; ++j) {
      const std::size_t s = i * slots_ + j;
      double* d = &in[index_[s] * 6];
      const double* p = &rotated_[s * 3];
      const double w = w_[s];
      d[0] += fi[0] * w;
      d[1] += fi[1] * w;
      d[2] += fi[2] * w;
      // τ += r × f
      d[3] += p[1] * fi[2] - p[2] * fi[1];
      d[4] += p[2] * fi[0] - p[0] * fi[2];
      d[5] += p[0] * fi[1] - p[1] * fi[0];
    }
  }
}

void SkinningMapping::jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const {
  if (out_dof >= count_.size()) return;
  for (unsigned j = 0; j < count_[out_dof]; ++j) {
    const std::size_t s = out_dof * slots_ + j;
    const double* p = &rotated_[s * 3];
    const double w = w_[s];
    const double t[6] = {v[0] * w, v[1] * w, v[2] * w, p[1] * v[2] - p[2] * v[1], p[2] * v[0] - p[0] * v[2],
                         p[0] * v[1] - p[1] * v[0]};
    sink.add(0, index_[s], t);
  }
}

bool SkinningMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t i = 0; i < count_.size(); ++i) {
    const std::uint32_t row = static_cast<std::uint32_t>(i * 3);
    for (unsigned j = 0; j < count_[i]; ++j) {
      const std::size_t s = i * slots_ + j;
      const std::uint32_t col = index_[s] * 6;
      const double* p = &rotated_[s * 3];
      // Pattern independent of the values (zeros emitted): assembled systems reuse it.
      const double m[3][3] = {{0, p[2], -p[1]}, {-p[2], 0, p[0]}, {p[1], -p[0], 0}};  // ω ↦ ω × r
      for (std::uint32_t a = 0; a < 3; ++a) {
        out.push_back({0, row + a, col + a, w_[s]});
        for (std::uint32_t b = 0; b < 3; ++b)
          if (a != b) out.push_back({0, row + a, col + 3 + b, m[a][b]});
      }
    }
  }
  return true;
}

void register_skinning_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "SkinningMapping";
  info.category = "Mapping/Linear";
  info.description = "points following several rigid frames with distance weights (linear blend skinning)";
  info.templates = {"Rigid3d,Vec3d"};
  info.default_template = "Rigid3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<SkinningMapping>(); };
  r.add(std::move(info));
}

}  // namespace sinew
