#include "runner/probes.h"

#include "regression/state_file.h"
#include "regression/topology_file.h"

namespace sinew::runner {

namespace {

bool has_mapping(const Node& n) {
  if (n.mechanical_mapping) return true;
  return n.find_local<Mapping>() != nullptr;
}

void select_states_rec(Node& n, bool solver_above, bool mapping_above, bool mapped, std::vector<StateTarget>& out) {
  if (!n.activated.value()) return;
  const bool solver = solver_above || !n.solvers.empty();
  const bool mapping = mapping_above || has_mapping(n);
  if (n.mechanical_state && solver && (mapped || !mapping))
    out.push_back({&n, n.mechanical_state, static_cast<int>(out.size()), n.mechanical_state->name.value()});
  for (auto& c : n.children()) select_states_rec(*c, solver, mapping, mapped, out);
}

void select_topologies_rec(Node& n, bool mapping_above, bool mapped, std::vector<TopologyTarget>& out) {
  if (!n.activated.value()) return;
  const bool mapping = mapping_above || has_mapping(n);
  if (auto* t = n.find_local<MeshTopologyBase>(); t && (mapped || !mapping))
    out.push_back({&n, t, static_cast<int>(out.size()), t->name.value()});
  for (auto& c : n.children()) select_topologies_rec(*c, mapping, mapped, out);
}

}  // namespace

std::vector<StateTarget> select_states(Node& root, bool mapped) {
  std::vector<StateTarget> out;
  select_states_rec(root, false, false, mapped, out);
  return out;
}

std::vector<TopologyTarget> select_topologies(Node& root, bool mapped) {
  std::vector<TopologyTarget> out;
  select_topologies_rec(root, false, mapped, out);
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

regression::TopologyView topology_view(const MeshTopologyBase& t) {
  regression::TopologyView view;
  auto flat = [](const auto& list) {
    using Elem = typename std::decay_t<decltype(list)>::value_type;
    return std::span<const std::uint32_t>(reinterpret_cast<const std::uint32_t*>(list.data()),
                                          list.size() * std::tuple_size_v<Elem>);
  };
  view.indices[0] = flat(t.edges());
  view.indices[1] = flat(t.triangles());
  view.indices[2] = flat(t.quads());
  view.indices[3] = flat(t.tetrahedra());
  view.indices[4] = flat(t.hexahedra());
  return view;
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
