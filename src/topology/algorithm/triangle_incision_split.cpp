// The topological half of the incision (triangle_incision.h): splitting the triangles along a
// path (SOFA's SplitAlongPath) and duplicating the path's points (InciseAlongEdgeList), through
// the modifier so that every consumer of the container follows.
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include <Eigen/Geometry>  // cross products

#include "core/roles.h"
#include "topology/algorithm/triangle_incision.h"
#include "topology/dynamic/triangle_set_topology_modifier.h"

namespace sinew::incision {

namespace {

unsigned edge_index(const MeshTopologyBase& t, unsigned a, unsigned b) {
  const auto& shells = t.edges_around_vertex();
  if (a >= shells.size()) return kInvalid;
  for (unsigned e : shells[a]) {
    const Edge& ed = t.edges()[e];
    if ((ed[0] == a && ed[1] == b) || (ed[0] == b && ed[1] == a)) return e;
  }
  return kInvalid;
}

int vertex_in_triangle(const Triangle& t, unsigned v) {
  for (int i = 0; i < 3; ++i)
    if (t[i] == v) return i;
  return -1;
}

int edge_in_triangle(const std::array<unsigned, 3>& eit, unsigned e) {
  for (int i = 0; i < 3; ++i)
    if (eit[i] == e) return i;
  return -1;
}

unsigned other_point(const Triangle& t, unsigned a, unsigned b) {
  if (t[0] != a && t[0] != b) return t[0];
  if (t[1] != a && t[1] != b) return t[1];
  return t[2];
}

// SOFA's isQuadDeulaunayOriented: quad p1 p2 p3 p4 cut along (p2, p4) meets the Delaunay
// condition when the angles at p1 and p3 sum to at most π.
bool delaunay_oriented(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const double alpha = std::acos((p2 - p1).normalized().dot((p4 - p1).normalized()));
  const double beta = std::acos((p2 - p3).normalized().dot((p4 - p3).normalized()));
  return alpha + beta <= std::numbers::pi;
}

// Where a new point of the path comes from (SOFA's PointAncestorElem): an edge and the
// coordinate on it, or a triangle.
struct Source {
  Elem kind;
  unsigned index;
};

}  // namespace

int split_along_path(Mesh& m, unsigned ind_a, Vec3& a, unsigned ind_b, Vec3& b, Path& path,
                     std::vector<unsigned>& new_edges, double eps_path, double eps_border, std::string* why) {
  if (path.indices.empty()) return 0;
  std::vector<std::vector<double>> snap;  // SOFA's points2Snap rows: vertex, x, y, z, ancestors…
  if (eps_path != 0.0) snap_along_path(m, path, snap, eps_path);
  if (eps_border != 0.0) {
    std::vector<unsigned> snapped;
    for (const auto& row : snap) snapped.push_back(static_cast<unsigned>(row[0]));
    snap_border_path(m, ind_a, a, ind_b, b, path, snapped, eps_border);
  }
  const std::size_t n = path.indices.size();
  if (n == 0) return 0;
  MeshTopologyBase& topo = *m.topology;
  const auto& tris = topo.triangles();
  const auto& edges = topo.edges();
  unsigned next_point = static_cast<unsigned>(topo.nb_points());
  unsigned next_triangle = static_cast<unsigned>(tris.size());
  std::vector<std::vector<unsigned>> p_ancestors;
  std::vector<std::vector<double>> p_coefs;
  std::vector<Source> sources;
  std::vector<unsigned> path_points;  // the path's point at each step (old or new)
  // New points: one per crossed edge and per end inside a triangle, in path order.
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned id = path.indices[i];
    const Vec3& c = path.barycoefs[i];
    switch (path.kinds[i]) {
      case Elem::point:
        path_points.push_back(id);
        // A snapped vertex moves between the path points around it (the new points just before
        // and after it, or the old points when those are path points too); at an end of the path
        // (border snap) between up to three of its neighbours.
        for (auto& row : snap) {
          if (static_cast<unsigned>(row[0]) != id) continue;
          if (i == 0 || i == n - 1) {
            int found = 0;
            for (unsigned e : topo.edges_around_vertex()[id]) {
              const Edge& ed = edges[e];
              row.push_back(ed[0] == id ? ed[1] : ed[0]);
              if (++found == 3) break;
            }
            if (found != 3 && why) *why += "snapping vertex " + std::to_string(id) + ": fewer than 3 neighbours; ";
            break;
          }
          row.push_back(next_point - 1.0);
          row.push_back(next_point);
          if (path.kinds[i - 1] == Elem::point) row[4] = path.indices[i - 1];
          if (path.kinds[i + 1] == Elem::point) row[5] = path.indices[i + 1];
          break;
        }
        break;
      case Elem::edge:
        p_ancestors.push_back({edges[id][0], edges[id][1]});
        p_coefs.push_back({1.0 - c[0], c[0]});
        sources.push_back({Elem::edge, id});
        path_points.push_back(next_point++);
        break;
      case Elem::triangle:
        p_ancestors.push_back({tris[id][0], tris[id][1], tris[id][2]});
        // SOFA adds these points from their ancestor element and local coordinates (c1, c2): the
        // first weight is recomputed as 1 − c1 − c2 (not c0), which rounds differently.
        p_coefs.push_back({1 - c[1] - c[2], c[1], c[2]});
        sources.push_back({Elem::triangle, id});
        path_points.push_back(next_point++);
        break;
    }
  }
  // The triangles replacing each crossed one, by pair of consecutive path objects.
  std::vector<Triangle> new_tris;
  std::vector<std::vector<unsigned>> tri_ancestors;
  std::vector<unsigned> removed;
  auto add = [&](unsigned a, unsigned b, unsigned c, unsigned ancestor) {
    new_tris.push_back({a, b, c});
    tri_ancestors.push_back({ancestor});
    ++next_triangle;
  };
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return -1;
  };
  // The triangle of edge `e`'s shell that holds vertex v (SOFA keeps the last one seen if none).
  auto triangle_of_edge_with = [&](unsigned e, unsigned v, unsigned& tid) {
    tid = kInvalid;
    for (unsigned s : topo.triangles_around_edge()[e]) {
      tid = s;
      if (vertex_in_triangle(tris[s], v) >= 0) return true;
    }
    return false;
  };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Elem k0 = path.kinds[i], k1 = path.kinds[i + 1];
    const unsigned o0 = path.indices[i], o1 = path.indices[i + 1];
    if (k0 == Elem::point && k1 == Elem::point) {
      if (edge_index(topo, o1, o0) == kInvalid)
        return fail("consecutive path points " + std::to_string(o0) + " and " + std::to_string(o1) +
                    " share no edge");
    } else if (k0 == Elem::point && k1 == Elem::edge) {
      unsigned tid;
      if (!triangle_of_edge_with(o1, o0, tid))
        return fail("no triangle of edge " + std::to_string(o1) + " holds point " + std::to_string(o0));
      const Triangle tri = tris[tid];
      const int v = vertex_in_triangle(tri, o0);
      add(tri[v], path_points[i + 1], tri[(v + 2) % 3], tid);
      add(tri[v], tri[(v + 1) % 3], path_points[i + 1], tid);
      removed.push_back(tid);
    } else if (k0 == Elem::point && k1 == Elem::triangle) {
      const Triangle tri = tris[o1];
      add(tri[0], tri[1], path_points[i + 1], o1);
      add(tri[1], tri[2], path_points[i + 1], o1);
      add(tri[2], tri[0], path_points[i + 1], o1);
      removed.push_back(o1);
    } else if (k0 == Elem::edge && k1 == Elem::point) {
      unsigned tid;
      if (!triangle_of_edge_with(o0, o1, tid))
        return fail("no triangle of edge " + std::to_string(o0) + " holds point " + std::to_string(o1));
      const Triangle tri = tris[tid];
      const int v = vertex_in_triangle(tri, o1);
      const unsigned p1 = path_points[i];
      add(o1, p1, tri[(v + 2) % 3], tid);
      add(o1, tri[(v + 1) % 3], p1, tid);
      removed.push_back(tid);
    } else if (k0 == Elem::edge && k1 == Elem::edge) {
      // The triangle holding both edges becomes the corner triangle plus a quad split by Delaunay.
      const unsigned p1 = path_points[i], p2 = path_points[i + 1];
      const Edge e1 = edges[o0], e2 = edges[o1];
      const double c1 = path.barycoefs[i][0], c2 = path.barycoefs[i + 1][0];
      const Vec3 pos1 = m.position(e1[0]) * (1 - c1) + m.position(e1[1]) * c1;
      const Vec3 pos2 = m.position(e2[0]) * (1 - c2) + m.position(e2[1]) * c2;
      unsigned tid = kInvalid;
      bool found = false;
      for (unsigned s : topo.triangles_around_edge()[o0]) {
        tid = s;
        if (edge_in_triangle(topo.edges_in_triangle()[s], o1) >= 0) {
          found = true;
          break;
        }
      }
      if (!found)
        return fail("edges " + std::to_string(o0) + " and " + std::to_string(o1) + " of the path share no triangle");
      const Triangle tri = tris[tid];
      const int corner_in_e1 = (e1[0] == e2[0] || e1[0] == e2[1]) ? 0 : 1;
      const int v = vertex_in_triangle(tri, e1[corner_in_e1]);
      unsigned order[5];  // corner, first cut point, tri+1, tri+2, second cut point
      Vec3 pos[4];
      order[0] = e1[corner_in_e1];
      if (tri[(v + 1) % 3] == e1[(corner_in_e1 + 1) % 2]) {
        pos[0] = pos1, order[1] = p1, pos[3] = pos2, order[4] = p2;
      } else {
        pos[0] = pos2, order[1] = p2, pos[3] = pos1, order[4] = p1;
      }
      pos[1] = m.position(tri[(v + 1) % 3]);
      pos[2] = m.position(tri[(v + 2) % 3]);
      order[2] = tri[(v + 1) % 3];
      order[3] = tri[(v + 2) % 3];
      add(order[0], order[1], order[4], tid);
      if (delaunay_oriented(pos[0], pos[1], pos[2], pos[3])) {
        add(order[1], order[2], order[4], tid);
        add(order[2], order[3], order[4], tid);
      } else {
        add(order[1], order[2], order[3], tid);
        add(order[4], order[1], order[3], tid);
      }
      removed.push_back(tid);
    } else if (k0 == Elem::edge && k1 == Elem::triangle) {
      const unsigned p1 = path_points[i], p2 = path_points[i + 1];
      const Triangle tri = tris[o1];
      const int j = edge_in_triangle(topo.edges_in_triangle()[o1], o0);
      if (j < 0) return fail("edge " + std::to_string(o0) + " is not an edge of triangle " + std::to_string(o1));
      add(p2, tri[j], tri[(j + 1) % 3], o1);
      add(p2, tri[(j + 2) % 3], tri[j], o1);
      add(p2, tri[(j + 1) % 3], p1, o1);
      add(p2, p1, tri[(j + 2) % 3], o1);
      removed.push_back(o1);
    } else if (k0 == Elem::triangle && k1 == Elem::point) {
      const unsigned p1 = path_points[i];
      const Triangle tri = tris[o0];
      add(p1, tri[0], tri[1], o0);
      add(p1, tri[1], tri[2], o0);
      add(p1, tri[2], tri[0], o0);
      removed.push_back(o0);
    } else if (k0 == Elem::triangle && k1 == Elem::edge) {
      const unsigned p1 = path_points[i], p2 = path_points[i + 1];
      const Triangle tri = tris[o0];
      const int j = edge_in_triangle(topo.edges_in_triangle()[o0], o1);
      if (j < 0) return fail("edge " + std::to_string(o1) + " is not an edge of triangle " + std::to_string(o0));
      add(p1, tri[j], tri[(j + 1) % 3], o0);
      add(p1, tri[(j + 2) % 3], tri[j], o0);
      add(p1, tri[(j + 1) % 3], p2, o0);
      add(p1, p2, tri[(j + 2) % 3], o0);
      removed.push_back(o0);
    } else {  // triangle → triangle: both ends in one triangle
      // SOFA builds five triangles around the inner segment; a path with both ends in the same
      // triangle never reaches here (intersected_objects_list refuses it), so it is refused too.
      return fail(o0 == o1 ? "the cut starts and ends inside triangle " + std::to_string(o0) +
                                  " (not supported: the path crosses no edge)"
                            : "incision not in the mesh plane (triangle " + std::to_string(o0) +
                                  " followed by triangle " + std::to_string(o1) + ")");
    }
  }
  // 1. the new points, with their DoFs interpolated from their edge or triangle.
  const unsigned first_new = next_point - static_cast<unsigned>(sources.size());
  if (!sources.empty()) m.modifier->add_points(static_cast<unsigned>(sources.size()), p_ancestors, p_coefs, true);
  // 2. the edges of the new triangles that do not exist yet (lower vertex first), in triangle order.
  std::set<std::pair<unsigned, unsigned>> seen;
  std::vector<Edge> edges_added;
  for (const Triangle& t : new_tris)
    for (int k = 0; k < 3; ++k) {
      unsigned a = t[k], b = t[(k + 1) % 3];
      if (a > b) std::swap(a, b);
      if (a < first_new && b < first_new && edge_index(topo, a, b) != kInvalid) continue;
      if (!seen.insert({a, b}).second) continue;
      edges_added.push_back({a, b});
    }
  if (!edges_added.empty()) m.modifier->add_edges(edges_added);
  // 3. SOFA's addRemoveTriangles: the new triangles (ancestor: the triangle they split), then the
  // split ones removed (with the edges and points they leave isolated).
  std::vector<std::vector<double>> tri_coefs(new_tris.size(), std::vector<double>{1.0});
  m.modifier->add_triangles(new_tris, tri_ancestors, tri_coefs);
  m.modifier->remove_triangles(removed, true, true);
  // 4. The snapped vertices move onto the path: coefficients of their mean position with respect
  //    to their ancestors (distances along the segment for two, barycentric for three).
  if (!snap.empty()) {
    std::vector<unsigned> ids;
    std::vector<std::vector<unsigned>> anc;
    std::vector<std::vector<double>> coefs;
    for (const auto& row : snap) {
      if (row.size() < 6) continue;  // SOFA would read past the row
      const Vec3 p(row[1], row[2], row[3]);
      const unsigned a0 = static_cast<unsigned>(row[4]), a1 = static_cast<unsigned>(row[5]);
      ids.push_back(static_cast<unsigned>(row[0]));
      if (row.size() == 7) {
        const unsigned a2 = static_cast<unsigned>(row[6]);
        anc.push_back({a0, a1, a2});
        const Vec3 c = barycoefs_of_points(m, p, a0, a1, a2);
        coefs.push_back({c[0], c[1], c[2]});
      } else {
        anc.push_back({a0, a1});
        const Vec3 q0 = m.position(a0), q1 = m.position(a1);
        const double d = (q1 - q0).norm();
        if (d < 1e-6) coefs.push_back({0.5, 0.5});  // SOFA's EQUALITY_THRESHOLD
        else coefs.push_back({(p - q1).norm() / d, (p - q0).norm() / d});
      }
    }
    if (!ids.empty()) m.modifier->move_points(ids, anc, coefs);
  }
  m.modifier->notify_ending_event();
  // The edges joining consecutive path points: the path, now made of edges.
  for (std::size_t i = 0; i + 1 < path_points.size(); ++i) {
    const unsigned e = edge_index(topo, path_points[i], path_points[i + 1]);
    if (e != kInvalid) new_edges.push_back(e);
    else if (why)
      *why += "edge " + std::to_string(path_points[i]) + " - " + std::to_string(path_points[i + 1]) + " not found; ";
  }
  return static_cast<int>(sources.size());
}

bool incise_along_edge_list(Mesh& m, const std::vector<unsigned>& edges, std::vector<unsigned>& new_points,
                            std::vector<unsigned>& end_points, bool& reach_border, std::string* why) {
  MeshTopologyBase& topo = *m.topology;
  const std::size_t ne = edges.size();
  if (ne == 0) return true;
  const auto& all_edges = topo.edges();
  // The path's points in order.
  std::vector<unsigned> pts = {all_edges[edges[0]][0], all_edges[edges[0]][1]};
  if (ne > 1) {
    const Edge& e = all_edges[edges[1]];
    if (pts[0] == e[0] || pts[0] == e[1]) std::swap(pts[0], pts[1]);
    for (std::size_t i = 1; i < ne; ++i) {
      const Edge& ed = all_edges[edges[i]];
      if (ed[0] == pts.back()) pts.push_back(ed[1]);
      else if (ed[1] == pts.back()) pts.push_back(ed[0]);
      else {
        if (why) *why = "the edges of the cut are not connected after number " + std::to_string(i - 1);
        return false;
      }
    }
  }
  for (unsigned e : edges)
    if (topo.triangles_around_edge()[e].size() != 2) {
      if (why) *why = "cannot split edge " + std::to_string(e) + ": it has " +
                      std::to_string(topo.triangles_around_edge()[e].size()) + " triangles, not 2";
      return false;
    }
  // An end on the border (fewer triangles than edges around it) is duplicated too; an inner end stays.
  auto on_border = [&](unsigned p) {
    return topo.triangles_around_vertex()[p].size() < topo.edges_around_vertex()[p].size();
  };
  const bool begin_border = on_border(pts.front()), end_border = on_border(pts.back());
  if (!begin_border) end_points.push_back(pts.front());
  if (!end_border) end_points.push_back(pts.back());
  else reach_border = true;
  const std::size_t first = begin_border ? 0 : 1;
  const std::size_t last = end_border ? pts.size() - 1 : pts.size() - 2;
  unsigned next_point = static_cast<unsigned>(topo.nb_points());
  std::vector<std::vector<unsigned>> p_ancestors;
  std::vector<std::vector<double>> p_coefs;
  std::map<unsigned, unsigned> split;
  for (std::size_t i = first; i <= last && i < pts.size(); ++i) {
    p_ancestors.push_back({pts[i]});
    p_coefs.push_back({1.0});
    new_points.push_back(next_point);
    split[pts[i]] = next_point++;
  }
  // The triangles on one side of the path: turning around each path point, from the side of the
  // first edge's first triangle, until the next path edge (or the border).
  const auto& tris = topo.triangles();
  std::set<unsigned> updated;
  auto turn = [&](unsigned tid, unsigned p0, unsigned p1, unsigned stop, std::size_t min_shell) {
    for (std::size_t guard = 0; guard <= tris.size(); ++guard) {
      updated.insert(tid);
      const unsigned p2 = other_point(tris[tid], p0, p1);
      if (p2 == stop) break;
      const unsigned e = edge_index(topo, p0, p2);
      if (e == kInvalid) break;
      const auto& around = topo.triangles_around_edge()[e];
      if (min_shell == 2 ? around.size() != 2 : around.size() < 2) break;  // border or non-manifold
      tid = around[0] == tid ? around[1] : around[0];
      p1 = p2;
    }
    return tid;
  };
  unsigned t0 = topo.triangles_around_edge()[edges[0]][0];
  if (begin_border) turn(t0, pts[0], pts[1], kInvalid, 2);
  for (std::size_t i = 0; i + 1 < ne; ++i) t0 = turn(t0, pts[i + 1], pts[i], pts[i + 2], 1);
  if (end_border) turn(t0, pts[ne], pts[ne - 1], kInvalid, 2);
  std::vector<Triangle> new_tris;
  std::vector<std::vector<unsigned>> tri_ancestors;
  std::vector<std::vector<double>> tri_coefs;
  std::vector<unsigned> removed;
  for (unsigned tid : updated) {  // increasing index, as SOFA's std::set
    Triangle t = tris[tid];
    bool changed = false;
    for (int c = 0; c < 3; ++c) {
      auto it = split.find(t[c]);
      if (it != split.end()) {
        t[c] = it->second;
        changed = true;
      }
    }
    if (!changed) continue;  // SOFA reports it; the triangle keeps its points
    new_tris.push_back(t);
    removed.push_back(tid);
    tri_ancestors.push_back({tid});
    tri_coefs.push_back({1.0});
  }
  // The copies (each DoF equal to its original), then the triangles moved onto them.
  if (!p_ancestors.empty())
    m.modifier->add_points(static_cast<unsigned>(p_ancestors.size()), p_ancestors, p_coefs, true);
  m.modifier->add_triangles(new_tris, tri_ancestors, tri_coefs);
  m.modifier->remove_triangles(removed, true, true);
  return true;
}

}  // namespace sinew::incision
