#include "mapping/linear/tubular_mapping.h"

#include <cmath>

#include "core/registry.h"

namespace sinew {

bool TubularMapping::init_mapping() {
  if (!radius.is_set()) {
    msg_error("No radius defined (set radius=\"...\")");
    return false;
  }
  n_ = nb_points_on_each_circle.value();
  if (n_ == 0) msg_warning("nbPointsOnEachCircle is 0: the tube has no point");
  cos_.resize(n_);
  sin_.resize(n_);
  for (unsigned j = 0; j < n_; ++j) {
    const double a = 2.0 * j * M_PI / n_;  // SOFA's angle expression, same rounding
    cos_[j] = std::cos(a);
    sin_[j] = std::sin(a);
  }
  rotated_.assign(in_size() * n_ * 3, 0.0);
  resize_output(in_size() * n_);
  return true;
}

void TubularMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const std::vector<double>& in = in_coord(x);
  const std::size_t nf = in.size() / 7;
  const double rho = radius.value();
  const int pk = peak.value();
  std::vector<double>& out = *outp;
  out.resize(nf * n_ * 3);
  rotated_.resize(nf * n_ * 3);
  for (std::size_t i = 0; i < nf; ++i) {
    double rho_i = rho;
    if (pk > 0) {
      const int test = static_cast<int>(i);
      if (test < pk) rho_i = static_cast<double>(test) / static_cast<double>(pk) * rho;
    } else {
      const int test = static_cast<int>(nf - (i + 1));
      if (test < -pk) rho_i = -static_cast<double>(test) / static_cast<double>(pk) * rho;
    }
    const double* c = &in[i * 7];
    const double qx = c[3], qy = c[4], qz = c[5], qw = c[6];
    // Columns 1 and 2 of SOFA's Quat::toMatrix: the frame's y and z axes.
    const double Y[3] = {2 * (qx * qy - qz * qw), 1 - 2 * (qz * qz + qx * qx), 2 * (qy * qz + qx * qw)};
    const double Z[3] = {2 * (qz * qx + qy * qw), 2 * (qy * qz - qx * qw), 1 - 2 * (qy * qy + qx * qx)};
    for (unsigned j = 0; j < n_; ++j) {
      double* r = &rotated_[(i * n_ + j) * 3];
      double* o = &out[(i * n_ + j) * 3];
      for (int k = 0; k < 3; ++k) {
        r[k] = (Y[k] * cos_[j] + Z[k] * sin_[j]) * rho_i;
        o[k] = c[k] + r[k];
      }
    }
  }
}

void TubularMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  const std::vector<double>& in = in_deriv(v, role);
  const std::size_t nf = in.size() / 6;
  std::vector<double>& out = *outp;
  out.resize(nf * n_ * 3);
  if (rotated_.size() < out.size()) rotated_.resize(out.size(), 0.0);
  for (std::size_t i = 0; i < nf; ++i) {
    const double* d = &in[i * 6];
    const double* w = d + 3;
    for (unsigned j = 0; j < n_; ++j) {
      const double* r = &rotated_[(i * n_ + j) * 3];
      double* o = &out[(i * n_ + j) * 3];
      // v − r × ω (= v + ω × r)
      o[0] = d[0] - (r[1] * w[2] - r[2] * w[1]);
      o[1] = d[1] - (r[2] * w[0] - r[0] * w[2]);
      o[2] = d[2] - (r[0] * w[1] - r[1] * w[0]);
    }
  }
}

void TubularMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t nf = in.size() / 6;
  const std::size_t n_out = std::min(out.size(), rotated_.size()) / 3;
  for (std::size_t i = 0; i < nf; ++i) {
    if ((i + 1) * n_ > n_out) break;
    double v[3] = {0, 0, 0}, t[3] = {0, 0, 0};
    for (unsigned j = 0; j < n_; ++j) {
      const double* fi = &out[(i * n_ + j) * 3];
      const double* r = &rotated_[(i * n_ + j) * 3];
      v[0] += fi[0];
      v[1] += fi[1];
      v[2] += fi[2];
      t[0] += r[1] * fi[2] - r[2] * fi[1];
      t[1] += r[2] * fi[0] - r[0] * fi[2];
      t[2] += r[0] * fi[1] - r[1] * fi[0];
    }
    double* d = &in[i * 6];
    for (int k = 0; k < 3; ++k) {
      d[k] += v[k];
      d[3 + k] += t[k];
    }
  }
}

void TubularMapping::jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const {
  if (n_ == 0 || static_cast<std::size_t>(out_dof) * 3 + 3 > rotated_.size()) return;
  const double* r = &rotated_[out_dof * 3];
  const double t[6] = {v[0], v[1], v[2], r[1] * v[2] - r[2] * v[1], r[2] * v[0] - r[0] * v[2],
                       r[0] * v[1] - r[1] * v[0]};
  sink.add(0, out_dof / n_, t);
}

bool TubularMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::size_t n_pts = rotated_.size() / 3;
  for (std::size_t k = 0; k < n_pts; ++k) {
    const std::uint32_t col = static_cast<std::uint32_t>(k / n_) * 6;
    const std::uint32_t row = static_cast<std::uint32_t>(k * 3);
    const double* r = &rotated_[k * 3];
    // ω ↦ ω × r; its zeros off the diagonal are emitted so that the pattern never depends on r.
    const double m[3][3] = {{0, r[2], -r[1]}, {-r[2], 0, r[0]}, {r[1], -r[0], 0}};
    for (std::uint32_t a = 0; a < 3; ++a) {
      out.push_back({0, row + a, col + a, 1.0});
      for (std::uint32_t b = 0; b < 3; ++b)
        if (a != b) out.push_back({0, row + a, col + 3 + b, m[a][b]});
    }
  }
  return true;
}

void register_tubular_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "TubularMapping";
  info.category = "Mapping/Linear";
  info.description = "a tube of rings of points around rigid frames (the skin of a beam)";
  info.templates = {"Rigid3d,Vec3d"};
  info.default_template = "Rigid3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    if (t != "Rigid3d,Vec3d") return nullptr;
    return std::make_unique<TubularMapping>();
  };
  r.add(std::move(info));
}

}  // namespace sinew
