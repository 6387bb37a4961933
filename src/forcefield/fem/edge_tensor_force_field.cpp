#include "forcefield/fem/edge_tensor_force_field.h"

#include <algorithm>
#include <string>

#include "core/init_checks.h"
#include "core/node.h"
#include "forcefield/fem/sofa_mat3.h"

namespace sinew {

namespace {
// SOFA's Mat3 (three rows): M·v row by row, Mᵀ·v column by column, each sum in index order.
double tensor_row_dot(const Mat3& m, int u, const Vec3& v) {
  double r = m(u, 0) * v[0];
  r += m(u, 1) * v[1];
  r += m(u, 2) * v[2];
  return r;
}
double tensor_col_dot(const Mat3& m, int u, const Vec3& v) { return v[0] * m(0, u) + v[1] * m(1, u) + v[2] * m(2, u); }
}  // namespace

void EdgeTensorForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, kind_.requirement)) return;
  if (element_count(*topology) == 0)
    msg_warning("no " + std::string(kind_.plural) + " found in the topology " + topology->describe());
  if (!lame(young_modulus.get(), poisson_ratio.get(), lambda_, mu_)) {
    set_state(ComponentState::invalid);
    return;
  }
  if (!elements_ready(*topology)) {
    set_state(ComponentState::invalid);
    return;
  }
  const std::vector<double>& r = mstate->read(kRestPosition);
  initial_points_.resize(r.size() / 3);
  for (std::size_t i = 0; i < initial_points_.size(); ++i)
    initial_points_[i] = fem::at3(r.data(), static_cast<unsigned>(i));
  rebuild();
  if (state() != ComponentState::valid) return;
  follow_.owner = this;
  follow_.attach(topology.get());
}

// SOFA's init: every edge tensor set to 0, then every element's terms added.
void EdgeTensorForceField::rebuild() {
  const MeshTopologyBase& t = *topology;
  edge_tensor_.assign(t.edges().size(), Mat3::Zero());
  bool ok = true;
  const auto n = static_cast<unsigned>(element_count(t));
  for (unsigned i = 0; i < n; ++i) ok = element_terms(i, t, 1.0) && ok;
  if (!ok) set_state(ComponentState::invalid);
}

// SOFA's edge data with its element-added / element-removed callbacks: removals before the
// lists change, additions after.
void EdgeTensorForceField::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  auto& o = *owner;
  if (c.type == o.kind_.removed) {
    for (unsigned r : c.indices)
      if (r < o.element_count(t)) o.element_terms(r, t, -1.0);
    return;
  }
  if (c.type == o.kind_.added) {
    for (unsigned i : c.indices)
      if (i < o.element_count(t)) o.element_terms(i, t, 1.0);
    return;
  }
  switch (c.type) {
    case TopologyChangeType::edges_removed:
      remove_swap_last(o.edge_tensor_, c.indices);
      break;
    case TopologyChangeType::edges_added:
      for (unsigned e : c.indices) {
        if (e >= t.edges().size()) continue;
        if (e >= o.edge_tensor_.size()) o.edge_tensor_.resize(e + 1, Mat3::Zero());
        o.edge_tensor_[e] = Mat3::Zero();
      }
      break;
    case TopologyChangeType::points_removed:
      // Kept from SOFA: its initial positions are a plain array taken at init.
      if (!o.warned_points_) {
        o.msg_warning("points were removed: the initial positions do not follow (as in SOFA), so a point moved "
                      "into a removed slot is pulled towards that slot's initial position");
        o.warned_points_ = true;
      }
      break;
    case TopologyChangeType::points_added: {
      const double* x0 = o.mstate->read(kRestPosition).data();
      const std::size_t n = o.mstate->size();
      for (unsigned i : c.indices)
        if (i >= o.initial_points_.size() && i < n) {
          o.initial_points_.resize(i + 1, Vec3::Zero());
          o.initial_points_[i] = fem::at3(x0, i);
        }
      break;
    }
    default:
      break;
  }
}

void EdgeTensorForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  const auto& edges = topology->edges();
  if (edge_tensor_.size() != edges.size()) {
    // Lists changed without events (a topology that does not propagate them): start again.
    msg_warning("the topology's lists changed without topological events; the edge tensors are rebuilt from the "
                "rest positions");
    rebuild();
    if (state() != ComponentState::valid) return;
  }
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  double* f = s.write(p.f).data();
  const std::size_t np = initial_points_.size();
  double energy = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Mat3& m = edge_tensor_[i];
    const unsigned v0 = edges[i][0], v1 = edges[i][1];
    if (v0 >= np || v1 >= np) continue;
    const Vec3 dp0 = fem::at3(x, v0) - initial_points_[v0];
    const Vec3 dp1 = fem::at3(x, v1) - initial_points_[v1];
    const Vec3 dp = dp1 - dp0;
    for (int u = 0; u < 3; ++u) {
      const double a = tensor_row_dot(m, u, dp), b = tensor_col_dot(m, u, dp);
      f[3 * v1 + u] += a;
      f[3 * v0 + u] -= b;
      energy -= 0.5 * (dp1[u] * a - dp0[u] * b);
    }
  }
  energy_ = energy;
}

void EdgeTensorForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  const auto& edges = topology->edges();
  const std::size_t ne = std::min(edges.size(), edge_tensor_.size());
  for (std::size_t i = 0; i < ne; ++i) {
    const Mat3& m = edge_tensor_[i];
    const unsigned v0 = edges[i][0], v1 = edges[i][1];
    const Vec3 dp = fem::at3(dx, v1) - fem::at3(dx, v0);
    for (int u = 0; u < 3; ++u) {
      df[3 * v1 + u] += tensor_row_dot(m, u, dp) * kfactor;
      df[3 * v0 + u] -= tensor_col_dot(m, u, dp) * kfactor;
    }
  }
}

// K as add_dforce applies it (SOFA's buildStiffnessMatrix): per edge (v0, v1), +D on (v1, v1),
// −D on (v1, v0), −Dᵀ on (v0, v1), +Dᵀ on (v0, v0).
bool EdgeTensorForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  const MechanicalState* s = mstate.get();
  const auto& edges = topology->edges();
  const std::size_t ne = std::min(edges.size(), edge_tensor_.size());
  for (std::size_t i = 0; i < ne; ++i) {
    const std::size_t v0 = edges[i][0], v1 = edges[i][1];
    const Mat3& m = edge_tensor_[i];
    const Mat3 mt = m.transpose();
    K.add_block(s, 3 * v1, s, 3 * v1, m);
    K.add_block(s, 3 * v1, s, 3 * v0, -m);
    K.add_block(s, 3 * v0, s, 3 * v1, -mt);
    K.add_block(s, 3 * v0, s, 3 * v0, mt);
  }
  return true;
}

}  // namespace sinew
