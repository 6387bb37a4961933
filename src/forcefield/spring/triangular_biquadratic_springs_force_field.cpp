#include "forcefield/spring/triangular_biquadratic_springs_force_field.h"

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
Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
Vec3 point(const double* x, unsigned i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }
}  // namespace

void TriangularBiquadraticSpringsForceField::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (topology->triangles().empty()) msg_warning("no triangles found in the topology " + topology->describe());
  if (compressible.get() && !use_angular_springs.get())
    msg_warning("compressible is only computed with useAngularSprings; without it the compression term is left "
                "out (SOFA's stiffness then reads areas it never computed)");
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

bool TriangularBiquadraticSpringsForceField::rebuild() {
  const MeshTopologyBase& t = *topology;
  update_matrix_ = true;
  return build_triangle_springs(
      t, edge_info_, tri_info_, [&](unsigned e) { create_edge(e, t); },
      [&](unsigned i) { return create_triangle(i, t); });
}

void TriangularBiquadraticSpringsForceField::create_edge(unsigned e, const MeshTopologyBase& t) {
  const double* x0 = mstate->read(kRestPosition).data();
  const Edge& ed = t.edges()[e];
  const Vec3 d = point(x0, ed[1]) - point(x0, ed[0]);
  EdgeInfo& ei = edge_info_[e];
  ei.rest_square_length = dot(d, d);
  ei.stiffness = 0;
}

bool TriangularBiquadraticSpringsForceField::create_triangle(unsigned i, const MeshTopologyBase& t) {
  const double* x0 = mstate->read(kRestPosition).data();
  const Triangle& tri = t.triangles()[i];
  const auto& te = t.edges_in_triangle()[i];
  TriangleInfo& ti = tri_info_[i];
  double rs[3], cot[3];
  for (int j = 0; j < 3; ++j) rs[j] = edge_info_[te[j]].rest_square_length;
  double area = 0;
  if (!triangle_rest_cotangents(*this, i, tri, rs, area, cot)) {
    ti = TriangleInfo{};
    return false;
  }
  ti.rest_area = area;
  const Vec3 a = point(x0, tri[0]);
  ti.current_normal = cross(point(x0, tri[1]) - a, point(x0, tri[2]) - a) / (2 * area);
  ti.last_valid_normal = ti.current_normal;
  for (int j = 0; j < 3; ++j) {
    const int k = (j + 1) % 3, l = (j + 2) % 3;
    ti.gamma[j] = (2 * cot[k] * cot[l] * (lambda_ + mu_) - mu_) / (16 * area);
    ti.stiffness[j] = (2 * cot[j] * cot[j] * (lambda_ + mu_) + mu_) / (16 * area);
    edge_info_[te[j]].stiffness += ti.stiffness[j];
  }
  return true;
}

// SOFA's edge and triangle data: removals before the lists change, additions after.
void TriangularBiquadraticSpringsForceField::Follow::apply(const MeshTopologyBase& t, const TopologyChange& c) {
  auto& o = *owner;
  follow_triangle_springs(
      t, c, o.edge_info_, o.tri_info_, [&](unsigned e) { o.create_edge(e, t); },
      [&](unsigned i) { o.create_triangle(i, t); });
}

bool TriangularBiquadraticSpringsForceField::lists_match() const {
  return tri_info_.size() == topology->triangles().size() && edge_info_.size() == topology->edges().size();
}

void TriangularBiquadraticSpringsForceField::add_force(const MechParams& p) {
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
  const bool angular = use_angular_springs.value(), comp = compressible.value();
  const double area_stiffness = (lambda_ + mu_) * 3;
  double energy = 0;

  for (std::size_t i = 0; i < edges.size(); ++i) {
    EdgeInfo& ei = edge_info_[i];
    const unsigned v0 = edges[i][0], v1 = edges[i][1];
    const Vec3 dp = point(x, v0) - point(x, v1);
    const Vec3 dv = point(v, v0) - point(v, v1);
    const double L = ei.current_square_length = dot(dp, dp);
    const double geometric = ei.current_square_length - ei.rest_square_length;
    ei.delta_l2 = geometric + damping * dot(dv, dp) / L;
    energy += 0.25 * ei.stiffness * geometric * geometric;
    const double val = ei.stiffness * ei.delta_l2;
    for (int c = 0; c < 3; ++c) {
      const double fc = dp[c] * val;
      f[3 * v1 + c] += fc;
      f[3 * v0 + c] -= fc;
    }
  }
  if (angular) {
    flipped_.clear();
    for (std::size_t i = 0; i < tris.size(); ++i) {
      TriangleInfo& ti = tri_info_[i];
      const auto& tea = eit[i];
      const Triangle& ta = tris[i];
      for (int j = 0; j < 3; ++j) {
        const int k = (j + 1) % 3, l = (j + 2) % 3;
        ti.dp[j] = point(x, ta[l]) - point(x, ta[k]);
        const double coef = edge_info_[tea[k]].delta_l2 * ti.gamma[l] + edge_info_[tea[l]].delta_l2 * ti.gamma[k];
        const double gk = edge_info_[tea[k]].current_square_length - edge_info_[tea[k]].rest_square_length;
        const double gl = edge_info_[tea[l]].current_square_length - edge_info_[tea[l]].rest_square_length;
        energy += 0.5 * ti.gamma[j] * gk * gl;
        for (int c = 0; c < 3; ++c) {
          const double fc = -ti.dp[j][c] * coef;
          f[3 * ta[l] + c] += fc;
          f[3 * ta[k] + c] -= fc;
        }
      }
      ti.compressed = false;
      if (!comp) continue;
      ti.current_normal = -cross(ti.dp[2], ti.dp[1]);
      ti.area = std::sqrt(dot(ti.current_normal, ti.current_normal)) / 2;
      ti.J = ti.area / ti.rest_area;
      if (!(ti.J < 1)) continue;  // only a compressed triangle resists
      ti.compressed = true;
      const double JJ = ti.J - 1;
      if (ti.J < 1e-2) {
        // Too flat for its normal to mean anything: keep the last reasonable one.
        ti.current_normal = ti.last_valid_normal;
      } else {
        ti.current_normal /= (2 * ti.area);
        if (dot(ti.current_normal, ti.last_valid_normal) > -0.5) {
          ti.last_valid_normal = ti.current_normal;
        } else {  // the normal flipped suddenly: keep the old side
          flipped_.push_back(static_cast<unsigned>(i));
          ti.current_normal *= -1.0;
        }
      }
      const double val = area_stiffness * JJ * JJ * JJ;
      energy += area_stiffness * ti.rest_area * JJ * JJ * JJ * JJ / 4;
      for (int j = 0; j < 3; ++j) {
        ti.area_vector[j] = cross(ti.current_normal, ti.dp[j]) / 2;
        for (int c = 0; c < 3; ++c) f[3 * ta[j] + c] -= ti.area_vector[j][c] * val;
      }
    }
    if (!flipped_.empty()) {
      std::string list;
      for (std::size_t k = 0; k < std::min<std::size_t>(50, flipped_.size()); ++k)
        list += (k ? ", " : "") + std::to_string(flipped_[k]);
      if (flipped_.size() >= 50) list += ", ... " + std::to_string(flipped_.size() - 50) + " more";
      msg_warning("these triangles have flipped: [" + list + "]");
    }
  }
  energy_ = energy;
  update_matrix_ = true;
}

// The per-triangle blocks DfDx[k], for the edge opposite vertex k, from the last add_force.
void TriangularBiquadraticSpringsForceField::update_matrix() {
  update_matrix_ = false;
  const auto& eit = topology->edges_in_triangle();
  const bool angular = use_angular_springs.value(), comp = compressible.value();
  const double area_stiffness = (lambda_ + mu_) * 3;
  for (std::size_t l = 0; l < tri_info_.size(); ++l) {
    TriangleInfo& ti = tri_info_[l];
    const auto& tea = eit[l];
    for (int k = 0; k < 3; ++k) {
      Mat3& m = ti.dfdx[k];
      const Vec3 dpk = -ti.dp[k];
      if (!angular) {
        const double val1 = -ti.stiffness[k] * edge_info_[tea[k]].delta_l2;
        const double val2 = -2 * ti.stiffness[k];
        for (int u = 0; u < 3; ++u) {
          for (int w = 0; w < 3; ++w) m(u, w) = dpk[u] * dpk[w] * val2;
          m(u, u) += val1;
        }
      } else {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const Vec3 dpj = ti.dp[j];
        const Vec3 dpi = -ti.dp[i];
        const double val1 = -(ti.stiffness[k] * edge_info_[tea[k]].delta_l2 + ti.gamma[i] * edge_info_[tea[j]].delta_l2 +
                              ti.gamma[j] * edge_info_[tea[i]].delta_l2);
        const double val2 = -2 * ti.stiffness[k];
        const double valk = 2 * ti.gamma[k], vali = 2 * ti.gamma[i], valj = 2 * ti.gamma[j];
        for (int u = 0; u < 3; ++u) {
          for (int w = 0; w < 3; ++w)
            m(u, w) = dpk[u] * dpk[w] * val2 + dpj[u] * dpi[w] * valk - dpj[u] * dpk[w] * vali +
                      dpk[u] * dpi[w] * valj;
          m(u, u) += val1;
        }
      }
    }
    // SOFA tests J < 1 whatever the force did; J is only computed with angular springs.
    if (!(comp && angular && ti.compressed)) continue;
    const double JJ = ti.J - 1;
    const double h = -JJ;
    const double val2 = 3 * area_stiffness * JJ * JJ / ti.rest_area;
    double val1 = area_stiffness * JJ * JJ * JJ / 2;
    const Vec3 anti = -ti.current_normal * val1;  // the vector of the antisymmetric part
    val1 /= 2 * ti.area;
    Mat3 m1;
    for (int u = 0; u < 3; ++u)
      for (int w = 0; w < 3; ++w) m1(u, w) = ti.current_normal[u] * ti.current_normal[w] * val1;
    const double ls[3] = {edge_info_[tea[0]].current_square_length, edge_info_[tea[1]].current_square_length,
                          edge_info_[tea[2]].current_square_length};
    const double total = ls[0] + ls[1] + ls[2];
    for (int k = 0; k < 3; ++k) {
      Mat3& m = ti.dfdx[k];
      const double w1 = total - 2 * ls[k];
      m(0, 1) += anti[2];
      m(0, 2) -= anti[1];
      m(1, 0) -= anti[2];
      m(1, 2) += anti[0];
      m(2, 0) += anti[1];
      m(2, 1) -= anti[0];
      const Vec3& dpi = ti.area_vector[(k + 1) % 3];
      const Vec3& dpj = ti.area_vector[(k + 2) % 3];
      const double dpij = dot(dpi, dpj);
      // A blend of the area vectors' product and its trace times the identity: singular at h = 0,
      // proportional to the identity at h = 1.
      for (int u = 0; u < 3; ++u)
        for (int w = 0; w < 3; ++w) {
          m(u, w) += (1 - h) * dpi[u] * dpj[w] * val2;
          m(u, w) += m1(u, w) * w1;
          if (u == w) m(u, w) += h * val2 * dpij;
        }
    }
  }
}

void TriangularBiquadraticSpringsForceField::add_dforce(const MechParams& p, double kfactor) {
  if (state() != ComponentState::valid) return;
  if (update_matrix_) update_matrix();
  MechanicalState& s = *mstate;
  add_triangle_edge_dforce(topology->triangles(), tri_info_, s.read(p.dx).data(), s.write(p.df).data(), kfactor);
}

bool TriangularBiquadraticSpringsForceField::build_stiffness(MatrixSink& K) {
  if (state() != ComponentState::valid) return true;
  if (update_matrix_) update_matrix();
  add_triangle_edge_stiffness(topology->triangles(), tri_info_, mstate.get(), K);
  return true;
}

void register_triangular_biquadratic_springs_force_field(Registry& r) {
  ComponentInfo info;
  info.name = "TriangularBiquadraticSpringsForceField";
  info.category = "ForceField/Spring";
  info.description = "biquadratic springs on the edges of a triangle mesh, with angular and compression terms";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangularBiquadraticSpringsForceField>();
  r.add(std::move(info));
}

}  // namespace sinew
