#include "animation/default_animation_loop.h"

#include <oneapi/tbb/parallel_for.h>

#include "core/node.h"
#include "core/registry.h"
#include "core/simulation.h"
#include "core/timer.h"

namespace sinew {

void DefaultAnimationLoop::step(double dt) {
  Node& root = *node()->root();
  const double t0 = root.time.value();
  const double t1 = t0 + dt;

  SINEW_TIMED("step");
  {
    SINEW_TIMED("step/begin events");
    Event begin{Event::Kind::animate_begin, dt};
    propagate_event(root, begin);
  }

  {
  SINEW_TIMED("step/solve");
  if (parallel_ode_solving.value()) {
    solver_nodes_.clear();
    collect_solver_nodes(root);
    // Scopes of sibling solvers are disjoint: same results as in sequence.
    tbb::parallel_for(std::size_t{0}, solver_nodes_.size(), [&](std::size_t i) { solve(*solver_nodes_[i], dt); });
  } else {
    solve(root, dt);
  }
  }
  {
    SINEW_TIMED("step/project and propagate");
    project_and_propagate(root, t1);
  }
  end_integration(root);
  advance_time(root, dt);

  Event end{Event::Kind::animate_end, dt};
  propagate_event(root, end);
}

void DefaultAnimationLoop::solve(Node& node, double dt) {
  if (!node.activated.value() || node.sleeping.value()) return;
  if (!node.solvers.empty()) {
    // A solver integrates its whole subtree; solvers below it never run.
    for (OdeSolver* s : node.solvers)
      if (s->state() == ComponentState::valid) s->solve(dt, kPosition, kVelocity);
    return;
  }
  // Interaction force fields above the solver nodes are explicit: computed
  // once, from start-of-step positions, into the states' externalForce.
  if (!node.interaction_force_fields.empty()) {
    MechParams p;
    p.f = kExternalForce;
    for (ForceField* ff : node.interaction_force_fields)
      if (ff->state() == ComponentState::valid) ff->add_force(p);
  }
  for (std::size_t i = 0; i < node.children().size(); ++i) solve(*node.children()[i], dt);
}

void DefaultAnimationLoop::collect_solver_nodes(Node& node) {
  if (!node.activated.value() || node.sleeping.value()) return;
  if (!node.solvers.empty()) {
    solver_nodes_.push_back(&node);
    return;
  }
  if (!node.interaction_force_fields.empty()) {
    MechParams p;
    p.f = kExternalForce;
    for (ForceField* ff : node.interaction_force_fields)
      if (ff->state() == ComponentState::valid) ff->add_force(p);
  }
  for (std::size_t i = 0; i < node.children().size(); ++i) collect_solver_nodes(*node.children()[i]);
}

void DefaultAnimationLoop::project_and_propagate(Node& root, double t1) {
  if (!whole_graph_) whole_graph_ = std::make_unique<MechanicalOps>(root);
  whole_graph_->project_position(kPosition, t1);
  whole_graph_->project_velocity(kVelocity, t1);
  whole_graph_->propagate_x_and_v(kPosition, kVelocity);
}

void DefaultAnimationLoop::end_integration(Node& root) {
  for (MechanicalState* s : whole_graph_->all_states()) s->end_integration();
}

void DefaultAnimationLoop::advance_time(Node& root, double dt) {
  root.time.set(root.time.value() + dt);
  for_each_node(root, [](Node& n) { n.update_context(); });
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
