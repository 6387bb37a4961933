// Per-edge maths shared by DistanceMapping, SquareDistanceMapping and
// DistanceMultiMapping. An edge joins p0 to p1; every function reads 3
// coordinates through a pointer, so a Vec3d, the centre of a Rigid3d or a
// point of another input all fit. The mapping owns the loops and the storage.
//
// The regression scenes compare with SOFA to round-off, so each expression
// keeps the operation order the mappings used; do not "simplify" them.
// Signs are applied as `sign * n[k]` with sign = ±1: exact, hence the same
// bits as writing −n[k] or n[k].
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/matrix_sink.h"
#include "mapping/mapping_base.h"

namespace sinew::edge {

// u = p1 − p0; returns |u|².
inline double edge_vector(const double* p0, const double* p1, double* u) {
  u[0] = p1[0] - p0[0];
  u[1] = p1[1] - p0[1];
  u[2] = p1[2] - p0[2];
  return u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
}

// |p1 − p0| (rest lengths at init).
inline double edge_length(const double* p0, const double* p1) {
  const double d0 = p0[0] - p1[0], d1 = p0[1] - p1[1], d2 = p0[2] - p1[2];
  return std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

// n = unit direction p0 → p1 and inv_length = 1/|p1 − p0|; returns the length.
// A degenerate edge gets n = (1,1,1)/√3 and inv_length = 0 (no geometric
// stiffness), so J stays defined.
inline double unit_direction(const double* p0, const double* p1, double* n, double& inv_length) {
  static const double p = 1.0 / std::sqrt(3.0);
  const double length = std::sqrt(edge_vector(p0, p1, n));
  if (length > std::numeric_limits<double>::epsilon()) {
    inv_length = 1 / length;
    n[0] *= inv_length;
    n[1] *= inv_length;
    n[2] *= inv_length;
  } else {
    inv_length = 0;
    n[0] = n[1] = n[2] = p;
  }
  return length;
}

// s + (sign·g)·x: one end's part of a Jacobian row (g the row's gradient, −g
// on p0, +g on p1) applied to that end's derivative x.
inline double add_end_dot(double s, double sign, const double* g, const double* x) {
  for (int k = 0; k < 3; ++k) s += (sign * g[k]) * x[k];
  return s;
}

// J row · dx for an edge whose ends live in one state: −g·dx0 + g·dx1,
// summed in increasing column order (the lower point index first, as a
// sparse row product does).
inline double row_dot(const double* g, const double* dx0, const double* dx1, bool end1_first) {
  if (end1_first) return add_end_dot(add_end_dot(0, 1.0, g, dx1), -1.0, g, dx0);
  return add_end_dot(add_end_dot(0, -1.0, g, dx0), 1.0, g, dx1);
}

// f += (sign·g)·lambda: one end's share of Jᵀ·lambda.
inline void add_end_force(double* f, double sign, const double* g, double lambda) {
  for (int k = 0; k < 3; ++k) f[k] += (sign * g[k]) * lambda;
}

// Whether an edge with output force lambda gets geometric stiffness: every
// edge with Exact (1), edges in extension (lambda < 0) with Stabilized (2).
inline bool has_geometric_stiffness(int gs, double lambda) { return lambda < 0 || gs == 1; }

// Geometric stiffness block of a distance edge: b = (I − n nᵀ)·(lambda/L·scale).
inline void distance_gs_block(const double* n, double lambda, double inv_length, double scale, double b[3][3]) {
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) b[j][k] = 1.0 * (j == k) - n[j] * n[k];
  const double s = lambda * inv_length * scale;
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) b[j][k] *= s;
}

// With r = b·(dx1 − dx0): f0 −= r, f1 += r (the block acts as [b −b; −b b]).
inline void add_block_product(const double b[3][3], const double* dx0, const double* dx1, double* f0, double* f1) {
  double u[3], r[3] = {0, 0, 0};
  for (int c = 0; c < 3; ++c) u[c] = dx1[c] - dx0[c];
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 3; ++c) r[j] += b[j][c] * u[c];
  for (int j = 0; j < 3; ++j) {
    f0[j] -= r[j];
    f1[j] += r[j];
  }
}

// Jacobian row `row` of an edge whose ends live in input 0 at columns col0 and
// col1: −g on p0, +g on p1, entries interleaved per coordinate (this order is
// the pattern other code relies on).
void append_edge_row(std::vector<JacobianEntry>& out, std::uint32_t row, std::uint32_t col0, std::uint32_t col1,
                     const double* g);

// Adds [b −b; −b b] at rows/columns (s0, i0) and (s1, i1), row by row.
void add_edge_block(MatrixSink& K, const MechanicalState* s0, std::size_t i0, const MechanicalState* s1,
                    std::size_t i1, const double b[3][3]);

// out[e] = J row e · in for every edge (J rows = `rows`, 3 per edge, −row on
// the first end, +row on the second); out is resized to the edge count.
void apply_rows(const std::vector<Edge>& edges, const std::vector<double>& rows, const std::vector<double>& in,
                int dw, std::vector<double>& out);
// in += Jᵀ·out for the edges out holds a value for.
void apply_rows_transposed(const std::vector<Edge>& edges, const std::vector<double>& rows,
                           const std::vector<double>& out, int dw, std::vector<double>& in);

// The shared start of init_mapping for the edge mappings: the
// geometricStiffness mode (into gs), the topology (linked, else the node's)
// and its edges (into edges), each edge checked against the n_in input
// points. False after an error reported on `m`.
bool init_edges(MappingBase& m, const std::string& geometric_stiffness, Link<MeshTopologyBase>& topology,
                std::size_t n_in, int& gs, std::vector<Edge>& edges);

}  // namespace sinew::edge
