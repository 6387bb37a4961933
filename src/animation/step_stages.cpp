#include "animation/step_stages.h"

#include <chrono>
#include <cmath>
#include <string>

#include <oneapi/tbb/parallel_for.h>

#include "core/simulation.h"

namespace sinew {

namespace {

void gather(Node& root, GraphView& v) {
  traverse(root, [&](Node& node, bool pruned) {
    if (!node.activated.value() || node.sleeping.value()) return Visit::skip;
    // Below a solver (through every parent, in a DAG): integrated by that solver.
    if (pruned) return Visit::prune;
    if (!node.solvers.empty()) {
      // A solver integrates its whole subtree; solvers below it never run.
      v.solver_nodes.push_back(&node);
      v.solve_order.push_back({&node, true});
      return Visit::prune;
    }
    if (!node.interaction_force_fields.empty()) {
      if (v.solver_nodes.empty()) v.early_interactions.push_back(&node);
      else v.solve_order.push_back({&node, false});
    }
    return Visit::descend;
  });
}

// Interaction force fields above the solver nodes are explicit: computed
// once, from the positions of that moment, into the states' externalForce.
void add_interaction_forces(Node& node) {
  MechParams p;
  p.f = kExternalForce;
  for (ForceField* ff : node.interaction_force_fields) {
    if (ff->state() != ComponentState::valid) continue;
    // externalForce is empty between steps (and not sized on demand like the other
    // vectors): sized here for the force fields that write into it, as SOFA's
    // addForce resizes f to x.
    for (MechanicalState* s : ff->states()) {
      if (!s) continue;
      const std::size_t n = s->size() * static_cast<std::size_t>(s->info().deriv_width);
      if (s->read(kExternalForce).size() < n) s->write(kExternalForce).resize(n, 0.0);
    }
    ff->add_force(p);
  }
}

void solve_node(Node& node, double dt) {
  for (OdeSolver* s : node.solvers)
    if (s->state() == ComponentState::valid) s->solve(dt, kPosition, kVelocity);
}

// Index of the first non-finite scalar, or -1.
long first_non_finite(const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i])) return static_cast<long>(i);
  return -1;
}

// The solver that integrates a state: the first one up the graph, through every parent (valid or not).
OdeSolver* solver_up(const Node* n) {
  if (!n) return nullptr;
  if (!n->solvers.empty()) return n->solvers.front();
  for (const Node* p : n->parents())
    if (OdeSolver* s = solver_up(p)) return s;
  return nullptr;
}
OdeSolver* solver_of(const Component& c) { return solver_up(c.node()); }

// States whose solver (or, without one, the state itself) was stopped are not checked again.
bool stopped(const Component& c) {
  const OdeSolver* solver = solver_of(c);
  return (solver ? solver->state() : c.state()) != ComponentState::valid;
}

// Reports a non-finite value and stops the solver that integrates it (or the
// state itself when none does), so that its other states are not reported again.
void report_divergence(StepContext& s, Component& state, const char* what, long point, const Mapping* via) {
  OdeSolver* solver = solver_of(state);
  std::string text = "the simulation diverged at step " + std::to_string(s.root.step_index) + ", t = " +
                     parse::format_double(s.t1) + ": non-finite " + what + " of point " + std::to_string(point) +
                     " in " + state.describe();
  if (via) text += " (mapped by " + via->describe() + ")";
  text += std::string("; ") + (solver ? solver->divergence_hint() : "reduce dt");
  Component& culprit = solver ? static_cast<Component&>(*solver) : state;
  culprit.msg_error(text);
  culprit.set_state(ComponentState::invalid);
}

void run_stage(StepContext& s, Stage stage) {
  switch (stage) {
    case Stage::begin_events: return stage_begin_events(s);
    case Stage::free_motion: return stage_free_motion(s);
    case Stage::collision: return stage_collision(s);
    case Stage::interaction_forces: return stage_interaction_forces(s);
    case Stage::solve: return stage_solve(s);
    case Stage::constraint_correction: return stage_constraint_correction(s);
    case Stage::project_and_propagate: return stage_project_and_propagate(s);
    case Stage::check_state: return stage_check_state(s);
    case Stage::end_integration: return stage_end_integration(s);
    case Stage::advance_time: return stage_advance_time(s);
    case Stage::end_events: return stage_end_events(s);
  }
}

// Event stages leave the graph open: controllers may add or remove components
// there. So does the collision stage: the response attaches and detaches contacts.
bool is_event_stage(Stage stage) { return stage == Stage::begin_events || stage == Stage::end_events; }
bool locks_graph(Stage stage) { return !is_event_stage(stage) && stage != Stage::collision; }

}  // namespace

void build_graph_view(Node& root, GraphView& v) {
  v.version = root.structure_version();
  if (!v.whole) v.whole = std::make_unique<MechanicalOps>(root);
  v.whole->rebuild();
  v.early_interactions.clear();
  v.solve_order.clear();
  v.solver_nodes.clear();
  gather(root, v);
}

void stage_begin_events(StepContext& s) {
  Event begin{Event::Kind::animate_begin, s.dt};
  propagate_event(s.root, begin);
}

// Collision detection and response (spec/interaction.md §1.3, §1.7): the
// pipeline of every active node that has one, top-down (SOFA's CollisionVisitor).
// Contacts created here are attached to the graph; the view is brought up to
// date before the next stage.
void stage_collision(StepContext& s) {
  for_each_node(s.root, [&](Node& n) {
    if (CollisionPipelineBase* p = n.collision_pipeline; p && p->state() == ComponentState::valid) p->collide(s.dt);
  });
}

void stage_interaction_forces(StepContext& s) {
  for (Node* n : s.view.early_interactions) add_interaction_forces(*n);
  if (s.parallel_solvers)  // every one before any solver runs: the solver nodes then run concurrently
    for (const GraphView::SolveItem& item : s.view.solve_order)
      if (!item.solves) add_interaction_forces(*item.node);
}

void stage_solve(StepContext& s) {
  if (s.parallel_solvers) {
    // Scopes of sibling solvers are disjoint: same results as in sequence.
    const auto& nodes = s.view.solver_nodes;
    tbb::parallel_for(std::size_t{0}, nodes.size(), [&](std::size_t i) { solve_node(*nodes[i], s.dt); });
    return;
  }
  for (const GraphView::SolveItem& item : s.view.solve_order) {
    if (item.solves) solve_node(*item.node, s.dt);
    else add_interaction_forces(*item.node);
  }
}

// Free motion (spec/interaction.md §5.1 step 5): every solver node integrates
// its subtree from x, v into the free vectors (solver-less interaction force
// fields are not evaluated), vf is projected and mapped down, then
// xf = x + dt·vf on every state, mapped ones included (a first-order
// extrapolation there, not the mapping of xf).
void stage_free_motion(StepContext& s) {
  MechanicalOps& ops = *s.view.whole;
  // The free vectors start as copies of x and v, once (while they are empty).
  for (MechanicalState* st : ops.all_states()) {
    if (!st->has_vec(kFreePosition)) st->write(kFreePosition) = st->read(kPosition);
    if (!st->has_vec(kFreeVelocity)) st->write(kFreeVelocity) = st->read(kVelocity);
  }
  auto free_solve = [&](Node& n) {
    for (OdeSolver* solver : n.solvers)
      if (solver->state() == ComponentState::valid) solver->solve(s.dt, kFreePosition, kFreeVelocity);
  };
  if (s.parallel_solvers) {
    const auto& nodes = s.view.solver_nodes;
    tbb::parallel_for(std::size_t{0}, nodes.size(), [&](std::size_t i) { free_solve(*nodes[i]); });
  } else {
    for (const GraphView::SolveItem& item : s.view.solve_order)
      if (item.solves) free_solve(*item.node);
  }
  ops.project_response(kFreeVelocity);
  ops.propagate_dx(kFreeVelocity);
  if (s.constraint_order == ConstraintOrder::pos || s.constraint_order == ConstraintOrder::pos_and_vel)
    for (MechanicalState* st : ops.all_states()) st->add_deriv_to_coord(kFreePosition, kPosition, kFreeVelocity, s.dt);
}

// Lagrangian constraints (spec/interaction.md §5.1 step 6): the constraint
// solver corrects x and v of every body with a constraint correction (the
// others keep their start-of-step state); the correction is then projected
// and mapped down. Empty for DefaultAnimationLoop (no constraint solver).
void stage_constraint_correction(StepContext& s) {
  ConstraintSolver* solver = s.constraint_solver;
  if (!solver || solver->state() != ComponentState::valid) return;
  ConstraintParams p;
  p.order = s.constraint_order;
  p.dt = s.dt;
  MechanicalOps& ops = *s.view.whole;
  if (p.order == ConstraintOrder::vel) {
    solver->solve_constraint(p, kVelocity, kVelocity);
    for (MechanicalState* st : ops.independent_states()) st->add_deriv_to_coord(kPosition, kPosition, kVelocity, s.dt);
  } else {
    solver->solve_constraint(p, kPosition, kVelocity);
  }
  ops.project_response(solver->dx_vec());
  ops.propagate_dx(solver->dx_vec());
}

void stage_project_and_propagate(StepContext& s) {
  MechanicalOps& ops = *s.view.whole;
  ops.project_position(kPosition, s.t1);
  ops.project_velocity(kVelocity, s.t1);
  ops.propagate_x_and_v(kPosition, kVelocity);
}

void stage_check_state(StepContext& s) {
  // The one place where numerical health is checked (MuJoCo's mj_checkPos/Vel):
  // a state that stopped being finite stops its solver, with one message
  // naming the step, the state and the first bad point. Independent states
  // first (where a divergence starts), then every mapping's output, visual
  // models included (a mapping can produce what its input does not hold).
  MechanicalOps& ops = *s.view.whole;
  auto check = [&](MechanicalState& st, const Mapping* via) {
    for (int id : {kPosition, kVelocity}) {
      const long bad = first_non_finite(st.read(id));
      if (bad < 0) continue;
      const int width = id == kPosition ? st.info().coord_width : st.info().deriv_width;
      report_divergence(s, st, id == kPosition ? "position" : "velocity", bad / width, via);
      return;
    }
  };
  for (MechanicalState* st : ops.independent_states())
    if (!stopped(*st)) check(*st, nullptr);
  for (Mapping* m : ops.all_mappings()) {
    if (m->state() != ComponentState::valid) continue;
    if (MechanicalState* out = m->output()) {
      if (!stopped(*out)) check(*out, m);
    } else if (VisualState* vis = m->visual_output(); vis && !stopped(*vis)) {
      const std::vector<double>* x = vis->visual_vec(kPosition);
      const long bad = x ? first_non_finite(*x) : -1;
      if (bad >= 0) report_divergence(s, *vis, "position", bad / 3, m);
    }
  }
}

void stage_end_integration(StepContext& s) {
  for (MechanicalState* st : s.view.whole->all_states()) st->end_integration();
}

void stage_advance_time(StepContext& s) {
  s.root.time.set(s.t1);
  for_each_node(s.root, [](Node& n) { n.update_context(); });
}

void stage_end_events(StepContext& s) {
  Event end{Event::Kind::animate_end, s.dt};
  propagate_event(s.root, end);
}

void run_stages(StepContext& s, std::span<const Stage> stages) {
  using clock = std::chrono::steady_clock;
  StepProfile& profile = s.root.profile();
  const bool timed = profile.enabled();
  const auto step_start = timed ? clock::now() : clock::time_point{};
  // Unlocked on every way out, exceptions included.
  struct Unlock {
    Node& root;
    ~Unlock() { root.set_graph_locked(false); }
  } unlock{s.root};
  for (Stage stage : stages) {
    if (is_event_stage(stage)) {
      s.root.set_graph_locked(false);
    } else {
      // Before a mechanical stage: bring the view up to date with what changed
      // since it was gathered (components added by controllers or by the
      // collision response are initialised first). One comparison otherwise.
      if (s.view.version != s.root.structure_version()) {
        init_added(s.root);
        build_graph_view(s.root, s.view);
      }
      s.root.set_graph_locked(locks_graph(stage));
    }
    notify_step_observers(s.root, stage, /*after=*/false);
    const auto t = timed ? clock::now() : clock::time_point{};
    run_stage(s, stage);
    if (timed) profile.add_stage(stage, std::chrono::duration<double>(clock::now() - t).count());
    notify_step_observers(s.root, stage, /*after=*/true);
  }
  if (timed) profile.add_step(std::chrono::duration<double>(clock::now() - step_start).count());
}

}  // namespace sinew
