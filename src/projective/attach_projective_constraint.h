// AttachProjectiveConstraint (old name AttachConstraint): attaches points of object2 to
// points of object1 (indices1[i] ↔ indices2[i]) by projection, as SOFA's component of that
// name does for vector DoFs:
//   positions:  x2 −= (x2 − x1)·½·positionFactor·c_i   (x1 itself is left alone)
//   velocities: both move by the half difference: v1 += d, v2 −= d, d = (v2 − v1)·½·velocityFactor·c_i
//   responses:  one-way: dx2 = 0; twoWay: dx1 += d, dx2 −= d with d = (dx2 − dx1)·½·responseFactor·c_i
// c_i = constraintFactor[i] (1 when the list is empty). A pair further apart than
// minDistance (when not −1) is released until it comes back. With lastDir, a pair whose
// object1 point passed the plane (x1 − lastPos)·lastDir > 0 is inactive (or held at lastPos
// with clamp). Assembled systems (one-way): the attached DoFs of object2 are Dirichlet rows.
// Vec1d/Vec2d/Vec3d; the rotation options (freeRotations, lastFreeRotation, restRotations)
// only matter for rigid DoFs, which are not supported here.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/node.h"
#include "core/roles.h"

namespace sinew {

class AttachProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit AttachProjectiveConstraint(StateType t) : type_(t) {}

  Link<MechanicalState> object1{this, "object1", "state of the source points (default: the node's)"};
  Link<MechanicalState> object2{this, "object2", "state of the attached points (default: the node's)"};
  Field<std::vector<unsigned>> indices1{this, "indices1", {}, "indices of the source points on the first model",
                                        "Constraint"};
  Field<std::vector<unsigned>> indices2{this, "indices2", {}, "indices of the attached points on the second model",
                                        "Constraint"};
  Field<bool> two_way{this, "twoWay", false,
                      "responses of both objects go to their average (else object2 only follows object1)",
                      "Constraint"};
  Field<bool> free_rotations{this, "freeRotations", false, "keep rotations free (rigid DoFs only)", "Constraint"};
  Field<bool> last_free_rotation{this, "lastFreeRotation", false,
                                 "keep the rotation of the last attached point free (rigid DoFs only)", "Constraint"};
  Field<bool> rest_rotations{this, "restRotations", false, "use rest rotation offsets (rigid DoFs only)",
                             "Constraint"};
  Field<Vec3> last_pos{this, "lastPos", Vec3::Zero(), "position at which the attachment becomes inactive",
                       "Constraint", "length"};
  Field<Vec3> last_dir{this, "lastDir", Vec3::Zero(),
                       "direction from lastPos beyond which the attachment becomes inactive", "Constraint"};
  Field<bool> clamp{this, "clamp", false, "hold inactive points at lastPos instead of freeing them", "Constraint"};
  Field<double> min_distance{this, "minDistance", -1.0,
                             "a pair further apart than this is released (-1: never)", "Constraint", "length"};
  Field<double> position_factor{this, "positionFactor", 1.0, "factor of the position projection", "Constraint"};
  Field<double> velocity_factor{this, "velocityFactor", 1.0, "factor of the velocity projection", "Constraint"};
  Field<double> response_factor{this, "responseFactor", 1.0, "factor of the response projection", "Constraint"};
  Field<std::vector<double>> constraint_factor{
      this, "constraintFactor", {}, "per pair: 0 releases the attachment, 1 applies it fully", "Constraint"};

  void init() override {
    MechanicalState* local = node() ? node()->get_mechanical_state() : nullptr;
    s1_ = object1 ? object1.get() : local;
    s2_ = object2 ? object2.get() : local;
    if (!s1_ || !s2_) {
      msg_error("no mechanical state found (object1/object2 or the node's state)");
      set_state(ComponentState::invalid);
      return;
    }
    mstate.set(s2_);
    for (MechanicalState* s : {s1_, s2_})
      if (s->state_type() != type_) {
        msg_error(std::string("state ") + s->describe() + " is " + s->info().name + ", not " +
                  state_type_info(type_).name);
        set_state(ComponentState::invalid);
        return;
      }
    w_ = s2_->info().deriv_width;
  }

  // The indices are checked once every state is initialised: object1/object2 are often
  // states of child nodes, initialised after this node's objects.
  void bwd_init() override {
    if (state() != ComponentState::valid) return;
    const auto& i1 = indices1.get();
    const auto& i2 = indices2.get();
    if (i1.size() != i2.size())
      msg_warning("size mismatch between indices1 and indices2 (" + std::to_string(i1.size()) +
                  " != " + std::to_string(i2.size()) + "): the extra indices are ignored");
    for (std::size_t i = 0; i < std::min(i1.size(), i2.size()); ++i) {
      if (i1[i] >= s1_->size() || i2[i] >= s2_->size()) {
        msg_error("pair " + std::to_string(i) + " (" + std::to_string(i1[i]) + ", " + std::to_string(i2[i]) +
                  ") is out of range: object1 has " + std::to_string(s1_->size()) + " points, object2 " +
                  std::to_string(s2_->size()));
        set_state(ComponentState::invalid);
        return;
      }
    }
    const auto& cf = constraint_factor.get();
    if (!cf.empty()) {
      if (cf.size() != i2.size()) {
        msg_warning("constraintFactor has " + std::to_string(cf.size()) + " values for " +
                    std::to_string(i2.size()) + " attached points: it is not used");
      } else {
        for (std::size_t j = 0; j < cf.size(); ++j)
          if (cf[j] > 1.0 || cf[j] < 0.0)
            msg_warning("constraintFactor[" + std::to_string(j) + "] = " + std::to_string(cf[j]) +
                        " is outside [0, 1]");
      }
    }
    released_.assign(i2.size(), 0);
    active_.assign(i2.size(), 1);
  }

  void project_position(int xid, double) override {
    if (state() != ComponentState::valid) return;
    const std::vector<double>& x1 = s1_->read(vec_for(*s1_, xid, kPosition));
    std::vector<double>& x2 = s2_->write(xid);
    const auto& i1 = indices1.get();
    const auto& i2 = indices2.get();
    const std::size_t n = pairs();
    const bool last = last_dir.is_set() && last_dir.get().norm() > 1.0e-10;
    for (std::size_t i = 0; i < n; ++i) {
      bool active = true;
      if (last) {
        double d = 0;
        for (int c = 0; c < std::min(w_, 3); ++c) d += (x1[i1[i] * w_ + c] - last_pos.get()[c]) * last_dir.get()[c];
        if (d > 0.0) active = false;
      }
      active_[i] = active ? 1 : 0;
    }
    double p[3];
    for (std::size_t i = 0; i < n; ++i) {
      if (active_[i]) {
        for (int c = 0; c < w_; ++c) p[c] = x1[i1[i] * w_ + c];
      } else if (clamp.value()) {
        for (int c = 0; c < w_; ++c) p[c] = last_pos.get()[c];
      } else {
        continue;
      }
      double* q = &x2[i2[i] * w_];
      if (min_distance.get() != -1) {
        double d2 = 0;
        for (int c = 0; c < w_; ++c) d2 += (q[c] - p[c]) * (q[c] - p[c]);
        if (std::sqrt(d2) > min_distance.get()) {
          released_[i] = 1;
          continue;
        }
      }
      released_[i] = 0;
      const double s = 0.5 * position_factor.get() * factor(i);
      for (int c = 0; c < w_; ++c) q[c] -= (q[c] - p[c]) * s;  // the copy of x1 moves, not x1
    }
  }

  void project_velocity(int vid, double) override {
    if (state() != ComponentState::valid) return;
    std::vector<double>& v1 = s1_->write(vec_for(*s1_, vid, kVelocity));
    std::vector<double>& v2 = s2_->write(vid);
    const auto& i1 = indices1.get();
    const auto& i2 = indices2.get();
    for (std::size_t i = 0; i < pairs(); ++i) {
      if (released_[i]) continue;
      double* q = &v2[i2[i] * w_];
      const double s = 0.5 * velocity_factor.get() * factor(i);
      if (active_[i]) {
        double* a = &v1[i1[i] * w_];
        for (int c = 0; c < w_; ++c) {
          const double d = (q[c] - a[c]) * s;
          a[c] += d;
          q[c] -= d;
        }
      } else if (clamp.value()) {
        for (int c = 0; c < w_; ++c) q[c] -= q[c] * s;
      }
    }
  }

  void project_response(int dx) override {
    if (state() != ComponentState::valid) return;
    std::vector<double>& d1 = s1_->write(vec_for(*s1_, dx, kDx));
    std::vector<double>& d2 = s2_->write(dx);
    const auto& i1 = indices1.get();
    const auto& i2 = indices2.get();
    const bool two = two_way.value();
    for (std::size_t i = 0; i < pairs(); ++i) {
      if (released_[i]) continue;
      if (!active_[i] && !clamp.value()) continue;
      double* q = &d2[i2[i] * w_];
      if (!two || !active_[i]) {
        for (int c = 0; c < w_; ++c) q[c] = 0.0;
        continue;
      }
      double* a = &d1[i1[i] * w_];
      const double rf = response_factor.get(), cf = factor(i);
      for (int c = 0; c < w_; ++c) {
        // SOFA's (dx2 − dx1)·½·responseFactor·c, scaled left to right.
        const double d = (q[c] - a[c]) * 0.5 * rf * cf;
        a[c] += d;
        q[c] -= d;
      }
    }
  }

  // SOFA leaves constraint rows alone.
  void project_jacobian(ConstraintMatrix&) override {}

  bool dirichlet_indices(std::vector<std::size_t>& out) override {
    if (state() != ComponentState::valid || two_way.value()) return true;
    const auto& i2 = indices2.get();
    for (std::size_t i = 0; i < i2.size() && i < s2_->size(); ++i) {
      if (!clamp.value() && i < active_.size() && !active_[i]) continue;
      for (int c = 0; c < w_; ++c) out.push_back(static_cast<std::size_t>(i2[i]) * w_ + c);
    }
    return true;
  }

  // The two states once initialised, and whether each pair is active (lastDir; empty before
  // the first position projection).
  MechanicalState* state1() const { return s1_; }
  MechanicalState* state2() const { return s2_; }
  const std::vector<char>& active_pairs() const { return active_; }

 private:
  std::size_t pairs() const {
    return std::min({indices1.get().size(), indices2.get().size(), released_.size()});
  }
  double factor(std::size_t i) const {
    const auto& cf = constraint_factor.get();
    return cf.empty() ? 1.0 : (i < cf.size() ? cf[i] : 1.0);
  }

  StateType type_;
  MechanicalState* s1_ = nullptr;
  MechanicalState* s2_ = nullptr;
  int w_ = 3;
  std::vector<char> released_, active_;
};

}  // namespace sinew
