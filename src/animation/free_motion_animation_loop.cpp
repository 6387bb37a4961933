#include "animation/free_motion_animation_loop.h"

#include <memory>

#include "constraint/solver/block_gauss_seidel_constraint_solver.h"
#include "core/registry.h"

namespace sinew {

void FreeMotionAnimationLoop::init() {
  if (constraint_solver) return;
  constraint_solver.set(node()->find_down<ConstraintSolver>());
  if (constraint_solver) return;
  // SOFA creates a default solver, with a warning, rather than stopping.
  msg_warning("no constraint solver found from this node down: a BlockGaussSeidelConstraintSolver with default "
              "settings is added");
  auto solver = std::make_unique<BlockGaussSeidelConstraintSolver>();
  solver->name.set("BlockGaussSeidelConstraintSolver");
  Component* added = node()->add_object(std::move(solver));
  if (added) {
    added->init();
    constraint_solver.set(static_cast<ConstraintSolver*>(added));
  }
}

void FreeMotionAnimationLoop::step(double dt) {
  Node& root = *node()->root();
  const double t0 = root.time.value();
  StepContext s{root, view_, dt, t0, t0 + dt, parallel_ode_solving.value()};
  s.constraint_solver = constraint_solver.get();
  s.constraint_order =
      solve_velocity_constraint_first.value() ? ConstraintOrder::vel : ConstraintOrder::pos_and_vel;
  run_stages(s, kStages);
}

void register_free_motion_animation_loop(Registry& r) {
  ComponentInfo info;
  info.name = "FreeMotionAnimationLoop";
  info.category = "AnimationLoop";
  info.description = "step with Lagrangian constraints: free motion, collision, constraint solve and correction";
  info.create = creator<FreeMotionAnimationLoop>();
  r.add(std::move(info));
}

}  // namespace sinew
