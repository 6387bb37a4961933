#include "animation/default_animation_loop.h"

#include "core/registry.h"

namespace sinew {

void DefaultAnimationLoop::step(double dt) {
  Node& root = *node()->root();
  const double t0 = root.time.value();
  StepContext s{root, view_, dt, t0, t0 + dt, parallel_ode_solving.value()};
  run_stages(s, kStages);
}

void register_default_animation_loop(Registry& r) {
  ComponentInfo info;
  info.name = "DefaultAnimationLoop";
  info.category = "AnimationLoop";
  info.description = "standard simulation step: solve every solver node, project, propagate, advance time";
  info.create = creator<DefaultAnimationLoop>();
  r.add(std::move(info));
}

}  // namespace sinew
