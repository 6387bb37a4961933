#include "projective/movement_to_final_positions.h"

#include <algorithm>
#include <string>

#include "core/node.h"
#include "projective/indices_in_state.h"

namespace sinew {

void MovementToFinalPositions::init() {
  if (!init_state_of_type(*this, type_)) return;
  cw_ = mstate->info().coord_width;
  w_ = mstate->info().deriv_width;
  follow_.bind(&indices);
  follow_.attach(topology.get() ? topology.get() : node()->get_mesh_topology_link());
  // SOFA reports indices beyond the state and drops them from the list.
  drop_indices_beyond_state(*this, indices, mstate->size());
  if (end_time.get() <= begin_time.get())
    msg_warning("endConstraintTime (" + std::to_string(end_time.get()) + ") is not after beginConstraintTime (" +
                std::to_string(begin_time.get()) + "): the points jump to their final positions after it");
  x0_.clear();
  xf_.clear();
  mesh_x0_.clear();
  mesh_xf_.clear();
}

void MovementToFinalPositions::zero(int id) {
  if (state() != ComponentState::valid) return;
  std::vector<double>& d = mstate->write(id);
  const std::size_t n = mstate->size();
  for (unsigned i : indices.get()) {
    if (i >= n) continue;
    for (int c = 0; c < w_; ++c) d[i * w_ + c] = 0.0;
  }
}

void MovementToFinalPositions::project_response(int dx) { zero(dx); }

// SOFA projects velocities as responses: the constrained DoFs never carry a velocity, even
// while they are moved.
void MovementToFinalPositions::project_velocity(int v, double) { zero(v); }

void MovementToFinalPositions::project_jacobian(ConstraintMatrix& J) {
  if (J.empty() || warned_rows_) return;
  warned_rows_ = true;
  msg_error("cannot project Lagrangian constraint rows (SOFA does not either); the rows on its DoFs are kept");
}

// x0 sized to the state (SOFA's resize: default coordinates, identity orientations), then
// the listed DoFs' positions.
void MovementToFinalPositions::take_initial(const std::vector<unsigned>& idx, const std::vector<double>& x,
                                            std::vector<double>& x0) const {
  const std::size_t old = x0.size() / cw_, n = x.size() / cw_;
  x0.resize(n * cw_, 0.0);
  if (type_ == StateType::rigid3)
    for (std::size_t i = old; i < n; ++i) x0[i * cw_ + 6] = 1.0;
  for (unsigned i : idx)
    if (i < n)
      for (int c = 0; c < cw_; ++c) x0[i * cw_ + c] = x[i * cw_ + c];
}

void MovementToFinalPositions::take_final(const std::vector<unsigned>& idx, const std::vector<double>& x,
                                          std::vector<double>& x0, std::vector<double>& xf) const {
  const std::size_t old = xf.size() / cw_, n = x.size() / cw_;
  xf.resize(n * cw_, 0.0);
  if (type_ == StateType::rigid3)
    for (std::size_t i = old; i < n; ++i) xf[i * cw_ + 6] = 1.0;
  if (x0.empty()) take_initial(idx, x, x0);
  final_of(idx, x, x0, xf);
}

void MovementToFinalPositions::project_position(int xid, double) {
  if (state() != ComponentState::valid) return;
  std::vector<double>& x = mstate->write(xid);
  const std::vector<unsigned>& idx = indices.get();
  const double begin = begin_time.get(), end = end_time.get(), total = end - begin;

  // Taken once, at the first projection, in SOFA's order (the mesh points first).
  if (mesh_x0_.empty()) take_initial(mesh_indices.get(), x, mesh_x0_);
  if (mesh_xf_.empty()) take_final(mesh_indices.get(), x, mesh_x0_, mesh_xf_);
  if (x0_.empty()) take_initial(idx, x, x0_);
  if (xf_.empty()) take_final(idx, x, x0_, xf_);

  const double time = node()->time.value();
  const std::size_t n = std::min({x.size(), x0_.size(), xf_.size()}) / cw_;
  if (time > begin && time <= end && total > 0) {
    for (unsigned i : idx) {
      if (i >= n) continue;
      const double* a = &x0_[i * cw_];
      const double* b = &xf_[i * cw_];
      for (int c = 0; c < 3; ++c) x[i * cw_ + c] = ((b[c] - a[c]) * time + (a[c] * end - b[c] * begin)) / total;
    }
  } else if (time > end) {
    for (unsigned i : idx) {
      if (i >= n) continue;
      for (int c = 0; c < cw_; ++c) x[i * cw_ + c] = xf_[i * cw_ + c];
    }
  }
}

}  // namespace sinew
