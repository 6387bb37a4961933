// What HermiteSplineProjectiveConstraint and ParabolicProjectiveConstraint share (SOFA's two
// have the same Data and time law): between BeginTime and EndTime the listed DoFs follow a
// path the subclass gives; while the motion lasts their responses and constraint rows are
// zeroed; outside [BeginTime, EndTime] they are free. Templates Vec3d and Rigid3d (a frame's
// centre follows the path, its orientation is kept). Assembled systems are not projected
// (SOFA does not either). Indices past the state's end are skipped with a warning.
#pragma once

#include <vector>

#include "core/roles.h"

namespace sinew {

class TimedPathConstraint : public ProjectiveConstraint {
 public:
  explicit TimedPathConstraint(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the constrained points", "Constraint"};
  Field<double> t_begin{this, "BeginTime", 0.0, "begin time of the motion", "Constraint", "time"};
  Field<double> t_end{this, "EndTime", 0.0, "end time of the motion", "Constraint", "time"};
  Link<MeshTopologyBase> topology{this, "topology", "topology of the points (accepted)"};

  // The state, its widths and the indices; an error unless EndTime > BeginTime.
  void init() override;
  void project_response(int dx) override;
  void project_jacobian(ConstraintMatrix& J) override;

 protected:
  // Valid, and the node's time within [BeginTime, EndTime].
  bool active_now() const;
  // (t − BeginTime) / (EndTime − BeginTime).
  double relative(double t) const { return (t - t_begin.value()) / (t_end.value() - t_begin.value()); }
  // The first three components of every listed DoF of vector `id` (DoFs `stride` apart) set
  // to `value`.
  void write(int id, unsigned stride, const Vec3& value);

  unsigned cw_ = 3, dw_ = 3;  // coordinate and derivative widths

 private:
  StateType type_;
  std::vector<unsigned> active_;
};

}  // namespace sinew
