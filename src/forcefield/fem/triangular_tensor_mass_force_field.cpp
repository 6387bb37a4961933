#include "forcefield/fem/triangular_tensor_mass_force_field.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "forcefield/triangle_edge_setup.h"

namespace sinew {

namespace {
Vec3 point(const double* x, unsigned i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }
double norm2(const Vec3& a) {
  double r = a[0] * a[0];
  r += a[1] * a[1];
  r += a[2] * a[2];
  return r;
}
// SOFA's Mat3 (three rows): M·v row by row, Mᵀ·v column by column, each sum in index order.
double row_dot(const Mat3& m, int u, const Vec3& v) {
  double r = m(u, 0) * v[0];
  r += m(u, 1) * v[1];
  r += m(u, 2) * v[2];
  return r;
}
double col_dot(const Mat3& m, int u, const Vec3& v) { return v[0] * m(0, u) + v[1] * m(1, u) + v[2] * m(2, u); }
}  // namespace

void TriangularTensorMassForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (topology->triangles().empty()) msg_warning("no triangles found in the topology " + topology->describe());
  if (!triangle_edge_lame(*this, young_modulus.get(), poisson_ratio.get(), lambda_, mu_)) return;
  if (!triangle_edges_ready(*this, *topology)) return;
  const std::vector<double>& r = mstate->read(kRestPosition);
  initial_points_.resize(r.size() / 3);
  for (std::size_t i = 0; i < initial_points_.size(); ++i)
    initial_points_[i] = point(r.data(), static_cast<unsigned>(i));
  rebuild();
  if (state() != ComponentState::valid) return;
  follow_.owner = this;
  follow_.attach(topology.get());
}

// SOFA's init: every edge tensor set to 0, then every triangle's terms added.
void TriangularTensorMassForceField::rebuild() {
  const MeshTopologyBase& t = *topology;
  edge_tensor_.assign(t.edges().size(), Mat3::Zero());
  bool ok = true;
  for (unsigned i = 0; i < t.triangles().size(); ++i) ok = triangle_terms(i, t, 1.0) && ok;
  if (!ok) set_state(ComponentState::invalid);
}

bool TriangularTensorMassForceField::triangle_terms(unsigned i, const MeshTopologyBase& t, double sign) {
  const double* x0 = mstate->read(kRestPosition).data();
  const auto& te = t.edges_in_triangle()[i];
  const Triangle& tri = t.triangles()[i];
  Vec3 p[3];
  double rs[3], cot[3];
  for (int j = 0; j < 3; ++j) p[j] = point(x0, tri[j]);
  for (int j = 0; j < 3; ++j) rs[j] = norm2(p[(j + 1) % 3] - p[(j + 2) % 3]);
  double area = 0;
  if (!triangle_rest_cotangents(*this, i, tri, rs, area, cot)) return false;
  const double lambdastar = lambda_ / (4 * area), mustar = mu_ / (8 * area);
  for (int j = 0; j < 3; ++j) {
    const int k = (j + 1) % 3, l = (j + 2) % 3;
    if (te[j] >= edge_tensor_.size()) continue;
    Mat3& m = edge_tensor_[te[j]];
    const Vec3 dpl = p[j] - p[k], dpk = p[j] - p[l];
    const double val1 = -cot[j] * (lambda_ + mu_) / 2;
    // SOFA adds (or subtracts) the term in place: the same roundings on removal as on creation.
    const bool direct = t.edges()[te[j]][0] == tri[l];
    for (int u = 0; u < 3; ++u) {
      for (int v = 0; v < 3; ++v) {
        const double term = lambdastar * dpl[u] * dpk[v] + mustar * dpk[u] * dpl[v];
        double& e = direct ? m(u, v) : m(v, u);
        if (sign > 0) e += term; else e -= term;
      }
      if (sign > 0) m(u, u) += val1; else m(u, u) -= val1;
    }
  }
  return true;
}

// SOFA's edge data with its TRIANGLESADDED / TRIANGLESREMOVED callbacks: removals before the
// lists change, additions after.
void TriangularTensorMassForceField::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  auto& o = *owner;
  switch (c.type) {
    case TopologyChangeType::triangles_removed:
      for (unsigned r : c.indices)
        if (r < t.triangles().size() && r < t.edges_in_triangle().size()) o.triangle_terms(r, t, -1.0);
      break;
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
    case TopologyChangeType::triangles_added:
      for (unsigned i : c.indices)
        if (i < t.triangles().size() && i < t.edges_in_triangle().size()) o.triangle_terms(i, t, 1.0);
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
          o.initial_points_[i] = point(x0, i);
        }
      break;
    }
    default:
      break;
  }
}

void TriangularTensorMassForceField::add_force(const MechParams& p) {
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
    const Vec3 dp0 = point(x, v0) - initial_points_[v0];
    const Vec3 dp1 = point(x, v1) - initial_points_[v1];
    const Vec3 dp = dp1 - dp0;
    for (int u = 0; u < 3; ++u) {
      const double a = row_dot(m, u, dp), b = col_dot(m, u, dp);
      f[3 * v1 + u] += a;
      f[3 * v0 + u] -= b;
      energy -= 0.5 * (dp1[u] * a - dp0[u] * b);
    }
  }
  energy_ = energy;
}

void TriangularTensorMassForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  const auto& edges = topology->edges();
  const std::size_t ne = std::min(edges.size(), edge_tensor_.size());
  for (std::size_t i = 0; i < ne; ++i) {
    const Mat3& m = edge_tensor_[i];
    const unsigned v0 = edges[i][0], v1 = edges[i][1];
    const Vec3 dp = point(dx, v1) - point(dx, v0);
    for (int u = 0; u < 3; ++u) {
      df[3 * v1 + u] += row_dot(m, u, dp) * kfactor;
      df[3 * v0 + u] -= col_dot(m, u, dp) * kfactor;
    }
  }
}

// K as add_dforce applies it: per edge (v0, v1), +D on (v1, v1), −D on (v1, v0), −Dᵀ on (v0, v1),
// +Dᵀ on (v0, v0). SOFA has no assembled form of this force field.
bool TriangularTensorMassForceField::build_stiffness(MatrixSink& K) {
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

void register_triangular_tensor_mass_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TriangularTensorMassForceField";
  info.category = "ForceField/FEM";
  info.description = "linear elastic membrane on a triangular mesh, as one tensor per edge";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangularTensorMassForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
