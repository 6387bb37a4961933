#include "core/simulation.h"

#include "core/mechanical_ops.h"
#include "core/registry.h"

namespace sinew {

namespace {

void init_node(Node& node) {
  if (!node.activated.value()) return;  // inactive subtrees are not even initialised
  node.update_context();
  // Objects added during this loop (e.g. helper objects) are initialised too.
  for (std::size_t i = 0; i < node.objects().size(); ++i) node.objects()[i]->init();
  for (std::size_t i = 0; i < node.children().size(); ++i) init_node(*node.children()[i]);
}

void bwd_init_node(Node& node) {
  if (!node.activated.value()) return;
  for (std::size_t i = node.children().size(); i-- > 0;) bwd_init_node(*node.children()[i]);
  for (std::size_t i = node.objects().size(); i-- > 0;) node.objects()[i]->bwd_init();
}

void store_reset(Node& node) {
  for_each_node(node, [](Node& n) {
    for (auto& o : n.objects()) o->store_reset_state();
  });
}

}  // namespace

void propagate_event(Node& root, Event& e) {
  if (!root.activated.value()) return;
  for (std::size_t i = 0; i < root.objects().size(); ++i) {
    Component* c = root.objects()[i].get();
    if (c->wants_events()) c->handle_event(e);
  }
  if (e.handled) return;
  for (std::size_t i = 0; i < root.children().size(); ++i) propagate_event(*root.children()[i], e);
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
  if (!root.animation_loop) {
    if (const ComponentInfo* info = registry().find("DefaultAnimationLoop")) {
      auto loop = info->create({});
      loop->set_type(info->name, {});
      loop->name.set("DefaultAnimationLoop1");
      diag.warning(root.where, "no animation loop in the root node: a DefaultAnimationLoop was added");
      root.add_object(std::move(loop), /*at_front=*/true);
    }
  }
  init_node(root);
  bwd_init_node(root);
  Event done{Event::Kind::simulation_init_done};
  propagate_event(root, done);
  project_and_propagate(root, root.time.value());
  store_reset(root);
  return diag.error_count() == errors_before;
}

void animate(Node& root, double dt) {
  if (dt == 0) dt = root.dt.value();
  if (root.animation_loop && root.animation_loop->state() == ComponentState::valid) root.animation_loop->step(dt);
}

}  // namespace sinew
