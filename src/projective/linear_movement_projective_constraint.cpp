#include "projective/linear_movement_projective_constraint.h"

#include <string>

#include "core/node.h"
#include "core/registry.h"
#include "projective/indices_in_state.h"
#include "core/state_creator.h"
#include "io/sofa_quat.h"

namespace sinew {

const std::vector<double>& LinearMovementProjectiveConstraint::movement_list() const {
  return movements.is_set() ? movements.get() : default_movement_;
}

void LinearMovementProjectiveConstraint::init() {
  if (!init_state_of_type(*this, type_)) return;
  w_ = mstate->info().deriv_width;
  cw_ = mstate->info().coord_width;
  default_movement_.assign(static_cast<std::size_t>(w_), 0.0);
  const auto& kt = key_times.get();
  const auto& km = movement_list();
  if (km.size() % static_cast<std::size_t>(w_) != 0 || km.size() / w_ < kt.size()) {
    msg_error("movements must hold one " + std::to_string(w_) + "-component movement per key time (" +
              std::to_string(kt.size()) + " key times, " + std::to_string(km.size()) + " values)");
    set_state(ComponentState::invalid);
    return;
  }
  // SOFA walks key times and movements side by side, so movements beyond the last key time are
  // never read (SOFA's own examples give 6 numbers per key to Vec3 states: the list is read as
  // twice as many Vec3 movements, of which the first ones pair with the key times).
  if (km.size() / w_ > kt.size())
    msg_warning("movements holds " + std::to_string(km.size() / w_) + " movements of " + std::to_string(w_) +
                " components for " + std::to_string(kt.size()) + " key times; as in SOFA, the first " +
                std::to_string(kt.size()) + " are used and the rest ignored");
  for (std::size_t k = 1; k < kt.size(); ++k)
    if (kt[k] < kt[k - 1]) {
      msg_warning("keyTimes are not in ascending order (" + std::to_string(kt[k - 1]) + " then " +
                  std::to_string(kt[k]) + "); the keys are read in the given order");
      break;
    }
  for (unsigned i : indices.get())
    if (i >= mstate->size())
      msg_warning("index " + std::to_string(i) + " is out of range (the state has " +
                  std::to_string(mstate->size()) + " DoFs); ignored");
  follow_.bind(&indices);
  follow_.attach(topology.get() ? topology.get() : node()->get_mesh_topology_link());
  x0_.clear();
  have_x0_ = false;
  prev_m_.assign(static_cast<std::size_t>(w_), 0.0);
  next_m_.assign(static_cast<std::size_t>(w_), 0.0);
  found_next_ = false;
}

void LinearMovementProjectiveConstraint::reset() {
  prev_t_ = next_t_ = 0.0;
  prev_m_.assign(static_cast<std::size_t>(w_), 0.0);
  next_m_.assign(static_cast<std::size_t>(w_), 0.0);
  found_next_ = false;
}

// SOFA's findKeyTimes: outside [first key, last key] nothing is updated and
// the constraint is inactive; inside, prev = last key ≤ t, next = first key > t.
void LinearMovementProjectiveConstraint::find_key_times() {
  const double t = node()->time.value();
  found_next_ = false;
  const auto& kt = key_times.get();
  const auto& km = movement_list();
  if (kt.empty() || km.size() < kt.size() * static_cast<std::size_t>(w_)) return;
  if (!(t >= kt.front() && t <= kt.back())) return;
  prev_t_ = next_t_ = kt.front();
  for (std::size_t k = 0; k < kt.size() && !found_next_; ++k) {
    const auto first = km.begin() + static_cast<std::ptrdiff_t>(k * w_);
    if (kt[k] <= t) {
      prev_t_ = kt[k];
      prev_m_.assign(first, first + w_);
    } else {
      next_t_ = kt[k];
      next_m_.assign(first, first + w_);
      found_next_ = true;
    }
  }
}

void LinearMovementProjectiveConstraint::project_response(int dx) {
  if (state() != ComponentState::valid) return;
  find_key_times();
  if (!active()) return;
  std::vector<double>& d = mstate->write(dx);
  const std::size_t n = mstate->size();
  for (unsigned i : indices.get()) {
    if (i >= n) continue;
    for (int c = 0; c < w_; ++c) d[i * w_ + c] = 0.0;
  }
}

// Same DOFs as project_response: their columns are cleared while the movement runs.
void LinearMovementProjectiveConstraint::project_jacobian(ConstraintMatrix& J) {
  if (state() != ComponentState::valid) return;
  find_key_times();
  if (!active()) return;
  for (unsigned i : indices.get())
    if (i < mstate->size()) J.zero_dof(static_cast<int>(i), 0, J.width());
}

void LinearMovementProjectiveConstraint::project_velocity(int vid, double) {
  if (state() != ComponentState::valid) return;
  find_key_times();
  if (!active()) return;
  const double inv = 1.0 / (next_t_ - prev_t_);
  std::vector<double>& v = mstate->write(vid);
  const std::size_t n = mstate->size();
  for (unsigned i : indices.get()) {
    if (i >= n) continue;
    for (int c = 0; c < w_; ++c) v[i * w_ + c] = (next_m_[c] - prev_m_[c]) * inv;
  }
}

void LinearMovementProjectiveConstraint::project_position(int xid, double) {
  if (state() != ComponentState::valid) return;
  std::vector<double>& x = mstate->write(xid);
  const std::size_t n = mstate->size();
  if (!have_x0_) {  // positions of the constrained DoFs at the first projection
    x0_.assign(x.size(), 0.0);
    for (unsigned i : indices.get()) {
      if (i >= n) continue;
      for (int c = 0; c < cw_; ++c) x0_[i * cw_ + c] = x[i * cw_ + c];
    }
    have_x0_ = true;
  }
  find_key_times();
  if (!active()) return;
  const double t = node()->time.value();
  const double s = (t - prev_t_) / (next_t_ - prev_t_);
  double m[6];
  for (int c = 0; c < w_; ++c) m[c] = prev_m_[c] + (next_m_[c] - prev_m_[c]) * s;
  const bool relative = relative_movements.value();

  if (type_ != StateType::rigid3) {
    for (unsigned i : indices.get()) {
      if (i >= n || (i + 1) * cw_ > x0_.size()) continue;
      for (int c = 0; c < cw_; ++c) x[i * cw_ + c] = relative ? x0_[i * cw_ + c] + m[c] : m[c];
    }
    return;
  }
  // Rigid3: centre as above, orientation interpolated by slerp2 between the
  // quaternions of the two keys' Euler angles.
  const io::SQuat qp = io::SQuat::from_euler(Vec3(prev_m_[3], prev_m_[4], prev_m_[5]));
  const io::SQuat qn = io::SQuat::from_euler(Vec3(next_m_[3], next_m_[4], next_m_[5]));
  const io::SQuat q = io::slerp2(qp, qn, s);
  for (unsigned i : indices.get()) {
    if (i >= n || (i + 1) * cw_ > x0_.size()) continue;
    double* xi = &x[i * cw_];
    const double* x0 = &x0_[i * cw_];
    io::SQuat r = q;
    if (relative) {
      io::SQuat q0;
      q0.q = {x0[3], x0[4], x0[5], x0[6]};
      r = q0 * q;
    }
    for (int c = 0; c < 3; ++c) xi[c] = relative ? x0[c] + m[c] : m[c];
    for (int c = 0; c < 4; ++c) xi[3 + c] = r.q[c];
  }
}

bool LinearMovementProjectiveConstraint::dirichlet_indices(std::vector<std::size_t>& out) {
  if (state() != ComponentState::valid) return true;
  const std::size_t w = static_cast<std::size_t>(w_), n = mstate->size();
  for (unsigned i : indices.get()) {
    if (i >= n) continue;
    for (std::size_t c = 0; c < w; ++c) out.push_back(i * w + c);
  }
  return true;
}

void register_linear_movement_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "LinearMovementProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "imposes a movement given at key times, interpolated linearly between them";
  info.templates = {"Vec1d", "Vec2d", "Vec3d", "Vec6d", "Rigid3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<LinearMovementProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
