#include "forcefield/load/interaction_ellipsoid_force_field.h"

#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "math/sofa_vec.h"
#include "forcefield/load/ellipsoid_penalty.h"

namespace sinew {

namespace {
// SOFA's Quat::rotate (sign = +1) and inverseRotate (sign = −1):
// t = 2·(q×v), v + w·t + q×t.
inline void rotate(const double* q, const double* v, double* out, double sign) {
  const double qv[3] = {sign * q[0], sign * q[1], sign * q[2]};
  double t[3], u[3];
  sofa_cross(qv, v, t);
  for (double& c : t) c *= 2;
  sofa_cross(qv, t, u);
  for (int c = 0; c < 3; ++c) out[c] = v[c] + q[3] * t[c] + u[c];
}
}  // namespace

void InteractionEllipsoidForceField::init() {
  MechanicalState* local = node() ? node()->get_mechanical_state() : nullptr;
  s1_ = object1 ? object1.get() : local;
  s2_ = object2 ? object2.get() : local;
  if (!s1_ || !s2_) {
    msg_error("object1 and object2 must be mechanical states");
    set_state(ComponentState::invalid);
    return;
  }
  if (!mstate) mstate.set(s1_);
  if (s1_->state_type() != StateType::vec3 || s2_->state_type() != StateType::rigid3) {
    msg_error(std::string("object1 must be Vec3d and object2 Rigid3d (got ") + s1_->info().name + ", " +
              s2_->info().name + ")");
    set_state(ComponentState::invalid);
    return;
  }
  if (object2_invert.get()) {
    msg_error("object2_invert=\"true\" is not supported");
    set_state(ComponentState::invalid);
    return;
  }
  const int idx = object2_dof_index.get();
  if (idx < 0 || static_cast<std::size_t>(idx) >= s2_->size()) {
    msg_error("object2_dof_index " + std::to_string(idx) + " is out of range (object2 has " +
              std::to_string(s2_->size()) + " frames)");
    set_state(ComponentState::invalid);
    return;
  }
  // Missing entries repeat the last one (radius default 1, center 0).
  const auto& vr = vradius.get();
  const auto& vc = center.get();
  const std::size_t n = std::max(vr.size(), vc.size());
  c_.assign(n, Vec3::Zero());
  inv_r2_.assign(n, Vec3::Ones());
  for (std::size_t e = 0; e < n; ++e) {
    const Vec3 r = e < vr.size() ? vr[e] : (vr.empty() ? Vec3(1, 1, 1) : vr.back());
    c_[e] = e < vc.size() ? vc[e] : (vc.empty() ? Vec3::Zero() : vc.back());
    for (int j = 0; j < 3; ++j) {
      if (r[j] == 0) {
        msg_error("ellipsoid " + std::to_string(e) + " has a zero radius");
        set_state(ComponentState::invalid);
        return;
      }
      inv_r2_[e][j] = 1 / (r[j] * r[j]);
    }
  }
}

void InteractionEllipsoidForceField::add_force(const MechParams& p) {
  MechanicalState& a = *s1_;
  MechanicalState& b = *s2_;
  const std::vector<double>& x1 = a.read(vec_for(a, p.x, kPosition));
  const std::vector<double>& v1 = a.read(vec_for(a, p.v, kVelocity));
  std::vector<double>& f1 = a.write(vec_for(a, p.f, kForce));
  const std::vector<double>& x2 = b.read(vec_for(b, p.x, kPosition));
  const std::size_t k = static_cast<std::size_t>(object2_dof_index.value());
  const double* frame = &x2[7 * k];
  const double C[3] = {frame[0], frame[1], frame[2]};
  for (int i = 0; i < 4; ++i) q_[i] = frame[3 + i];
  const double ks = stiffness.value(), kd = damping.value();
  double f2[3] = {0, 0, 0};
  contacts_.clear();
  const std::size_t n = x1.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    const double rel[3] = {x1[3 * i] - C[0], x1[3 * i + 1] - C[1], x1[3 * i + 2] - C[2]};
    double pl[3], vl[3];
    rotate(q_, rel, pl, -1.0);
    rotate(q_, &v1[3 * i], vl, -1.0);
    // Nearest ellipsoid in the normalised metric (first one on ties).
    int be = -1;
    double bn2 = -1, bdp[3] = {0, 0, 0};
    for (std::size_t e = 0; e < c_.size(); ++e) {
      const double dp[3] = {pl[0] - c_[e][0], pl[1] - c_[e][1], pl[2] - c_[e][2]};
      double n2 = 0;
      for (int j = 0; j < 3; ++j) n2 += (dp[j] * dp[j]) * inv_r2_[e][j];
      if (be == -1 || n2 < bn2) {
        bn2 = n2;
        be = static_cast<int>(e);
        for (int j = 0; j < 3; ++j) bdp[j] = dp[j];
      }
    }
    if (be < 0) continue;
    EllipsoidPenalty pen;
    if (!ellipsoid_penalty(bdp, inv_r2_[be].data(), 3, ks, kd, vl, pen)) continue;
    const double* fl = pen.force;
    Contact c;
    c.index = static_cast<unsigned>(i);
    for (int ci = 0; ci < 3; ++ci)
      for (int cj = 0; cj < 3; ++cj) c.m[ci][cj] = pen.m[ci][cj];
    double fw[3];
    rotate(q_, fl, fw, 1.0);
    for (int j = 0; j < 3; ++j) {
      f1[3 * i + j] += fw[j];
      f2[j] -= fw[j];
    }
    contacts_.push_back(c);
  }
  if (object2_forces.value()) {
    std::vector<double>& f2v = b.write(vec_for(b, p.f, kForce));
    for (int j = 0; j < 3; ++j) f2v[6 * k + j] += f2[j];
  }
}

void InteractionEllipsoidForceField::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& a = *s1_;
  MechanicalState& b = *s2_;
  const std::vector<double>& dx1 = a.read(vec_for(a, p.dx, kDx));
  std::vector<double>& df1 = a.write(vec_for(a, p.df, kDforce));
  const std::size_t k = static_cast<std::size_t>(object2_dof_index.value());
  const bool two = object2_forces.value();
  double dx2[3] = {0, 0, 0};
  if (two) {
    const std::vector<double>& d2 = b.read(vec_for(b, p.dx, kDx));
    for (int j = 0; j < 3; ++j) dx2[j] = d2[6 * k + j];
  }
  double df2[3] = {0, 0, 0};
  for (const Contact& c : contacts_) {
    const double du[3] = {dx1[3 * c.index] - dx2[0], dx1[3 * c.index + 1] - dx2[1], dx1[3 * c.index + 2] - dx2[2]};
    double dl[3], dfl[3], dfw[3];
    rotate(q_, du, dl, -1.0);
    for (int i = 0; i < 3; ++i) dfl[i] = (c.m[i][0] * dl[0] + c.m[i][1] * dl[1] + c.m[i][2] * dl[2]) * kfactor;
    rotate(q_, dfl, dfw, 1.0);
    for (int j = 0; j < 3; ++j) {
      df1[3 * c.index + j] += dfw[j];
      df2[j] -= dfw[j];
    }
  }
  if (two) {
    std::vector<double>& d2 = b.write(vec_for(b, p.df, kDforce));
    for (int j = 0; j < 3; ++j) d2[6 * k + j] += df2[j];
  }
}

bool InteractionEllipsoidForceField::build_stiffness(MatrixSink& K) {
  // Block R·m·Rᵀ from the rotations of the basis vectors (SOFA's tangent).
  const std::size_t k = static_cast<std::size_t>(object2_dof_index.value());
  const bool two = object2_forces.value();
  for (const Contact& c : contacts_) {
    Mat3 blk;
    for (int col = 0; col < 3; ++col) {
      double e[3] = {0, 0, 0}, l[3], ml[3], w[3];
      e[col] = 1;
      rotate(q_, e, l, -1.0);
      for (int i = 0; i < 3; ++i) ml[i] = c.m[i][0] * l[0] + c.m[i][1] * l[1] + c.m[i][2] * l[2];
      rotate(q_, ml, w, 1.0);
      for (int r = 0; r < 3; ++r) blk(r, col) = w[r];
    }
    const std::size_t r1 = 3 * static_cast<std::size_t>(c.index);
    K.add_block(s1_, r1, s1_, r1, blk);
    if (two) {
      K.add_block(s1_, r1, s2_, 6 * k, -blk);
      K.add_block(s2_, 6 * k, s1_, r1, -blk);
      K.add_block(s2_, 6 * k, s2_, 6 * k, blk);
    }
  }
  return true;
}

void register_interaction_ellipsoid_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "InteractionEllipsoidForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "repulsion of points by ellipsoids attached to a rigid frame";
  info.templates = {"Vec3d,Rigid3d"};
  info.default_template = "Vec3d,Rigid3d";
  info.requirement = Requirement::none;
  info.create = creator<InteractionEllipsoidForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
