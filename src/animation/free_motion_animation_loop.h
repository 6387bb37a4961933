// FreeMotionAnimationLoop: the step of scenes with Lagrangian constraints
// (spec/interaction.md §5.1), as a declared list of stages:
//
//   begin events → free motion (solvers write xf, vf; xf = x + dt·vf on every
//   state) → collision (at x) → constraint solve and correction (x = xf + …)
//   → end integration → project and propagate → check state → time += dt →
//   end events.
//
// A body without a constraint correction never moves under this loop (its x
// is never set from xf), as in SOFA.
#pragma once

#include "animation/step_stages.h"
#include "core/roles.h"

namespace sinew {

class FreeMotionAnimationLoop final : public AnimationLoop {
 public:
  Field<bool> solve_velocity_constraint_first{this, "solveVelocityConstraintFirst", false,
                                              "solve the constraints on velocities, then integrate positions",
                                              "Solver"};
  Field<bool> thread_safe_visitor{this, "threadSafeVisitor", false, "no effect (SOFA allocation detail)", "Solver"};
  Field<bool> parallel_collision_detection_and_free_motion{
      this, "parallelCollisionDetectionAndFreeMotion", false,
      "overlap collision detection with the free motion (same results; run in sequence here)", "Solver"};
  Field<bool> parallel_ode_solving{this, "parallelODESolving", false,
                                   "solve sibling solver nodes concurrently (results are identical)", "Solver"};
  Field<bool> compute_bounding_box{this, "computeBoundingBox", true, "update bounding boxes (viewer only)",
                                   "Visualization"};
  Link<ConstraintSolver> constraint_solver{this, "constraintSolver",
                                           "constraint solver (default: the first one from this node down)"};

  static constexpr Stage kStages[] = {
      Stage::begin_events,          Stage::free_motion,   Stage::collision,    Stage::constraint_correction,
      Stage::end_integration,       Stage::project_and_propagate, Stage::check_state, Stage::advance_time,
      Stage::end_events,
  };

  void init() override;
  void step(double dt) override;

 private:
  GraphView view_;
};

}  // namespace sinew
