// Component: the unit a scene is made of (one XML element).
//
// A component declares its fields as members (see core/field.h); the
// registry creates it, the builder inserts it in a node and parses its
// attributes, then `init()` runs in scene order.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "core/base.h"
#include "core/field.h"

namespace sinew {

class Node;
class MeshTopologyBase;
struct Event;

enum class ComponentState { valid, invalid };

// Attributes of one XML element, with "used" flags so that unread ones can be
// reported ("Unused attribute"). Iteration is alphabetical, as SOFA parses them.
class AttributeMap {
 public:
  void set(std::string name, std::string value) { values_[std::move(name)] = {std::move(value), false}; }
  // Returns the value and marks the attribute used; nullptr when absent.
  const std::string* take(std::string_view name);
  const std::string* peek(std::string_view name) const;
  struct Entry {
    std::string value;
    bool used = false;
  };
  std::map<std::string, Entry, std::less<>>& entries() { return values_; }
  const std::map<std::string, Entry, std::less<>>& entries() const { return values_; }

 private:
  std::map<std::string, Entry, std::less<>> values_;
};

class Component : public Base {
 public:
  Component();
  ~Component() override;

  Field<std::string> name{this, "name", "", "object name (default: class name + counter)", "Infos"};
  Field<bool> print_log{this, "printLog", false, "print debug messages of this component", "Infos"};
  Field<std::vector<std::string>> tags{this, "tags", {}, "tags filtering which solvers see this component", "Infos"};
  Field<bool> listening{this, "listening", false, "receive events (AnimateBegin, ...) even without a handler", "Infos"};

  // Set by the registry when created.
  const std::string& class_name() const { return class_name_; }
  const std::string& template_name() const { return template_name_; }
  void set_type(std::string cls, std::string tmpl) {
    class_name_ = std::move(cls);
    template_name_ = std::move(tmpl);
  }

  Node* node() const { return node_; }
  void set_node(Node* n) { node_ = n; }

  // Parses attributes into fields. Components with pseudo-attributes
  // (MechanicalObject's dx/rx/scale...) override it, take theirs, then call
  // the base version. Messages go to `diag` with this component's location.
  virtual void parse(AttributeMap& attrs, Diagnostics& diag);

  // Life cycle, in SOFA's order: init top-down in node order, bwd_init bottom-up reversed.
  virtual void init() {}
  virtual void bwd_init() {}
  virtual void reinit() {}
  virtual void reset() {}
  virtual void store_reset_state() {}
  // The simulation is closed (SOFA's cleanup, before the graph is deleted): exporters
  // write their last file here (exportAtEnd). Called once, by cleanup_root.
  virtual void cleanup() {}
  virtual void handle_event(Event&) {}
  // A topology this component may depend on is changing: called during the top-down
  // visit of a propagation (core/topology_change.h); `source.topology_changes()` lists
  // the events. Per-element data follows through TopologyHandlers instead.
  virtual void handle_topology_change(MeshTopologyBase& source) {}
  // Whether handle_event should be called (true for components that react to events).
  virtual bool wants_events() const { return listening.value(); }

  // Viewer-only components accept any attribute silently (nothing to check in batch runs).
  virtual bool accepts_any_attribute() const { return false; }

  // An invalid component is skipped by the step (it cannot work: bad input,
  // missing link, diverged). Changing the state bumps the graph's structure
  // version, so gathered scopes drop or take back the component.
  ComponentState state() const { return state_; }
  void set_state(ComponentState s);
  // Set by the simulation once init() ran (init_root, or init_added for components added later).
  bool initialised() const { return initialised_; }
  void mark_initialised() { initialised_ = true; }

  std::string describe() const override;

  // Messages raised during init or a step, attributed to this component.
  void msg_error(const std::string& text) const;
  void msg_warning(const std::string& text) const;
  void msg_info(const std::string& text) const;

 private:
  ComponentState state_ = ComponentState::valid;
  bool initialised_ = false;
  std::string class_name_, template_name_;
  Node* node_ = nullptr;
};

// Events broadcast top-down through the graph.
struct Event {
  // Key events come from a front end (viewer, script) with the key's character;
  // script events from a script (SofaPython3's Node.sendEvent), named, with a payload
  // only that front end reads.
  // The two constraint events are sent by a constraint solver to its node and below once
  // its problem is built (W, dfree) and once it is solved (λ), as SOFA's ConstraintSolverImpl.
  enum class Kind {
    animate_begin,
    animate_end,
    simulation_init_done,
    key_pressed,
    key_released,
    script,
    build_constraint_system_end,
    solve_constraint_system_end
  } kind;
  double dt = 0;
  bool handled = false;
  char key = 0;
  const Node* sender = nullptr;  // script events
  std::string name{};            // script events
  void* payload = nullptr;       // script events (not owned)
};

}  // namespace sinew
