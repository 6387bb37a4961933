// The stages of a step as free functions over one StepContext, so that every
// animation loop (DefaultAnimationLoop now, the free-motion loop later) is a
// short list of stages (spec/framework.md §4.1; MuJoCo's mj_step, Box2D's
// solver stages). A stage only reads what the graph view gathered at init or
// after the last structural change: no stage creates what another needs.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/mechanical_ops.h"
#include "core/node.h"
#include "core/profile.h"

namespace sinew {

// What the stages work on, gathered from the graph and gathered again when
// the root's structure version moves.
struct GraphView {
  std::uint64_t version = 0;  // structure version it was built at (0: never)
  // Every active state, mapping and projective constraint under the root.
  std::unique_ptr<MechanicalOps> whole;
  // SOFA's SolveVisitor order (top-down): a node with ODE solvers is solved
  // and its subtree skipped; a node without one first adds its interaction
  // force fields explicitly. Interaction force fields met before the first
  // solver node form the interaction stage; the rest keep their place
  // between solver nodes, as SOFA computes them.
  struct SolveItem {
    Node* node;
    bool solves;  // true: its ODE solvers run; false: its interaction force fields add forces
  };
  std::vector<Node*> early_interactions;
  std::vector<SolveItem> solve_order;
  std::vector<Node*> solver_nodes;
};

// Gathers the view from the root (active, awake nodes only).
void build_graph_view(Node& root, GraphView& view);

struct StepContext {
  Node& root;
  GraphView& view;
  double dt;
  double t0, t1;              // time at the start and the end of the step
  bool parallel_solvers = false;  // parallelODESolving
  // FreeMotionAnimationLoop: the constraint solver and the order it solves for.
  ConstraintSolver* constraint_solver = nullptr;
  ConstraintOrder constraint_order = ConstraintOrder::pos_and_vel;
};

// One function per Stage, in its order.
void stage_begin_events(StepContext& s);
void stage_free_motion(StepContext& s);
void stage_collision(StepContext& s);
void stage_interaction_forces(StepContext& s);
void stage_solve(StepContext& s);
void stage_constraint_correction(StepContext& s);
void stage_project_and_propagate(StepContext& s);
void stage_check_state(StepContext& s);
void stage_end_integration(StepContext& s);
void stage_advance_time(StepContext& s);
void stage_end_events(StepContext& s);

// Runs the stages in the given order: brings the view up to date (new
// components are initialised first) after the begin events, locks the graph
// for the mechanical stages, calls the root's step observers around each
// stage and times everything into the root's profile when it is enabled.
void run_stages(StepContext& s, std::span<const Stage> stages);

}  // namespace sinew
