#include "core/node.h"

namespace sinew {

Node::Node(std::string n) { name.set(std::move(n)); }
Node::~Node() = default;

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
  child->parent_ = this;
  children_.push_back(std::move(child));
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
  Component* raw = c.get();
  raw->set_node(this);
  if (at_front) objects_.insert(objects_.begin(), std::move(c));
  else objects_.push_back(std::move(c));

  if (auto* loop = dynamic_cast<AnimationLoop*>(raw)) {
    warn_replaced(*this, animation_loop, raw, "animation loop");
    animation_loop = loop;
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
  return raw;
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
