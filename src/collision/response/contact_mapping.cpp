#include "collision/response/contact_mapping.h"

#include "math/types.h"

namespace sinew {

namespace {
// out_i = Σ_k in[v_k]·w_k, summed in the element's vertex order (SOFA's order).
void map_points(const std::vector<ContactMapping::Point>& pts, std::span<const Vec3> in, std::span<Vec3> out) {
  for (std::size_t i = 0; i < pts.size() && i < out.size(); ++i) {
    const ContactMapping::Point& p = pts[i];
    Vec3 s = in[p.v[0]] * p.w[0];
    for (int k = 1; k < p.n; ++k) s += in[p.v[k]] * p.w[k];
    out[i] = s;
  }
}
}  // namespace

void ContactMapping::apply(int x) {
  map_points(points_, as_vec3(in_->read(vec_for(*in_, x, kPosition))),
             as_vec3(out_->write(vec_for(*out_, x, kPosition))));
}

void ContactMapping::apply_j(int v, int role) {
  map_points(points_, as_vec3(in_->read(vec_for(*in_, v, role))), as_vec3(out_->write(vec_for(*out_, v, role))));
}

void ContactMapping::apply_jt(int f, int role) {
  auto out = as_vec3(out_->read(vec_for(*out_, f, role)));
  auto in = as_vec3(in_->write(vec_for(*in_, f, role)));
  for (std::size_t i = 0; i < points_.size() && i < out.size(); ++i) {
    const Point& p = points_[i];
    for (int k = 0; k < p.n; ++k) in[p.v[k]] += out[i] * p.w[k];
  }
}

bool ContactMapping::jacobian(std::vector<JacobianEntry>& out) {
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Point& p = points_[i];
    for (int k = 0; k < p.n; ++k)
      for (std::uint32_t c = 0; c < 3; ++c)
        out.push_back({0, static_cast<std::uint32_t>(3 * i + c), 3 * p.v[k] + c, p.w[k]});
  }
  return true;
}

}  // namespace sinew
