#include "runner/probes.h"

#include <unordered_map>

#include "regression/state_file.h"
#include "exporter/playback/topology_view.h"
#include "regression/topology_file.h"

namespace sinew::runner {

namespace {

bool has_mapping(const Node& n) {
  if (n.mechanical_mapping) return true;
  return n.find_local<Mapping>() != nullptr;
}

// What a node inherits from the nodes above it (through every parent, in a DAG).
struct Above {
  bool solver = false;
  bool mapping = false;
};

// Visits the active nodes top-down with what is above each (its own solver and mapping included).
template <class F>
void visit_with_above(Node& root, F&& f) {
  std::unordered_map<const Node*, Above> above;
  traverse(root, [&](Node& n, bool) {
    if (!n.activated.value()) return Visit::skip;
    Above a;
    for (const Node* p : n.parents())
      if (auto it = above.find(p); it != above.end()) {
        a.solver = a.solver || it->second.solver;
        a.mapping = a.mapping || it->second.mapping;
      }
    a.solver = a.solver || !n.solvers.empty();
    a.mapping = a.mapping || has_mapping(n);
    above[&n] = a;
    f(n, a);
    return Visit::descend;
  });
}

}  // namespace

std::vector<StateTarget> select_states(Node& root, bool mapped) {
  std::vector<StateTarget> out;
  visit_with_above(root, [&](Node& n, const Above& a) {
    if (n.mechanical_state && a.solver && (mapped || !a.mapping))
      out.push_back({&n, n.mechanical_state, static_cast<int>(out.size()), n.mechanical_state->name.value()});
  });
  return out;
}

std::vector<TopologyTarget> select_topologies(Node& root, bool mapped) {
  std::vector<TopologyTarget> out;
  visit_with_above(root, [&](Node& n, const Above& a) {
    if (auto* t = n.find_local<MeshTopologyBase>(); t && (mapped || !a.mapping))
      out.push_back({&n, t, static_cast<int>(out.size()), t->name.value()});
  });
  return out;
}

std::string state_file_suffix(const StateTarget& t) {
  return "_" + std::to_string(t.index) + "_" + t.name + "_mstate.txt";
}
std::string topology_file_suffix(const TopologyTarget& t) {
  return "_" + std::to_string(t.index) + "_" + t.name + "_topology.txt";
}

void StateWriterProbe::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  const auto& x = state_->read(kPosition);
  const auto& v = state_->read(kVelocity);
  regression::append_state_block(text_, node()->time.value(), x.data(), x.size(), v.data(), v.size());
}

void StateCompareProbe::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  const auto& x = state_->read(kPosition);
  const auto& v = state_->read(kVelocity);
  comparer_.on_step_begin(node()->time.value(), x.data(), x.size(), v.data(), v.size(), state_->size());
}

void TopologyWriterProbe::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  regression::append_topology_block(text_, node()->time.value(), topology_view(*topo_));
}

void TopologyCompareProbe::handle_event(Event& e) {
  if (e.kind != Event::Kind::animate_begin) return;
  comparer_.on_step_begin(node()->time.value(), topology_view(*topo_));
}

}  // namespace sinew::runner
