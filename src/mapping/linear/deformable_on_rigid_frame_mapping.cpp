#include "mapping/linear/deformable_on_rigid_frame_mapping.h"

#include <string>

#include "core/node.h"
#include "core/registry.h"
#include "math/quat.h"

namespace sinew {

namespace {

// SOFA's Quat::toMatrix (row-major), valid for a unit quaternion only, as used there.
void quat_matrix(const double* q, double m[9]) {
  m[0] = 1 - 2 * (q[1] * q[1] + q[2] * q[2]);
  m[1] = 2 * (q[0] * q[1] - q[2] * q[3]);
  m[2] = 2 * (q[2] * q[0] + q[1] * q[3]);
  m[3] = 2 * (q[0] * q[1] + q[2] * q[3]);
  m[4] = 1 - 2 * (q[2] * q[2] + q[0] * q[0]);
  m[5] = 2 * (q[1] * q[2] - q[0] * q[3]);
  m[6] = 2 * (q[2] * q[0] - q[1] * q[3]);
  m[7] = 2 * (q[1] * q[2] + q[0] * q[3]);
  m[8] = 1 - 2 * (q[1] * q[1] + q[0] * q[0]);
}

// a × b, SOFA's component order.
inline void cross(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace

DeformableOnRigidFrameMapping::DeformableOnRigidFrameMapping()
    : input1(this, "input1", "the deformable points, in the frame (Vec3d)", /*multi=*/true, false),
      input2(this, "input2", "the rigid frames (Rigid3d)", /*multi=*/true, false),
      output_link(this, "output", "the mapped points (Vec3d)", /*multi=*/true, false) {}

std::vector<MechanicalState*> DeformableOnRigidFrameMapping::inputs() const {
  std::vector<MechanicalState*> v;
  if (in_) v.push_back(in_);
  if (root_) v.push_back(root_);
  return v;
}

bool DeformableOnRigidFrameMapping::resolve_links() {
  in_ = first_link_state(*this, input1, StateType::vec3, "input1");
  if (!in_) return false;
  out_ = first_link_state(*this, output_link, StateType::vec3, "output");
  if (!out_) return false;
  root_ = nullptr;
  if (!input2.targets().empty()) {
    root_ = first_link_state(*this, input2, StateType::rigid3, "input2");
    if (!root_) return false;
  } else {
    warned_no_root_ = true;
    msg_warning("input2 (the rigid frames) is not set: the output copies input1 and constraint rows stop here "
                "(SOFA's 'NO ROOT MODEL')");
  }
  if (in_ == out_ || root_ == out_) {
    msg_error("an input is also the output");
    return false;
  }
  return true;
}

void DeformableOnRigidFrameMapping::init() {
  if (!resolve_links()) {
    set_state(ComponentState::invalid);
    return;
  }
  if (out_->size() != in_->size()) out_->resize(in_->size());
  rotated_.assign(in_->size() * 3, 0.0);
  apply(kPosition);
  apply_j(kVelocity, kVelocity);
  if (apply_rest_position.value()) apply(kRestPosition);
}

long DeformableOnRigidFrameMapping::frame(std::size_t frames, std::size_t from_end_count) {
  const long i = index_from_end.value() ? static_cast<long>(from_end_count) - 1 - static_cast<long>(index.value())
                                        : static_cast<long>(index.value());
  if (i >= 0 && static_cast<std::size_t>(i) < frames) return i;
  if (!warned_range_) {
    warned_range_ = true;
    msg_error("frame " + std::to_string(i) + " (index " + std::to_string(index.value()) +
              (index_from_end.value() ? ", from the end" : "") + ") does not exist: input2 has " +
              std::to_string(frames) + " frames; the mapping is skipped");
  }
  return -1;
}

void DeformableOnRigidFrameMapping::apply(int x) {
  const std::vector<double>& in = in_->read(vec_for(*in_, x, kPosition));
  std::vector<double>& out = out_->write(vec_for(*out_, x, kPosition));
  const std::size_t n = std::min(in.size(), out.size()) / 3;
  rotated_.resize(n * 3);
  if (!root_) {
    for (int k = 0; k < 7; ++k) root_x_[k] = k == 6 ? 1.0 : 0.0;
    for (std::size_t k = 0; k < n * 3; ++k) rotated_[k] = out[k] = in[k];
    return;
  }
  const std::vector<double>& rigid = root_->read(vec_for(*root_, x, kPosition));
  const std::size_t frames = rigid.size() / 7;
  double m[9];
  // Points [first, first + count) on frame f.
  auto map_points = [&](std::size_t f, std::size_t first, std::size_t count) {
    const double* c = &rigid[f * 7];
    quat_matrix(c + 3, m);
    for (int k = 0; k < 7; ++k) root_x_[k] = c[k];
    for (std::size_t i = first; i < first + count; ++i) {
      const double* p = &in[i * 3];
      double* r = &rotated_[i * 3];
      for (int a = 0; a < 3; ++a) {
        r[a] = m[a * 3] * p[0] + m[a * 3 + 1] * p[1] + m[a * 3 + 2] * p[2];
        out[i * 3 + a] = r[a] + c[a];
      }
    }
  };
  const std::vector<unsigned>& rep = repartition.value();
  if (rep.empty()) {
    const long f = frame(frames, frames);
    if (f >= 0) map_points(static_cast<std::size_t>(f), 0, n);
    return;
  }
  if (rep.size() != 1 && rep.size() != frames) {
    if (!warned_repartition_) {
      warned_repartition_ = true;
      msg_error("repartition has " + std::to_string(rep.size()) + " values for " + std::to_string(frames) +
                " frames (one value, or one per frame): the mapping is skipped");
    }
    return;
  }
  std::size_t next = 0;
  for (std::size_t f = 0; f < frames; ++f) {
    std::size_t count = rep.size() == 1 ? rep[0] : rep[f];
    if (next + count > n) {
      if (!warned_repartition_) {
        warned_repartition_ = true;
        msg_error("repartition maps more points than the " + std::to_string(n) + " of input1: the rest is skipped");
      }
      count = n - next;
    }
    map_points(f, next, count);
    next += count;
  }
}

void DeformableOnRigidFrameMapping::apply_j(int v, int role) {
  const std::vector<double>& in = in_->read(vec_for(*in_, v, role));
  std::vector<double>& out = out_->write(vec_for(*out_, v, role));
  const std::size_t n = std::min({in.size(), out.size(), rotated_.size()}) / 3;
  if (!root_) {
    for (std::size_t k = 0; k < n * 3; ++k) out[k] = in[k];
    return;
  }
  const std::vector<double>& rigid = root_->read(vec_for(*root_, v, role));
  const long f = frame(rigid.size() / 6, rigid.size() / 6);
  if (f < 0) return;
  const double* vel = &rigid[f * 6];
  const double* omega = vel + 3;
  const Quat q = Quat::from(root_x_ + 3);
  for (std::size_t i = 0; i < n; ++i) {
    double o[3];
    cross(omega, &rotated_[i * 3], o);
    const Vec3 r = quat_rotate(q, Vec3(in[i * 3], in[i * 3 + 1], in[i * 3 + 2]));
    for (int a = 0; a < 3; ++a) out[i * 3 + a] = o[a] + r[a] + vel[a];
  }
}

void DeformableOnRigidFrameMapping::apply_jt(int fid, int role) {
  const std::vector<double>& f = out_->read(vec_for(*out_, fid, role));
  std::vector<double>& in = in_->write(vec_for(*in_, fid, role));
  const std::size_t n = std::min({in.size(), f.size(), rotated_.size()}) / 3;
  if (!root_) {
    for (std::size_t k = 0; k < n * 3; ++k) in[k] = f[k];  // SOFA assigns here
    return;
  }
  std::vector<double>& rf = root_->write(vec_for(*root_, fid, role));
  const long fr = frame(rf.size() / 6, rf.size() / 6);
  if (fr < 0) return;
  double v[3] = {0, 0, 0}, w[3] = {0, 0, 0}, t[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double* fi = &f[i * 3];
    cross(&rotated_[i * 3], fi, t);
    for (int a = 0; a < 3; ++a) {
      v[a] += fi[a];
      w[a] += t[a];
    }
  }
  for (int a = 0; a < 3; ++a) {
    rf[fr * 6 + a] += v[a];
    rf[fr * 6 + 3 + a] += w[a];
  }
  const Quat q = Quat::from(root_x_ + 3);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r = quat_inverse_rotate(q, Vec3(f[i * 3], f[i * 3 + 1], f[i * 3 + 2]));
    for (int a = 0; a < 3; ++a) in[i * 3 + a] += r[a];
  }
}

// J as apply_j computes it: per point the 3×3 block of q·(·)·q⁻¹ on input1
// (columns = the rotation of unit vectors), and [I | −[r_i]×] on the frame.
// Every block entry is emitted, zeros included, so the pattern is fixed.
bool DeformableOnRigidFrameMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::size_t n = points();
  if (!root_) {
    for (std::size_t k = 0; k < n * 3; ++k)
      out.push_back({0, static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k), 1.0});
    return true;
  }
  const long f = frame(root_->size(), root_->size());
  if (f < 0) return false;
  const Quat q = Quat::from(root_x_ + 3);
  Vec3 col[3];
  for (int b = 0; b < 3; ++b) col[b] = quat_rotate(q, Vec3::Unit(b));
  const std::uint32_t fc = static_cast<std::uint32_t>(f) * 6;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t row = static_cast<std::uint32_t>(i * 3);
    for (std::uint32_t a = 0; a < 3; ++a)
      for (std::uint32_t b = 0; b < 3; ++b) out.push_back({0, row + a, row + b, col[b][a]});
    const double* r = &rotated_[i * 3];
    const double skew[3][3] = {{0, r[2], -r[1]}, {-r[2], 0, r[0]}, {r[1], -r[0], 0}};
    for (std::uint32_t a = 0; a < 3; ++a) {
      out.push_back({1, row + a, fc + a, 1.0});
      for (std::uint32_t b = 0; b < 3; ++b) out.push_back({1, row + a, fc + 3 + b, skew[a][b]});
    }
  }
  return true;
}

// SOFA's applyJT on constraint rows: per row, the point entries rotated back
// into the frame on input1, and one frame entry (scaled sums) on input2.
bool DeformableOnRigidFrameMapping::apply_jt_constraints() {
  ConstraintMatrix& c = out_->constraint_jacobian();
  if (c.empty()) return true;
  if (!root_) return true;  // SOFA carries nothing without a frame
  c.compress();
  // SOFA counts indexFromEnd on input1's size here.
  const long f = frame(root_->size(), in_->size());
  if (f < 0) return true;
  ConstraintMatrix& j1 = in_->constraint_jacobian();
  ConstraintMatrix& j2 = root_->constraint_jacobian();
  const Quat q = Quat::from(root_x_ + 3);
  const double sl = root_linear_force_scale_factor.value(), sa = root_angular_force_scale_factor.value();
  const std::size_t n = points();
  const auto entries = c.entries();
  for (const ConstraintMatrix::Row& row : c.rows()) {
    if (row.end <= row.begin) continue;
    double v[3] = {0, 0, 0}, w[3] = {0, 0, 0}, t[3];
    for (int e = row.begin; e < row.end; ++e) {
      const std::size_t node = static_cast<std::size_t>(entries[e].dof);
      if (node >= n) continue;
      const double* fv = c.value(e);
      cross(&rotated_[node * 3], fv, t);
      for (int a = 0; a < 3; ++a) {
        v[a] += fv[a];
        w[a] += t[a];
      }
      const Vec3 local = quat_inverse_rotate(q, Vec3(fv[0], fv[1], fv[2]));
      j1.add(row.id, static_cast<int>(node), local.data());
    }
    const double frame_row[6] = {sl * v[0], sl * v[1], sl * v[2], sa * w[0], sa * w[1], sa * w[2]};
    j2.add(row.id, static_cast<int>(f), frame_row);
  }
  return true;
}

void register_deformable_on_rigid_frame_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "DeformableOnRigidFrameMapping";
  info.category = "Mapping/Linear";
  info.description = "points of a deformable state expressed in a rigid frame (inputs Vec3d and Rigid3d)";
  info.templates = {"Vec3d,Rigid3d,Vec3d"};
  info.default_template = "Vec3d,Rigid3d,Vec3d";
  info.create = creator<DeformableOnRigidFrameMapping>();
  r.add(std::move(info));
}

}  // namespace sinew
