// ParabolicProjectiveConstraint: between BeginTime and EndTime the listed DoFs
// follow the parabola through P1, P2 and P3 (P1 at BeginTime, P3 at EndTime),
// SOFA's ParabolicProjectiveConstraint (templates Vec3d, Rigid3d: a frame's
// centre follows it, its orientation is kept).
//
// In the frame with origin P1, x along P1P3 and P2 in the xy plane, the
// point at relative time r = (t − t0)/(t1 − t0) is (x3·r, y(x3·r), 0) with
// y(X) = −y2/(x3·x2 − x2²)·X² + x3·y2/(x3·x2 − x2²)·X. The velocity is the
// difference of the positions at t + dt and t over dt (SOFA's), and while the
// motion lasts, the responses of the listed DoFs are zeroed. Outside
// [BeginTime, EndTime] the DoFs are free. Assembled systems are not projected
// (SOFA does not either).
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "core/constraint_matrix.h"
#include "core/node.h"
#include "core/roles.h"
#include "projective/indices_in_state.h"

namespace sinew {

class ParabolicProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit ParabolicProjectiveConstraint(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the constrained points", "Constraint"};
  Field<Vec3> p1{this, "P1", Vec3::Zero(), "first point of the parabola (at BeginTime)", "Constraint", "length"};
  Field<Vec3> p2{this, "P2", Vec3::Zero(), "second point of the parabola", "Constraint", "length"};
  Field<Vec3> p3{this, "P3", Vec3::Zero(), "third point of the parabola (at EndTime)", "Constraint", "length"};
  Field<double> t_begin{this, "BeginTime", 0.0, "begin time of the motion", "Constraint", "time"};
  Field<double> t_end{this, "EndTime", 0.0, "end time of the motion", "Constraint", "time"};
  Link<MeshTopologyBase> topology{this, "topology", "topology of the points (accepted)"};

  void init() override {
    if (!init_state_of_type(*this, type_)) return;
    cw_ = static_cast<unsigned>(mstate->info().coord_width);
    dw_ = static_cast<unsigned>(mstate->info().deriv_width);
    keep_indices_in_state(*this, indices.value(), mstate->size(), active_);
    const Vec3 a = p1.value(), b = p2.value(), c = p3.value();
    if (a == b || a == c || b == c) {
      msg_error("P1, P2 and P3 must be three distinct points");
      set_state(ComponentState::invalid);
      return;
    }
    if (!(t_end.value() > t_begin.value())) {
      msg_error("EndTime must be after BeginTime");
      set_state(ComponentState::invalid);
      return;
    }
    const Vec3 p1p2 = b - a, p1p3 = c - a;
    Vec3 az = p1p3.cross(p1p2), ax = p1p3, ay = az.cross(ax);
    if (!(az.norm() > 0)) {
      msg_error("P1, P2 and P3 are aligned: they define no parabola");
      set_state(ComponentState::invalid);
      return;
    }
    ax.normalize();
    ay.normalize();
    az.normalize();
    rot_.col(0) = ax;
    rot_.col(1) = ay;
    rot_.col(2) = az;
    loc2_ = rot_.transpose() * p1p2;
    loc3_ = rot_.transpose() * p1p3;
    const double den = loc3_.x() * loc2_.x() - loc2_.x() * loc2_.x();
    if (den == 0) {
      msg_error("P2 projects onto P1 or P3 along P1P3: the parabola is vertical");
      set_state(ComponentState::invalid);
    }
  }

  void project_response(int dx) override {
    if (!active_now()) return;
    std::vector<double>& d = mstate->write(dx);
    for (unsigned i : active_)
      for (unsigned c = 0; c < dw_; ++c) d[i * dw_ + c] = 0.0;
  }

  void project_jacobian(ConstraintMatrix& J) override {
    if (!active_now()) return;
    for (unsigned i : active_) J.zero_dof(static_cast<int>(i), 0, J.width());
  }

  void project_velocity(int vid, double) override {
    if (!active_now()) return;
    const double t = node()->time.value(), dt = node()->dt.value();
    const Vec3 now = local(relative(t)), next = local(relative(t + dt));
    const Vec3 vel = rot_ * Vec3((next.x() - now.x()) / dt, (next.y() - now.y()) / dt, 0.0);
    std::vector<double>& v = mstate->write(vid);
    for (unsigned i : active_)
      for (int c = 0; c < 3; ++c) v[i * dw_ + static_cast<unsigned>(c)] = vel[c];
  }

  void project_position(int xid, double) override {
    if (!active_now()) return;
    const Vec3 pos = path_point(relative(node()->time.value()));
    std::vector<double>& x = mstate->write(xid);
    for (unsigned i : active_)
      for (int c = 0; c < 3; ++c) x[i * cw_ + static_cast<unsigned>(c)] = pos[c];
  }

  // The parabola's point at relative time r (P1 at 0, P3 at 1); valid components only.
  Vec3 path_point(double r) const { return p1.value() + rot_ * local(r); }

 private:
  bool active_now() const {
    if (state() != ComponentState::valid) return false;
    const double t = node()->time.value();
    return t >= t_begin.value() && t <= t_end.value();
  }
  double relative(double t) const { return (t - t_begin.value()) / (t_end.value() - t_begin.value()); }
  // The parabola's point at relative time r, in its own frame.
  Vec3 local(double r) const {
    const double x2 = loc2_.x(), y2 = loc2_.y(), x3 = loc3_.x();
    const double den = x3 * x2 - x2 * x2;
    const double px = x3 * r;
    return Vec3(px, (-y2 / den) * (px * px) + ((x3 * y2) / den) * px, 0.0);
  }

  StateType type_;
  unsigned cw_ = 3, dw_ = 3;
  std::vector<unsigned> active_;
  Mat3 rot_ = Mat3::Identity();  // columns: the parabola's frame axes
  Vec3 loc2_ = Vec3::Zero(), loc3_ = Vec3::Zero();
};

}  // namespace sinew
