#include "forcefield/load/edge_pressure_force_field.h"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "projective/subset_indices.h"

namespace sinew {

namespace {

Vec3 point_of(const std::vector<double>& x, unsigned v) { return Vec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]); }

// SOFA's Vec::normalize: divides by the norm only above machine epsilon, else leaves the vector.
void normalize_sofa(Vec3& v) {
  const double n = v.norm();
  if (n > std::numeric_limits<double>::epsilon()) v /= n;
}

}  // namespace

void EdgePressureForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "an edge topology is required")) return;
  // SOFA looks the "complete" topology up from the node (first found), whichever `topology` is.
  complete_ = node()->find_up<MeshTopologyBase>();
  if ((!complete_ || complete_->triangles().empty()) && edge_indices.get().empty() && edges.get().empty())
    msg_error("either a pressure vector or a topology with triangles is required");
  select();
  if (!check_selection()) {
    set_state(ComponentState::invalid);
    return;
  }
  follower_.attach(topology.get());
  compute_forces(false);
}

void EdgePressureForceField::select() {
  const auto& topo_edges = topology->edges();
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  const std::size_t np = x0.size() / 3;
  map_.clear();
  if (dmin.get() != dmax.get()) {
    const Vec3 n = normal.get();
    auto inside = [&](unsigned v) {
      if (v >= np) return false;
      const double d = point_of(x0, v).dot(n);
      return d > dmin.get() && d < dmax.get();
    };
    for (unsigned e = 0; e < topo_edges.size(); ++e)
      if (inside(topo_edges[e][0]) && inside(topo_edges[e][1])) map_.push_back(e);
  }
  if (!edge_indices.get().empty()) map_ = edge_indices.get();
  if (!edges.get().empty()) {
    // Each listed pair is looked up as an ordered pair; SOFA keeps the last match, index 0 when absent.
    const auto& want = edges.get();
    map_.assign(want.size(), 0);
    for (std::size_t i = 0; i < want.size(); ++i)
      for (unsigned j = 0; j < topo_edges.size(); ++j)
        if (want[i][0] == topo_edges[j][0] && want[i][1] == topo_edges[j][1]) map_[i] = j;
  }
  length_.assign(map_.size(), 0.0);
  force_.assign(map_.size(), Vec3::Zero());
}

bool EdgePressureForceField::check_selection() {
  const auto& topo_edges = topology->edges();
  const std::size_t np = mstate->size();
  for (std::size_t i = 0; i < map_.size(); ++i) {
    if (map_[i] >= topo_edges.size()) {
      msg_error("edge index " + std::to_string(map_[i]) + " (entry " + std::to_string(i) +
                ") is out of range (the topology has " + std::to_string(topo_edges.size()) + " edges)");
      return false;
    }
    const Edge& e = topo_edges[map_[i]];
    if (e[0] >= np || e[1] >= np) {
      msg_error("edge " + std::to_string(map_[i]) + " refers to a point out of the state (" + std::to_string(np) +
                " points)");
      return false;
    }
  }
  return true;
}

void EdgePressureForceField::Follower::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  if (c.type != TopologyChangeType::edges_removed) return;
  auto& ff = ff_;
  follow_subset_removal(ff.map_, c.indices, t.edges().size(), [&ff](std::size_t pos) {
    ff.length_.erase(ff.length_.begin() + static_cast<std::ptrdiff_t>(pos));
    ff.force_.erase(ff.force_.begin() + static_cast<std::ptrdiff_t>(pos));
  });
}

void EdgePressureForceField::compute_forces(bool with_update) {
  const std::vector<double>& x = mstate->read(kPosition);
  if (x.empty()) return;
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  const auto& topo_edges = topology->edges();
  const std::size_t np = std::min(x.size(), x0.size()) / 3;
  auto rest_length = [&](std::size_t k) {
    if (k >= topo_edges.size() || topo_edges[k][0] >= np || topo_edges[k][1] >= np) return 0.0;
    return (point_of(x0, topo_edges[k][1]) - point_of(x0, topo_edges[k][0])).norm();
  };
  auto edge_ok = [&](std::size_t i) {
    return map_[i] < topo_edges.size() && topo_edges[map_[i]][0] < np && topo_edges[map_[i]][1] < np;
  };

  const Vec3 P = pressure.get();
  if (P.norm() > 0) {
    for (std::size_t i = 0; i < map_.size(); ++i) {
      length_[i] = rest_length(map_[i]);
      force_[i] = P * length_[i];
    }
    return;
  }
  const std::vector<double>& intensities = p_intensity.get();
  if (intensities.empty()) return;
  auto intensity_of = [&](std::size_t i) {
    return intensities.size() > 1 && intensities.size() > i ? intensities[i] : intensities[0];
  };
  if (binormal.is_set()) {
    Vec3 b = binormal.get();
    normalize_sofa(b);
    for (std::size_t i = 0; i < map_.size(); ++i) {
      if (!edge_ok(i)) continue;
      const Edge& e = topo_edges[map_[i]];
      Vec3 tang = point_of(x, e[1]) - point_of(x, e[0]);
      normalize_sofa(tang);
      Vec3 n = b.cross(tang);
      normalize_sofa(n);
      length_[i] = rest_length(i);  // SOFA: the i-th edge of the topology
      force_[i] = n * intensity_of(i) * length_[i];
    }
    return;
  }
  // No binormal: only the edges with one triangle around them get a new force; the others keep
  // what SOFA's updateEdgeInformation leaves (its xy-swapped tangent times the stored length).
  for (std::size_t i = 0; i < map_.size(); ++i) {
    if (!edge_ok(i)) continue;
    if (with_update) {
      const Edge& e = topo_edges[map_[i]];
      const Vec3 p1 = point_of(x, e[0]);
      const Vec3 tang = point_of(x, e[1]) - p1;
      const Vec3 swapped(p1[0] * tang[1] > 0 ? tang[1] : -tang[1], p1[1] * tang[0] > 0 ? tang[0] : -tang[0], 0.0);
      force_[i] = swapped * length_[i];
    }
    triangle_normal_force(i, x, intensity_of(i));
  }
}

void EdgePressureForceField::triangle_normal_force(std::size_t i, const std::vector<double>& x, double intensity) {
  if (!complete_) return;
  const Edge& e = topology->edges()[map_[i]];
  const std::size_t np = x.size() / 3;
  // SOFA finds the complete topology's edge by its vertex positions (first match, same orientation).
  const auto& all = complete_->edges();
  std::size_t k = 0;
  const Vec3 a = point_of(x, e[0]), b = point_of(x, e[1]);
  for (; k < all.size(); ++k)
    if (all[k][0] < np && all[k][1] < np && (point_of(x, all[k][0]) - a).norm() < 1e-6 &&
        (point_of(x, all[k][1]) - b).norm() < 1e-6)
      break;
  const auto& around = complete_->triangles_around_edge();
  if (k >= around.size() || around[k].size() != 1) return;
  const Triangle& t = complete_->triangles()[around[k][0]];
  unsigned third;
  if (t[0] == e[0] || t[0] == e[1]) third = (t[1] == e[0] || t[1] == e[1]) ? t[2] : t[1];
  else third = t[0];
  if (third >= np) return;
  Vec3 tang = b - a;
  normalize_sofa(tang);
  Vec3 n = Vec3(0, 0, 1).cross(tang);
  if (n.dot(point_of(x, third) - a) < 0) n = -n;
  const auto& topo_edges = topology->edges();
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  length_[i] = 0.0;
  if (i < topo_edges.size() && 3 * std::max(topo_edges[i][0], topo_edges[i][1]) + 2 < x0.size())
    length_[i] = (point_of(x0, topo_edges[i][1]) - point_of(x0, topo_edges[i][0])).norm();  // SOFA: edge i
  force_[i] = n * length_[i] * intensity;
}

void EdgePressureForceField::add_force(const MechParams& p) {
  std::vector<double>& f = mstate->write(p.f);
  const auto& topo_edges = topology->edges();
  const std::size_t np = f.size() / 3;
  for (std::size_t i = 0; i < map_.size(); ++i) {
    if (map_[i] >= topo_edges.size()) continue;
    const Edge& e = topo_edges[map_[i]];
    if (e[0] >= np || e[1] >= np) continue;
    const Vec3 h = force_[i] / 2;
    for (unsigned v : e)
      for (int c = 0; c < 3; ++c) f[3 * v + c] += h[c];
  }
  // SOFA updates the forces after applying them: the next call uses these positions.
  compute_forces(true);
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
