#include "core/node.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

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
Node::~Node() {
  // Links with nodes that outlive this one are undone both ways; the children
  // this node owns are destroyed with it (owned_), whatever else links them.
  for (std::size_t i = 1; i < parents_.size(); ++i) {
    Node* p = parents_[i];
    std::erase(p->children_, this);
    if (Node* r = p->root(); r->dag_links_ > 0) --r->dag_links_;
  }
  for (Node* c : children_)
    if (c->parent() != this) c->unlink_parent(this);
  children_.clear();
}

void Node::unlink_parent(Node* p) {
  auto it = std::find(parents_.begin(), parents_.end(), p);
  if (it == parents_.end()) return;
  if (Node* r = root(); r->dag_links_ > 0) --r->dag_links_;
  parents_.erase(it);
}

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
  while (!n->parents_.empty()) n = n->parents_.front();
  return n;
}

Diagnostics& Node::diagnostics() {
  Node* r = root();
  if (!r->diagnostics_) r->diagnostics_ = std::make_unique<Diagnostics>();
  return *r->diagnostics_;
}

std::string Node::path() const {
  if (parents_.empty()) return "/";
  std::string p = parents_.front()->path();
  if (p.back() != '/') p += '/';
  return p + name.value();
}

Node* Node::add_child(std::unique_ptr<Node>&& child) {
  if (!child || refuse_if_locked("add child node '" + (child ? child->name.value() : "") + "'")) return nullptr;
  if (!child->parents_.empty()) {
    diagnostics().error(where, "cannot add " + child->describe() + " to " + describe() + ": it already has a parent");
    return nullptr;
  }
  if (root() == child.get()) {  // a root given back to a node of its own graph
    diagnostics().error(where, "cannot add " + child->describe() + " to " + describe() +
                                   ": this node is below it (the graph would have a cycle)");
    return nullptr;
  }
  child->parents_.push_back(this);
  // A subtree built on its own had its own root-owned data: messages move to this graph.
  if (child->diagnostics_) {
    for (const Message& m : child->diagnostics_->messages()) diagnostics().add(m.severity, m.where, m.who, m.text);
    child->diagnostics_.reset();
  }
  child->profile_.reset();
  root()->dag_links_ += child->dag_links_;
  child->dag_links_ = 0;
  Node* raw = child.get();
  owned_.push_back(std::move(child));
  children_.push_back(raw);
  bump_structure_version();
  return raw;
}

bool Node::add_linked_child(Node* child) {
  if (!child || refuse_if_locked("add child node '" + (child ? child->name.value() : "") + "'")) return false;
  auto refuse = [&](const std::string& why) {
    diagnostics().error(where, "cannot add " + child->describe() + " as a child of " + describe() + ": " + why);
    return false;
  };
  if (child->root() != root()) return refuse("it is not in the same graph (add it to a node of this graph first)");
  if (std::find(children_.begin(), children_.end(), child) != children_.end()) return refuse("it is already one");
  // A cycle: this node is the child itself or below it.
  std::vector<const Node*> stack{child};
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    if (n == this) return refuse("this node is below it (the graph would have a cycle)");
    stack.insert(stack.end(), n->children_.begin(), n->children_.end());
  }
  child->parents_.push_back(this);
  children_.push_back(child);
  ++root()->dag_links_;
  bump_structure_version();
  return true;
}

namespace {
template <class T>
void warn_replaced(Node& node, T* previous, Component* c, const char* what) {
  if (previous && previous != c)
    node.diagnostics().warning(c->where, std::string("only one ") + what + " is permitted in " + node.describe() +
                                             ": " + previous->describe() + " replaced by " + c->describe());
}
}  // namespace

Component* Node::add_object(std::unique_ptr<Component>&& c, bool at_front) {
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

// Everything a subtree owns: the nodes and their components.
void collect_subtree(Node& n, std::vector<const Base*>& out) {
  out.push_back(&n);
  for (auto& o : n.objects()) out.push_back(o.get());
  for (Node* c : n.children())
    if (n.owns(c)) collect_subtree(*c, out);
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
    for (Node* c : n.children())
      if (n.owns(c)) self(self, *c);
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
  auto it = std::find(children_.begin(), children_.end(), child);
  if (it == children_.end() || refuse_if_locked("remove child " + child->describe())) return nullptr;
  children_.erase(it);
  bump_structure_version();
  if (!owns(child)) {  // a linked child: only the link goes
    child->unlink_parent(this);
    return nullptr;
  }
  auto own = std::find_if(owned_.begin(), owned_.end(), [child](auto& n) { return n.get() == child; });
  std::unique_ptr<Node> out = std::move(*own);
  owned_.erase(own);
  if (child->parents_.size() > 1) {  // the next parent becomes the owner
    Node* heir = child->parents_[1];
    child->unlink_parent(this);
    heir->owned_.push_back(std::move(out));
    return nullptr;
  }
  // The subtree leaves as a tree: parent links across its border are cut both ways.
  std::vector<const Base*> gone;
  collect_subtree(*child, gone);
  std::unordered_set<const Base*> inside(gone.begin(), gone.end());
  Node* r = root();
  for (const Base* b : gone) {
    auto* n = dynamic_cast<Node*>(const_cast<Base*>(b));
    if (!n) continue;
    for (std::size_t i = n->parents_.size(); i-- > 1;)
      if (!inside.contains(n->parents_[i])) {
        std::erase(n->parents_[i]->children_, n);
        n->parents_.erase(n->parents_.begin() + static_cast<std::ptrdiff_t>(i));
        if (r->dag_links_ > 0) --r->dag_links_;
      }
    for (std::size_t i = n->children_.size(); i-- > 0;)
      if (Node* c = n->children_[i]; !inside.contains(c)) {
        n->children_.erase(n->children_.begin() + static_cast<std::ptrdiff_t>(i));
        c->unlink_parent(n);
      }
  }
  // Links inside the leaving subtree go with it.
  std::size_t inner = 0;
  for (const Base* b : gone)
    if (auto* n = dynamic_cast<const Node*>(b)) inner += n->parents_.size() > 1 ? n->parents_.size() - 1 : 0;
  r->dag_links_ -= std::min(r->dag_links_, inner);
  child->dag_links_ = inner;
  cut_links_into(*r, gone);
  child->parents_.clear();
  return out;
}

MechanicalState* Node::get_mechanical_state() const {
  if (mechanical_state) return mechanical_state;
  for (const Node* p : parents_)
    if (auto* s = p->find_up<MechanicalState>()) return s;
  return nullptr;
}

MeshTopologyBase* Node::get_mesh_topology_link() const {
  if (mesh_topology) return mesh_topology;
  for (const Node* p : parents_)
    if (auto* t = p->find_up<MeshTopologyBase>()) return t;
  return nullptr;
}

Component* Node::find_object_named(std::string_view n) const {
  for (auto& o : objects_)
    if (o->name.value() == n) return o.get();
  return nullptr;
}

Node* Node::find_child_named(std::string_view n) const {
  for (Node* c : children_)
    if (c->name.value() == n) return c;
  return nullptr;
}

void Node::update_context() {
  if (Node* p = parent()) {
    // Child nodes' own dt/gravity are overwritten by the parent's (trap T3).
    dt.set(p->dt.value());
    gravity.set(p->gravity.value());
    time.set(p->time.value());
  }
  for (ContextObject* co : context_objects) co->apply(*this);
}

bool graph_has_links(const Node& n) {
  const Node* r = &n;
  while (!r->parents_.empty()) r = r->parents_.front();
  return r->dag_links_ > 0;
}

namespace {

using Down = FunctionRef<Visit(Node&, bool)>;
using Up = FunctionRef<void(Node&)>;

// Trees: plain recursion. Children are read by index, so nodes added during
// the traversal (by init, by an event handler) are reached too.
void walk_tree(Node& n, bool pruned, Down down, Up up) {
  const Visit v = down(n, pruned);
  if (v == Visit::skip) return;
  pruned = pruned || v == Visit::prune;
  for (std::size_t i = 0; i < n.children().size(); ++i) walk_tree(*n.children()[i], pruned, down, up);
  if (up) up(n);
}

// DAGs: SOFA's status map. A node waits for all of its parents inside the
// traversal; it is pruned when they all are.
struct DagWalk {
  Down down;
  Up up;
  Node* top;
  std::unordered_set<const Node*> inside;
  std::unordered_map<const Node*, bool> pruned;  // visited nodes → pruned

  void walk(Node& n) {
    if (pruned.contains(&n)) return;
    bool all_pruned = true, has_parent = false;
    if (&n != top) {
      for (const Node* p : n.parents()) {
        if (!inside.contains(p)) continue;
        auto it = pruned.find(p);
        if (it == pruned.end()) return;  // the last parent to be visited brings it
        all_pruned = all_pruned && it->second;
        has_parent = true;
      }
    }
    const bool inherited = all_pruned && has_parent;
    const Visit v = down(n, inherited);
    pruned[&n] = inherited || v != Visit::descend;
    if (v == Visit::skip) return;
    for (std::size_t i = 0; i < n.children().size(); ++i) walk(*n.children()[i]);
    if (up) up(n);
  }
};

}  // namespace

void traverse(Node& top, Down down, Up up) {
  if (!graph_has_links(top)) {
    walk_tree(top, false, down, up);
    return;
  }
  DagWalk w{down, up, &top, {}, {}};
  std::vector<const Node*> stack{&top};
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    if (w.inside.insert(n).second) stack.insert(stack.end(), n->children().begin(), n->children().end());
  }
  w.walk(top);
}

void for_each_node(Node& root, FunctionRef<void(Node&)> f) {
  traverse(root, [&](Node& n, bool) {
    if (!n.activated.value()) return Visit::skip;
    f(n);
    return Visit::descend;
  });
}

}  // namespace sinew
