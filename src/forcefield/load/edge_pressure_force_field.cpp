#include "forcefield/load/edge_pressure_force_field.h"

#include <cmath>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

void EdgePressureForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "an edge topology is required")) return;
  const Vec3 P = pressure.get();
  if (!(P[0] * P[0] + P[1] * P[1] + P[2] * P[2] > 0)) {
    msg_error("a non-zero 'pressure' is required (the p_intensity/normal mode is not supported)");
    set_state(ComponentState::invalid);
    return;
  }
  if (!select()) set_state(ComponentState::invalid);
}

bool EdgePressureForceField::select() {
  const auto& topo_edges = topology->edges();
  edges_version_ = topology->elements_version(MeshTopologyBase::Elements::edges);
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  const std::size_t np = mstate->size();
  std::vector<unsigned> idx;
  if (dmin.get() != dmax.get()) {
    const Vec3 n = normal.get();
    std::vector<char> in(np, 0);
    for (std::size_t i = 0; i < np; ++i) {
      const double d = x0[3 * i] * n[0] + x0[3 * i + 1] * n[1] + x0[3 * i + 2] * n[2];
      in[i] = d > dmin.get() && d < dmax.get();
    }
    for (unsigned e = 0; e < topo_edges.size(); ++e)
      if (topo_edges[e][0] < np && topo_edges[e][1] < np && in[topo_edges[e][0]] && in[topo_edges[e][1]])
        idx.push_back(e);
  }
  if (!edge_indices.get().empty()) idx = edge_indices.get();
  if (!edges.get().empty()) {
    // Each listed pair is looked up as an ordered pair; SOFA keeps index 0 when absent.
    const auto& want = edges.get();
    idx.assign(want.size(), 0);
    for (std::size_t i = 0; i < want.size(); ++i)
      for (unsigned j = 0; j < topo_edges.size(); ++j)
        if (want[i][0] == topo_edges[j][0] && want[i][1] == topo_edges[j][1]) idx[i] = j;
  }
  selected_.clear();
  force_.clear();
  const Vec3 P = pressure.get();
  for (std::size_t i = 0; i < idx.size(); ++i) {
    if (idx[i] >= topo_edges.size()) {
      msg_error("edge index " + std::to_string(idx[i]) + " (entry " + std::to_string(i) +
                ") is out of range (the topology has " + std::to_string(topo_edges.size()) + " edges)");
      return false;
    }
    const Edge& e = topo_edges[idx[i]];
    if (e[0] >= np || e[1] >= np) {
      msg_error("edge " + std::to_string(idx[i]) + " refers to a point out of the state (" + std::to_string(np) +
                " points)");
      return false;
    }
    const double d[3] = {x0[3 * e[1]] - x0[3 * e[0]], x0[3 * e[1] + 1] - x0[3 * e[0] + 1],
                         x0[3 * e[1] + 2] - x0[3 * e[0] + 2]};
    const double L = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    selected_.push_back(e);
    force_.push_back(Vec3(P[0] * L, P[1] * L, P[2] * L));
  }
  return true;
}

void EdgePressureForceField::add_force(const MechParams& p) {
  // Topology changes: select again from the (linked) lists.
  if (topology->elements_version(MeshTopologyBase::Elements::edges) != edges_version_ && !select()) {
    set_state(ComponentState::invalid);
    selected_.clear();
    force_.clear();
  }
  std::vector<double>& f = mstate->write(p.f);
  for (std::size_t i = 0; i < selected_.size(); ++i) {
    const double h[3] = {force_[i][0] / 2, force_[i][1] / 2, force_[i][2] / 2};
    for (unsigned v : selected_[i])
      for (int c = 0; c < 3; ++c) f[3 * v + c] += h[c];
  }
}

void register_edge_pressure_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "EdgePressureForceField";
  info.category = "ForceField/MechanicalLoad";
  info.description = "pressure applied on a set of edges";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<EdgePressureForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
