// LinearVelocityProjectiveConstraint: imposes a velocity, interpolated
// linearly between key times, on listed DoFs and integrates their positions
// itself (spec/mechanics.md §4).
#pragma once

#include <limits>

#include "core/node.h"
#include "core/roles.h"
#include "math/rigid.h"

namespace sinew {

class LinearVelocityProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit LinearVelocityProjectiveConstraint(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> indices{this, "indices", {}, "indices of the driven DoFs", "Constraint"};
  Field<std::vector<double>> key_times{this, "keyTimes", {}, "times of the key velocities (ascending)",
                                       "Constraint"};
  Field<std::vector<double>> velocities{this, "velocities", {}, "one velocity (derivative) per key time",
                                        "Constraint", "length/time"};
  Field<std::vector<unsigned>> coordinates{this, "coordinates", {},
                                           "driven components (default: all)", "Constraint"};
  Field<bool> continue_after_end{this, "continueAfterEnd", false, "keep the last velocity after the last key",
                                 "Constraint"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override {
    ProjectiveConstraint::init();
    if (state() != ComponentState::valid) return;
    w_ = mstate->info().deriv_width;
    cw_ = mstate->info().coord_width;
    if (velocities.get().size() != key_times.get().size() * static_cast<std::size_t>(w_)) {
      msg_error("velocities must hold one " + std::to_string(w_) + "-component velocity per key time (" +
                std::to_string(key_times.get().size()) + " key times)");
      set_state(ComponentState::invalid);
      return;
    }
    for (unsigned i : indices.get())
      if (i >= mstate->size()) {
        msg_error("index " + std::to_string(i) + " is out of range");
        set_state(ComponentState::invalid);
        return;
      }
    x0_.clear();
    xp_.clear();
    prev_v_.assign(w_, 0.0);
    next_v_.assign(w_, 0.0);
    finished_ = false;
  }
  void reset() override {
    next_t_ = prev_t_ = 0.0;
    prev_v_.assign(w_, 0.0);
    next_v_.assign(w_, 0.0);
    finished_ = false;
    x0_.clear();
    xp_.clear();
  }

  // SOFA leaves the constraint rows alone for this constraint.
  void project_jacobian(ConstraintMatrix&) override {}

  void project_response(int dx) override {
    update_keys();
    if (!active()) return;
    std::vector<double>& d = mstate->write(dx);
    for (unsigned i : indices.get())
      for (int c = 0; c < w_; ++c) d[i * w_ + c] = 0.0;
  }

  void project_velocity(int vid, double) override {
    update_keys();
    if (!active()) return;
    const std::vector<double> v = current_velocity();
    std::vector<double>& d = mstate->write(vid);
    const auto& coords = coordinates.get();
    for (unsigned i : indices.get()) {
      if (coords.empty())
        for (int c = 0; c < w_; ++c) d[i * w_ + c] = v[c];
      else
        for (unsigned c : coords)
          if (static_cast<int>(c) < w_) d[i * w_ + c] = v[c];
    }
  }

  void project_position(int xid, double) override {
    std::vector<double>& x = mstate->write(xid);
    if (x0_.empty()) {  // remember the start positions at the first call
      x0_.assign(x.size(), 0.0);
      xp_.assign(x.size(), 0.0);
      for (unsigned i : indices.get())
        for (int c = 0; c < cw_; ++c) x0_[i * cw_ + c] = xp_[i * cw_ + c] = x[i * cw_ + c];
    }
    update_keys();
    if (!active()) return;
    const double dt_sim = node()->dt.value();
    const std::vector<double> m = current_velocity();
    const auto& coords = coordinates.get();
    for (unsigned i : indices.get()) {
      double* xi = &x[i * cw_];
      double* pi = &xp_[i * cw_];
      if (coords.empty()) {
        if (type_ == StateType::rigid3) rigid3_add_deriv(pi, m.data(), dt_sim, xi);
        else
          for (int c = 0; c < w_; ++c) xi[c] = pi[c] + m[c] * dt_sim;
        for (int c = 0; c < cw_; ++c) pi[c] = xi[c];
      } else {
        // SOFA indexes coordinate and velocity components with the same number.
        for (unsigned c : coords) {
          if (static_cast<int>(c) >= w_ || static_cast<int>(c) >= cw_) continue;
          xi[c] = pi[c] + m[c] * dt_sim;
          for (int k = 0; k < cw_; ++k) pi[k] = xi[k];
        }
      }
    }
  }

  // The driven DoFs' positions at the first position projection (empty before it), in the
  // state's layout; coordinate and derivative widths.
  const std::vector<double>& initial_positions() const { return x0_; }
  int coord_width() const { return cw_; }
  int deriv_width() const { return w_; }

 private:
  // SOFA's findKeyTimes, called until it reports the end: past the last key
  // the velocity stays at the last key's (kept only with continueAfterEnd);
  // inside the keys, the two around the current time.
  void update_keys() {
    if (finished_) return;
    const double t = node()->time.value();
    const auto& kt = key_times.get();
    const auto& kv = velocities.get();
    if (kt.empty()) return;
    if (t > kt.back()) {
      prev_v_ = next_v_;
      next_t_ = std::numeric_limits<double>::infinity();
      finished_ = true;
      return;
    }
    if (t < kt.front()) return;
    next_t_ = prev_t_ = kt.front();
    for (std::size_t k = 0; k < kt.size(); ++k) {
      if (kt[k] <= t) {
        prev_t_ = kt[k];
        prev_v_.assign(kv.begin() + k * w_, kv.begin() + (k + 1) * w_);
      } else {
        next_t_ = kt[k];
        next_v_.assign(kv.begin() + k * w_, kv.begin() + (k + 1) * w_);
        return;
      }
    }
  }
  bool active() const { return (!finished_ || continue_after_end.value()) && next_t_ != prev_t_; }
  // Linear interpolation between the keys; the last key's velocity once finished.
  std::vector<double> current_velocity() const {
    if (finished_) return prev_v_;
    const double t = node()->time.value();
    std::vector<double> v(w_);
    for (int c = 0; c < w_; ++c) v[c] = (next_v_[c] - prev_v_[c]) * ((t - prev_t_) / (next_t_ - prev_t_)) + prev_v_[c];
    return v;
  }

  StateType type_;
  int w_ = 3, cw_ = 3;
  std::vector<double> x0_, xp_, prev_v_, next_v_;
  double prev_t_ = 0, next_t_ = 0;
  bool finished_ = false;
};

}  // namespace sinew
