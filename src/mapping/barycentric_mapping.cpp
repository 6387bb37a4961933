#include "mapping/barycentric_mapping.h"

#include <cmath>
#include <limits>

#include "core/node.h"
#include "core/registry.h"
#include "topology/regular_grid_topology.h"
#include "topology/sparse_grid_topology.h"

namespace sinew {

namespace {

// SOFA's 3×3 inverse (cofactors over the determinant, same operation order).
bool invert3(const double f[3][3], double d[3][3]) {
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

struct Base3 {
  double b[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double c[3] = {0, 0, 0};  // element centre
};

// Base from three edge vectors e0, e1, e2 (the rows of m; SOFA inverts mᵀ).
Base3 make_base(const double* e0, const double* e1, const double* e2, bool* ok = nullptr) {
  Base3 out;
  double mt[3][3];
  for (int i = 0; i < 3; ++i) {
    mt[i][0] = e0[i];
    mt[i][1] = e1[i];
    mt[i][2] = e2[i];
  }
  const bool inv = invert3(mt, out.b);
  if (ok) *ok = inv;
  return out;
}

// Points farther out of their element than this (in element coordinates, a quarter of the
// element) are reported; surface points of a finer visual mesh, slightly outside, are not.
constexpr double kOutsideTolerance = 0.25;
inline bool outside_cell(double fx, double fy, double fz) {
  auto out = [](double f) { return f < -kOutsideTolerance || f > 1 + kOutsideTolerance; };
  return out(fx) || out(fy) || out(fz);
}

// "a, b, c" of the first few indices, "... (n in all)" beyond.
std::string index_list(const std::vector<std::size_t>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < 8; ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  if (v.size() > 8) s += ", ... (" + std::to_string(v.size()) + " in all)";
  return s;
}

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

template <std::size_t N>
void centre(const std::vector<double>& in, const std::array<unsigned, N>& e, double* c) {
  for (int k = 0; k < 3; ++k) {
    double s = in[e[0] * 3 + k];
    for (std::size_t j = 1; j < N; ++j) s += in[e[j] * 3 + k];
    c[k] = N == 3 ? s / 3 : N == 4 ? s * 0.25 : s * 0.125;
  }
}

bool is_set_container(const MeshTopologyBase& t) {
  const std::string& n = t.class_name();
  const std::string suffix = "SetTopologyContainer";
  return n.size() >= suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

void BarycentricMapping::add_point(std::initializer_list<std::pair<unsigned, double>> terms) {
  for (const auto& [i, w] : terms) {
    idx_.push_back(i);
    w_.push_back(w);
  }
  start_.push_back(static_cast<std::uint32_t>(idx_.size()));
}

void BarycentricMapping::report_outside(const std::vector<std::size_t>& outside) {
  if (outside.empty()) return;
  msg_warning(std::to_string(outside.size()) + " output point(s) outside every element of " +
              input_topology->describe() + ", mapped by extrapolation from the nearest element: " +
              index_list(outside));
}

void BarycentricMapping::report_degenerate(const char* what, const std::vector<std::size_t>& bad, std::size_t total) {
  if (bad.empty()) return;
  msg_warning(std::to_string(bad.size()) + " of " + std::to_string(total) + " " + what + "(s) of " +
              input_topology->describe() + " are degenerate (zero volume or area) and cannot locate points: " +
              index_list(bad));
}

bool BarycentricMapping::init_mapping() {
  if (!input_topology) input_topology.set(in_[0]->node() ? in_[0]->node()->find_up<MeshTopologyBase>() : nullptr);
  if (!output_topology) {
    Component* oc = out_ ? static_cast<Component*>(out_) : static_cast<Component*>(vout_);
    if (oc->node()) output_topology.set(oc->node()->find_up<MeshTopologyBase>());
  }
  if (!input_topology) {
    msg_error("no input topology found; set input_topology=\"@...\"");
    return false;
  }
  start_.assign(1, 0);
  idx_.clear();
  w_.clear();

  const int x_id = use_rest_position.value() ? kRestPosition : kPosition;
  const std::vector<double>& in = in_coord(x_id);
  std::vector<double> out = *out_coord(x_id);  // copy: resizing the output must not invalidate it
  MeshTopologyBase& topo = *input_topology;

  bool ok = false;
  if (dynamic_cast<RegularGridTopology*>(&topo)) {
    ok = init_regular_grid(out);
  } else if (dynamic_cast<SparseGridTopology*>(&topo)) {
    ok = init_sparse_grid(out);
  } else if (topo.class_name() == "SparseGridRamificationTopology") {
    msg_error("input topology " + topo.describe() + ": the SparseGridRamificationTopology mapper is not supported yet");
    return false;
  } else {
    ok = init_mesh(out, in, is_set_container(topo));
  }
  if (!ok) return false;
  resize_output(start_.size() - 1);
  return true;
}

bool BarycentricMapping::init_regular_grid(const std::vector<double>& out) {
  auto& grid = static_cast<RegularGridTopology&>(*input_topology);
  grid.nb_points();  // make sure the grid is generated
  const VecNi<3> n = grid.dims();
  if (n[0] < 2 || n[1] < 2 || n[2] < 2) {
    msg_error("input topology " + grid.describe() + " has no volume (n = " + std::to_string(n[0]) + " " +
              std::to_string(n[1]) + " " + std::to_string(n[2]) + "): no barycentric mapper can be created");
    return false;
  }
  mapper_ = "RegularGrid";
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
  std::vector<std::size_t> outside;
  for (std::size_t i = 0; i < n_out; ++i) {
    const double p[3] = {out[i * 3] - p0[0], out[i * 3 + 1] - p0[1], out[i * 3 + 2] - p0[2]};
    const double x = dot(p, dx) * inv_dx2, y = dot(p, dy) * inv_dy2, z = dot(p, dz) * inv_dz2;
    int ix = static_cast<int>(std::floor(x)), iy = static_cast<int>(std::floor(y)), iz = static_cast<int>(std::floor(z));
    // findCube, else findNearestCube: clamped cell, unclamped (extrapolated) coordinates.
    ix = std::clamp(ix, 0, n[0] - 2);
    iy = std::clamp(iy, 0, n[1] - 2);
    iz = std::clamp(iz, 0, n[2] - 2);
    const double fx = x - ix, fy = y - iy, fz = z - iz;
    if (outside_cell(fx, fy, fz)) outside.push_back(i);
    auto pt = [&](int a, int b, int c) { return static_cast<unsigned>(grid.point_index(a, b, c)); };
    add_point({{pt(ix, iy, iz), (1 - fx) * (1 - fy) * (1 - fz)},
               {pt(ix + 1, iy, iz), (fx) * (1 - fy) * (1 - fz)},
               {pt(ix, iy + 1, iz), (1 - fx) * (fy) * (1 - fz)},
               {pt(ix + 1, iy + 1, iz), (fx) * (fy) * (1 - fz)},
               {pt(ix, iy, iz + 1), (1 - fx) * (1 - fy) * (fz)},
               {pt(ix + 1, iy, iz + 1), (fx) * (1 - fy) * (fz)},
               {pt(ix, iy + 1, iz + 1), (1 - fx) * (fy) * (fz)},
               {pt(ix + 1, iy + 1, iz + 1), (fx) * (fy) * (fz)}});
  }
  report_outside(outside);
  return true;
}

bool BarycentricMapping::init_sparse_grid(const std::vector<double>& out) {
  auto& grid = static_cast<SparseGridTopology&>(*input_topology);
  const std::vector<Hexa>& hexas = grid.hexahedra();
  if (hexas.empty()) {
    msg_error("input topology " + grid.describe() + " has no volume: no barycentric mapper can be created");
    return false;
  }
  mapper_ = "SparseGrid";
  const std::size_t n_out = out.size() / 3;
  std::vector<std::size_t> outside;
  for (std::size_t i = 0; i < n_out; ++i) {
    const Vec3 p(out[i * 3], out[i * 3 + 1], out[i * 3 + 2]);
    double fx = 0, fy = 0, fz = 0;
    unsigned cube = grid.find_cube(p, fx, fy, fz);
    if (cube == ~0u) {
      cube = grid.find_nearest_cube(p, fx, fy, fz);
      if (outside_cell(fx, fy, fz)) outside.push_back(i);
    }
    if (cube >= hexas.size()) {
      msg_error("output point " + std::to_string(i) + " could not be located in " + grid.describe());
      return false;
    }
    const Hexa& c = hexas[cube];
    add_point({{c[0], (1 - fx) * (1 - fy) * (1 - fz)},
               {c[1], (fx) * (1 - fy) * (1 - fz)},
               {c[3], (1 - fx) * (fy) * (1 - fz)},
               {c[2], (fx) * (fy) * (1 - fz)},
               {c[4], (1 - fx) * (1 - fy) * (fz)},
               {c[5], (fx) * (1 - fy) * (fz)},
               {c[7], (1 - fx) * (fy) * (fz)},
               {c[6], (fx) * (fy) * (fz)}});
  }
  report_outside(outside);
  return true;
}

bool BarycentricMapping::init_mesh(const std::vector<double>& out, const std::vector<double>& in, bool set_container) {
  MeshTopologyBase& topo = *input_topology;
  const std::size_t n_in = in.size() / 3;
  const std::size_t n_out = out.size() / 3;
  auto check = [&](const auto& list, const char* what) {
    for (std::size_t e = 0; e < list.size(); ++e)
      for (unsigned v : list[e])
        if (v >= n_in) {
          msg_error(std::string(what) + " " + std::to_string(e) + " of " + topo.describe() + " uses point " +
                    std::to_string(v) + " but the input state has " + std::to_string(n_in) + " points");
          return false;
        }
    return true;
  };
  const std::vector<Tetra>& tetras = topo.tetrahedra();
  const std::vector<Hexa>& hexas = topo.hexahedra();
  const double* X = in.data();

  // Candidate element sets: the set-container mappers use one element kind only.
  std::vector<Tetra> no_tetras;
  std::vector<Hexa> no_hexas;
  const bool volume = !tetras.empty() || !hexas.empty();
  if (volume) {
    const std::vector<Tetra>& T = set_container && !hexas.empty() ? no_tetras : tetras;
    const std::vector<Hexa>& H = set_container && hexas.empty() ? no_hexas : hexas;
    if (!check(T, "tetrahedron") || !check(H, "hexahedron")) return false;
    mapper_ = set_container ? (H.empty() ? "TetrahedronSet" : "HexahedronSet") : "Mesh";
    std::vector<Base3> bases(T.size() + H.size());
    std::vector<std::size_t> degenerate, outside;
    for (std::size_t t = 0; t < T.size(); ++t) {
      double e0[3], e1[3], e2[3];
      sub3(X + T[t][1] * 3, X + T[t][0] * 3, e0);
      sub3(X + T[t][2] * 3, X + T[t][0] * 3, e1);
      sub3(X + T[t][3] * 3, X + T[t][0] * 3, e2);
      bool ok = true;
      bases[t] = make_base(e0, e1, e2, &ok);
      if (!ok) degenerate.push_back(t);
      centre(in, T[t], bases[t].c);
    }
    for (std::size_t h = 0; h < H.size(); ++h) {
      double e0[3], e1[3], e2[3];
      sub3(X + H[h][1] * 3, X + H[h][0] * 3, e0);
      sub3(X + H[h][3] * 3, X + H[h][0] * 3, e1);
      sub3(X + H[h][4] * 3, X + H[h][0] * 3, e2);
      bool ok = true;
      bases[T.size() + h] = make_base(e0, e1, e2, &ok);
      if (!ok) degenerate.push_back(T.size() + h);
      centre(in, H[h], bases[T.size() + h].c);
    }
    report_degenerate("element", degenerate, T.size() + H.size());
    for (std::size_t i = 0; i < n_out; ++i) {
      const double* p = &out[i * 3];
      double best = set_container ? std::numeric_limits<double>::max() : 1e10;
      std::size_t index = std::numeric_limits<std::size_t>::max();
      double best_raw = 0;
      double coefs[3] = {0, 0, 0};
      for (std::size_t t = 0; t < T.size(); ++t) {
        double r[3], v[3];
        sub3(p, X + T[t][0] * 3, r);
        mul3(bases[t].b, r, v);
        double d = std::max(std::max(-v[0], -v[1]), std::max(-v[2], v[0] + v[1] + v[2] - 1));
        const double raw = d;
        if (d > 0) d = dist2(p, bases[t].c);
        if (d < best) {
          best = d;
          best_raw = raw;
          index = t;
          coefs[0] = v[0], coefs[1] = v[1], coefs[2] = v[2];
        }
      }
      for (std::size_t h = 0; h < H.size(); ++h) {
        double r[3], v[3];
        sub3(p, X + H[h][0] * 3, r);
        mul3(bases[T.size() + h].b, r, v);
        double d = std::max(std::max(-v[0], -v[1]), std::max(std::max(-v[2], v[0] - 1), std::max(v[1] - 1, v[2] - 1)));
        const double raw = d;
        if (d > 0) d = dist2(p, bases[T.size() + h].c);
        if (d < best) {
          best = d;
          best_raw = raw;
          index = T.size() + h;
          coefs[0] = v[0], coefs[1] = v[1], coefs[2] = v[2];
        }
      }
      if (index == std::numeric_limits<std::size_t>::max()) {
        msg_error("output point " + std::to_string(i) + " could not be located in " + topo.describe());
        return false;
      }
      if (best_raw > kOutsideTolerance) outside.push_back(i);
      const double fx = coefs[0], fy = coefs[1], fz = coefs[2];
      if (index < T.size()) {
        const Tetra& t = T[index];
        add_point({{t[0], 1 - fx - fy - fz}, {t[1], fx}, {t[2], fy}, {t[3], fz}});
      } else {
        const Hexa& c = H[index - T.size()];
        if (set_container)
          add_point({{c[0], (1 - fx) * (1 - fy) * (1 - fz)},
                     {c[1], (fx) * (1 - fy) * (1 - fz)},
                     {c[2], (fx) * (fy) * (1 - fz)},
                     {c[3], (1 - fx) * (fy) * (1 - fz)},
                     {c[4], (1 - fx) * (1 - fy) * (fz)},
                     {c[5], (fx) * (1 - fy) * (fz)},
                     {c[6], (fx) * (fy) * (fz)},
                     {c[7], (1 - fx) * (fy) * (fz)}});
        else
          add_point({{c[0], (1 - fx) * (1 - fy) * (1 - fz)},
                     {c[1], (fx) * (1 - fy) * (1 - fz)},
                     {c[3], (1 - fx) * (fy) * (1 - fz)},
                     {c[2], (fx) * (fy) * (1 - fz)},
                     {c[4], (1 - fx) * (1 - fy) * (fz)},
                     {c[5], (fx) * (1 - fy) * (fz)},
                     {c[7], (1 - fx) * (fy) * (fz)},
                     {c[6], (fx) * (fy) * (fz)}});
      }
    }
    report_outside(outside);
    return true;
  }

  const std::vector<Triangle>& tris = topo.triangles();
  const std::vector<Quad>& quads = topo.quads();
  if (!tris.empty() || !quads.empty()) {
    static const std::vector<Triangle> no_tris;
    static const std::vector<Quad> no_quads;
    const std::vector<Triangle>& T = set_container && !quads.empty() ? no_tris : tris;
    const std::vector<Quad>& Q = set_container && quads.empty() ? no_quads : quads;
    if (!check(T, "triangle") || !check(Q, "quad")) return false;
    mapper_ = set_container ? (Q.empty() ? "TriangleSet" : "QuadSet") : "Mesh";
    std::vector<Base3> bases(T.size() + Q.size());
    std::vector<std::size_t> degenerate, outside;
    for (std::size_t t = 0; t < T.size(); ++t) {
      double e0[3], e1[3], e2[3];
      sub3(X + T[t][1] * 3, X + T[t][0] * 3, e0);
      sub3(X + T[t][2] * 3, X + T[t][0] * 3, e1);
      cross3(e0, e1, e2);
      bool ok = true;
      bases[t] = make_base(e0, e1, e2, &ok);
      if (!ok) degenerate.push_back(t);
      centre(in, T[t], bases[t].c);
    }
    for (std::size_t q = 0; q < Q.size(); ++q) {
      double e0[3], e1[3], e2[3];
      sub3(X + Q[q][1] * 3, X + Q[q][0] * 3, e0);
      sub3(X + Q[q][3] * 3, X + Q[q][0] * 3, e1);
      cross3(e0, e1, e2);
      bool ok = true;
      bases[T.size() + q] = make_base(e0, e1, e2, &ok);
      if (!ok) degenerate.push_back(T.size() + q);
      centre(in, Q[q], bases[T.size() + q].c);
    }
    report_degenerate("surface element", degenerate, T.size() + Q.size());
    for (std::size_t i = 0; i < n_out; ++i) {
      const double* p = &out[i * 3];
      double best = set_container ? std::numeric_limits<double>::max() : 1e10;
      std::size_t index = std::numeric_limits<std::size_t>::max();
      double best_raw = 0;
      double coefs[3] = {0, 0, 0};
      for (std::size_t t = 0; t < T.size(); ++t) {
        double r[3], v[3];
        sub3(p, X + T[t][0] * 3, r);
        mul3(bases[t].b, r, v);
        double d = std::max(std::max(-v[0], -v[1]), std::max((v[2] < 0 ? -v[2] : v[2]) - 0.01, v[0] + v[1] - 1));
        const double raw = d;
        if (d > 0) d = dist2(p, bases[t].c);
        if (d < best) {
          best = d;
          best_raw = raw;
          index = t;
          coefs[0] = v[0], coefs[1] = v[1], coefs[2] = v[2];
        }
      }
      for (std::size_t q = 0; q < Q.size(); ++q) {
        double r[3], v[3];
        sub3(p, X + Q[q][0] * 3, r);
        mul3(bases[T.size() + q].b, r, v);
        double d = std::max(std::max(-v[0], -v[1]),
                            std::max(std::max(v[1] - 1, v[0] - 1), std::max(v[2] - 0.01, -v[2] - 0.01)));
        const double raw = d;
        if (d > 0) d = dist2(p, bases[T.size() + q].c);
        if (d < best) {
          best = d;
          best_raw = raw;
          index = T.size() + q;
          coefs[0] = v[0], coefs[1] = v[1], coefs[2] = v[2];
        }
      }
      if (index == std::numeric_limits<std::size_t>::max()) {
        msg_error("output point " + std::to_string(i) + " could not be located in " + topo.describe());
        return false;
      }
      if (best_raw > kOutsideTolerance) outside.push_back(i);
      const double fx = coefs[0], fy = coefs[1];
      if (index < T.size()) {
        const Triangle& t = T[index];
        add_point({{t[0], 1 - fx - fy}, {t[1], fx}, {t[2], fy}});
      } else {
        const Quad& q = Q[index - T.size()];
        if (set_container)
          add_point({{q[0], (1 - fx) * (1 - fy)}, {q[1], (fx) * (1 - fy)}, {q[2], (fx) * (fy)}, {q[3], (1 - fx) * (fy)}});
        else
          add_point({{q[0], (1 - fx) * (1 - fy)}, {q[1], (fx) * (1 - fy)}, {q[3], (1 - fx) * (fy)}, {q[2], (fx) * (fy)}});
      }
    }
    report_outside(outside);
    return true;
  }

  const std::vector<Edge>& edges = topo.edges();
  if (edges.empty()) {
    msg_error("input topology " + topo.describe() + " has no elements to map onto");
    return false;
  }
  if (!check(edges, "edge")) return false;
  mapper_ = set_container ? "EdgeSet" : "Mesh";
  std::vector<double> len(edges.size()), unit(edges.size() * 3);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    double d[3];
    sub3(X + edges[e][1] * 3, X + edges[e][0] * 3, d);
    len[e] = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k) unit[e * 3 + k] = len[e] > std::numeric_limits<double>::epsilon() ? d[k] / len[e] : d[k];
  }
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
    add_point({{edges[e][0], 1 - coef}, {edges[e][1], coef}});
  }
  return true;
}

void BarycentricMapping::apply(int x) {
  std::vector<double>* outp = out_coord(x);
  if (!outp) return;
  const std::vector<double>& in = in_coord(x);
  const std::size_t n = start_.size() - 1;
  std::vector<double>& out = *outp;
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    double s0 = 0, s1 = 0, s2 = 0;
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
      const double* p = &in[idx_[k] * 3];
      const double w = w_[k];
      s0 += p[0] * w;
      s1 += p[1] * w;
      s2 += p[2] * w;
    }
    out[i * 3] = s0;
    out[i * 3 + 1] = s1;
    out[i * 3 + 2] = s2;
  }
}

void BarycentricMapping::apply_j(int v, int role) {
  std::vector<double>* outp = out_deriv(v, role);
  if (!outp) return;
  const std::vector<double>& in = in_deriv(v, role);
  const std::size_t n = start_.size() - 1;
  std::vector<double>& out = *outp;
  out.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    double s0 = 0, s1 = 0, s2 = 0;
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
      const double* p = &in[idx_[k] * 3];
      const double w = w_[k];
      s0 += p[0] * w;
      s1 += p[1] * w;
      s2 += p[2] * w;
    }
    out[i * 3] = s0;
    out[i * 3 + 1] = s1;
    out[i * 3 + 2] = s2;
  }
}

void BarycentricMapping::apply_jt(int f, int role) {
  const std::vector<double>* outp = out_deriv(f, role);
  if (!outp) return;
  const std::vector<double>& out = *outp;
  std::vector<double>& in = in_deriv(f, role);
  const std::size_t n = std::min(start_.size() - 1, out.size() / 3);
  for (std::size_t i = 0; i < n; ++i) {
    const double* v = &out[i * 3];
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
      double* p = &in[idx_[k] * 3];
      const double w = w_[k];
      p[0] += v[0] * w;
      p[1] += v[1] * w;
      p[2] += v[2] * w;
    }
  }
}

bool BarycentricMapping::jacobian(std::vector<JacobianEntry>& out) {
  const std::size_t n = start_.size() - 1;
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k)
      for (std::uint32_t c = 0; c < 3; ++c)
        out.push_back({0, static_cast<std::uint32_t>(i * 3 + c), idx_[k] * 3 + c, w_[k]});
  return true;
}

void register_barycentric_mapping(Registry& r) {
  ComponentInfo info;
  info.name = "BarycentricMapping";
  info.category = "Mapping/Linear";
  info.description = "points embedded in the elements of the input topology (barycentric weights)";
  info.templates = {"Vec3d,Vec3d"};
  info.default_template = "Vec3d,Vec3d";
  info.requirement = Requirement::mapping;
  info.create = [](const std::string& t) -> std::unique_ptr<Component> {
    StateType in, out;
    if (!parse_mapping_template(t, in, out)) return nullptr;
    return std::make_unique<BarycentricMapping>(in, out);
  };
  r.add(std::move(info));
}

}  // namespace sinew
