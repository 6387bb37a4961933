// MultiStepAnimationLoop: several collision passes per step and several
// integration substeps per collision pass (dt / (collisionSteps ·
// integrationSteps) each), as SOFA's loop does.
//
// SOFA's clock quirk is kept: the time is set to start + (i+1)·substep inside
// each collision pass, so after the step it has advanced by integrationSteps
// substeps only, not by dt (projections and the next step see that time).
#include "animation/step_stages.h"
#include "core/registry.h"
#include "core/roles.h"

namespace sinew {

namespace {

class MultiStepAnimationLoop final : public AnimationLoop {
 public:
  Field<int> collision_steps{this, "collisionSteps", 1, "collision passes per step", "Solver"};
  Field<int> integration_steps{this, "integrationSteps", 1, "integration substeps per collision pass", "Solver"};
  Field<bool> compute_bounding_box{this, "computeBoundingBox", true, "update bounding boxes (viewer only)",
                                   "Visualization"};

  void init() override {
    if (collision_steps.value() < 1 || integration_steps.value() < 1) {
      msg_error("collisionSteps and integrationSteps must be at least 1");
      set_state(ComponentState::invalid);
    }
  }

  void step(double dt) override {
    if (state() != ComponentState::valid) return;
    Node& root = *node()->root();
    const double t0 = root.time.value();
    const int nc = collision_steps.value(), ni = integration_steps.value();
    const double h = dt / (nc * ni);
    static constexpr Stage kBegin[] = {Stage::begin_events};
    static constexpr Stage kCollision[] = {Stage::collision};
    static constexpr Stage kIntegrate[] = {Stage::interaction_forces, Stage::solve, Stage::project_and_propagate,
                                           Stage::check_state, Stage::end_integration, Stage::advance_time};
    static constexpr Stage kEnd[] = {Stage::end_events};
    StepContext begin{root, view_, dt, t0, t0 + dt};
    run_stages(begin, kBegin);
    for (int c = 0; c < nc; ++c) {
      StepContext col{root, view_, h, t0, t0 + h};
      run_stages(col, kCollision);
      for (int i = 0; i < ni; ++i) {
        StepContext sub{root, view_, h, t0 + i * h, t0 + (i + 1) * h};
        run_stages(sub, kIntegrate);
      }
    }
    StepContext end{root, view_, dt, t0, t0 + dt};
    run_stages(end, kEnd);
  }

 private:
  GraphView view_;
};

}  // namespace

void register_multi_step_animation_loop(Registry& r) {
  ComponentInfo info;
  info.name = "MultiStepAnimationLoop";
  info.category = "AnimationLoop";
  info.description = "several collision passes and integration substeps per step";
  info.create = creator<MultiStepAnimationLoop>();
  r.add(std::move(info));
}

}  // namespace sinew
