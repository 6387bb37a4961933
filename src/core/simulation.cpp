#include "core/simulation.h"

#include <algorithm>
#include <cmath>

#include "core/mechanical_ops.h"
#include "core/path.h"
#include "core/registry.h"

namespace sinew {

namespace {

// Init top-down in traversal order; components already initialised are left
// alone. Inactive subtrees are not even initialised. New nodes are collected
// for the projection that follows; `order` receives the nodes visited, for
// bwd_init in reverse.
void init_nodes(Node& root, std::vector<Node*>& new_nodes, std::vector<Component*>& fresh, std::vector<Node*>& order) {
  traverse(root, [&](Node& node, bool) {
    if (!node.activated.value()) return Visit::skip;
    if (!node.initialised) {
      node.initialised = true;
      new_nodes.push_back(&node);
    }
    order.push_back(&node);
    node.update_context();
    // Objects added during this loop (e.g. helper objects) are initialised too.
    for (std::size_t i = 0; i < node.objects().size(); ++i) {
      Component* c = node.objects()[i].get();
      if (c->initialised()) continue;
      c->mark_initialised();
      c->init();
      fresh.push_back(c);
    }
    return Visit::descend;
  });
}

// bwd_init bottom-up (the reverse of the init order, objects in reverse), on
// the components init_nodes just initialised (sorted).
void bwd_init_nodes(const std::vector<Node*>& order, const std::vector<Component*>& fresh) {
  for (std::size_t k = order.size(); k-- > 0;) {
    Node& node = *order[k];
    for (std::size_t i = node.objects().size(); i-- > 0;) {
      Component* c = node.objects()[i].get();
      if (std::binary_search(fresh.begin(), fresh.end(), c)) c->bwd_init();
    }
  }
}

// Init then bwd_init of everything not initialised yet; returns the new nodes.
std::vector<Node*> init_fresh(Node& root) {
  std::vector<Node*> new_nodes, order;
  std::vector<Component*> fresh;
  init_nodes(root, new_nodes, fresh, order);
  std::sort(fresh.begin(), fresh.end());
  bwd_init_nodes(order, fresh);
  return new_nodes;
}

void store_reset(Node& node) {
  for_each_node(node, [](Node& n) {
    for (auto& o : n.objects()) o->store_reset_state();
  });
}

}  // namespace

void propagate_event(Node& root, Event& e) {
  // A handled event goes no further down that branch (SOFA's PropagateEventVisitor prunes).
  traverse(root, [&](Node& n, bool pruned) {
    if (!n.activated.value()) return Visit::skip;
    if (pruned) return Visit::prune;
    for (std::size_t i = 0; i < n.objects().size(); ++i) {
      Component* c = n.objects()[i].get();
      if (c->wants_events()) c->handle_event(e);
    }
    return e.handled ? Visit::prune : Visit::descend;
  });
}

void project_and_propagate(Node& root, double t) {
  MechanicalOps ops(root);
  ops.project_position(kPosition, t);
  ops.project_velocity(kVelocity, t);
  ops.propagate_x_and_v(kPosition, kVelocity);
}

bool init_root(Node& root) {
  Diagnostics& diag = root.diagnostics();
  const int errors_before = diag.error_count();
  // A step of dt <= 0 would never advance time (and divides by dt in places): refused.
  if (const double dt = root.dt.value(); !(dt > 0) || !std::isfinite(dt)) {
    diag.error(root.where, "node '" + root.name.value() + "': dt = " + root.dt.text() +
                               ": the time step must be a positive number (time would not advance)");
    return false;
  }
  if (!root.animation_loop) {
    if (const ComponentInfo* info = registry().find("DefaultAnimationLoop")) {
      auto loop = info->create({});
      loop->set_type(info->name, {});
      loop->name.set("DefaultAnimationLoop1");
      diag.warning(root.where, "no animation loop in the root node: a DefaultAnimationLoop was added");
      root.add_object(std::move(loop), /*at_front=*/true);
    }
  }
  resolve_pending_links(root, diag);
  init_fresh(root);
  Event done{Event::Kind::simulation_init_done};
  propagate_event(root, done);
  project_and_propagate(root, root.time.value());
  store_reset(root);
  return diag.error_count() == errors_before;
}

bool init_added(Node& root) {
  Diagnostics& diag = root.diagnostics();
  const int errors_before = diag.error_count();
  resolve_pending_links(root, diag);
  const std::vector<Node*> new_nodes = init_fresh(root);
  // Only new subtrees are projected: re-projecting settled states could move
  // them by round-off. New nodes below new nodes are covered by their top one.
  for (Node* n : new_nodes) {
    bool under_new = false;
    for (Node* p = n->parent(); p && !under_new; p = p->parent())
      under_new = std::find(new_nodes.begin(), new_nodes.end(), p) != new_nodes.end();
    if (under_new) continue;
    project_and_propagate(*n, root.time.value());
    store_reset(*n);
  }
  return diag.error_count() == errors_before;
}

void cleanup_root(Node& root) {
  if (root.cleaned_up) return;
  root.cleaned_up = true;
  traverse(root, [](Node& n, bool) {
    for (std::size_t i = 0; i < n.objects().size(); ++i) n.objects()[i]->cleanup();
    return Visit::descend;
  });
}

void reset_root(Node& root) {
  root.time.set(0.0);
  for_each_node(root, [](Node& n) {
    n.update_context();
    for (auto& o : n.objects()) o->reset();
  });
  project_and_propagate(root, 0.0);
}

void notify_step_observers(Node& root, Stage stage, bool after) {
  for (StepObserver* o : root.step_observers()) {
    if (after) o->after_stage(stage, root);
    else o->before_stage(stage, root);
  }
}

void add_step_observer(Node& root, StepObserver* o) { root.step_observers().push_back(o); }

void remove_step_observer(Node& root, StepObserver* o) { std::erase(root.step_observers(), o); }

void animate(Node& root, double dt) {
  if (dt == 0) dt = root.dt.value();
  if (root.animation_loop && root.animation_loop->state() == ComponentState::valid) root.animation_loop->step(dt);
}

}  // namespace sinew
