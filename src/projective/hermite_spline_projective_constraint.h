// HermiteSplineProjectiveConstraint: between BeginTime and EndTime the listed
// DoFs follow the cubic Hermite spline from X0 (tangent dX0) to X1 (tangent
// dX1), SOFA's HermiteSplineProjectiveConstraint (templates Vec3d, Rigid3d: a
// frame's centre follows it, its orientation is kept).
//
// The spline parameter s is itself a Hermite blend of the relative time
// u = (t − t0)/(t1 − t0): s = (SX0·h10(u) + (1, 1)·h01(u) + SX1·h11(u)).y,
// which lets SX0/SX1 shape the speed along the curve. Position:
// X0·h00(s) + dX0·h10(s) + X1·h01(s) + dX1·h11(s). Velocity (SOFA's): the same
// blend with the derivatives of the basis functions in s, not scaled by
// ds/dt. The time window and what it zeroes are TimedPathConstraint's.
#pragma once

#include "core/node.h"
#include "projective/timed_path_constraint.h"

namespace sinew {

class HermiteSplineProjectiveConstraint final : public TimedPathConstraint {
 public:
  explicit HermiteSplineProjectiveConstraint(StateType t) : TimedPathConstraint(t) {}

  Field<Vec3> x0{this, "X0", Vec3::Zero(), "first control point", "Constraint", "length"};
  Field<Vec3> dx0{this, "dX0", Vec3::Zero(), "first control tangent", "Constraint", "length"};
  Field<Vec3> x1{this, "X1", Vec3::Zero(), "second control point", "Constraint", "length"};
  Field<Vec3> dx1{this, "dX1", Vec3::Zero(), "second control tangent", "Constraint", "length"};
  Field<Vec2> sx0{this, "SX0", Vec2::Zero(), "first interpolation vector of the time blend", "Constraint"};
  Field<Vec2> sx1{this, "SX1", Vec2::Zero(), "second interpolation vector of the time blend", "Constraint"};

  void project_velocity(int vid, double) override {
    if (!active_now()) return;
    const double s = blend(relative(node()->time.value()));
    const double s2 = s * s;
    const double h00 = 6 * s2 - 6 * s, h10 = 3 * s2 - 4 * s + 1, h01 = -6 * s2 + 6 * s, h11 = 3 * s2 - 2 * s;
    write(vid, dw_, x0.value() * h00 + dx0.value() * h10 + x1.value() * h01 + dx1.value() * h11);
  }

  void project_position(int xid, double) override {
    if (!active_now()) return;
    write(xid, cw_, curve_point(blend(relative(node()->time.value()))));
  }

  // The spline at parameter s in [0, 1] (X0 at 0, X1 at 1).
  Vec3 curve_point(double s) const {
    const double s2 = s * s, s3 = s * s * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    return x0.value() * h00 + dx0.value() * h10 + x1.value() * h01 + dx1.value() * h11;
  }

 private:
  // The spline parameter at relative time u.
  double blend(double u) const {
    const double u2 = u * u, u3 = u * u * u;
    const double h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return sx0.value().y() * h10 + 1.0 * h01 + sx1.value().y() * h11;
  }
};

}  // namespace sinew
