// Node: a scene-graph node holding components and child nodes.
//
// Each component is filed in typed slots on insertion (spec/framework.md
// §3.1): single slots hold the last inserted component of that role, lists
// keep insertion order. The context (dt, gravity, time) is copied from the
// root at init and every step.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/base.h"
#include "core/field.h"
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
  Node* parent() const { return parent_; }
  Node* root();
  const std::vector<std::unique_ptr<Node>>& children() const { return children_; }
  const std::vector<std::unique_ptr<Component>>& objects() const { return objects_; }
  // Structural edits. Each bumps the root's structure version. While the
  // graph is locked (the mechanical stages of a step) they are refused: an
  // error is reported and nullptr returned, the graph is left unchanged.
  Node* add_child(std::unique_ptr<Node> child);
  // Inserts a component at the end (or at the front) and files it in its slots.
  Component* add_object(std::unique_ptr<Component> c, bool at_front = false);
  // Takes a component out of this node: unfiled from its slots (a single slot
  // that held it becomes empty, as in SOFA), links and data links elsewhere in
  // the graph that pointed to it are cut (their components are told, and
  // become invalid when the link was required). Returns the component (nullptr
  // when it is not an object of this node or the graph is locked).
  std::unique_ptr<Component> remove_object(Component* c);
  // Takes a child node (and its subtree) out; links into the subtree are cut as above.
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
  // First in this node, then ancestors.
  template <class T>
  T* find_up() const {
    for (const Node* n = this; n; n = n->parent_)
      if (T* t = n->find_local<T>()) return t;
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
  // Objects of type T in this subtree, top-down (node objects in order, then children).
  template <class T>
  void collect_down(std::vector<T*>& out) const {
    for (auto& o : objects_)
      if (auto* t = dynamic_cast<T*>(o.get())) out.push_back(t);
    for (auto& c : children_) c->collect_down(out);
  }
  Component* find_object_named(std::string_view n) const;
  Node* find_child_named(std::string_view n) const;

  // ------------------------------------------------------------ context
  // Copies dt, gravity and time from the parent, then applies context objects.
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
  // Root only: the data folders resources were searched in when the scene was
  // loaded, in search order (SOFA's DataRepository; the first is where SOFA
  // writes caches such as PrecomputedConstraintCorrection's compliance).
  std::vector<std::string> data_dirs;
 private:
  Node* parent_ = nullptr;
  std::vector<std::unique_ptr<Node>> children_;
  std::vector<std::unique_ptr<Component>> objects_;
  std::map<std::string, int> default_names_;
  std::unique_ptr<Diagnostics> diagnostics_;  // root only
  std::unique_ptr<StepProfile> profile_;      // root only
  std::uint64_t structure_version_ = 1;       // root only
  bool graph_locked_ = false;                 // root only
  std::vector<StepObserver*> step_observers_;  // root only

  bool refuse_if_locked(const std::string& what);
  void unfile(Component* c);
};

// Depth-first pre-order over active nodes (SOFA's DAG order for trees).
void for_each_node(Node& root, const std::function<void(Node&)>& f);

}  // namespace sinew
