// Snapping an incision path (triangle_incision.h). SOFA's SnapAlongPath: a mesh vertex the path
// passes within epsilonSnapPath of (on two or more of its objects) replaces them, and later moves
// to their mean position, instead of the path making slivers around it. SOFA's SnapBorderPath: an end
// inside a triangle close to one of its edges (a coefficient below epsilonSnapBorder) moves onto
// that triangle's vertex when the edge is inner and a coefficient exceeds 1 − epsilon, or onto
// the edge itself (projection) when the edge is on the border — so that a cut ending near the
// border reaches it and one ending near a vertex ends on it instead of making a sliver.
#include <Eigen/Geometry>  // cross products

#include <algorithm>
#include <map>

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

void snap_along_path(const Mesh& m, Path& path, std::vector<std::vector<double>>& points2snap, double eps) {
  const auto& topo = *m.topology;
  const auto& tris = topo.triangles();
  const auto& edges = topo.edges();
  // 1. The vertices the path passes close to: an edge crossing within eps of an end, an end
  //    triangle with a coefficient above 1 − eps.
  std::map<unsigned, std::vector<unsigned>> near;  // vertex → path positions close to it
  std::map<unsigned, Vec3> sum;                    // vertex → sum of those positions
  for (std::size_t i = 0; i < path.kinds.size(); ++i) {
    const Vec3& c = path.barycoefs[i];
    if (path.kinds[i] == Elem::edge) {
      if (c[0] < eps) near[edges[path.indices[i]][0]];
      else if (c[0] > 1.0 - eps) near[edges[path.indices[i]][1]];
    } else if (path.kinds[i] == Elem::triangle) {
      for (int j = 0; j < 3; ++j)
        if (c[j] > 1.0 - eps) {
          near[tris[path.indices[i]][j]];
          break;
        }
    }
  }
  if (near.empty()) return;
  for (auto& [v, s] : near) sum[v] = Vec3::Zero();
  // 2. Every path object touching such a vertex (a point on it, an edge having it, an end
  //    triangle close to it), with its position.
  for (std::size_t i = 0; i < path.kinds.size(); ++i) {
    const unsigned id = path.indices[i];
    if (path.kinds[i] == Elem::point) {
      if (near.count(id)) {
        near[id].push_back(static_cast<unsigned>(i));
        sum[id] += m.position(id);
      }
    } else if (path.kinds[i] == Elem::edge) {
      const Edge& e = edges[id];
      for (int k = 0; k < 2; ++k)
        if (near.count(e[k])) {
          near[e[k]].push_back(static_cast<unsigned>(i));
          sum[e[k]] += m.position(e[0]) * (1 - path.barycoefs[i][0]) + m.position(e[1]) * path.barycoefs[i][0];
          break;
        }
    } else {
      const Triangle& t = tris[id];
      for (int k = 0; k < 3; ++k)
        if (near.count(t[k]) && path.barycoefs[i][k] > 1 - eps) {
          near[t[k]].push_back(static_cast<unsigned>(i));
          const Vec3& c = path.barycoefs[i];
          sum[t[k]] += m.position(t[0]) * c[0] + m.position(t[1]) * c[1] + m.position(t[2]) * c[2];
          break;
        }
    }
  }
  // 3. Border vertices are not snapped (moving them would change the outline).
  for (auto it = near.begin(); it != near.end();) {
    bool border = false;
    for (unsigned e : topo.edges_around_vertex()[it->first])
      if (topo.triangles_around_edge()[e].size() == 1) {
        border = true;
        break;
      }
    it = border ? near.erase(it) : std::next(it);
  }
  // 4. A vertex close to two or more path objects replaces them (the first becomes the vertex,
  //    the others leave the path) and will move to their mean position; one alone is left.
  std::vector<unsigned> drop;
  for (const auto& [v, at] : near) {
    if (at.size() == 1) continue;  // border case or re-incision
    const Vec3 mean = sum[v] / static_cast<double>(at.size());
    points2snap.push_back({static_cast<double>(v), mean[0], mean[1], mean[2]});
    path.kinds[at[0]] = Elem::point;
    path.indices[at[0]] = v;
    path.barycoefs[at[0]][0] = -1.0;
    drop.insert(drop.end(), at.begin() + 1, at.end());
  }
  std::sort(drop.begin(), drop.end());
  for (auto it = drop.rbegin(); it != drop.rend(); ++it) erase_at(path, *it);
}

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
