#include "mapping/nonlinear/rigid_mapping.h"

#include <Eigen/Eigenvalues>

#include <cmath>

#include "core/registry.h"
#include "core/value_text.h"
#include "math/quat.h"

namespace sinew {

namespace {

// SOFA's Quat::rotate: t = 2·(q⃗ × v); r = v + w·t + q⃗ × t (same operation order).
inline void quat_rotate(double qx, double qy, double qz, double qw, const double* v, double* r) {
  const double t0 = (qy * v[2] - qz * v[1]) * 2;
  const double t1 = (qz * v[0] - qx * v[2]) * 2;
  const double t2 = (qx * v[1] - qy * v[0]) * 2;
  r[0] = v[0] + qw * t0 + (qy * t2 - qz * t1);
  r[1] = v[1] + qw * t1 + (qz * t0 - qx * t2);
  r[2] = v[2] + qw * t2 + (qx * t1 - qy * t0);
}

}  // namespace

bool RigidMapping::init_mapping() {
  rigid_out_ = out_type() == StateType::rigid3;
  dim_ = state_type_info(out_type()).coord_width;  // Vec3d: 3, Vec2d: 2, Rigid3d: 7
  dw_ = state_type_info(out_type()).deriv_width;
  pd_ = state_type_info(out_type()).spatial_dim;
  gs_ = geometric_stiffness_id(geometric_stiffness.get(), 0);
  if (gs_ < 0) {
    msg_error("geometricStiffness must be None, Exact or Stabilized (0, 1 or 2), not " +
              quote_value(geometric_stiffness.get()));
    return false;
  }
  if (gs_ != 0 && !rigid3()) {
    msg_error("geometricStiffness Exact and Stabilized are for Rigid3d inputs only (SOFA has none in 2D)");
    return false;
  }
  if (!filename.value().empty()) {
    msg_error("loading local coordinates from a file (filename=" + quote_value(filename.value()) +
              ") is not supported");
    return false;
  }
  const std::size_t n_in = in_size();
  if (n_in == 0) {
    msg_error("the input state has no rigid DoF");
    return false;
  }
  const int cw_in = state_type_info(in_type()).coord_width;
  std::vector<double> pts = initial_points.get();
  const std::vector<double>& x_out = initial_output_positions();
  const std::size_t n_out = x_out.size() / dim_;
  const std::vector<unsigned>& per_point = rigid_index_per_point.get();

  // Rigid index of each point (SOFA's getRigidIndex, on the number of local points).
  auto rigid_of = [&](std::size_t i, std::size_t n_points) -> long long {
    if (per_point.size() == n_points) return per_point[i];
    if (!index_from_end.value()) return index.value();
    return static_cast<long long>(n_in) - 1 - static_cast<long long>(index.value());
  };

  if (pts.empty() && !use_x0.value()) {
    pts.assign(n_out * dim_, 0.0);
    const std::vector<double>& x_in = in_coord(kPosition);
    for (std::size_t i = 0; i < n_out; ++i) {
      const double* p = &x_out[i * dim_];
      double* l = &pts[i * dim_];
      if (!global_to_local_coords.value()) {
        for (int c = 0; c < dim_; ++c) l[c] = p[c];
        continue;
      }
      const long long r = rigid_of(i, n_out);
      if (r < 0 || static_cast<std::size_t>(r) >= n_in) {
        msg_error("point " + std::to_string(i) + " is mapped from rigid " + std::to_string(r) + " but the input has " +
                  std::to_string(n_in) + " DoFs");
        return false;
      }
      const double* c = &x_in[r * cw_in];
      if (rigid_out_) {
        // Frame in the rigid's frame: centre by the inverse rotation, orientation q_r⁻¹·q.
        const Quat qi = quat_inverse(Quat::from(c + 3));
        const Vec3 lc = quat_rotate(qi, Vec3(p[0] - c[0], p[1] - c[1], p[2] - c[2]));
        for (int k = 0; k < 3; ++k) l[k] = lc[k];
        quat_mul(qi, Quat::from(p + 3)).store(l + 3);
      } else if (rigid3()) {
        const double d[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
        quat_rotate(-c[3], -c[4], -c[5], c[6], d, l);  // inverse rotation
      } else {
        const double s = std::sin(c[2]), co = std::cos(c[2]);
        const double d0 = p[0] - c[0], d1 = p[1] - c[1];
        l[0] = co * d0 + s * d1;
        l[1] = -s * d0 + co * d1;
      }
    }
    initial_points.set(pts);
  }
  const std::size_t n_pts = use_x0.value() ? n_out : pts.size() / dim_;
  if (!per_point.empty() && per_point.size() != n_pts)
    msg_warning("rigidIndexPerPoint has " + std::to_string(per_point.size()) + " entries for " +
                std::to_string(n_pts) + " mapped points: it is ignored and every point follows rigid " +
                (index_from_end.value() ? "index (from the end) " : "") + std::to_string(index.value()) +
                ", as in SOFA (it is not the old per-rigid point count)");
  local_ = std::move(pts);
  rigid_.assign(n_pts, 0);
  for (std::size_t i = 0; i < n_pts; ++i) {
    const long long r = rigid_of(i, n_pts);
    if (r < 0 || static_cast<std::size_t>(r) >= n_in) {
      msg_error("point " + std::to_string(i) + " is mapped from rigid " + std::to_string(r) + " but the input has " +
                std::to_string(n_in) + " DoFs");
      return false;
    }
    rigid_[i] = static_cast<unsigned>(r);
  }
  rotated_.assign(n_pts * pd_, 0.0);
  resize_output(n_pts);
  return true;
}

void RigidMapping::bind_contact_states(MechanicalState& in, MechanicalState& out) {
  in_ = {&in};
  out_ = &out;
  input.set_path("@" + in.name.value());
  input.set_targets({&in});
  output_link.set_path("@" + out.name.value());
  output_link.set_targets({&out});
  clear_points();
}

void RigidMapping::clear_points() {
  rigid_.clear();
  local_.clear();
  rotated_.clear();
}

unsigned RigidMapping::add_point(const Vec3& local, unsigned rigid) {
  rigid_.push_back(rigid);
  local_.insert(local_.end(), {local[0], local[1], local[2]});
  rotated_.insert(rotated_.end(), {0.0, 0.0, 0.0});
  return static_cast<unsigned>(rigid_.size() - 1);
}

void RigidMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const std::vector<double>& in = in_coord(x);
  const std::vector<double>* pts = &local_;
  if (use_x0.value() && out_) pts = &out_->read(kRestPosition);
  const std::size_t n = rigid_.size();
  std::vector<double>& out = *outp;
  out.resize(n * dim_);
  if (rigid_out_) {
    for (std::size_t i = 0; i < n; ++i) {
      const double* c = &in[rigid_[i] * 7];
      const double* l = &(*pts)[i * 7];
      double* rp = &rotated_[i * 3];
      quat_rotate(c[3], c[4], c[5], c[6], l, rp);
      double* o = &out[i * 7];
      o[0] = c[0] + rp[0];
      o[1] = c[1] + rp[1];
      o[2] = c[2] + rp[2];
      quat_mul(Quat::from(c + 3), Quat::from(l + 3)).store(o + 3);
    }
  } else if (rigid3()) {
    for (std::size_t i = 0; i < n; ++i) {
      const double* c = &in[rigid_[i] * 7];
      double* rp = &rotated_[i * 3];
      quat_rotate(c[3], c[4], c[5], c[6], &(*pts)[i * 3], rp);
      out[i * 3 + 0] = rp[0] + c[0];
      out[i * 3 + 1] = rp[1] + c[1];
      out[i * 3 + 2] = rp[2] + c[2];
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const double* c = &in[rigid_[i] * 3];
      const double* l = &(*pts)[i * 2];
      const double s = std::sin(c[2]), co = std::cos(c[2]);
      double* rp = &rotated_[i * 2];
      rp[0] = co * l[0] - s * l[1];
      rp[1] = s * l[0] + co * l[1];
      out[i * 2 + 0] = rp[0] + c[0];
      out[i * 2 + 1] = rp[1] + c[1];
    }
  }
}

void RigidMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  const std::vector<double>& in = in_deriv_write(v, role);
  const std::size_t n = rigid_.size();
  std::vector<double>& out = *outp;
  out.resize(n * dw_);
  if (rigid3()) {
    for (std::size_t i = 0; i < n; ++i) {
      const double* d = &in[rigid_[i] * 6];
      const double* p = &rotated_[i * 3];
      double* o = &out[i * dw_];
      // v + ω × p (and ω itself for frames)
      o[0] = d[0] + (d[4] * p[2] - d[5] * p[1]);
      o[1] = d[1] + (d[5] * p[0] - d[3] * p[2]);
      o[2] = d[2] + (d[3] * p[1] - d[4] * p[0]);
      if (rigid_out_) o[3] = d[3], o[4] = d[4], o[5] = d[5];
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const double* d = &in[rigid_[i] * 3];
      const double* p = &rotated_[i * 2];
      out[i * 2 + 0] = d[0] + -p[1] * d[2];
      out[i * 2 + 1] = d[1] + p[0] * d[2];
    }
  }
}

void RigidMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv_read(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv_write(f, role);
  const std::size_t n = std::min(rigid_.size(), out.size() / dw_);
  if (rigid_out_) {
    for (std::size_t i = 0; i < n; ++i) {
      double* d = &in[rigid_[i] * 6];
      const double* fi = &out[i * 6];
      const double* p = &rotated_[i * 3];
      d[0] += fi[0];
      d[1] += fi[1];
      d[2] += fi[2];
      // τ += τ_i + p × f
      d[3] += fi[3] + (p[1] * fi[2] - p[2] * fi[1]);
      d[4] += fi[4] + (p[2] * fi[0] - p[0] * fi[2]);
      d[5] += fi[5] + (p[0] * fi[1] - p[1] * fi[0]);
    }
  } else if (rigid3()) {
    for (std::size_t i = 0; i < n; ++i) {
      double* d = &in[rigid_[i] * 6];
      const double* fi = &out[i * 3];
      const double* p = &rotated_[i * 3];
      d[0] += fi[0];
      d[1] += fi[1];
      d[2] += fi[2];
      // τ += p × f
      d[3] += p[1] * fi[2] - p[2] * fi[1];
      d[4] += p[2] * fi[0] - p[0] * fi[2];
      d[5] += p[0] * fi[1] - p[1] * fi[0];
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      double* d = &in[rigid_[i] * 3];
      const double* fi = &out[i * 2];
      const double* p = &rotated_[i * 2];
      d[0] += fi[0];
      d[1] += fi[1];
      d[2] += p[0] * fi[1] - p[1] * fi[0];
    }
  }
}

void RigidMapping::stabilized_blocks() {
  const std::vector<double>& child_force = out_->read(kForce);
  const std::size_t frames = in_size();
  blocks_.assign(frames * 9, 0.0);
  has_children_.assign(frames, 0);
  const std::size_t n = std::min(rigid_.size(), child_force.size() / dw_);
  for (std::size_t i = 0; i < n; ++i) {
    const double* f = &child_force[i * dw_];  // the linear part for frames
    const double* p = &rotated_[i * 3];
    // SOFA's crossProductMatrix(f) · crossProductMatrix(p), summed k = 0, 1, 2.
    const double A[3][3] = {{0, -f[2], f[1]}, {f[2], 0, -f[0]}, {-f[1], f[0], 0}};
    const double B[3][3] = {{0, -p[2], p[1]}, {p[2], 0, -p[0]}, {-p[1], p[0], 0}};
    if (rigid_[i] >= frames) continue;  // a frame removed since the points were attached
    double* blk = &blocks_[rigid_[i] * 9];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) blk[a * 3 + b] += A[a][0] * B[0][b] + A[a][1] * B[1][b] + A[a][2] * B[2][b];
    has_children_[rigid_[i]] = 1;
  }
  for (std::size_t r = 0; r < frames; ++r) {
    if (!has_children_[r]) continue;
    double* blk = &blocks_[r * 9];
    for (int a = 0; a < 3; ++a)  // SOFA's symmetrize(): (a + b) · 0.5 on both sides
      for (int b = a + 1; b < 3; ++b) blk[a * 3 + b] = blk[b * 3 + a] = (blk[a * 3 + b] + blk[b * 3 + a]) * 0.5;
    // Negative semi-definite projection: positive eigenvalues set to zero, A = Q·diag(w)·Qᵀ.
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = blk[k];
    Eigen::SelfAdjointEigenSolver<Mat3> eig(m);
    if (eig.info() != Eigen::Success) continue;
    Vec3 w = eig.eigenvalues();
    bool modified = false;
    for (int c = 0; c < 3; ++c)
      if (w[c] > 0) {
        w[c] = 0;
        modified = true;
      }
    if (!modified) continue;
    const Mat3& Q = eig.eigenvectors();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        blk[a * 3 + b] = Q(a, 0) * w[0] * Q(b, 0) + Q(a, 1) * w[1] * Q(b, 1) + Q(a, 2) * w[2] * Q(b, 2);
  }
}

void RigidMapping::apply_djt(int df, int dx, double k) {
  if (gs_ == 0 || !out_ || !rigid3()) return;
  std::vector<double>& f = in_deriv_write(df, kDforce);
  const std::vector<double>& d = in_deriv_write(dx, kDx);
  if (gs_ == 2) {  // SOFA assembles the blocks, then adds k·K·dx
    stabilized_blocks();
    for (std::size_t r = 0; r < has_children_.size(); ++r) {
      if (!has_children_[r]) continue;
      const double* blk = &blocks_[r * 9];
      const double* w = &d[r * 6 + 3];
      double* t = &f[r * 6 + 3];
      for (int a = 0; a < 3; ++a) t[a] += (blk[a * 3] * w[0] + blk[a * 3 + 1] * w[1] + blk[a * 3 + 2] * w[2]) * k;
    }
    return;
  }
  const std::vector<double>& child_force = out_->read(kForce);
  const std::size_t n = std::min(rigid_.size(), child_force.size() / dw_);
  for (std::size_t i = 0; i < n; ++i) {
    const double* fi = &child_force[i * dw_];  // the linear part for frames
    const double* w = &d[rigid_[i] * 6 + 3];
    const double* p = &rotated_[i * 3];
    // torque −= k · f × (δω × p)
    const double c0 = w[1] * p[2] - w[2] * p[1];
    const double c1 = w[2] * p[0] - w[0] * p[2];
    const double c2 = w[0] * p[1] - w[1] * p[0];
    double* t = &f[rigid_[i] * 6 + 3];
    t[0] -= (fi[1] * c2 - fi[2] * c1) * k;
    t[1] -= (fi[2] * c0 - fi[0] * c2) * k;
    t[2] -= (fi[0] * c1 - fi[1] * c0) * k;
  }
}

bool RigidMapping::build_geometric_stiffness(MatrixSink& K) {
  if (gs_ == 0 || !out_) return true;
  if (gs_ == 1) return false;  // not symmetric: matrix-free only
  stabilized_blocks();
  const MechanicalState* s = in_[0];
  // All nine entries of each frame with points, zeros included: the pattern must not depend
  // on the values (assembled systems reuse it).
  for (std::size_t r = 0; r < has_children_.size(); ++r) {
    if (!has_children_[r]) continue;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) K.add(s, r * 6 + 3 + a, s, r * 6 + 3 + b, blocks_[r * 9 + a * 3 + b]);
  }
  return true;
}

bool RigidMapping::has_jt_entry() const { return rigid3() && out_ && out_->state_type() == StateType::vec3; }

void RigidMapping::jt_entry(unsigned out_dof, const double* v, ConstraintRowSink& sink) const {
  if (out_dof >= rigid_.size()) return;
  const double* p = &rotated_[out_dof * 3];
  const double t[6] = {v[0], v[1], v[2], p[1] * v[2] - p[2] * v[1], p[2] * v[0] - p[0] * v[2], p[0] * v[1] - p[1] * v[0]};
  sink.add(0, rigid_[out_dof], t);
}

bool RigidMapping::jacobian(std::vector<JacobianEntry>& out) {
  const int dw_in = state_type_info(in_type()).deriv_width;
  for (std::size_t i = 0; i < rigid_.size(); ++i) {
    const std::uint32_t col = rigid_[i] * dw_in;
    const std::uint32_t row = static_cast<std::uint32_t>(i * dw_);
    if (rigid3()) {
      const double* p = &rotated_[i * 3];
      // Off-diagonal entries are emitted even when zero: the pattern must not
      // depend on the values (assembled systems reuse it from step to step).
      const double m[3][3] = {{0, p[2], -p[1]}, {-p[2], 0, p[0]}, {p[1], -p[0], 0}};  // ω ↦ ω × p
      for (std::uint32_t a = 0; a < 3; ++a) {
        out.push_back({0, row + a, col + a, 1.0});
        for (std::uint32_t b = 0; b < 3; ++b)
          if (a != b) out.push_back({0, row + a, col + 3 + b, m[a][b]});
      }
      if (rigid_out_)
        for (std::uint32_t a = 0; a < 3; ++a) out.push_back({0, row + 3 + a, col + 3 + a, 1.0});
    } else {
      const double* p = &rotated_[i * 2];
      out.push_back({0, row, col, 1.0});
      out.push_back({0, row, col + 2, -p[1]});
      out.push_back({0, row + 1, col + 1, 1.0});
      out.push_back({0, row + 1, col + 2, p[0]});
    }
  }
  return true;
}

void register_rigid_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "RigidMapping";
  info.category = "Mapping/NonLinear";
  info.description = "points attached to rigid frames";
  info.templates = {"Rigid3d,Vec3d", "Rigid3d,Rigid3d", "Rigid2d,Vec2d"};
  info.default_template = "Rigid3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<RigidMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
