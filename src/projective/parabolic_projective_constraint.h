// ParabolicProjectiveConstraint: between BeginTime and EndTime the listed DoFs
// follow the parabola through P1, P2 and P3 (P1 at BeginTime, P3 at EndTime),
// SOFA's ParabolicProjectiveConstraint (templates Vec3d, Rigid3d: a frame's
// centre follows it, its orientation is kept).
//
// In the frame with origin P1, x along P1P3 and P2 in the xy plane, the
// point at relative time r = (t − t0)/(t1 − t0) is (x3·r, y(x3·r), 0) with
// y(X) = −y2/(x3·x2 − x2²)·X² + x3·y2/(x3·x2 − x2²)·X. The velocity is the
// difference of the positions at t + dt and t over dt (SOFA's). The time
// window and what it zeroes are TimedPathConstraint's.
#pragma once

#include <Eigen/Geometry>

#include "core/node.h"
#include "projective/timed_path_constraint.h"

namespace sinew {

class ParabolicProjectiveConstraint final : public TimedPathConstraint {
 public:
  explicit ParabolicProjectiveConstraint(StateType t) : TimedPathConstraint(t) {}

  Field<Vec3> p1{this, "P1", Vec3::Zero(), "first point of the parabola (at BeginTime)", "Constraint", "length"};
  Field<Vec3> p2{this, "P2", Vec3::Zero(), "second point of the parabola", "Constraint", "length"};
  Field<Vec3> p3{this, "P3", Vec3::Zero(), "third point of the parabola (at EndTime)", "Constraint", "length"};

  void init() override {
    TimedPathConstraint::init();
    if (state() != ComponentState::valid) return;
    const Vec3 a = p1.value(), b = p2.value(), c = p3.value();
    if (a == b || a == c || b == c) {
      msg_error("P1, P2 and P3 must be three distinct points");
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

  void project_velocity(int vid, double) override {
    if (!active_now()) return;
    const double t = node()->time.value(), dt = node()->dt.value();
    const Vec3 now = local(relative(t)), next = local(relative(t + dt));
    write(vid, dw_, rot_ * Vec3((next.x() - now.x()) / dt, (next.y() - now.y()) / dt, 0.0));
  }

  void project_position(int xid, double) override {
    if (!active_now()) return;
    write(xid, cw_, path_point(relative(node()->time.value())));
  }

  // The parabola's point at relative time r (P1 at 0, P3 at 1), once initialised valid.
  Vec3 path_point(double r) const { return p1.value() + rot_ * local(r); }

 private:
  // The parabola's point at relative time r, in its own frame.
  Vec3 local(double r) const {
    const double x2 = loc2_.x(), y2 = loc2_.y(), x3 = loc3_.x();
    const double den = x3 * x2 - x2 * x2;
    const double px = x3 * r;
    return Vec3(px, (-y2 / den) * (px * px) + ((x3 * y2) / den) * px, 0.0);
  }

  Mat3 rot_ = Mat3::Identity();  // columns: the parabola's frame axes
  Vec3 loc2_ = Vec3::Zero(), loc3_ = Vec3::Zero();
};

}  // namespace sinew
