#include "constraint/model/unilateral_lagrangian_constraint.h"

#include <cmath>

#include <Eigen/Geometry>

#include "core/registry.h"

namespace sinew {

void UnilateralLagrangianConstraint::clear(std::size_t reserve) {
  contacts_.clear();
  contacts_.reserve(reserve);
}

void UnilateralLagrangianConstraint::add_contact(double mu, const Vec3& normal, double distance, int m1, int m2,
                                                 std::int64_t id, std::int64_t local_id, double epsilon) {
  Contact c;
  c.m1 = m1;
  c.m2 = m2;
  c.P = as_vec3(s2_->read(kPosition))[m2];
  c.Q = as_vec3(s1_->read(kPosition))[m1];
  c.n = normal;
  // SOFA's tangent frame: t0 = (n.z, n.x, n.y), s = n × t0 normalised, t = (−n) × s.
  const Vec3 t0(normal.z(), normal.x(), normal.y());
  c.s = normal.cross(t0);
  c.s = c.s / c.s.norm();
  c.t = (-normal).cross(c.s);
  c.distance = distance;
  c.mu = mu;
  c.epsilon = epsilon;
  c.id = id;
  c.local_id = local_id;
  contacts_.push_back(c);
}

void UnilateralLagrangianConstraint::build_constraint_matrix(const ConstraintParams&, int& row) {
  ConstraintMatrix& c1 = s1_->constraint_jacobian();
  ConstraintMatrix& c2 = s2_->constraint_jacobian();
  for (Contact& c : contacts_) {
    c.row = row;
    const int rows = c.mu > 0.0 ? 3 : 1;
    const Vec3* dirs[3] = {&c.n, &c.t, &c.s};
    for (int k = 0; k < rows; ++k) {
      const Vec3 d = *dirs[k];
      const Vec3 nd = -d;
      c1.add(row + k, c.m1, nd.data());
      c2.add(row + k, c.m2, d.data());  // same matrix for self-collision: summed by compress()
    }
    row += rows;
  }
}

void UnilateralLagrangianConstraint::constraint_violation(const ConstraintParams& p, std::vector<double>& dfree) {
  if (p.order == ConstraintOrder::vel || p.order == ConstraintOrder::acc) {
    const auto P = as_vec3(s2_->read(kPosition));
    const auto Q = as_vec3(s1_->read(kPosition));
    const auto vp = as_vec3(s2_->read(kFreeVelocity));
    const auto vq = as_vec3(s1_->read(kFreeVelocity));
    const double inv_dt = 1.0 / p.dt;
    for (Contact& c : contacts_) {
      const Vec3 qp_inv_dt = (P[c.m2] - Q[c.m1]) * inv_dt;
      const Vec3 qp_vfree = vp[c.m2] - vq[c.m1];
      const Vec3 d = qp_vfree + qp_inv_dt;
      dfree[c.row] = d.dot(c.n) - c.distance * inv_dt;
      if (c.mu > 0.0) {
        dfree[c.row + 1] = qp_vfree.dot(c.t);
        dfree[c.row + 2] = qp_vfree.dot(c.s);
      }
    }
    return;
  }
  const auto pfree = as_vec3(s2_->read(kFreePosition));
  const auto qfree = as_vec3(s1_->read(kFreePosition));
  for (Contact& c : contacts_) {
    const Vec3& Pf = pfree[c.m2];
    const Vec3& Qf = qfree[c.m1];
    const Vec3 ppf = Pf - c.P, qqf = Qf - c.Q;
    const double ref = ppf.norm() + qqf.norm();
    const double d = (Pf - Qf).dot(c.n) - c.distance;
    const double delta = (c.P - c.Q).dot(c.n) - c.distance;
    double dt_ = 0.0, ds_ = 0.0;
    auto full = [&] {
      dt_ = ppf.dot(c.t) - qqf.dot(c.t);
      ds_ = ppf.dot(c.s) - qqf.dot(c.s);
    };
    if (std::fabs(delta) < 0.00001 * ref && std::fabs(d) < 0.00001 * ref) {
      full();
    } else if (std::fabs(delta - d) > 0.001 * delta) {
      // Only the motion after the moment of contact slides (linear in between).
      const double tau = delta / (delta - d);
      if (tau > 0.0 && tau < 1.0) {
        const Vec3 Pt = c.P * (1 - tau) + Pf * tau;
        const Vec3 Qt = c.Q * (1 - tau) + Qf * tau;
        const Vec3 ptpf = Pf - Pt, qtqf = Qf - Qt;
        dt_ = ptpf.dot(c.t) - qtqf.dot(c.t);
        ds_ = ptpf.dot(c.s) - qtqf.dot(c.s);
      } else if (d < 0.0) {
        full();
      }
    } else {
      full();
    }
    dfree[c.row] = d;
    c.dfree = d;
    if (c.mu > 0.0) {
      dfree[c.row + 1] = dt_;
      dfree[c.row + 2] = ds_;
    }
  }
}

void UnilateralLagrangianConstraint::constraint_resolutions(const ConstraintParams&, std::vector<ConstraintBlock>& out) {
  for (Contact& c : contacts_) {
    c.active = false;
    ConstraintBlock b;
    b.first = c.row;
    if (c.mu > 0.0) {
      b.kind = augmented ? ConstraintBlock::Kind::augmented_friction : ConstraintBlock::Kind::unilateral_friction;
      b.rows = 3;
      b.mu = c.mu;
      b.epsilon = c.epsilon;
      b.tolerance = custom_tolerance;
      b.active = &c.active;
    } else {
      b.kind = ConstraintBlock::Kind::unilateral;
      b.rows = 1;
    }
    out.push_back(b);
  }
}

void UnilateralLagrangianConstraint::constraint_info(std::vector<BlockInfo>& blocks, std::vector<std::int64_t>& ids) {
  if (contacts_.empty()) return;
  BlockInfo info;
  info.parent = this;
  info.first_row = contacts_[0].row;
  // SOFA reads the friction of the first contact only for the whole set.
  info.lines = contacts_[0].mu > 0.0 ? 3 : 1;
  info.has_id = true;
  info.offset = static_cast<int>(ids.size());
  info.groups = static_cast<int>(contacts_.size());
  // A contact set seen for the first time gives negated ids, so that its
  // forces are only reused from the step after next (SOFA's yetIntegrated).
  for (const Contact& c : contacts_) ids.push_back(yet_integrated ? c.id : -c.id);
  yet_integrated = true;
  blocks.push_back(info);
}

}  // namespace sinew
