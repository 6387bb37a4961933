#include "forcefield/spring/fast_triangular_bending_springs.h"

#include <cmath>

#include "core/init_checks.h"
#include "core/node.h"
#include "core/registry.h"

namespace sinew {

namespace {
// SOFA's Vec3 operations, in its evaluation order.
inline Vec3 sub(const double* a, const double* b) { return Vec3(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
}  // namespace

void FastTriangularBendingSprings::init() {
  ForceField::init();
  if (state() != ComponentState::valid) return;
  if (!require_vec3_state(*this)) return;
  if (!bind_node_topology(*this, topology, "a triangular mesh is required")) return;
  if (topology->triangles().empty()) msg_warning("no triangles found in the topology " + topology->describe());
  if (!rebuild()) set_state(ComponentState::invalid);
}

void FastTriangularBendingSprings::reinit() {
  if (state() == ComponentState::valid && !rebuild()) set_state(ComponentState::invalid);
}

bool FastTriangularBendingSprings::rebuild() {
  const auto& tris = topology->triangles();
  TriangleAdjacency adj;
  adj.build(tris, topology->edges());
  triangles_version_ = topology->elements_version(MeshTopologyBase::Elements::triangles);
  edges_version_ = topology->elements_version(MeshTopologyBase::Elements::edges);
  const std::vector<double>& x0 = mstate->read(kRestPosition);
  const std::size_t np = mstate->size();
  if (!element_points_in_state(*this, tris, "triangle", np)) return false;
  springs_.assign(adj.edges.size(), EdgeSpring{});
  double eps2 = min_dist_validity.get();
  eps2 *= eps2;
  const double k = bending_stiffness.get();
  // SOFA's triangle-creation pass: every triangle, in order, (re)sets the
  // spring of each of its edges shared with exactly one other triangle.
  for (unsigned t2 = 0; t2 < tris.size(); ++t2) {
    for (int j = 0; j < 3; ++j) {
      const int e = adj.edges_in_triangle[t2][j];
      if (e < 0) continue;
      EdgeSpring& es = springs_[e];
      const auto& shell = adj.triangles_around_edge[e];
      if (shell.size() != 2) {
        es.active = false;
        continue;
      }
      const unsigned t1 = shell[0] == t2 ? shell[1] : shell[0];
      const int i1 = adj.edge_index_in_triangle(t1, e);
      const int i2 = j;
      const unsigned v1 = tris[t1][i1], v2 = tris[t2][i2];
      const unsigned e1 = adj.edges[e][0], e2 = adj.edges[e][1];
      const Vec3 vp = sub(&x0[3 * v2], &x0[3 * v1]);
      const Vec3 ve = sub(&x0[3 * e2], &x0[3 * e1]);
      if (!(dot(vp, vp) > eps2 && dot(ve, ve) > eps2)) continue;
      es.active = true;
      es.vid = {v1, v2, e1, e2};
      const double* pA = &x0[3 * v1];
      const double* pB = &x0[3 * v2];
      const double* pC = &x0[3 * e1];
      const double* pD = &x0[3 * e2];
      const Vec3 NA = cross(sub(pA, pC), sub(pA, pD));
      const Vec3 NB = cross(sub(pB, pD), sub(pB, pC));
      const Vec3 NC = cross(sub(pC, pB), sub(pC, pA));
      const Vec3 ND = cross(sub(pD, pA), sub(pD, pB));
      es.alpha[0] = norm(NB) / (norm(NA) + norm(NB));
      es.alpha[1] = norm(NA) / (norm(NA) + norm(NB));
      es.alpha[2] = -norm(ND) / (norm(NC) + norm(ND));
      es.alpha[3] = -norm(NC) / (norm(NC) + norm(ND));
      Vec3 dir = sub(pC, pD);
      const double ld = norm(dir);
      if (ld > std::numeric_limits<double>::epsilon())
        for (int c = 0; c < 3; ++c) dir[c] /= ld;
      const Vec3 AC = sub(pC, pA);
      const Vec3 BC = sub(pC, pB);
      const double acd = dot(AC, dir), bcd = dot(BC, dir);
      const double ha = norm(Vec3(AC[0] - dir[0] * acd, AC[1] - dir[1] * acd, AC[2] - dir[2] * acd));
      const double hb = norm(Vec3(BC[0] - dir[0] * bcd, BC[1] - dir[1] * bcd, BC[2] - dir[2] * bcd));
      const double l = norm(sub(pC, pD));
      es.lambda = (2. / 3) * (ha + hb) / (ha * ha * hb * hb) * l * k;
      if (!std::isfinite(es.lambda) || !std::isfinite(es.alpha[0]) || !std::isfinite(es.alpha[2])) {
        msg_error("edge " + std::to_string(e) + ": degenerate triangles around the edge (flat or zero-area rest shape)");
        return false;
      }
    }
  }
  return true;
}

void FastTriangularBendingSprings::check_topology() {
  // Topology changes: rebuild the springs from the new lists (no per-event handling).
  if (topology->elements_version(MeshTopologyBase::Elements::triangles) != triangles_version_ || topology->elements_version(MeshTopologyBase::Elements::edges) != edges_version_) {
    if (!rebuild()) {
      set_state(ComponentState::invalid);
      springs_.clear();
    }
  }
}

void FastTriangularBendingSprings::add_force(const MechParams& p) {
  check_topology();
  MechanicalState& s = *mstate;
  const double* x = s.read(p.x).data();
  double* f = s.write(p.f).data();
  energy_ = 0;
  for (const EdgeSpring& es : springs_) {
    if (!es.active) continue;
    const double* pa = x + 3 * es.vid[0];
    const double* pb = x + 3 * es.vid[1];
    const double* pc = x + 3 * es.vid[2];
    const double* pd = x + 3 * es.vid[3];
    double R[3];
    for (int c = 0; c < 3; ++c)
      R[c] = pa[c] * es.alpha[0] + pb[c] * es.alpha[1] + pc[c] * es.alpha[2] + pd[c] * es.alpha[3];
    for (int k = 0; k < 4; ++k) {
      double* fk = f + 3 * es.vid[k];
      for (int c = 0; c < 3; ++c) fk[c] -= R[c] * es.lambda * es.alpha[k];
    }
    energy_ += (R[0] * R[0] + R[1] * R[1] + R[2] * R[2]) * es.lambda * 0.5;
  }
}

void FastTriangularBendingSprings::add_dforce(const MechParams& p, double kfactor) {
  MechanicalState& s = *mstate;
  const double* dx = s.read(p.dx).data();
  double* df = s.write(p.df).data();
  for (const EdgeSpring& es : springs_) {
    if (!es.active) continue;
    double dk[4][3];
    for (int k = 0; k < 4; ++k) {
      const double* d = dx + 3 * es.vid[k];
      for (int c = 0; c < 3; ++c) dk[k][c] = d[c] * es.lambda * kfactor * es.alpha[k];
    }
    for (int j = 0; j < 4; ++j) {
      double* dfj = df + 3 * es.vid[j];
      for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) dfj[c] -= dk[k][c] * es.alpha[j];
    }
  }
}

bool FastTriangularBendingSprings::build_stiffness(MatrixSink& K) {
  const MechanicalState* s = mstate.get();
  for (const EdgeSpring& es : springs_) {
    if (!es.active) continue;
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const double v = -es.lambda * es.alpha[j] * es.alpha[k];
        for (int c = 0; c < 3; ++c) K.add(s, 3 * es.vid[j] + c, s, 3 * es.vid[k] + c, v);
      }
  }
  return true;
}

void register_fast_triangular_bending_springs(Registry& r) {
  ComponentInfo info;
  info.name = "FastTriangularBendingSprings";
  info.category = "ForceField/Spring";
  info.description = "linear bending forces across the edges shared by two triangles (Volino 2006)";
  info.templates = {"Vec3d"};
  info.default_template = "Vec3d";
  info.requirement = Requirement::state;
  info.create = creator<FastTriangularBendingSprings>();
  r.add(std::move(info));
}

}  // namespace sinew
