#include "forcefield/spring/quadular_bending_springs.h"

#include <cmath>
#include <map>
#include <utility>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "forcefield/spring/spring_stiffness.h"

namespace sinew {

void QuadularBendingSprings::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  ks_ = stiffness.get();
  kd_ = damping.get();
  if (!bind_node_topology(*this, topology, "a quad mesh is required")) return;
  if (topology->quads().empty()) msg_warning("no quads found in the topology " + topology->describe());
  if (!rebuild()) set_state(ComponentState::invalid);
}

void QuadularBendingSprings::reinit() {
  if (state() == ComponentState::valid && !rebuild()) set_state(ComponentState::invalid);
}

bool QuadularBendingSprings::rebuild() {
  const auto& quads = topology->quads();
  quads_version_ = topology->elements_version(MeshTopologyBase::Elements::quads);
  const std::size_t np = mstate->size();
  if (!element_points_in_state(*this, quads, "quad", np)) return false;
  // Edges: the topology's list, else derived from the quads (first occurrence).
  std::vector<Edge> edges = topology->edges();
  std::map<std::pair<unsigned, unsigned>, unsigned> index;
  auto key = [](unsigned a, unsigned b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); };
  for (unsigned i = 0; i < edges.size(); ++i) index.emplace(key(edges[i][0], edges[i][1]), i);
  if (edges.empty())
    for (const Quad& q : quads)
      for (int j = 0; j < 4; ++j)
        if (index.emplace(key(q[j], q[(j + 1) % 4]), static_cast<unsigned>(edges.size())).second)
          edges.push_back({q[j], q[(j + 1) % 4]});
  std::vector<std::array<int, 4>> eiq(quads.size(), {-1, -1, -1, -1});
  std::vector<std::vector<unsigned>> around(edges.size());
  for (unsigned i = 0; i < quads.size(); ++i)
    for (int j = 0; j < 4; ++j) {
      auto it = index.find(key(quads[i][j], quads[i][(j + 1) % 4]));
      if (it == index.end()) continue;
      eiq[i][j] = static_cast<int>(it->second);
      around[it->second].push_back(i);
    }
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  std::vector<std::array<Spring, 2>> per_edge(edges.size());
  std::vector<char> init(edges.size(), 0), active(edges.size(), 0);
  for (unsigned q2 = 0; q2 < quads.size(); ++q2)
    for (int j = 0; j < 4; ++j) {
      const int e = eiq[q2][j];
      if (e < 0 || init[e]) continue;
      init[e] = 1;
      const auto& shell = around[e];
      if (shell.size() != 2) continue;
      const unsigned q1 = shell[0] == q2 ? shell[1] : shell[0];
      int i1 = 0;
      for (int k = 0; k < 4; ++k)
        if (eiq[q1][k] == e) i1 = k;
      const int i2 = j;
      const Quad& t1 = quads[q1];
      const Quad& t2 = quads[q2];
      per_edge[e][0].e0 = t1[i1];
      per_edge[e][0].e1 = t2[(i2 + 3) % 4];
      per_edge[e][1].e0 = t1[(i1 + 3) % 4];
      per_edge[e][1].e1 = t2[i2];
      for (Spring& s : per_edge[e]) {
        const double d[3] = {x0[3 * s.e0] - x0[3 * s.e1], x0[3 * s.e0 + 1] - x0[3 * s.e1 + 1],
                             x0[3 * s.e0 + 2] - x0[3 * s.e1 + 2]};
        s.rest_length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      }
      active[e] = 1;
    }
  springs_.clear();
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (active[e]) {
      springs_.push_back(per_edge[e][0]);
      springs_.push_back(per_edge[e][1]);
    }
  return true;
}

void QuadularBendingSprings::add_force(const MechParams& p) {
  if (topology->elements_version(MeshTopologyBase::Elements::quads) != quads_version_ && !rebuild()) {
    set_state(ComponentState::invalid);
    springs_.clear();
  }
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  const double* v = s.read(p.v).data();
  double* f = s.write(p.f).data();
  for (Spring& sp : springs_) {
    sp.dfdx.fill(0.0);
    const unsigned a = sp.e0, b = sp.e1;
    const double diff[3] = {x[3 * b] - x[3 * a], x[3 * b + 1] - x[3 * a + 1], x[3 * b + 2] - x[3 * a + 2]};
    const double dist = std::sqrt(diff[0] * diff[0] + diff[1] * diff[1] + diff[2] * diff[2]);
    if (!(dist > 1.0e-4)) continue;
    const double inv = 1 / dist;
    double u[3];
    for (int c = 0; c < 3; ++c) u[c] = diff[c] * inv;
    const double el = dist - sp.rest_length;
    const double ev = u[0] * (v[3 * b] - v[3 * a]) + u[1] * (v[3 * b + 1] - v[3 * a + 1]) + u[2] * (v[3 * b + 2] - v[3 * a + 2]);
    const double F = ks_ * el + kd_ * ev;
    for (int c = 0; c < 3; ++c) {
      const double fc = u[c] * F;
      f[3 * a + c] += fc;
      f[3 * b + c] -= fc;
    }
    // SOFA: (ks − F/d)·dyad(n, n) + F/d·I with n = diff / d (a division, not ·1/d).
    const double tgt = F * inv;
    double n[3];
    for (int c = 0; c < 3; ++c) n[c] = diff[c] / dist;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) sp.dfdx[i * 3 + j] = (ks_ - tgt) * (n[i] * n[j]);
      sp.dfdx[i * 3 + i] += tgt;
    }
  }
}

void QuadularBendingSprings::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  for (const Spring& sp : springs_) {
    const unsigned a = sp.e0, b = sp.e1;
    double d[3];
    for (int c = 0; c < 3; ++c) d[c] = (dx[3 * b + c] - dx[3 * a + c]) * kfactor;
    for (int i = 0; i < 3; ++i) {
      const double r = sp.dfdx[i * 3] * d[0] + sp.dfdx[i * 3 + 1] * d[1] + sp.dfdx[i * 3 + 2] * d[2];
      df[3 * a + i] += r;
      df[3 * b + i] -= r;
    }
  }
}

bool QuadularBendingSprings::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  for (const Spring& sp : springs_) add_spring_stiffness(K, s, sp.e0, sp.e1, sp.dfdx.data());
  return true;
}

void register_quadular_bending_springs(Registry& r) {
  ComponentInfo info;
  info.name = "QuadularBendingSprings";
  info.category = "ForceField/Spring";
  info.description = "bending springs across the edges shared by two quads";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<QuadularBendingSprings>();
  r.add(std::move(info));
}

}  // namespace sinew
