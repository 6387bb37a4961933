// The geometric half of the incision (triangle_incision.h): barycentric coefficients, point
// location and the walk of a segment across the triangles. Reads the mesh, never edits it.
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>  // cross products

#include "core/roles.h"
#include "topology/algorithm/triangle_incision.h"

namespace sinew::incision {

Vec3 Mesh::position(unsigned i) const {
  const std::vector<double>& x = state->read(kPosition);
  if (3 * static_cast<std::size_t>(i) + 2 >= x.size()) return Vec3::Zero();
  return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
}

namespace {

// SOFA's getEdgeIndex: the first edge of a's shell joining a and b (either orientation).
unsigned edge_index(const MeshTopologyBase& t, unsigned a, unsigned b) {
  const auto& shells = t.edges_around_vertex();
  if (a >= shells.size()) return kInvalid;
  for (unsigned e : shells[a]) {
    const Edge& ed = t.edges()[e];
    if ((ed[0] == a && ed[1] == b) || (ed[0] == b && ed[1] == a)) return e;
  }
  return kInvalid;
}

// SOFA's computeSegmentTriangleIntersection: where the segment from a (inside triangle `tri`)
// towards b (projected on the triangle's plane) leaves the triangle. `indices` holds the vertices
// of the edge crossed (in the triangle's order), `bary` the coordinate on it from indices[0],
// `coord_kmin` the parameter along the segment. With `is_entered`, the edge given in `indices`
// (the one the walk came through) is not tested.
bool segment_triangle_intersection(const Mesh& m, bool is_entered, const Vec3& a, const Vec3& b, unsigned tri,
                                   std::vector<unsigned>& indices, double& bary, double& coord_kmin) {
  unsigned first = 0, second = 0;
  if (indices.size() > 1) {
    first = indices[0];
    second = indices[1];
  }
  indices.clear();
  const Triangle& t = m.topology->triangles()[tri];
  auto same = [&](unsigned u, unsigned v) {
    return is_entered && ((u == first && v == second) || (v == first && u == second));
  };
  const bool full[3] = {same(t[0], t[1]), same(t[1], t[2]), same(t[2], t[0])};
  const Vec3 p[3] = {m.position(t[0]), m.position(t[1]), m.position(t[2])};
  Vec3 normal = (p[2] - p[0]).cross(p[1] - p[0]);
  const double norm = normal.norm();
  if (norm == 0.0) return false;  // flat triangle
  normal /= norm;
  const Vec3 ab = b - a;
  const Vec3 ab_proj = ab - normal * ab.dot(normal);
  const Vec3 pb_proj = ab_proj + a;
  const double norm2 = ab_proj.dot(ab_proj);
  if (norm2 == 0.0) return false;  // a and b project on the same point
  const Vec3 n_proj = ab_proj.cross(normal);
  bool validated = false, initialised = false;
  coord_kmin = 0.0;
  // Edges (p0,p1), (p1,p2), (p2,p0) in turn; the farthest crossing along the segment wins.
  for (int j = 0; j < 3; ++j) {
    if (full[j]) continue;
    const Vec3& q0 = p[j];
    const Vec3& q1 = p[(j + 1) % 3];
    const Vec3 n_edge = (q1 - q0).cross(normal);
    const double s_t = (q0 - q1).dot(n_proj);
    const double s_k = (a - pb_proj).dot(n_edge);
    double coord_t = 0.0, coord_k = 0.0;
    bool hit = false;
    if (s_t == 0.0) {  // parallel
      if ((q0 - a).dot(n_proj) == 0.0) {  // on the same line
        const double c1 = (a - q0).dot(a - pb_proj) / norm2;
        const double c2 = (a - q1).dot(a - pb_proj) / norm2;
        if (c1 >= 0) {
          coord_k = c1;
          coord_t = 0.0;
        } else {
          coord_k = c2;
          coord_t = 1.0;
        }
        hit = coord_k > 0.0 && coord_t >= 0.0 && coord_t <= 1.0;
      }
    } else {
      coord_k = (a - q0).dot(n_edge) * 1.0 / s_k;
      coord_t = (q0 - a).dot(n_proj) * 1.0 / s_t;
      hit = coord_k > 0.0 && coord_t >= 0.0 && coord_t <= 1.0;
    }
    if (hit) {
      if (!initialised || coord_k > coord_kmin) {
        indices = {t[j], t[(j + 1) % 3]};
        bary = coord_t;
        coord_kmin = coord_k;
      }
      initialised = true;
    }
    validated = validated || initialised;
  }
  return validated;
}

// SOFA's computeIntersectedPointsList: walks from a's triangle towards b, one crossed edge at a
// time, choosing among the triangles past the crossing (its edge's, or its vertex's when it
// falls on one) the one whose exit lies closest to b.
bool intersected_points_list(const Mesh& m, unsigned last_point, const Vec3& a, const Vec3& b, unsigned& tri_a,
                             unsigned& tri_b, std::vector<unsigned>& edges, std::vector<double>& coords,
                             std::string* why) {
  const MeshTopologyBase& topo = *m.topology;
  bool validated = true, on_boundary = false;
  std::vector<unsigned> indices;
  double coord_t = 0.0, coord_k = 0.0;
  Vec3 p_current = a;
  unsigned t_current = tri_a, t_last = tri_a;
  bool intersected = segment_triangle_intersection(m, false, p_current, b, t_current, indices, coord_t, coord_k);
  // Starting on the previous cut's end point: a's triangle may be the wrong one of its shell.
  if ((!intersected || indices[0] == last_point || indices[1] == last_point) && last_point != kInvalid &&
      last_point < topo.triangles_around_vertex().size()) {
    const std::vector<unsigned> shell = topo.triangles_around_vertex()[last_point];
    for (unsigned s : shell) {
      if (s != t_current)
        intersected = segment_triangle_intersection(m, false, p_current, b, s, indices, coord_t, coord_k);
      if (intersected && indices[0] != last_point && indices[1] != last_point) {
        t_current = s;
        tri_a = s;
        break;
      }
    }
  }
  if (tri_a == tri_b) {
    if (why) *why = "the cut is not made: both ends are in the same triangle " + std::to_string(tri_a);
    return false;
  }
  double coord_k_test = coord_k;
  double dist_min = (b - a).dot(b - a);
  // Each turn crosses one edge; more turns than edges means the walk goes round in circles.
  std::size_t guard = topo.edges().size() + 2;
  while (coord_k_test < 1.0 && validated && intersected) {
    if (guard-- == 0) {
      if (why) *why = "the walk along the cut does not end (more steps than edges)";
      return false;
    }
    const unsigned e = edge_index(topo, indices[0], indices[1]);
    if (e == kInvalid) {
      if (why) *why = "crossed edge (" + std::to_string(indices[0]) + ", " + std::to_string(indices[1]) + ") not found";
      return false;
    }
    edges.push_back(e);
    coords.push_back(topo.edges()[e][0] == indices[0] ? coord_t : 1.0 - coord_t);
    const Vec3 c_current = (1.0 - coord_t) * m.position(indices[0]) + coord_t * m.position(indices[1]);
    p_current = c_current;
    // The triangles past the crossing: around its vertex when it falls on one, else around its edge.
    std::vector<unsigned> shell;
    bool on_vertex = coord_t == 0.0 || coord_t == 1.0;
    if (on_vertex) {
      const unsigned v = coord_t == 0.0 ? indices[0] : indices[1];
      shell = topo.triangles_around_vertex()[v];
    } else {
      shell = topo.triangles_around_edge()[e];
    }
    if (!shell.empty()) t_last = shell[0];
    if (shell.empty() || (on_vertex && shell.size() <= 1)) {
      on_boundary = true;
      validated = false;
      break;
    }
    bool test_init = false;
    const unsigned from = t_current;
    for (unsigned s : shell) {
      if (s == from) continue;
      t_last = s;
      intersected = segment_triangle_intersection(m, true, p_current, b, s, indices, coord_t, coord_k);
      if (!intersected) continue;
      const Vec3 c_test = (1.0 - coord_t) * m.position(indices[0]) + coord_t * m.position(indices[1]);
      const double dist = (b - c_test).dot(b - c_test);
      if (!test_init || (dist < dist_min && coord_k <= 1)) {
        test_init = true;
        coord_k_test = coord_k;
        dist_min = dist;
        t_current = s;
      }
    }
    intersected = test_init;
  }
  if (tri_b == kInvalid) tri_b = t_last;
  const bool reached = tri_b == t_last && coord_k_test >= 1.0;
  if (!(reached && validated && intersected) && why) {
    if (on_boundary) *why = "the cut meets the border of the mesh before reaching triangle " + std::to_string(tri_b);
    else *why = "the cut does not reach triangle " + std::to_string(tri_b) + " (walk ended in triangle " +
                std::to_string(t_last) + ")";
  }
  return reached && validated && intersected;
}

}  // namespace

Vec3 triangle_barycoefs(const Mesh& m, unsigned tri, const Vec3& p) {
  const Triangle& t = m.topology->triangles()[tri];
  return barycoefs_of_points(m, p, t[0], t[1], t[2]);
}

Vec3 barycoefs_of_points(const Mesh& m, const Vec3& p, unsigned i0, unsigned i1, unsigned i2) {
  const Vec3 a = m.position(i0), b = m.position(i1), c = m.position(i2);
  const Vec3 n = (b - a).cross(c - a);
  const double norm2 = n.dot(n);
  if (norm2 < 1e-12) {
    const double third = 1.0 / 3.0;
    return Vec3(third, third, 1.0 - (third + third));
  }
  const Vec3 nn = n / norm2;
  const double ca = nn.dot((b - p).cross(c - p));
  const double cb = nn.dot((c - p).cross(a - p));
  return Vec3(ca, cb, 1.0 - (ca + cb));
}

bool is_point_inside_triangle(const Mesh& m, unsigned tri, const Vec3& p) {
  const Triangle& t = m.topology->triangles()[tri];
  const Vec3 p0 = m.position(t[0]), p1 = m.position(t[1]), p2 = m.position(t[2]);
  const Vec3 n = (p2 - p0).cross(p1 - p0);
  if (n.dot(n) == 0.0) return false;  // flat
  const double zero = -1e-12;
  return (p - p0).dot((p1 - p0).cross(n)) > zero && (p - p1).dot((p2 - p1).cross(n)) > zero &&
         (p - p2).dot((p0 - p2).cross(n)) > zero;
}

unsigned find_element_index(const Mesh& m, const Vec3& p, unsigned old_triangle) {
  const auto& tris = m.topology->triangles();
  const unsigned n = static_cast<unsigned>(tris.size());
  std::vector<unsigned> found;
  // Fast scan: the triangles whose bounding box holds p, then the inside test.
  for (unsigned i = 0; i < n; ++i) {
    Vec3 lo = m.position(tris[i][0]), hi = lo;
    for (int k = 1; k < 3; ++k) {
      lo = lo.cwiseMin(m.position(tris[i][k]));
      hi = hi.cwiseMax(m.position(tris[i][k]));
    }
    bool in = true;
    for (int j = 0; j < 3 && in; ++j) in = !(p[j] < lo[j] || p[j] > hi[j]);
    if (!in || !is_point_inside_triangle(m, i, p)) continue;
    found.push_back(i);
    if (i == old_triangle) return old_triangle;
  }
  if (found.size() == 1) return found[0];
  found.clear();
  // Else p projected on each triangle's plane.
  for (unsigned i = 0; i < n; ++i) {
    const Triangle& t = tris[i];
    const Vec3 p0 = m.position(t[0]);
    Vec3 normal = (m.position(t[1]) - p0).cross(m.position(t[2]) - p0);
    if (normal.norm() == 0.0) break;  // as SOFA: a flat triangle ends the search
    normal /= normal.norm();
    const double d = -p0.dot(normal);
    const double x = p[0], y = p[1], z = p[2], a = normal[0], b = normal[1], c = normal[2];
    const Vec3 proj((b * b + c * c) * x - a * b * y - a * c * z - d * a,
                    -a * b * x + (a * a + c * c) * y - b * c * z - d * b,
                    -a * c * x - b * c * y + (a * a + b * b) * z - d * c);
    if (!is_point_inside_triangle(m, i, proj)) continue;
    if (i == old_triangle) return i;
    found.push_back(i);
  }
  return found.empty() ? kInvalid : found[0];
}

bool intersected_objects_list(const Mesh& m, unsigned last_point, const Vec3& a, const Vec3& b, unsigned& tri_a,
                              unsigned& tri_b, Path& path, std::string* why) {
  const std::size_t nt = m.topology->triangles().size();
  if (tri_a >= nt || tri_b >= nt) {
    if (why) *why = "a point of the cut is in no triangle (index out of range)";
    return false;
  }
  std::vector<unsigned> edges;
  std::vector<double> coords;
  if (!intersected_points_list(m, last_point, a, b, tri_a, tri_b, edges, coords, why)) return false;
  // Start: the previous cut's end point (its position as "coefficients", as SOFA), else a's triangle.
  if (last_point != kInvalid) {
    path.kinds.push_back(Elem::point);
    path.indices.push_back(last_point);
    path.barycoefs.push_back(m.position(last_point));
  } else {
    path.kinds.push_back(Elem::triangle);
    path.indices.push_back(tri_a);
    path.barycoefs.push_back(triangle_barycoefs(m, tri_a, a));
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    path.kinds.push_back(Elem::edge);
    path.indices.push_back(edges[i]);
    path.barycoefs.push_back(Vec3(coords[i], 0.0, 0.0));
  }
  // End: b's vertex when b sits on it (coefficient above 0.9999), else b's triangle.
  const Vec3 cb = triangle_barycoefs(m, tri_b, b);
  bool on_point = false;
  for (int i = 0; i < 3 && !on_point; ++i)
    if (cb[i] > 0.9999) {
      path.kinds.push_back(Elem::point);
      path.indices.push_back(m.topology->triangles()[tri_b][i]);
      on_point = true;
    }
  if (!on_point) {
    path.kinds.push_back(Elem::triangle);
    path.indices.push_back(tri_b);
  }
  path.barycoefs.push_back(cb);
  return true;
}

}  // namespace sinew::incision
