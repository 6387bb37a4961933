// Probes: components attached to a loaded scene that record or compare
// states and topologies at the start of every step, as SOFA's regression
// harness does (spec/regression-protocol.md §2–§7).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/node.h"
#include "regression/state_compare.h"
#include "regression/topology_compare.h"

namespace sinew::runner {

// A state selected for regression files, in numbering order.
struct StateTarget {
  Node* node;
  MechanicalState* state;
  int index;         // N in <base>_<N>_<NAME>_mstate.txt
  std::string name;  // the state's name
};
// §4.2: nodes holding a state, with an ODE solver in the node or an ancestor,
// and (unless `mapped`) no mapping in the node or any ancestor.
std::vector<StateTarget> select_states(Node& root, bool mapped);

struct TopologyTarget {
  Node* node;
  MeshTopologyBase* topology;
  int index;
  std::string name;
};
// §4.3 (comparer rule): nodes holding a mesh topology themselves (first one),
// and (unless `mapped`) no mapping in the node or any ancestor.
std::vector<TopologyTarget> select_topologies(Node& root, bool mapped);

// File name suffixes: "_<N>_<NAME>_mstate.txt" / "_<N>_<NAME>_topology.txt".
std::string state_file_suffix(const StateTarget& t);
std::string topology_file_suffix(const TopologyTarget& t);

// Appends one block per step (T=, X=, V=) to an in-memory text; written at the end.
class StateWriterProbe final : public Component {
 public:
  explicit StateWriterProbe(MechanicalState* s) : state_(s) {}
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;
  const std::string& text() const { return text_; }

 private:
  MechanicalState* state_;
  std::string text_;
};

class StateCompareProbe final : public Component {
 public:
  StateCompareProbe(MechanicalState* s, std::vector<regression::StateBlock> blocks, double dt)
      : state_(s), comparer_(std::move(blocks), dt) {}
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;
  const regression::StateComparer& comparer() const { return comparer_; }

 private:
  MechanicalState* state_;
  regression::StateComparer comparer_;
};

class TopologyWriterProbe final : public Component {
 public:
  explicit TopologyWriterProbe(MeshTopologyBase* t) : topo_(t) {}
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;
  const std::string& text() const { return text_; }

 private:
  MeshTopologyBase* topo_;
  std::string text_;
};

class TopologyCompareProbe final : public Component {
 public:
  TopologyCompareProbe(MeshTopologyBase* t, std::vector<regression::TopologyBlock> blocks)
      : topo_(t), comparer_(std::move(blocks)) {}
  bool wants_events() const override { return true; }
  void handle_event(Event& e) override;
  const regression::TopologyComparer& comparer() const { return comparer_; }

 private:
  MeshTopologyBase* topo_;
  regression::TopologyComparer comparer_;
};

}  // namespace sinew::runner
