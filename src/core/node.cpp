#include "core/node.h"

#include <algorithm>

namespace sinew {

namespace {
// `activated` and `sleeping` decide which nodes the scopes gather.
void on_scope_field_changed(BaseField& f) { static_cast<Node*>(f.owner())->bump_structure_version(); }
}  // namespace

Node::Node(std::string n) {
  name.set(std::move(n));
  activated.set_change_hook(&on_scope_field_changed);
  sleeping.set_change_hook(&on_scope_field_changed);
}
Node::~Node() = default;

StepProfile& Node::profile() {
  Node* r = root();
  if (!r->profile_) r->profile_ = std::make_unique<StepProfile>();
  return *r->profile_;
}

bool Node::refuse_if_locked(const std::string& what) {
  if (!graph_locked()) return false;
  diagnostics().error(where, "cannot " + what + " in " + describe() + " while a step is running (step " +
                                 std::to_string(root()->step_index) +
                                 "): the graph may change only between steps or in begin/end event handlers");
  return true;
}

Node* Node::root() {
  Node* n = this;
  while (n->parent_) n = n->parent_;
  return n;
}

Diagnostics& Node::diagnostics() {
  Node* r = root();
  if (!r->diagnostics_) r->diagnostics_ = std::make_unique<Diagnostics>();
  return *r->diagnostics_;
}

std::string Node::path() const {
  if (!parent_) return "/";
  std::string p = parent_->path();
  if (p.back() != '/') p += '/';
  return p + name.value();
}

Node* Node::add_child(std::unique_ptr<Node> child) {
  if (!child || refuse_if_locked("add child node '" + (child ? child->name.value() : "") + "'")) return nullptr;
  child->parent_ = this;
  // A subtree built on its own had its own root-owned data: messages move to this graph.
  if (child->diagnostics_) {
    for (const Message& m : child->diagnostics_->messages()) diagnostics().add(m.severity, m.where, m.who, m.text);
    child->diagnostics_.reset();
  }
  child->profile_.reset();
  children_.push_back(std::move(child));
  bump_structure_version();
  return children_.back().get();
}

namespace {
template <class T>
void warn_replaced(Node& node, T* previous, Component* c, const char* what) {
  if (previous && previous != c)
    node.diagnostics().warning(c->where, std::string("only one ") + what + " is permitted in " + node.describe() +
                                             ": " + previous->describe() + " replaced by " + c->describe());
}
}  // namespace

Component* Node::add_object(std::unique_ptr<Component> c, bool at_front) {
  if (!c || refuse_if_locked("add " + (c ? c->describe() : std::string("a component")))) return nullptr;
  bump_structure_version();
  Component* raw = c.get();
  raw->set_node(this);
  if (at_front) objects_.insert(objects_.begin(), std::move(c));
  else objects_.push_back(std::move(c));

  if (auto* loop = dynamic_cast<AnimationLoop*>(raw)) {
    warn_replaced(*this, animation_loop, raw, "animation loop");
    animation_loop = loop;
  }
  if (auto* p = dynamic_cast<CollisionPipelineBase*>(raw)) {
    warn_replaced(*this, collision_pipeline, raw, "collision pipeline");
    collision_pipeline = p;
  }
  if (auto* s = dynamic_cast<MechanicalState*>(raw)) {
    warn_replaced(*this, mechanical_state, raw, "mechanical state");
    mechanical_state = s;
  }
  if (auto* m = dynamic_cast<Mapping*>(raw)) mechanical_mapping = m;  // every XML mapping lands here (trap T1)
  if (auto* m = dynamic_cast<Mass*>(raw)) mass = m;
  if (auto* ff = dynamic_cast<ForceField*>(raw)) {
    if (ff->is_interaction()) interaction_force_fields.push_back(ff);
    else force_fields.push_back(ff);
  }
  if (auto* t = dynamic_cast<MeshTopologyBase*>(raw)) mesh_topology = t;
  if (auto* p = dynamic_cast<ProjectiveConstraint*>(raw)) projective_constraints.push_back(p);
  if (auto* s = dynamic_cast<OdeSolver*>(raw)) solvers.push_back(s);
  if (auto* s = dynamic_cast<LinearSolver*>(raw)) linear_solvers.push_back(s);
  if (auto* co = dynamic_cast<ContextObject*>(raw)) context_objects.push_back(co);
  if (auto* lc = dynamic_cast<LagrangianConstraint*>(raw)) lagrangian_constraints.push_back(lc);
  if (auto* cc = dynamic_cast<ConstraintCorrection*>(raw)) constraint_corrections.push_back(cc);
  if (auto* cs = dynamic_cast<ConstraintSolver*>(raw)) constraint_solvers.push_back(cs);
  return raw;
}

void Node::unfile(Component* c) {
  // Single slots that held it become empty (SOFA's SingleLink remove); lists drop it.
  if (animation_loop == c) animation_loop = nullptr;
  if (collision_pipeline == c) collision_pipeline = nullptr;
  if (mechanical_state == c) mechanical_state = nullptr;
  if (mechanical_mapping == c) mechanical_mapping = nullptr;
  if (mass == c) mass = nullptr;
  if (mesh_topology == c) mesh_topology = nullptr;
  auto drop = [c](auto& list) { std::erase_if(list, [c](auto* p) { return static_cast<Component*>(p) == c; }); };
  drop(force_fields);
  drop(interaction_force_fields);
  drop(projective_constraints);
  drop(solvers);
  drop(linear_solvers);
  drop(context_objects);
  drop(lagrangian_constraints);
  drop(constraint_corrections);
  drop(constraint_solvers);
}

namespace {

// Everything in a subtree: the nodes and their components.
void collect_subtree(Node& n, std::vector<const Base*>& out) {
  out.push_back(&n);
  for (auto& o : n.objects()) out.push_back(o.get());
  for (auto& c : n.children()) collect_subtree(*c, out);
}

// Cuts every link and data link from the rest of the graph into `gone`.
// A component that loses an object link cannot work any more: it becomes
// invalid (it was initialised against the removed object). A data link keeps
// its last value.
void cut_links_into(Node& root, const std::vector<const Base*>& gone) {
  auto is_gone = [&](const Base* b) { return std::find(gone.begin(), gone.end(), b) != gone.end(); };
  auto visit = [&](auto&& self, Node& n) -> void {
    if (is_gone(&n)) return;
    std::vector<Base*> owners{&n};
    for (auto& o : n.objects()) owners.push_back(o.get());
    for (Base* b : owners) {
      for (BaseField* f : b->fields())
        if (f->parent() && is_gone(f->parent()->owner())) {
          f->update();  // last value from the leaving parent
          f->set_parent(nullptr);
        }
      for (BaseLink* l : b->links())
        for (const Base* g : gone)
          if (l->references(g)) {
            l->forget(g);
            if (auto* c = dynamic_cast<Component*>(b)) {
              c->msg_warning("link '" + l->name() + "' pointed to " + g->describe() +
                             ", which was removed from the graph: this component is disabled");
              c->set_state(ComponentState::invalid);
            }
          }
    }
    for (auto& c : n.children()) self(self, *c);
  };
  visit(visit, root);
}

}  // namespace

std::unique_ptr<Component> Node::remove_object(Component* c) {
  auto it = std::find_if(objects_.begin(), objects_.end(), [c](auto& o) { return o.get() == c; });
  if (it == objects_.end() || refuse_if_locked("remove " + c->describe())) return nullptr;
  std::unique_ptr<Component> out = std::move(*it);
  objects_.erase(it);
  unfile(c);
  cut_links_into(*root(), {c});
  c->set_node(nullptr);
  bump_structure_version();
  return out;
}

void Node::move_to_end(Component* c) {
  auto it = std::find_if(objects_.begin(), objects_.end(), [c](auto& o) { return o.get() == c; });
  if (it == objects_.end()) return;
  bool moved = false;
  if (std::next(it) != objects_.end()) {
    std::rotate(it, std::next(it), objects_.end());
    moved = true;
  }
  auto to_end = [&](auto& list) {
    auto p = std::find_if(list.begin(), list.end(), [c](auto* q) { return static_cast<Component*>(q) == c; });
    if (p != list.end() && std::next(p) != list.end()) {
      std::rotate(p, std::next(p), list.end());
      moved = true;
    }
  };
  to_end(force_fields);
  to_end(interaction_force_fields);
  to_end(projective_constraints);
  to_end(lagrangian_constraints);
  if (moved) bump_structure_version();
}

std::unique_ptr<Node> Node::remove_child(Node* child) {
  auto it = std::find_if(children_.begin(), children_.end(), [child](auto& n) { return n.get() == child; });
  if (it == children_.end() || refuse_if_locked("remove child " + child->describe())) return nullptr;
  std::unique_ptr<Node> out = std::move(*it);
  children_.erase(it);
  std::vector<const Base*> gone;
  collect_subtree(*out, gone);
  cut_links_into(*root(), gone);
  out->parent_ = nullptr;
  bump_structure_version();
  return out;
}

MechanicalState* Node::get_mechanical_state() const {
  if (mechanical_state) return mechanical_state;
  for (const Node* n = parent_; n; n = n->parent_)
    if (auto* s = n->find_local<MechanicalState>()) return s;
  return nullptr;
}

MeshTopologyBase* Node::get_mesh_topology_link() const {
  if (mesh_topology) return mesh_topology;
  for (const Node* n = parent_; n; n = n->parent_)
    if (auto* t = n->find_local<MeshTopologyBase>()) return t;
  return nullptr;
}

Component* Node::find_object_named(std::string_view n) const {
  for (auto& o : objects_)
    if (o->name.value() == n) return o.get();
  return nullptr;
}

Node* Node::find_child_named(std::string_view n) const {
  for (auto& c : children_)
    if (c->name.value() == n) return c.get();
  return nullptr;
}

void Node::update_context() {
  if (parent_) {
    // Child nodes' own dt/gravity are overwritten by the parent's (trap T3).
    dt.set(parent_->dt.value());
    gravity.set(parent_->gravity.value());
    time.set(parent_->time.value());
  }
  for (ContextObject* co : context_objects) co->apply(*this);
}

void for_each_node(Node& root, const std::function<void(Node&)>& f) {
  if (!root.activated.value()) return;
  f(root);
  for (std::size_t i = 0; i < root.children().size(); ++i) for_each_node(*root.children()[i], f);
}

}  // namespace sinew
