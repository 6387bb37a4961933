#include "mapping/linear/barycentric_coords.h"

#include <algorithm>
#include <cmath>

#include "topology/grid/regular_grid_topology.h"
#include "topology/grid/sparse_grid_topology.h"

namespace sinew {

bool bary_invert3(const double f[3][3], double d[3][3]) {
  const double det = f[0][0] * f[1][1] * f[2][2] + f[1][0] * f[2][1] * f[0][2] + f[2][0] * f[0][1] * f[1][2] -
                     f[0][0] * f[2][1] * f[1][2] - f[1][0] * f[0][1] * f[2][2] - f[2][0] * f[1][1] * f[0][2];
  if (std::abs(det) < std::numeric_limits<double>::epsilon()) return false;
  d[0][0] = (f[1][1] * f[2][2] - f[2][1] * f[1][2]) / det;
  d[1][0] = (f[1][2] * f[2][0] - f[2][2] * f[1][0]) / det;
  d[2][0] = (f[1][0] * f[2][1] - f[2][0] * f[1][1]) / det;
  d[0][1] = (f[2][1] * f[0][2] - f[0][1] * f[2][2]) / det;
  d[1][1] = (f[2][2] * f[0][0] - f[0][2] * f[2][0]) / det;
  d[2][1] = (f[2][0] * f[0][1] - f[0][0] * f[2][1]) / det;
  d[0][2] = (f[0][1] * f[1][2] - f[1][1] * f[0][2]) / det;
  d[1][2] = (f[0][2] * f[1][0] - f[1][2] * f[0][0]) / det;
  d[2][2] = (f[0][0] * f[1][1] - f[1][0] * f[0][1]) / det;
  return true;
}

namespace {

// Points farther out of their element than this (in element coordinates, a quarter of the
// element) are reported; surface points of a finer visual mesh, slightly outside, are not.
constexpr double kOutsideTolerance = 0.25;

inline bool outside_cell(double fx, double fy, double fz) {
  auto out = [](double f) { return f < -kOutsideTolerance || f > 1 + kOutsideTolerance; };
  return out(fx) || out(fy) || out(fz);
}

// ---------------------------------------------------------------- weights of cells

// Trilinear weights of a cell's corners in lattice order (x fastest, then y, then z).
inline void trilinear(double fx, double fy, double fz, double w[8]) {
  w[0] = (1 - fx) * (1 - fy) * (1 - fz);
  w[1] = (fx) * (1 - fy) * (1 - fz);
  w[2] = (1 - fx) * (fy) * (1 - fz);
  w[3] = (fx) * (fy) * (1 - fz);
  w[4] = (1 - fx) * (1 - fy) * (fz);
  w[5] = (fx) * (1 - fy) * (fz);
  w[6] = (1 - fx) * (fy) * (fz);
  w[7] = (fx) * (fy) * (fz);
}
inline void bilinear(double fx, double fy, double w[4]) {
  w[0] = (1 - fx) * (1 - fy);
  w[1] = (fx) * (1 - fy);
  w[2] = (1 - fx) * (fy);
  w[3] = (fx) * (fy);
}

// A hexahedron (quad) numbers its vertices around each face: lattice corner k is vertex
// kAround[k] and the other way round. SOFA's grid and mesh mappers sum in lattice order, its
// set-container mappers in vertex order.
constexpr int kAround[8] = {0, 1, 3, 2, 4, 5, 7, 6};

template <std::size_t N>
void add_corners(BaryTable& table, const std::array<unsigned, N>& v, const double (&w)[N], bool vertex_order) {
  for (std::size_t k = 0; k < N; ++k) {
    if (vertex_order)
      table.add(v[k], w[kAround[k]]);
    else
      table.add(v[kAround[k]], w[k]);
  }
}

// ---------------------------------------------------------------- small vector kernels

inline void sub3(const double* a, const double* b, double* r) {
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
inline void cross3(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
inline void mul3(const double b[3][3], const double* v, double* r) {
  for (int i = 0; i < 3; ++i) {
    double s = b[i][0] * v[0];
    s += b[i][1] * v[1];
    s += b[i][2] * v[2];
    r[i] = s;
  }
}
inline double dist2(const double* a, const double* b) {
  const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return d0 * d0 + d1 * d1 + d2 * d2;
}

// ---------------------------------------------------------------- element types

// An element's local frame: the inverse of its axes (zero when degenerate) and its centre.
struct Frame {
  double b[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double c[3] = {0, 0, 0};
};

// What the nearest-element search needs of one element type:
//  - axes: the vertices v with x[v] − x[0] as local axes; surface elements take e0 × e1 as third axis;
//  - outside(v): SOFA's measure of how far local coordinates v lie outside (> 0: outside);
//  - weights(e, v): the vertex weights of local coordinates v, in SOFA's summation order.
struct TetraType {
  using Element = Tetra;
  static constexpr int axes[3] = {1, 2, 3};
  static constexpr bool surface = false;
  static double outside(const double* v) {
    return std::max(std::max(-v[0], -v[1]), std::max(-v[2], v[0] + v[1] + v[2] - 1));
  }
  static void weights(const Tetra& t, const double* v, bool, BaryTable& table) {
    const double fx = v[0], fy = v[1], fz = v[2];
    table.add(t[0], 1 - fx - fy - fz);
    table.add(t[1], fx);
    table.add(t[2], fy);
    table.add(t[3], fz);
  }
};

struct HexaType {
  using Element = Hexa;
  static constexpr int axes[3] = {1, 3, 4};
  static constexpr bool surface = false;
  static double outside(const double* v) {
    return std::max(std::max(-v[0], -v[1]), std::max(std::max(-v[2], v[0] - 1), std::max(v[1] - 1, v[2] - 1)));
  }
  static void weights(const Hexa& h, const double* v, bool vertex_order, BaryTable& table) {
    double w[8];
    trilinear(v[0], v[1], v[2], w);
    add_corners(table, h, w, vertex_order);
  }
};

struct TriangleType {
  using Element = Triangle;
  static constexpr int axes[2] = {1, 2};
  static constexpr bool surface = true;
  static double outside(const double* v) {
    return std::max(std::max(-v[0], -v[1]), std::max((v[2] < 0 ? -v[2] : v[2]) - 0.01, v[0] + v[1] - 1));
  }
  static void weights(const Triangle& t, const double* v, bool, BaryTable& table) {
    const double fx = v[0], fy = v[1];
    table.add(t[0], 1 - fx - fy);
    table.add(t[1], fx);
    table.add(t[2], fy);
  }
};

struct QuadType {
  using Element = Quad;
  static constexpr int axes[2] = {1, 3};
  static constexpr bool surface = true;
  static double outside(const double* v) {
    return std::max(std::max(-v[0], -v[1]), std::max(std::max(v[1] - 1, v[0] - 1), std::max(v[2] - 0.01, -v[2] - 0.01)));
  }
  static void weights(const Quad& q, const double* v, bool vertex_order, BaryTable& table) {
    double w[4];
    bilinear(v[0], v[1], w);
    add_corners(table, q, w, vertex_order);
  }
};

// ---------------------------------------------------------------- nearest-element search

// Frames of elements E, stored from frames[first] on.
template <class Type>
void build_frames(const std::vector<typename Type::Element>& E, const std::vector<double>& in, std::size_t first,
                  std::vector<Frame>& frames, std::vector<std::size_t>& degenerate) {
  const double* X = in.data();
  constexpr std::size_t N = std::tuple_size_v<typename Type::Element>;
  for (std::size_t e = 0; e < E.size(); ++e) {
    const double* x0 = X + E[e][0] * 3;
    double axis[3][3];
    sub3(X + E[e][Type::axes[0]] * 3, x0, axis[0]);
    sub3(X + E[e][Type::axes[1]] * 3, x0, axis[1]);
    if constexpr (Type::surface)
      cross3(axis[0], axis[1], axis[2]);
    else
      sub3(X + E[e][Type::axes[2]] * 3, x0, axis[2]);
    // SOFA inverts the matrix whose columns are the axes.
    double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = axis[j][i];
    Frame& f = frames[first + e];
    if (!bary_invert3(m, f.b)) degenerate.push_back(first + e);
    for (int k = 0; k < 3; ++k) {
      double s = X[E[e][0] * 3 + k];
      for (std::size_t j = 1; j < N; ++j) s += X[E[e][j] * 3 + k];
      f.c[k] = N == 3 ? s / 3 : N == 4 ? s * 0.25 : s * 0.125;
    }
  }
}

struct Nearest {
  double d;                   // best distance so far (SOFA's criterion)
  double raw = 0;             // its outside measure
  std::size_t index = BaryReport::kNone;
  double v[3] = {0, 0, 0};    // its local coordinates
};

template <class Type>
void search(const std::vector<typename Type::Element>& E, const std::vector<Frame>& frames, std::size_t first,
            const double* X, const double* p, Nearest& best) {
  for (std::size_t e = 0; e < E.size(); ++e) {
    const Frame& f = frames[first + e];
    double r[3], v[3];
    sub3(p, X + E[e][0] * 3, r);
    mul3(f.b, r, v);
    double d = Type::outside(v);
    const double raw = d;
    if (d > 0) d = dist2(p, f.c);
    if (d < best.d) {
      best.d = d;
      best.raw = raw;
      best.index = first + e;
      best.v[0] = v[0], best.v[1] = v[1], best.v[2] = v[2];
    }
  }
}

// Elements of type A (indices 0..) then B (indices A.size()..) compete for each point.
template <class A, class B>
BaryReport nearest_element(const std::vector<typename A::Element>& EA, const std::vector<typename B::Element>& EB,
                           bool set_container, const std::vector<double>& in, const std::vector<double>& out,
                           BaryTable& table) {
  BaryReport report;
  std::vector<Frame> frames(EA.size() + EB.size());
  build_frames<A>(EA, in, 0, frames, report.degenerate);
  build_frames<B>(EB, in, EA.size(), frames, report.degenerate);
  const std::size_t n_out = out.size() / 3;
  for (std::size_t i = 0; i < n_out; ++i) {
    const double* p = &out[i * 3];
    Nearest best{set_container ? std::numeric_limits<double>::max() : 1e10};
    search<A>(EA, frames, 0, in.data(), p, best);
    search<B>(EB, frames, EA.size(), in.data(), p, best);
    if (best.index == BaryReport::kNone) {
      report.unlocated = i;
      return report;
    }
    if (best.raw > kOutsideTolerance) report.outside.push_back(i);
    if (best.index < EA.size())
      A::weights(EA[best.index], best.v, set_container, table);
    else
      B::weights(EB[best.index - EA.size()], best.v, set_container, table);
    table.end_point(static_cast<unsigned>(best.index));
  }
  return report;
}

}  // namespace

// ---------------------------------------------------------------- entry points

BaryReport bary_regular_grid(const RegularGridTopology& grid, const std::vector<double>& out, BaryTable& table) {
  BaryReport report;
  const VecNi<3> n = grid.dims();
  const Vec3 p0 = grid.origin(), dx = grid.dx(), dy = grid.dy(), dz = grid.dz();
  const double inv_dx2 = 1 / (dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
  const double inv_dy2 = 1 / (dy[0] * dy[0] + dy[1] * dy[1] + dy[2] * dy[2]);
  const double inv_dz2 = 1 / (dz[0] * dz[0] + dz[1] * dz[1] + dz[2] * dz[2]);
  auto dot = [](const double* a, const Vec3& b) {
    double s = a[0] * b[0];
    s += a[1] * b[1];
    s += a[2] * b[2];
    return s;
  };
  const std::size_t n_out = out.size() / 3;
  for (std::size_t i = 0; i < n_out; ++i) {
    const double p[3] = {out[i * 3] - p0[0], out[i * 3 + 1] - p0[1], out[i * 3 + 2] - p0[2]};
    const double x = dot(p, dx) * inv_dx2, y = dot(p, dy) * inv_dy2, z = dot(p, dz) * inv_dz2;
    // findCube, else findNearestCube: clamped cell, unclamped (extrapolated) coordinates.
    const int ix = std::clamp(static_cast<int>(std::floor(x)), 0, n[0] - 2);
    const int iy = std::clamp(static_cast<int>(std::floor(y)), 0, n[1] - 2);
    const int iz = std::clamp(static_cast<int>(std::floor(z)), 0, n[2] - 2);
    const double fx = x - ix, fy = y - iy, fz = z - iz;
    if (outside_cell(fx, fy, fz)) report.outside.push_back(i);
    double w[8];
    trilinear(fx, fy, fz, w);
    for (int k = 0; k < 8; ++k)
      table.add(static_cast<unsigned>(grid.point_index(ix + (k & 1), iy + (k >> 1 & 1), iz + (k >> 2))), w[k]);
    table.end_point(static_cast<unsigned>(ix + (n[0] - 1) * (iy + (n[1] - 1) * iz)));  // the grid's cube order
  }
  return report;
}

BaryReport bary_sparse_grid(const SparseGridTopology& grid, const std::vector<double>& out, BaryTable& table) {
  BaryReport report;
  const std::vector<Hexa>& hexas = grid.hexahedra();
  const std::size_t n_out = out.size() / 3;
  for (std::size_t i = 0; i < n_out; ++i) {
    const Vec3 p(out[i * 3], out[i * 3 + 1], out[i * 3 + 2]);
    double fx = 0, fy = 0, fz = 0;
    unsigned cube = grid.find_cube(p, fx, fy, fz);
    if (cube == ~0u) {
      cube = grid.find_nearest_cube(p, fx, fy, fz);
      if (outside_cell(fx, fy, fz)) report.outside.push_back(i);
    }
    if (cube >= hexas.size()) {
      report.unlocated = i;
      return report;
    }
    double w[8];
    trilinear(fx, fy, fz, w);
    add_corners(table, hexas[cube], w, false);
    table.end_point(cube);
  }
  return report;
}

BaryReport bary_volume(const std::vector<Tetra>& tetras, const std::vector<Hexa>& hexas, bool set_container,
                       const std::vector<double>& in, const std::vector<double>& out, BaryTable& table) {
  return nearest_element<TetraType, HexaType>(tetras, hexas, set_container, in, out, table);
}

BaryReport bary_surface(const std::vector<Triangle>& triangles, const std::vector<Quad>& quads, bool set_container,
                        const std::vector<double>& in, const std::vector<double>& out, BaryTable& table) {
  return nearest_element<TriangleType, QuadType>(triangles, quads, set_container, in, out, table);
}

void bary_edges(const std::vector<Edge>& edges, const std::vector<double>& in, const std::vector<double>& out,
                BaryTable& table) {
  const double* X = in.data();
  std::vector<double> len(edges.size()), unit(edges.size() * 3);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    double d[3];
    sub3(X + edges[e][1] * 3, X + edges[e][0] * 3, d);
    len[e] = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k) unit[e * 3 + k] = len[e] > std::numeric_limits<double>::epsilon() ? d[k] / len[e] : d[k];
  }
  const std::size_t n_out = out.size() / 3;
  for (std::size_t i = 0; i < n_out; ++i) {
    const double* p = &out[i * 3];
    double coef = 0;
    std::size_t e = 0;
    for (; e < edges.size(); ++e) {
      double r[3];
      sub3(p, X + edges[e][0] * 3, r);
      const double* u = &unit[e * 3];
      coef = (u[0] * r[0] + u[1] * r[1] + u[2] * r[2]) / len[e];
      if (coef >= 0 && coef <= 1) break;
    }
    if (e == edges.size()) e = edges.size() - 1;
    table.add(edges[e][0], 1 - coef);
    table.add(edges[e][1], coef);
    table.end_point(static_cast<unsigned>(e));
  }
}

}  // namespace sinew
