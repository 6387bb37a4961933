#include "mapping/linear/beam_linear_mapping.h"

#include <cmath>

#include "core/registry.h"

namespace sinew {

namespace {

// SOFA's Quat::rotate (same operation order as RigidMapping's).
inline void quat_rotate(const double* q, const double* v, double* r) {
  const double qx = q[0], qy = q[1], qz = q[2], qw = q[3];
  const double t0 = (qy * v[2] - qz * v[1]) * 2;
  const double t1 = (qz * v[0] - qx * v[2]) * 2;
  const double t2 = (qx * v[1] - qy * v[0]) * 2;
  r[0] = v[0] + qw * t0 + (qy * t2 - qz * t1);
  r[1] = v[1] + qw * t1 + (qz * t0 - qx * t2);
  r[2] = v[2] + qw * t2 + (qx * t1 - qy * t0);
}

// Beam index (clamped to [0, n−2]) and the local coordinates in that beam.
inline int beam_of(const double* p, std::size_t n_in, double* local) {
  int j = static_cast<int>(std::floor(p[0]));
  if (j < 0) j = 0;
  else if (j > static_cast<int>(n_in) - 2) j = static_cast<int>(n_in) - 2;
  local[0] = p[0] - j;
  local[1] = p[1];
  local[2] = p[2];
  return j;
}

inline double smooth(double t) { return 3 * (t * t) - 2 * (t * t * t); }

}  // namespace

bool BeamLinearMapping::init_mapping() {
  const std::size_t n_in = in_size();
  if (n_in < 2) {
    msg_error("the input needs at least 2 rigid frames (it has " + std::to_string(n_in) + ")");
    return false;
  }
  const std::vector<double>& xf = in_coord(kPosition);
  length_.assign(n_in, 0.0);
  for (std::size_t i = 0; i + 1 < n_in; ++i) {
    const double d0 = xf[i * 7] - xf[(i + 1) * 7], d1 = xf[i * 7 + 1] - xf[(i + 1) * 7 + 1],
                 d2 = xf[i * 7 + 2] - xf[(i + 1) * 7 + 2];
    length_[i] = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
  }
  length_[n_in - 1] = length_[n_in - 2];
  const std::vector<double>& x = initial_output_positions();
  const std::size_t n = x.size() / 3;
  points_.assign(n * 3, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double* p = &points_[i * 3];
    if (local_coord.value()) {
      p[0] = x[i * 3], p[1] = x[i * 3 + 1], p[2] = x[i * 3 + 2];
      continue;
    }
    // World → frame 0, then walk along the beams.
    const double d[3] = {x[i * 3] - xf[0], x[i * 3 + 1] - xf[1], x[i * 3 + 2] - xf[2]};
    const double qi[4] = {-xf[3], -xf[4], -xf[5], xf[6]};
    quat_rotate(qi, d, p);
    std::size_t j = 0;
    while (j < length_.size() && p[0] >= length_[j]) {
      p[0] -= length_[j];
      ++j;
    }
    if (j == length_.size()) j = length_.size() - 1;
    for (int c = 0; c < 3; ++c) p[c] /= length_[j];
    p[0] += static_cast<double>(j);
  }
  r0_.assign(n * 3, 0.0);
  r1_.assign(n * 3, 0.0);
  resize_output(n);
  return true;
}

void BeamLinearMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const std::vector<double>& in = in_coord(x);
  const std::size_t n_in = in.size() / 7, n = points_.size() / 3;
  std::vector<double>& out = *outp;
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    double l0[3];
    const int j = beam_of(&points_[i * 3], n_in, l0);
    const double l1[3] = {l0[0] - 1, l0[1], l0[2]};
    const double* c0 = &in[j * 7];
    const double* c1 = &in[(j + 1) * 7];
    double* r0 = &r0_[i * 3];
    double* r1 = &r1_[i * 3];
    quat_rotate(c0 + 3, l0, r0);
    quat_rotate(c1 + 3, l1, r1);
    const double L = length_[j];
    const double h = smooth(l0[0]);
    for (int c = 0; c < 3; ++c) {
      r0[c] *= L;
      r1[c] *= L;
      const double o0 = c0[c] + r0[c], o1 = c1[c] + r1[c];
      out[i * 3 + c] = o0 * (1 - h) + o1 * h;
    }
  }
}

void BeamLinearMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  const std::vector<double>& in = in_deriv_write(v, role);
  const std::size_t n_in = in.size() / 6, n = points_.size() / 3;
  std::vector<double>& out = *outp;
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    double l0[3];
    const int j = beam_of(&points_[i * 3], n_in, l0);
    const double* d0 = &in[j * 6];
    const double* d1 = &in[(j + 1) * 6];
    const double* r0 = &r0_[i * 3];
    const double* r1 = &r1_[i * 3];
    const double h = smooth(l0[0]);
    // v − r × ω (SOFA's form of v + ω × r)
    const double a[3] = {d0[0] - (r0[1] * d0[5] - r0[2] * d0[4]), d0[1] - (r0[2] * d0[3] - r0[0] * d0[5]),
                         d0[2] - (r0[0] * d0[4] - r0[1] * d0[3])};
    const double b[3] = {d1[0] - (r1[1] * d1[5] - r1[2] * d1[4]), d1[1] - (r1[2] * d1[3] - r1[0] * d1[5]),
                         d1[2] - (r1[0] * d1[4] - r1[1] * d1[3])};
    for (int c = 0; c < 3; ++c) out[i * 3 + c] = a[c] * (1 - h) + b[c] * h;
  }
}

void BeamLinearMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n_in = in.size() / 6, n = std::min(points_.size() / 3, out.size() / 3);
  for (std::size_t i = 0; i < n; ++i) {
    double l0[3];
    const int j = beam_of(&points_[i * 3], n_in, l0);
    const double* fi = &out[i * 3];
    const double* r0 = &r0_[i * 3];
    const double* r1 = &r1_[i * 3];
    const double h = smooth(l0[0]);
    double* g0 = &in[j * 6];
    double* g1 = &in[(j + 1) * 6];
    const double t0[3] = {r0[1] * fi[2] - r0[2] * fi[1], r0[2] * fi[0] - r0[0] * fi[2], r0[0] * fi[1] - r0[1] * fi[0]};
    const double t1[3] = {r1[1] * fi[2] - r1[2] * fi[1], r1[2] * fi[0] - r1[0] * fi[2], r1[0] * fi[1] - r1[1] * fi[0]};
    for (int c = 0; c < 3; ++c) g0[c] += fi[c] * (1 - h);
    for (int c = 0; c < 3; ++c) g0[3 + c] += t0[c] * (1 - h);
    for (int c = 0; c < 3; ++c) g1[c] += fi[c] * h;
    for (int c = 0; c < 3; ++c) g1[3 + c] += t1[c] * h;
  }
}

bool BeamLinearMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::size_t n_in = in_size(), n = points_.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    double l0[3];
    const int j = beam_of(&points_[i * 3], n_in, l0);
    const double h = smooth(l0[0]);
    const std::uint32_t row = static_cast<std::uint32_t>(i * 3);
    for (int side = 0; side < 2; ++side) {
      const double w = side == 0 ? 1 - h : h;
      const double* r = side == 0 ? &r0_[i * 3] : &r1_[i * 3];
      const std::uint32_t col = static_cast<std::uint32_t>((j + side) * 6);
      // Off-diagonal entries are emitted even when zero: the pattern must not
      // depend on the values (assembled systems reuse it from step to step).
      const double m[3][3] = {{0, r[2], -r[1]}, {-r[2], 0, r[0]}, {r[1], -r[0], 0}};  // ω ↦ ω × r
      for (std::uint32_t a = 0; a < 3; ++a) {
        out.push_back({0, row + a, col + a, w});
        for (std::uint32_t b = 0; b < 3; ++b)
          if (a != b) out.push_back({0, row + a, col + 3 + b, m[a][b] * w});
      }
    }
  }
  return true;
}

void register_beam_linear_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "BeamLinearMapping";
  info.category = "Mapping/Linear";
  info.description = "points attached to a chain of rigid beams (smooth interpolation between frames)";
  info.templates = {"Rigid3d,Vec3d"};
  info.default_template = "Rigid3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string&) -> std::unique_ptr<Component> { return std::make_unique<BeamLinearMapping>(); };
  r.add(std::move(info));
}

}  // namespace sinew
