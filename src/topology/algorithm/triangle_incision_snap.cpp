// Snapping the ends of an incision path (SOFA's SnapBorderPath, triangle_incision.h): an end
// inside a triangle close to one of its edges (a coefficient below epsilonSnapBorder) moves onto
// that triangle's vertex when the edge is inner and a coefficient exceeds 1 − epsilon, or onto
// the edge itself (projection) when the edge is on the border — so that a cut ending near the
// border reaches it and one ending near a vertex ends on it instead of making a sliver.
#include <Eigen/Geometry>  // cross products

#include "core/roles.h"
#include "topology/algorithm/triangle_incision.h"

namespace sinew::incision {

namespace {

void erase_at(Path& p, std::size_t i) {
  p.kinds.erase(p.kinds.begin() + static_cast<std::ptrdiff_t>(i));
  p.indices.erase(p.indices.begin() + static_cast<std::ptrdiff_t>(i));
  p.barycoefs.erase(p.barycoefs.begin() + static_cast<std::ptrdiff_t>(i));
}

// Barycentric coordinates (on e[0], on e[1]) of the orthogonal projection of c on edge e; false
// when it falls outside the edge.
bool project_on_edge(const Mesh& m, unsigned e, const Vec3& c, double& on0, double& on1) {
  const Edge& ed = m.topology->edges()[e];
  const Vec3 p0 = m.position(ed[0]), p1 = m.position(ed[1]);
  const Vec3 ab = p1 - p0;
  const double l2 = ab.dot(ab);
  if (l2 == 0.0) return false;
  const double t = (c - p0).dot(ab) / l2;
  if (t < 0.0 || t > 1.0) return false;
  on0 = 1.0 - t;
  on1 = t;
  return true;
}

// One end: `back` selects the last path object (and its neighbour before it), else the first.
void snap_end(const Mesh& m, bool back, Vec3& a, const Vec3& end_point, Path& path, double eps) {
  const auto& topo = *m.topology;
  auto end = [&] { return back ? path.kinds.size() - 1 : std::size_t{0}; };
  for (int i = 0; i < 3; ++i) {
    if (!(path.barycoefs[end()][i] < eps)) continue;
    const unsigned tri = path.indices[end()];
    const unsigned edge = topo.edges_in_triangle()[tri][i];
    if (topo.triangles_around_edge()[edge].size() > 1) {
      // Inner edge: snap onto a vertex when one coefficient is large, dropping the path objects
      // next to the end that now lie on that vertex (its edges, or itself).
      bool found = false;
      unsigned vertex = 0;
      for (int j = 0; j < 3; ++j)
        if (path.barycoefs[end()][j] > 1 - eps) {
          vertex = topo.triangles()[tri][j];
          path.kinds[end()] = Elem::point;
          path.indices[end()] = vertex;
          found = true;
          break;
        }
      if (path.kinds.size() <= 2) break;
      while (found) {
        const std::size_t next = back ? path.kinds.size() - 2 : 1;
        bool point_done = true, all_done = true;
        if (path.kinds[next] == Elem::edge) {
          for (unsigned e : topo.edges_around_vertex()[vertex])
            if (e == path.indices[next]) {
              erase_at(path, next);
              all_done = false;
              break;
            }
        } else if (path.kinds[next] == Elem::point) {
          if (path.indices[next] == vertex) {
            erase_at(path, next);
            point_done = false;
          }
        } else {
          found = false;
        }
        if (point_done && all_done) found = false;
        if (path.kinds.size() < 2) break;  // guard: SOFA would read before the path
      }
      break;
    }
    // Border edge: the end moves onto it (projection of the end point).
    const std::size_t nb = back ? path.kinds.size() - 2 : 1;
    if (path.kinds.size() >= 2 && path.indices[nb] == edge && path.kinds[nb] == Elem::edge) {
      // The path already crosses that edge next to the end: the end is dropped (SOFA warns too).
      erase_at(path, end());
      break;
    }
    double on0 = 0, on1 = 0;
    if (!project_on_edge(m, edge, end_point, on0, on1)) continue;
    path.kinds[end()] = Elem::edge;
    path.indices[end()] = edge;
    path.barycoefs[end()] = Vec3(on1, on0, 0.0);
    const Edge& ed = topo.edges()[edge];
    // SOFA writes the projected position into the start point `a`, for either end.
    a = m.position(ed[0]) * (1 - on1) + m.position(ed[1]) * on1;
    break;
  }
}

}  // namespace

void snap_border_path(const Mesh& m, unsigned pa, Vec3& a, unsigned pb, Vec3& b, Path& path,
                      const std::vector<unsigned>& snapped, double eps) {
  bool snap_a = false, snap_b = false;
  for (unsigned p : snapped) {
    if (p == pa) snap_a = true;
    else if (p == pb) snap_b = true;
  }
  if (path.kinds.empty()) return;
  if (!snap_a && path.kinds.front() == Elem::triangle) snap_end(m, false, a, a, path, eps);
  if (path.kinds.empty()) return;
  const Vec3 end_b = b;
  if (!snap_b && path.kinds.back() == Elem::triangle) snap_end(m, true, a, end_b, path, eps);
}

}  // namespace sinew::incision
