#include "forcefield/spring/triangular_quadratic_springs_force_field.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "forcefield/triangle_edge_setup.h"
#include "forcefield/spring/triangle_edge_springs.h"

namespace sinew {

namespace {
// SOFA's Vec arithmetic, written out so that sums keep its left-to-right order.
double dot(const Vec3& a, const Vec3& b) {
  double r = a[0] * b[0];
  r += a[1] * b[1];
  r += a[2] * b[2];
  return r;
}
Vec3 point(const double* x, unsigned i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }
}  // namespace

void TriangularQuadraticSpringsForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (topology->triangles().empty()) {
    // SOFA: an error, the component then does nothing.
    msg_error("the topology " + topology->describe() + " has no triangles (a triangular set topology is required)");
    set_state(ComponentState::invalid);
    return;
  }
  if (!triangle_edge_lame(*this, young_modulus.get(), poisson_ratio.get(), lambda_, mu_)) return;
  if (!triangle_edges_ready(*this, *topology)) return;
  default_initial_points(*mstate, initial_points);
  if (!rebuild()) {
    set_state(ComponentState::invalid);
    return;
  }
  follow_.owner = this;
  follow_.attach(topology.get());
}

bool TriangularQuadraticSpringsForceField::rebuild() {
  const MeshTopologyBase& t = *topology;
  update_matrix_ = true;
  return build_triangle_springs(
      t, edge_info_, tri_info_, [&](unsigned e) { create_edge(e, t); },
      [&](unsigned i) { return create_triangle(i, t); });
}

void TriangularQuadraticSpringsForceField::create_edge(unsigned e, const MeshTopologyBase& t) {
  const double* x0 = mstate->read(kRestPosition).data();
  const Edge& ed = t.edges()[e];
  const Vec3 d = point(x0, ed[1]) - point(x0, ed[0]);
  EdgeInfo& ei = edge_info_[e];
  ei.rest_length = std::sqrt(dot(d, d));
  ei.stiffness = 0;
}

// False (with an error naming the triangle) for a triangle of zero rest area: its constants stay 0.
bool TriangularQuadraticSpringsForceField::create_triangle(unsigned i, const MeshTopologyBase& t) {
  const auto& te = t.edges_in_triangle()[i];
  TriangleInfo& ti = tri_info_[i];
  double l[3], rs[3], cot[3];
  for (int j = 0; j < 3; ++j) {
    l[j] = edge_info_[te[j]].rest_length;
    rs[j] = l[j] * l[j];
  }
  double area = 0;
  if (!triangle_rest_cotangents(*this, i, t.triangles()[i], rs, area, cot)) {
    ti = TriangleInfo{};
    return false;
  }
  for (int j = 0; j < 3; ++j) {
    const int k = (j + 1) % 3, m = (j + 2) % 3;
    ti.gamma[j] = l[k] * l[m] * (2 * cot[k] * cot[m] * (lambda_ + mu_) - mu_) / (8 * area);
    ti.stiffness[j] = l[j] * l[j] * (2 * cot[j] * cot[j] * (lambda_ + mu_) + mu_) / (8 * area);
    edge_info_[te[j]].stiffness += ti.stiffness[j];
  }
  return true;
}

// SOFA's edge and triangle data: removals before the lists change, additions after.
void TriangularQuadraticSpringsForceField::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  auto& o = *owner;
  follow_triangle_springs(
      t, c, o.edge_info_, o.tri_info_, [&](unsigned e) { o.create_edge(e, t); },
      [&](unsigned i) { o.create_triangle(i, t); });
}

bool TriangularQuadraticSpringsForceField::lists_match() const {
  return tri_info_.size() == topology->triangles().size() && edge_info_.size() == topology->edges().size();
}

void TriangularQuadraticSpringsForceField::add_force(const MechParams& p) {
  if (state() != ComponentState::valid) return;
  if (!lists_match()) {
    // Lists changed without events (a topology that does not propagate them): start again.
    msg_warning("the topology's lists changed without topological events; the springs are rebuilt from the rest "
                "positions");
    rebuild();
  }
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  const double* v = s.read(p.v).data();
  double* f = s.write(p.f).data();
  const auto& edges = topology->edges();
  const auto& tris = topology->triangles();
  const auto& eit = topology->edges_in_triangle();
  const double damping = damping_ratio.value();
  double energy = 0;

  for (std::size_t i = 0; i < edges.size(); ++i) {
    EdgeInfo& ei = edge_info_[i];
    const unsigned v0 = edges[i][0], v1 = edges[i][1];
    const Vec3 dp = point(x, v0) - point(x, v1);
    const Vec3 dv = point(v, v0) - point(v, v1);
    const double L = ei.current_length = std::sqrt(dot(dp, dp));
    const double geometric = ei.current_length - ei.rest_length;
    ei.dl = geometric + damping * dot(dv, dp) / L;
    energy += 0.5 * ei.stiffness * geometric * geometric;
    const double val = ei.stiffness * ei.dl / L;
    for (int c = 0; c < 3; ++c) {
      const double fc = dp[c] * val;
      f[3 * v1 + c] += fc;
      f[3 * v0 + c] -= fc;
    }
  }
  if (use_angular_springs.value()) {
    for (std::size_t i = 0; i < tris.size(); ++i) {
      const TriangleInfo& ti = tri_info_[i];
      const auto& tea = eit[i];
      const Triangle& ta = tris[i];
      for (int j = 0; j < 3; ++j) {
        const int k = (j + 1) % 3, l = (j + 2) % 3;
        const EdgeInfo &ek = edge_info_[tea[k]], &el = edge_info_[tea[l]];
        const double coef = (ek.dl * ti.gamma[l] + el.dl * ti.gamma[k]) / edge_info_[tea[j]].current_length;
        energy += ti.gamma[j] * (ek.current_length - ek.rest_length) * (el.current_length - el.rest_length);
        for (int c = 0; c < 3; ++c) {
          const double fc = (x[3 * ta[k] + c] - x[3 * ta[l] + c]) * coef;
          f[3 * ta[l] + c] += fc;
          f[3 * ta[k] + c] -= fc;
        }
      }
    }
  }
  energy_ = energy;
  update_matrix_ = true;
}

// The per-triangle blocks DfDx[k], for the edge opposite vertex k, from the last add_force's edge
// lengths and the current positions (SOFA reads the state's position here).
void TriangularQuadraticSpringsForceField::update_matrix() {
  update_matrix_ = false;
  const double* x = mstate->read(kPosition).data();
  const auto& tris = topology->triangles();
  const auto& eit = topology->edges_in_triangle();
  const bool angular = use_angular_springs.value();
  const std::size_t nt = std::min(tris.size(), tri_info_.size());
  for (std::size_t t = 0; t < nt; ++t) {
    TriangleInfo& ti = tri_info_[t];
    const auto& tea = eit[t];
    const Triangle& ta = tris[t];
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      Mat3& m = ti.dfdx[k];
      const Vec3 dpk = point(x, ta[i]) - point(x, ta[j]);
      const EdgeInfo &ek = edge_info_[tea[k]], &ei = edge_info_[tea[i]], &ej = edge_info_[tea[j]];
      if (!angular) {
        double val1 = -ti.stiffness[k] * ek.dl;
        val1 /= ek.current_length;
        double val2 = -ti.stiffness[k] * ek.rest_length;
        val2 /= ek.current_length * ek.current_length * ek.current_length;
        for (int u = 0; u < 3; ++u) {
          for (int w = 0; w < 3; ++w) m(u, w) = dpk[u] * dpk[w] * val2;
          m(u, u) += val1;
        }
      } else {
        const Vec3 dpj = point(x, ta[i]) - point(x, ta[k]);
        const Vec3 dpi = point(x, ta[j]) - point(x, ta[k]);
        double val1 = -(ti.stiffness[k] * ek.dl + ti.gamma[i] * ej.dl + ti.gamma[j] * ei.dl);
        // SOFA's edge-direction coefficient: the rest length where the derivative has the current one.
        double val2 = -val1 - ti.stiffness[k] * ek.rest_length;
        val1 /= ek.current_length;
        val2 /= ek.current_length * ek.current_length * ek.current_length;
        const double valk = ti.gamma[k] / (ej.current_length * ei.current_length);
        const double vali = ti.gamma[i] / (ej.current_length * ek.current_length);
        const double valj = ti.gamma[j] / (ek.current_length * ei.current_length);
        for (int u = 0; u < 3; ++u) {
          for (int w = 0; w < 3; ++w)
            m(u, w) = dpk[u] * dpk[w] * val2 + dpj[u] * dpi[w] * valk - dpj[u] * dpk[w] * vali +
                      dpk[u] * dpi[w] * valj;
          m(u, u) += val1;
        }
      }
    }
  }
}

void TriangularQuadraticSpringsForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  if (update_matrix_) update_matrix();
  MechanicalState& s = *mstate;
  add_triangle_edge_dforce(topology->triangles(), tri_info_, s.read(p.dx).data(), s.write(p.df).data(), kfactor);
}

bool TriangularQuadraticSpringsForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  if (update_matrix_) update_matrix();
  add_triangle_edge_stiffness(topology->triangles(), tri_info_, mstate.get(), K);
  return true;
}

void register_triangular_quadratic_springs_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TriangularQuadraticSpringsForceField";
  info.category = "ForceField/Spring";
  info.description = "quadratic springs on the edges of a triangle mesh, with angular springs";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangularQuadraticSpringsForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
