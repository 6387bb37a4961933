// PositionBasedDynamicsProjectiveConstraint: after each solve, moves every
// point a fraction `stiffness` of the way to its target (`position`, usually
// ShapeMatching's targetPosition) and sets its velocity to the distance it
// went since the last projection over dt (SOFA's Constraint/Projective; the
// velocity it keeps replaces the solver's). The solver's increments are not
// projected.
#include <cmath>

#include "core/node.h"
#include "core/registry.h"
#include "core/roles.h"
#include "core/state_creator.h"
#include "engine/empty_coords.h"

namespace sinew {

namespace {

class PositionBasedDynamicsProjectiveConstraint final : public ProjectiveConstraint {
 public:
  explicit PositionBasedDynamicsProjectiveConstraint(StateType t)
      : position(this, "position", empty_coords(t), "Target positions.", "Constraint"),
        velocity(this, "velocity", empty_coords(t), "Velocities.", "Constraint"),
        old_position(this, "old_position", empty_coords(t), "Old positions.", "Constraint") {}

  Field<double> stiffness{this, "stiffness", 1.0, "Blending between current pos and target pos.", "Constraint"};
  Field<FlatVec> position, velocity, old_position;

  void init() override {
    ProjectiveConstraint::init();
    if (state() != ComponentState::valid) return;
    if (!std::isfinite(stiffness.value())) {
      msg_error("stiffness must be finite (got " + stiffness.text() + ")");
      set_state(ComponentState::invalid);
      return;
    }
    if (position.get().data.size() != mstate->read(kPosition).size())
      msg_error("Invalid target position vector size: " + std::to_string(position.get().data.size() / 3) +
                " targets for " + std::to_string(mstate->size()) + " points");
  }
  void reset() override {
    FlatVec v = velocity.get();
    std::fill(v.data.begin(), v.data.end(), 0.0);
    velocity.set(std::move(v));
    FlatVec old;
    old.width = 3;
    old.data = mstate->read(kPosition);
    old_position.set(std::move(old));
  }

  void project_jacobian(ConstraintMatrix&) override {}
  void project_response(int) override {}

  void project_velocity(int vid, double) override {
    if (state() != ComponentState::valid) return;
    std::vector<double>& v = mstate->write(vid);
    const std::vector<double>& vel = velocity.get().data;
    if (vel.size() != v.size()) {
      msg_error("Invalid target position vector size: " + std::to_string(vel.size() / 3) + " velocities for " +
                std::to_string(v.size() / 3) + " points");
      return;
    }
    std::copy(vel.begin(), vel.end(), v.begin());
  }

  void project_position(int xid, double) override {
    if (state() != ComponentState::valid) return;
    // The targets first: reading them may update the engine that computes them from this state.
    const std::vector<double> target = position.get().data;
    std::vector<double>& x = mstate->write(xid);
    if (target.size() != x.size()) {
      msg_error("Invalid target position vector size: " + std::to_string(target.size() / 3) + " targets for " +
                std::to_string(x.size() / 3) + " points");
      return;
    }
    const double dt = node()->dt.value();
    if (dt == 0) return;
    const double inv_dt = 1. / dt;
    FlatVec vel = velocity.get(), old = old_position.get();
    vel.width = old.width = 3;
    vel.data.resize(x.size());
    if (old.data.size() != x.size()) old.data = x;
    const double k = stiffness.value();
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] += (target[i] - x[i]) * k;
      vel.data[i] = (x[i] - old.data[i]) * inv_dt;
      old.data[i] = x[i];
    }
    velocity.set(std::move(vel));
    old_position.set(std::move(old));
  }
};

}  // namespace

void register_position_based_dynamics_projective_constraint(Registry& r) {
  ComponentInfo info;
  info.name = "PositionBasedDynamicsProjectiveConstraint";
  info.category = "Constraint/Projective";
  info.description = "moves points toward target positions and derives their velocities (position-based dynamics)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = state_creator<PositionBasedDynamicsProjectiveConstraint>();
  r.add(std::move(info));
}

}  // namespace sinew
