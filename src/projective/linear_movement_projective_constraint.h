// LinearMovementProjectiveConstraint (old name LinearMovementConstraint):
// imposes on listed DoFs a displacement given at key times and interpolated
// linearly between them (SOFA's LinearMovementProjectiveConstraint).
//
// At context time t, the keys around t are the last key ≤ t (prev) and the
// first key > t (next); the constraint acts only while such a pair exists,
// i.e. for first key ≤ t < last key. While it acts:
//   position  x_i = x0_i + m(t) (relativeMovements) or m(t) (absolute), with
//             m(t) = m_prev + (m_next − m_prev)·(t − t_prev)/(t_next − t_prev)
//             and x0 the positions at the first projection; Rigid3 centres the
//             same, orientations x0_q · slerp2(q(m_prev), q(m_next), s) with
//             q(·) the quaternion of the movement's Euler angles;
//   velocity  v_i = (m_next − m_prev)/(t_next − t_prev);
//   response  dx_i = 0.
// Before the first key and from the last key on it does nothing (the DoFs are
// free again). Assembled systems always get Dirichlet rows for the indices,
// as SOFA's applyConstraint. `indices` follows point removals (SOFA's
// TopologySubsetIndices); x0 keeps the slots of the first projection, so a
// renumbered DoF reads the x0 of its new index, as in SOFA.
#pragma once

#include <vector>

#include "core/roles.h"
#include "projective/subset_indices.h"

namespace sinew {

class LinearMovementProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit LinearMovementProjectiveConstraint(StateType t) : type_(t) {}

  Field<std::vector<unsigned>> indices{this, "indices", {0}, "indices of the constrained DoFs (default: 0)",
                                       "Constraint"};
  Field<std::vector<double>> key_times{this, "keyTimes", {0.0}, "key times of the movements (ascending)",
                                       "Constraint", "time"};
  Field<std::vector<double>> movements{this, "movements", {},
                                       "one movement (a derivative: translation, then Euler angles for "
                                       "rigids) per key time (default: one zero movement)",
                                       "Constraint"};
  Field<bool> relative_movements{this, "relativeMovements", true,
                                 "movements are relative to the first position (else absolute)", "Constraint"};
  Field<bool> show_movement{this, "showMovement", false, "draw the path of the constrained DoFs (viewer)",
                            "Visualization"};
  Link<MeshTopologyBase> topology{this, "topology", "topology the indices refer to"};

  void init() override;
  void reset() override;
  void project_response(int dx) override;
  void project_jacobian(ConstraintMatrix& J) override;
  void project_velocity(int v, double t) override;
  void project_position(int x, double t) override;
  bool dirichlet_indices(std::vector<std::size_t>& out) override;

  // Keys around the current time (after the last projection): whether the
  // constraint acts, and the interpolation bounds.
  bool active() const { return found_next_ && next_t_ != prev_t_; }
  // For drawing: the movements in use (the default one when none is given), `deriv_width()`
  // numbers each; the positions at the first projection (`coord_width()` per DoF of the
  // state), null before it.
  const std::vector<double>& key_movements() const { return movement_list(); }
  const std::vector<double>* initial_positions() const { return have_x0_ ? &x0_ : nullptr; }
  int deriv_width() const { return w_; }
  int coord_width() const { return cw_; }

 private:
  void find_key_times();
  const std::vector<double>& movement_list() const;

  StateType type_;
  int w_ = 3, cw_ = 3;
  std::vector<double> x0_;          // positions at the first projection (constrained DoFs only)
  bool have_x0_ = false;
  std::vector<double> default_movement_;  // SOFA's default: one zero derivative
  std::vector<double> prev_m_, next_m_;
  double prev_t_ = 0.0, next_t_ = 0.0;
  bool found_next_ = false;
  SubsetIndicesFollower follow_;
};

}  // namespace sinew
