#include "forcefield/spring/triangular_bending_springs.h"

#include <cmath>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"
#include "forcefield/spring/spring_stiffness.h"
#include "forcefield/spring/triangle_adjacency.h"

namespace sinew {

void TriangularBendingSprings::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  // SOFA keeps its defaults when a negative value is given (with a warning).
  ks_ = stiffness.get();
  kd_ = damping.get();
  if (ks_ < 0) {
    msg_warning("stiffness " + parse::format_double(ks_) + " is negative: using 100000");
    ks_ = 100000.0;
  }
  if (kd_ < 0) {
    msg_warning("damping " + parse::format_double(kd_) + " is negative: using 1");
    kd_ = 1.0;
  }
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (topology->triangles().empty()) {
    msg_error("the topology " + topology->describe() + " has no triangles (a triangular set topology is required)");
    set_state(ComponentState::invalid);
    return;
  }
  if (!rebuild()) set_state(ComponentState::invalid);
}

void TriangularBendingSprings::reinit() {
  if (state() == ComponentState::valid && !rebuild()) set_state(ComponentState::invalid);
}

bool TriangularBendingSprings::rebuild() {
  const auto& tris = topology->triangles();
  TriangleAdjacency adj;
  adj.build(tris, topology->edges());
  triangles_version_ = topology->elements_version(MeshTopologyBase::Elements::triangles);
  edges_version_ = topology->elements_version(MeshTopologyBase::Elements::edges);
  const std::size_t np = mstate->size();
  if (!element_points_in_state(*this, tris, "triangle", np)) return false;
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  // SOFA's triangle-creation pass: the first triangle (in order) holding an
  // edge initialises its spring: m1 opposite in the other triangle, m2 in this one.
  std::vector<springs::LinearSpring> per_edge(adj.edges.size());
  std::vector<char> init(adj.edges.size(), 0), active(adj.edges.size(), 0);
  for (unsigned t2 = 0; t2 < tris.size(); ++t2)
    for (int j = 0; j < 3; ++j) {
      const int e = adj.edges_in_triangle[t2][j];
      if (e < 0 || init[e]) continue;
      init[e] = 1;
      const auto& shell = adj.triangles_around_edge[e];
      if (shell.size() != 2) continue;
      const unsigned t1 = shell[0] == t2 ? shell[1] : shell[0];
      springs::LinearSpring s;
      s.m1 = tris[t1][adj.edge_index_in_triangle(t1, e)];
      s.m2 = tris[t2][j];
      s.ks = ks_;
      s.kd = kd_;
      const double u0 = x0[3 * s.m1] - x0[3 * s.m2], u1 = x0[3 * s.m1 + 1] - x0[3 * s.m2 + 1],
                   u2 = x0[3 * s.m1 + 2] - x0[3 * s.m2 + 2];
      s.l0 = std::sqrt(u0 * u0 + u1 * u1 + u2 * u2);
      per_edge[e] = s;
      active[e] = 1;
    }
  springs_.clear();
  for (std::size_t e = 0; e < per_edge.size(); ++e)
    if (active[e]) springs_.push_back(per_edge[e]);
  dfdx_.assign(springs_.size(), springs::Block{});
  return true;
}

void TriangularBendingSprings::add_force(const MechParams& p) {
  // Topology changes: rebuild the springs from the new lists (no per-event handling).
  if ((topology->elements_version(MeshTopologyBase::Elements::triangles) != triangles_version_ || topology->elements_version(MeshTopologyBase::Elements::edges) != edges_version_) && !rebuild()) {
    set_state(ComponentState::invalid);
    springs_.clear();
    dfdx_.clear();
  }
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  const double* v = s.read(p.v).data();
  double* f = s.write(p.f).data();
  energy_ = 0;
  for (std::size_t i = 0; i < springs_.size(); ++i)
    springs::add_spring_force<3>(springs_[i], x, v, f, x, v, f, dfdx_[i], energy_, 1.0e-4);
}

void TriangularBendingSprings::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  for (std::size_t i = 0; i < springs_.size(); ++i)
    springs::add_spring_dforce<3>(springs_[i], dfdx_[i], dx, df, dx, df, kfactor);
}

bool TriangularBendingSprings::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  for (std::size_t e = 0; e < springs_.size(); ++e)
    add_spring_stiffness(K, s, springs_[e].m1, springs_[e].m2, dfdx_[e].data());
  return true;
}

void register_triangular_bending_springs(Registry& r) {
  ComponentInfo info;
  info.name = "TriangularBendingSprings";
  info.category = "ForceField/Spring";
  info.description = "springs between the opposite vertices of triangles sharing an edge";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<TriangularBendingSprings>();
  r.add(std::move(info));
}

}  // namespace sinew
