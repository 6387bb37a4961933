// What the triangular spring force fields share (SOFA's TriangularQuadraticSpringsForceField
// and TriangularBiquadraticSpringsForceField): their per-edge and per-triangle data following
// topological changes, and their force differential.
//
// `TriInfo` is a force field's per-triangle record with `stiffness[3]` (given to its edges)
// and `std::array<Mat3, 3> dfdx`; `EdgeInfo` a per-edge record with `stiffness`.
#pragma once

#include <algorithm>
#include <vector>

#include "core/matrix_sink.h"
#include "core/roles.h"
#include "core/topology_change.h"

namespace sinew {

// SOFA's init of that data: every edge created, then every triangle (adding its stiffness to its
// edges). False when a triangle could not be created (degenerate: its error already given).
template <class EdgeInfo, class TriInfo, class CreateEdge, class CreateTriangle>
bool build_triangle_springs(const MeshTopologyBase& t, std::vector<EdgeInfo>& edges, std::vector<TriInfo>& tris,
                            CreateEdge&& create_edge, CreateTriangle&& create_triangle) {
  edges.assign(t.edges().size(), EdgeInfo{});
  tris.assign(t.triangles().size(), TriInfo{});
  for (unsigned e = 0; e < edges.size(); ++e) create_edge(e);
  bool ok = true;
  for (unsigned i = 0; i < tris.size(); ++i) ok = create_triangle(i) && ok;
  return ok;
}

// SOFA's edge and triangle data through one topological event (removals arrive before the lists
// change, additions after): a removed triangle takes its stiffness back from its edges, then the
// last record moves into its slot; added edges and triangles get records made by
// `create_edge(e)` / `create_triangle(i)` (which add a triangle's stiffness to its edges).
template <class EdgeInfo, class TriInfo, class CreateEdge, class CreateTriangle>
void follow_triangle_springs(const MeshTopologyBase& t, const TopologyChange& c, std::vector<EdgeInfo>& edges,
                             std::vector<TriInfo>& tris, CreateEdge&& create_edge, CreateTriangle&& create_triangle) {
  switch (c.type) {
    case TopologyChangeType::triangles_removed:
      for (unsigned r : c.indices) {
        if (r >= tris.size() || r >= t.edges_in_triangle().size()) continue;
        const auto& te = t.edges_in_triangle()[r];
        for (int j = 0; j < 3; ++j)
          if (te[j] < edges.size()) edges[te[j]].stiffness -= tris[r].stiffness[j];
      }
      remove_swap_last(tris, c.indices);
      break;
    case TopologyChangeType::edges_removed:
      remove_swap_last(edges, c.indices);
      break;
    case TopologyChangeType::edges_added:
      for (unsigned e : c.indices) {
        if (e >= t.edges().size()) continue;
        if (e >= edges.size()) edges.resize(e + 1);
        create_edge(e);
      }
      break;
    case TopologyChangeType::triangles_added:
      for (unsigned i : c.indices) {
        if (i >= t.triangles().size()) continue;
        if (i >= tris.size()) tris.resize(i + 1);
        create_triangle(i);
      }
      break;
    default:
      break;
  }
}

// The force differential: per triangle t and per k, one 3×3 block M = dfdx[k] acting on the
// edge opposite vertex k, from a = t[k+1] to b = t[k+2]:
//   df_a += kfactor·M·(dx_a − dx_b),  df_b −= kfactor·Mᵀ·(dx_a − dx_b),
// sums written in SOFA's order (row products left to right).
template <class Info>
void add_triangle_edge_dforce(const std::vector<Triangle>& tris, const std::vector<Info>& info, const double* dx,
                              double* df, double kfactor) {
  const std::size_t nt = std::min(tris.size(), info.size());
  for (std::size_t l = 0; l < nt; ++l) {
    const Triangle& ta = tris[l];
    for (int k = 0; k < 3; ++k) {
      const unsigned a = ta[(k + 1) % 3], b = ta[(k + 2) % 3];
      const double d[3] = {dx[3 * a] - dx[3 * b], dx[3 * a + 1] - dx[3 * b + 1], dx[3 * a + 2] - dx[3 * b + 2]};
      const Mat3& m = info[l].dfdx[k];
      for (int u = 0; u < 3; ++u) {
        double r = m(u, 0) * d[0];  // row · d
        r += m(u, 1) * d[1];
        r += m(u, 2) * d[2];
        const double t = d[0] * m(0, u) + d[1] * m(1, u) + d[2] * m(2, u);  // column · d
        df[3 * a + u] += r * kfactor;
        df[3 * b + u] -= t * kfactor;
      }
    }
  }
}

// K as add_triangle_edge_dforce applies it: per triangle and k, +M on (a, a), −M on (a, b),
// −Mᵀ on (b, a), +Mᵀ on (b, b). SOFA assembles neither force field; this is the matrix their
// addDForce uses.
template <class Info>
void add_triangle_edge_stiffness(const std::vector<Triangle>& tris, const std::vector<Info>& info,
                                 const MechanicalState* s, MatrixSink& K) {
  const std::size_t nt = std::min(tris.size(), info.size());
  for (std::size_t l = 0; l < nt; ++l)
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = tris[l][(k + 1) % 3], b = tris[l][(k + 2) % 3];
      const Mat3& m = info[l].dfdx[k];
      const Mat3 mt = m.transpose();
      K.add_block(s, 3 * a, s, 3 * a, m);
      K.add_block(s, 3 * a, s, 3 * b, -m);
      K.add_block(s, 3 * b, s, 3 * a, -mt);
      K.add_block(s, 3 * b, s, 3 * b, mt);
    }
}

}  // namespace sinew
