#include "projective/timed_path_constraint.h"

#include "core/constraint_matrix.h"
#include "core/node.h"
#include "projective/indices_in_state.h"

namespace sinew {

void TimedPathConstraint::init() {
  if (!init_state_of_type(*this, type_)) return;
  cw_ = static_cast<unsigned>(mstate->info().coord_width);
  dw_ = static_cast<unsigned>(mstate->info().deriv_width);
  keep_indices_in_state(*this, indices.value(), mstate->size(), active_);
  if (!(t_end.value() > t_begin.value())) {
    msg_error("EndTime must be after BeginTime");
    set_state(ComponentState::invalid);
  }
}

bool TimedPathConstraint::active_now() const {
  if (state() != ComponentState::valid) return false;
  const double t = node()->time.value();
  return t >= t_begin.value() && t <= t_end.value();
}

void TimedPathConstraint::project_response(int dx) {
  if (!active_now()) return;
  std::vector<double>& d = mstate->write(dx);
  for (unsigned i : active_)
    for (unsigned c = 0; c < dw_; ++c) d[i * dw_ + c] = 0.0;
}

void TimedPathConstraint::project_jacobian(ConstraintMatrix& J) {
  if (!active_now()) return;
  for (unsigned i : active_) J.zero_dof(static_cast<int>(i), 0, J.width());
}

void TimedPathConstraint::write(int id, unsigned stride, const Vec3& value) {
  std::vector<double>& x = mstate->write(id);
  for (unsigned i : active_)
    for (unsigned c = 0; c < 3; ++c) x[i * stride + c] = value[static_cast<int>(c)];
}

}  // namespace sinew
