#include "collision/pipeline.h"

#include <algorithm>
#include <type_traits>

#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
const char* element_name(CollisionModelBase::Kind k) {
  switch (k) {
    case CollisionModelBase::Kind::point:
      return "points";
    case CollisionModelBase::Kind::line:
      return "edges";
    case CollisionModelBase::Kind::triangle:
      return "triangles";
    case CollisionModelBase::Kind::sphere:
      return "spheres";
    case CollisionModelBase::Kind::tetrahedron:
      return "tetrahedra";
    case CollisionModelBase::Kind::obb:
      return "boxes";
  }
  return "elements";
}
}  // namespace

std::string CollisionScope::missing() const {
  std::string m;
  auto need = [&](bool ok, const char* what) {
    if (ok) return;
    if (!m.empty()) m += ", ";
    m += what;
  };
  need(intersection, "an intersection method (e.g. MinProximityIntersection)");
  need(broad, "a broad phase (BruteForceBroadPhase)");
  need(narrow, "a narrow phase (BVHNarrowPhase or RayTraceNarrowPhase)");
  need(manager, "a contact manager (CollisionResponse)");
  return m;
}

void CollisionScope::detect(double dt) {
  for (Component* c : std::initializer_list<Component*>{intersection, broad, narrow, manager})
    if (c->state() != ComponentState::valid) return;
  intersection->begin_detection();
  // Bounding trees (BVHNarrowPhase needs the deep ones), then the broad phase over the roots.
  broad->begin(*intersection);
  for (CollisionModelBase* m : models) {
    if (!m->is_active()) continue;
    if (intersection->use_continuous()) {
      m->compute_continuous_bounding_tree(dt, intersection->continuous_motion(), depth);
    } else {
      m->clear_end_positions();
      m->compute_bounding_tree(depth);
    }
    if (m->empty()) {
      m->warn_once(std::string("has no ") + element_name(m->kind()) +
                   " (its state or topology is empty): it collides with nothing");
      continue;
    }
    broad->add_model(m);
  }
  narrow->detect(broad->pairs(), *intersection);
  manager->create_contacts(narrow->outputs(), *intersection);
  // numberOfContacts: contacts (model pairs) touching each model.
  for (CollisionModelBase* m : models) {
    int n = 0;
    for (Contact* c : manager->contacts())
      if (&c->model1() == m || &c->model2() == m) ++n;
    if (m->number_of_contacts.value() != n) m->number_of_contacts.set(n);
  }
}

void CollisionScope::respond(Node& root) {
  if (!manager || manager->state() != ComponentState::valid) return;
  touched_.clear();
  auto attach = [&](Contact* c, Node& where) {
    c->create_response(where);
    if (std::find(touched_.begin(), touched_.end(), &where) == touched_.end()) touched_.push_back(&where);
  };
  const auto& contacts = manager->contacts();
  for (Contact* c : contacts) {
    if (!c->model1().simulated.value())
      attach(c, *c->model2().node());
    else if (!c->model2().simulated.value())
      attach(c, *c->model1().node());
  }
  for (Contact* c : contacts)
    if (c->model1().simulated.value() && c->model2().simulated.value()) attach(c, root);
  // SOFA re-attaches every response at the end of its node each step: keep
  // the responses of each node last, in contact order (no change, no cost).
  // Penalty responses are interaction force fields, constraint responses
  // Lagrangian constraints: each kind is kept last in its own list.
  auto keep_last = [&](Node* n, const auto& list) {
    using Item = std::remove_pointer_t<typename std::decay_t<decltype(list)>::value_type>;
    wanted_.clear();
    for (Contact* c : contacts)
      if (c->response() && c->response()->node() == n && dynamic_cast<Item*>(c->response()))
        wanted_.push_back(c->response());
    bool in_order = list.size() >= wanted_.size();
    for (std::size_t k = 0; in_order && k < wanted_.size(); ++k)
      in_order = static_cast<Component*>(list[list.size() - wanted_.size() + k]) == wanted_[k];
    if (!in_order)
      for (Component* r : wanted_) n->move_to_end(r);
  };
  for (Node* n : touched_) {
    keep_last(n, n->interaction_force_fields);
    keep_last(n, n->lagrangian_constraints);
  }
}

void SubCollisionPipeline::init() {
  if (depth.value() < 0) {
    msg_warning("depth must be positive; reset to 6");
    depth.set(6);
  }
  scope_.models = collision_models.get();
  scope_.intersection = intersection_method.get();
  scope_.broad = broad_phase.get();
  scope_.narrow = narrow_phase.get();
  scope_.manager = contact_manager.get();
  scope_.depth = depth.value();
  if (const std::string m = scope_.missing(); !m.empty()) {
    msg_error("needs " + m + " (links intersectionMethod, broadPhaseDetection, narrowPhaseDetection, contactManager)");
    set_state(ComponentState::invalid);
  }
}

namespace {

// One pipeline over the components and models found below its node (SOFA's
// CollisionPipeline: the first of each kind in scene order).
class CollisionPipeline final : public CollisionPipelineBase {
 public:
  Field<bool> verbose{this, "verbose", false, "log the collision steps", "Collision"};
  Field<bool> draw{this, "draw", false, "draw contacts (viewer)", "Visualization"};
  Field<int> depth{this, "depth", 6, "number of split levels of the bounding-volume hierarchies", "Collision"};
  Field<bool> parallel_detection{this, "parallelDetection", false, "detect collisions in parallel", "Collision"};

  void init() override {
    if (depth.value() < 0) {
      msg_warning("depth must be positive; reset to 6");
      depth.set(6);
    }
    scope_.intersection = node()->find_down<Intersection>();
    scope_.broad = node()->find_down<BruteForceBroadPhase>();
    scope_.narrow = node()->find_down<NarrowPhase>();
    scope_.manager = node()->find_down<CollisionResponse>();
    scope_.depth = depth.value();
    scope_.models.clear();
    node()->collect_down(scope_.models);
    if (const std::string m = scope_.missing(); !m.empty()) {
      if (!scope_.models.empty()) msg_error("needs " + m + " in its node or below: no collision is detected");
      set_state(ComponentState::invalid);
    }
  }

  void collide(double dt) override {
    scope_.detect(dt);
    scope_.respond(*node());
  }

 private:
  CollisionScope scope_;
};

class CompositeCollisionPipeline final : public CollisionPipelineBase {
 public:
  Field<bool> parallel_detection{this, "parallelDetection", false, "run the sub-pipelines' detections in parallel",
                                 "Collision"};
  Field<int> depth{this, "depth", 6, "unused (each sub-pipeline has its own depth)", "Collision"};
  MultiLink<SubCollisionPipeline> sub_pipelines{this, "subCollisionPipelines", "the pipelines run, in order"};

  void init() override {
    if (sub_pipelines.get().empty()) {
      msg_error("subCollisionPipelines is empty: no collision is detected");
      set_state(ComponentState::invalid);
      return;
    }
    // Models of the scene that no sub-pipeline covers never collide: say so.
    std::vector<CollisionModelBase*> all;
    node()->collect_down(all);
    for (CollisionModelBase* m : all) {
      bool covered = false;
      for (SubCollisionPipeline* p : sub_pipelines.get()) {
        const auto& ms = p->collision_models.get();
        covered = covered || std::find(ms.begin(), ms.end(), m) != ms.end();
      }
      if (!covered) msg_warning(m->describe() + " is in no sub-pipeline: it collides with nothing");
    }
  }

  void collide(double dt) override {
    for (SubCollisionPipeline* p : sub_pipelines.get())
      if (p->state() == ComponentState::valid) p->scope().detect(dt);
    for (SubCollisionPipeline* p : sub_pipelines.get())
      if (p->state() == ComponentState::valid) p->scope().respond(*node());
  }
};

}  // namespace

void register_collision_pipelines(Registry& r) {
  ComponentInfo info;
  info.name = "CollisionPipeline";
  info.category = "Collision/Detection";
  info.description =
      "collision detection and response over the models below its node (reset, bounding trees, "
      "broad phase, narrow phase, contacts)";
  info.create = creator<CollisionPipeline>();
  r.add(std::move(info));
  ComponentInfo composite;
  composite.name = "CompositeCollisionPipeline";
  composite.category = "Collision/Detection";
  composite.description = "runs several SubCollisionPipelines, each over its own collision models";
  composite.create = creator<CompositeCollisionPipeline>();
  r.add(std::move(composite));
  ComponentInfo sub;
  sub.name = "SubCollisionPipeline";
  sub.category = "Collision/Detection";
  sub.description = "one collision detection over the listed models with the linked phases and contact manager";
  sub.create = creator<SubCollisionPipeline>();
  r.add(std::move(sub));
}

}  // namespace sinew
