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
// ds/dt. While the motion lasts, the responses of the listed DoFs are zeroed.
// Assembled systems are not projected (SOFA does not either).
#pragma once

#include <string>
#include <vector>

#include "core/constraint_matrix.h"
#include "core/node.h"
#include "core/roles.h"
#include "projective/indices_in_state.h"

namespace sinew {

class HermiteSplineProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit HermiteSplineProjectiveConstraint(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the constrained points", "Constraint"};
  Field<double> t_begin{this, "BeginTime", 0.0, "begin time of the motion", "Constraint", "time"};
  Field<double> t_end{this, "EndTime", 0.0, "end time of the motion", "Constraint", "time"};
  Field<Vec3> x0{this, "X0", Vec3::Zero(), "first control point", "Constraint", "length"};
  Field<Vec3> dx0{this, "dX0", Vec3::Zero(), "first control tangent", "Constraint", "length"};
  Field<Vec3> x1{this, "X1", Vec3::Zero(), "second control point", "Constraint", "length"};
  Field<Vec3> dx1{this, "dX1", Vec3::Zero(), "second control tangent", "Constraint", "length"};
  Field<Vec2> sx0{this, "SX0", Vec2::Zero(), "first interpolation vector of the time blend", "Constraint"};
  Field<Vec2> sx1{this, "SX1", Vec2::Zero(), "second interpolation vector of the time blend", "Constraint"};
  Link<MeshTopologyBase> topology{this, "topology", "topology of the points (accepted)"};

  void init() override {
    if (!init_state_of_type(*this, type_)) return;
    cw_ = static_cast<unsigned>(mstate->info().coord_width);
    dw_ = static_cast<unsigned>(mstate->info().deriv_width);
    keep_indices_in_state(*this, indices.value(), mstate->size(), active_);
    if (!(t_end.value() > t_begin.value())) {
      msg_error("EndTime must be after BeginTime");
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
    const double s = blend(relative());
    const double s2 = s * s;
    const double h00 = 6 * s2 - 6 * s, h10 = 3 * s2 - 4 * s + 1, h01 = -6 * s2 + 6 * s, h11 = 3 * s2 - 2 * s;
    write(vid, dw_, x0.value() * h00 + dx0.value() * h10 + x1.value() * h01 + dx1.value() * h11);
  }

  void project_position(int xid, double) override {
    if (!active_now()) return;
    write(xid, cw_, curve_point(blend(relative())));
  }

  // The spline at parameter s in [0, 1] (X0 at 0, X1 at 1).
  Vec3 curve_point(double s) const {
    const double s2 = s * s, s3 = s * s * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    return x0.value() * h00 + dx0.value() * h10 + x1.value() * h01 + dx1.value() * h11;
  }

 private:
  bool active_now() const {
    if (state() != ComponentState::valid) return false;
    const double t = node()->time.value();
    return t >= t_begin.value() && t <= t_end.value();
  }
  double relative() const {
    return (node()->time.value() - t_begin.value()) / (t_end.value() - t_begin.value());
  }
  // The spline parameter at relative time u.
  double blend(double u) const {
    const double u2 = u * u, u3 = u * u * u;
    const double h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return sx0.value().y() * h10 + 1.0 * h01 + sx1.value().y() * h11;
  }
  void write(int id, unsigned stride, const Vec3& value) {
    std::vector<double>& x = mstate->write(id);
    for (unsigned i : active_)
      for (int c = 0; c < 3; ++c) x[i * stride + static_cast<unsigned>(c)] = value[c];
  }

  StateType type_;
  unsigned cw_ = 3, dw_ = 3;
  std::vector<unsigned> active_;
};

}  // namespace sinew
