// DefaultAnimationLoop: SOFA's standard step (spec/framework.md §4.1), as a
// declared list of stages (animation/step_stages.h):
//
//   begin events → collision → explicit interaction forces → solve every
//   solver node → constraint correction → project and propagate → check
//   state → end integration → time += dt → end events.
#pragma once

#include "animation/step_stages.h"
#include "core/roles.h"

namespace sinew {

class DefaultAnimationLoop final : public AnimationLoop {
 public:
  Field<bool> parallel_ode_solving{this, "parallelODESolving", false,
                                   "solve sibling solver nodes concurrently (results are identical)", "Solver"};
  Field<bool> compute_bounding_box{this, "computeBoundingBox", true, "update bounding boxes (viewer only)",
                                   "Visualization"};

  static constexpr Stage kStages[] = {
      Stage::begin_events,          Stage::collision,   Stage::interaction_forces, Stage::solve,
      Stage::constraint_correction, Stage::project_and_propagate, Stage::check_state,
      Stage::end_integration,       Stage::advance_time, Stage::end_events,
  };

  void step(double dt) override;

 private:
  GraphView view_;
};

}  // namespace sinew
