// Node: a scene-graph node holding components and child nodes.
//
// Each component is filed in typed slots on insertion (spec/framework.md
// §3.1): single slots hold the last inserted component of that role, lists
// keep insertion order. The context (dt, gravity, time) is copied from the
// root at init and every step.
//
// The graph is a DAG, as SOFA's: a node may be the child of several nodes
// (SofaPython3 scenes do `simulation.addChild(modelling)` to put a subtree
// that lives elsewhere under a solver). Its first parent owns it and gives it
// its context, path and root; the others only link to it. Traversals visit
// such a node once, after all of its parents (traverse() below).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/base.h"
#include "core/field.h"
#include "core/function_ref.h"
#include "core/constraint_problem.h"
#include "core/profile.h"
#include "core/roles.h"
#include "core/step_observer.h"

namespace sinew {

class Node final : public Base {
 public:
  explicit Node(std::string name = {});
  ~Node() override;

  Field<std::string> name{this, "name", "", "node name", "Infos"};
  Field<double> dt{this, "dt", 0.01, "time step; only the root's value is used", "Context", "time"};
  Field<Vec3> gravity{this, "gravity", Vec3(0, -9.81, 0), "gravity; only the root's value is used",
                      "Context", "length/time²"};
  Field<double> time{this, "time", 0.0, "current time", "Context", "time"};
  Field<bool> animate{this, "animate", false, "start animating when loaded in a viewer", "Context"};
  Field<bool> activated{this, "activated", true, "inactive nodes and their subtree are skipped", "Context"};
  Field<bool> sleeping{this, "sleeping", false, "sleeping nodes are skipped by mechanical operations",
                       "Context"};
  Field<bool> can_change_sleeping_state{this, "canChangeSleepingState", false, "", "Context"};
  Field<std::vector<std::string>> tags{this, "tags", {}, "tags filtering which solvers see this node", "Infos"};
  Field<bool> print_log{this, "printLog", false, "print debug messages", "Infos"};
  Field<std::vector<double>> bbox{this, "bbox", {}, "fixed bounding box (viewer only)", "Visualization"};

  std::string describe() const override { return "node '" + name.value() + "'"; }

  // ------------------------------------------------------------ structure
  // The first parent (the owner), nullptr for a root.
  Node* parent() const { return parents_.empty() ? nullptr : parents_.front(); }
  // Every parent, the owner first, then the nodes that linked this one as a child.
  const std::vector<Node*>& parents() const { return parents_; }
  Node* root();
  // Children in insertion order: the ones this node owns and the ones it links.
  const std::vector<Node*>& children() const { return children_; }
  // Whether this node owns `child` (is its first parent).
  bool owns(const Node* child) const { return child && child->parent() == this; }
  const std::vector<std::unique_ptr<Component>>& objects() const { return objects_; }
  // Structural edits. Each bumps the root's structure version. While the
  // graph is locked (the mechanical stages of a step) they are refused: an
  // error is reported and nullptr returned, the graph is left unchanged.
  // Additions take ownership only when they succeed: on refusal the caller's
  // pointer still holds the node or component (when it is a unique_ptr<Node>
  // or unique_ptr<Component> itself: one of a derived type converts to a
  // temporary, which is destroyed).
  Node* add_child(std::unique_ptr<Node>&& child);
  // Adds `child`, a node of this same graph, as a further child: it keeps its
  // owner and gains this node as a parent (SOFA's addChild of a node that
  // already has one). Refused with an error (false) when it would make a
  // cycle, when `child` is already a child of this node or in another graph.
  bool add_linked_child(Node* child);
  // Inserts a component at the end (or at the front) and files it in its slots.
  Component* add_object(std::unique_ptr<Component>&& c, bool at_front = false);
  // Takes a component out of this node: unfiled from its slots (a single slot
  // that held it becomes empty, as in SOFA), links and data links elsewhere in
  // the graph that pointed to it are cut (their components are told, and
  // become invalid when the link was required). Returns the component (nullptr
  // when it is not an object of this node or the graph is locked).
  std::unique_ptr<Component> remove_object(Component* c);
  // Takes a child node out of this node. When the child has other parents it
  // stays in the graph under them (the next parent becomes its owner) and
  // nullptr is returned. Otherwise its subtree leaves the graph and is
  // returned: links into it are cut as above, and so are the parent links
  // between the subtree and the rest of the graph (it leaves as a tree).
  // nullptr too when `child` is not a child of this node or the graph is locked.
  std::unique_ptr<Node> remove_child(Node* child);
  // Moves an object to the end of the object list and of its slot lists, as
  // if removed and added again, without cutting links (a contact response is
  // re-attached after the other objects each step, spec/interaction.md §4.2).
  // Bumps the structure version only when the order changed.
  void move_to_end(Component* c);
  // Index counter for default names ("MechanicalObject1", ...), per class within this node.
  int next_default_index(const std::string& class_name) { return ++default_names_[class_name]; }
  // Path of this node from the root ("/", "/child/grandchild").
  std::string path() const;

  // ------------------------------------------------------------ slots
  AnimationLoop* animation_loop = nullptr;
  CollisionPipelineBase* collision_pipeline = nullptr;  // SOFA's single collisionPipeline slot
  MechanicalState* mechanical_state = nullptr;
  Mapping* mechanical_mapping = nullptr;
  Mass* mass = nullptr;
  MeshTopologyBase* mesh_topology = nullptr;  // last mesh topology inserted
  std::vector<ForceField*> force_fields;      // masses included
  std::vector<ForceField*> interaction_force_fields;
  std::vector<ProjectiveConstraint*> projective_constraints;
  std::vector<OdeSolver*> solvers;
  std::vector<LinearSolver*> linear_solvers;
  std::vector<ContextObject*> context_objects;
  std::vector<LagrangianConstraint*> lagrangian_constraints;  // constraintSet
  std::vector<ConstraintCorrection*> constraint_corrections;
  std::vector<ConstraintSolver*> constraint_solvers;

  // ------------------------------------------------------------ look-ups (§3.3)
  // Node slot, else the first state (object order) of the nearest ancestor that has one.
  MechanicalState* get_mechanical_state() const;
  // Node slot (last inserted), else the first mesh topology of the nearest ancestor that has one.
  MeshTopologyBase* get_mesh_topology_link() const;
  // First object of type T in this node's object order.
  template <class T>
  T* find_local() const {
    for (auto& o : objects_)
      if (auto* t = dynamic_cast<T*>(o.get())) return t;
    return nullptr;
  }
  // First in this node, then its parents in order, each searched upwards (SOFA's SearchUp).
  template <class T>
  T* find_up() const {
    if (T* t = find_local<T>()) return t;
    for (const Node* p : parents_)
      if (T* t = p->find_up<T>()) return t;
    return nullptr;
  }
  // First in this node, then children depth-first.
  template <class T>
  T* find_down() const {
    if (T* t = find_local<T>()) return t;
    for (auto& c : children_)
      if (T* t = c->find_down<T>()) return t;
    return nullptr;
  }
  // Objects of type T in this subtree, each once, top-down in traverse() order
  // (node objects in order, then children), inactive nodes included.
  template <class T>
  void collect_down(std::vector<T*>& out) const;
  Component* find_object_named(std::string_view n) const;
  Node* find_child_named(std::string_view n) const;

  // ------------------------------------------------------------ context
  // Copies dt, gravity and time from the first parent, then applies context objects.
  void update_context();
  // Diagnostics sink of the whole graph (owned by the root).
  Diagnostics& diagnostics();
  // Current step number (for messages raised during a step).
  long step_index = -1;

  // ------------------------------------------------------------ per simulation (root-owned)
  // Stage timings of this simulation's steps.
  StepProfile& profile();
  // Bumped by every structural change of the graph: objects or nodes added or
  // removed, a node (de)activated or put to sleep, a component made invalid.
  // Scopes gathered from the graph (MechanicalOps, the loop's graph view)
  // remember the version they were built at and rebuild when it moved.
  std::uint64_t structure_version() { return root()->structure_version_; }
  void bump_structure_version() { ++root()->structure_version_; }
  // Locked while the mechanical stages of a step run (Box2D's world->locked).
  bool graph_locked() { return root()->graph_locked_; }
  void set_graph_locked(bool on) { root()->graph_locked_ = on; }
  // Observers called around every stage of this simulation's steps (not owned).
  std::vector<StepObserver*>& step_observers() { return root()->step_observers_; }
  // Set once init() ran on this node's components (init_root, or init_added later).
  bool initialised = false;
  // Root only: cleanup_root ran (the scene is closed; exporters wrote their last files).
  bool cleaned_up = false;
  // Root only: the data folders resources were searched in when the scene was
  // loaded, in search order (SOFA's DataRepository; the first is where SOFA
  // writes caches such as PrecomputedConstraintCorrection's compliance).
  std::vector<std::string> data_dirs;
 private:
  std::vector<Node*> parents_;                  // owner first
  std::vector<Node*> children_;                 // owned and linked, in insertion order
  std::vector<std::unique_ptr<Node>> owned_;    // the children this node owns
  std::size_t dag_links_ = 0;                   // root only: parent links beyond the owners
  std::vector<std::unique_ptr<Component>> objects_;
  std::map<std::string, int> default_names_;
  std::unique_ptr<Diagnostics> diagnostics_;  // root only
  std::unique_ptr<StepProfile> profile_;      // root only
  std::uint64_t structure_version_ = 1;       // root only
  bool graph_locked_ = false;                 // root only
  std::vector<StepObserver*> step_observers_;  // root only

  bool refuse_if_locked(const std::string& what);
  void unfile(Component* c);
  void unlink_parent(Node* p);
  friend bool graph_has_links(const Node& n);
};

// ------------------------------------------------------------ traversal

// What a traversal callback asks for a node (SOFA's visitor results).
enum class Visit : unsigned char {
  descend,  // go on into the children
  prune,    // the children see this node as pruned (they are still reached)
  skip,     // stop here: the children are not reached from this node (inactive, asleep)
};

// Top-down over `top` and the nodes below it in SOFA's order for a DAG
// (Node::executeVisitorTopDown): depth-first, children in order; a node with
// several parents is visited once, when the last of its parents below `top`
// was (parents outside `top`'s subtree are ignored). `down(node, pruned)` is
// called for every node reached; `pruned` is true when all of its parents in
// the traversal pruned it (SOFA does not execute such a node but goes on to
// its children, which may have an unpruned parent elsewhere). `up(node)`, when
// given, runs after the node's children (not for skipped nodes). For a tree
// this is plain pre-order and allocates nothing.
void traverse(Node& top, FunctionRef<Visit(Node&, bool pruned)> down, FunctionRef<void(Node&)> up = {});

// Pre-order over active nodes, each once (SOFA's DAG order; for trees, depth-first pre-order).
void for_each_node(Node& root, FunctionRef<void(Node&)> f);

// Whether some node of `n`'s graph has several parents.
bool graph_has_links(const Node& n);

template <class T>
void Node::collect_down(std::vector<T*>& out) const {
  traverse(const_cast<Node&>(*this), [&](Node& n, bool) {
    for (auto& o : n.objects_)
      if (auto* t = dynamic_cast<T*>(o.get())) out.push_back(t);
    return Visit::descend;
  });
}

}  // namespace sinew
